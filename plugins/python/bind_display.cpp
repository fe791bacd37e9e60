// What an OCIO config offers (displays, views, looks, colour spaces): the Blender add-on lists these.
#include "bindings.h"
#include "cgtmo/display/display.h"

namespace cgtmo::python {

void bind_display(py::module_& m) {
  m.def(
      "color_config",
      [](const std::string& path) {
        std::string origin;
        const auto cfg = display::load_config(path, &origin);
        py::dict d;
        d["origin"] = origin;
        d["default_display"] = std::string(cfg->getDefaultDisplay());
        py::dict displays;
        for (int i = 0; i < cfg->getNumDisplays(); ++i) {
          const char* disp = cfg->getDisplay(i);
          py::list views;
          for (int j = 0; j < cfg->getNumViews(disp); ++j) views.append(std::string(cfg->getView(disp, j)));
          displays[py::str(disp)] = views;
        }
        d["displays"] = displays;
        py::list looks;
        for (int i = 0; i < cfg->getNumLooks(); ++i) looks.append(std::string(cfg->getLookNameByIndex(i)));
        d["looks"] = looks;
        py::list spaces;  // what colorspace= accepts (roles and aliases too)
        for (int i = 0; i < cfg->getNumColorSpaces(); ++i) spaces.append(std::string(cfg->getColorSpaceNameByIndex(i)));
        d["colorspaces"] = spaces;
        return d;
      },
      py::arg("path") = "",
      "The OCIO config that apply() uses (path, else $OCIO, else built-in): origin, default_display, "
      "displays (name -> list of views), looks and colorspaces (the names colorspace= takes).");
}

}  // namespace cgtmo::python
