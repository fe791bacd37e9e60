#include "cgtmo/bake/config_writer.h"

#include <cmath>
#include <sstream>

#include "cgtmo/color/chromaticities.h"
#include "cgtmo/color/matrix.h"
#include "cgtmo/color/working_space.h"
#include "cgtmo/display/display.h"
#include "cgtmo/util/repro_math.h"

namespace cgtmo::bake {

namespace {

constexpr const char* kShaperSpaceName = "Log2 Shaper";
constexpr const char* kStandardView = "Standard";

// Linear spaces into Rec.709 from their chromaticities (color/chromaticities.h, the one
// derivation the input colour space uses too); all share the D65 white except the ACES ones.
color::Mat3 rec2020_to_rec709() {
  return color::rgb_to_xyz(color::rec709()).inverse() * color::rgb_to_xyz(color::rec2020());
}

OCIO::ColorSpaceRcPtr linear_space(const char* name, const char* description, const color::Mat3& to_rec709) {
  auto cs = OCIO::ColorSpace::Create(OCIO::REFERENCE_SPACE_SCENE);
  cs->setName(name);
  cs->setFamily("Linear");
  cs->setDescription(description);
  cs->setEncoding("scene-linear");
  cs->setTransform(color::matrix_transform(to_rec709), OCIO::COLORSPACE_DIR_TO_REFERENCE);
  return cs;
}

OCIO::LookRcPtr make_look(const std::string& name, const std::string& description, OCIO::TransformRcPtr t) {
  auto look = OCIO::Look::Create();
  look->setName(name.c_str());
  look->setProcessSpace(kShaperSpaceName);
  look->setDescription(description.c_str());
  look->setTransform(t);
  return look;
}

// Exposure in the shaper space: decode, scale by 2^stops, then `rest` (a view's chain from
// scene-linear to display-linear, or nothing), encode.
OCIO::TransformRcPtr exposure_look_transform(int stops, const ConfigView* view) {
  auto g = OCIO::GroupTransform::Create();
  g->appendTransform(kShaperSpace.transform(OCIO::TRANSFORM_DIR_INVERSE));
  const double k = repro::exp2(stops);
  g->appendTransform(color::matrix_transform(color::Mat3{{{{k, 0, 0}, {0, k, 0}, {0, 0, k}}}}));
  if (view) {
    auto v = view_transform(*view->lut, view->lut_file);
    for (int i = 0; i < v->getNumTransforms(); ++i) g->appendTransform(v->getTransform(i));
  }
  g->appendTransform(kShaperSpace.transform());
  return g;
}

std::string stops_text(int stops) {
  return (stops > 0 ? "+" : "") + std::to_string(stops) + (std::abs(stops) == 1 ? " stop" : " stops");
}

}  // namespace

std::string exposure_look_name(const std::string& view, int stops) { return view + " - " + stops_text(stops); }

void add_view(OCIO::ConfigRcPtr& config, const ConfigView& view) {
  config->addLook(make_look(view.name, view.description, look_transform(*view.lut, view.lut_file)));
  for (int stops : kExposureStops)
    config->addLook(make_look(exposure_look_name(view.name, stops),
                              stops_text(stops) + " of exposure, then " + view.name + " (Blender lists it under the " + view.name + " view)",
                              exposure_look_transform(stops, &view)));
  // Insert the view before Raw on every display, keeping Raw last.
  for (int d = 0; d < config->getNumDisplays(); ++d) {
    const std::string display = config->getDisplay(d);
    const std::string encoding = config->getDisplayViewColorSpaceName(display.c_str(), kStandardView);
    bool has_raw = false;
    for (int v = 0; v < config->getNumViews(display.c_str()); ++v) has_raw = has_raw || std::string(config->getView(display.c_str(), v)) == "Raw";
    if (has_raw) config->removeDisplayView(display.c_str(), "Raw");
    config->addDisplayView(display.c_str(), view.name.c_str(), encoding.c_str(), view.name.c_str());
    if (has_raw) config->addDisplayView(display.c_str(), "Raw", "Raw", "");
  }
  std::string active = config->getActiveViews();
  const auto raw = active.rfind(", Raw");
  if (raw != std::string::npos && raw + 5 == active.size()) active = active.substr(0, raw) + ", " + view.name + ", Raw";
  else active += ", " + view.name;
  config->setActiveViews(active.c_str());
}

OCIO::ConfigRcPtr build_config(const std::vector<ConfigView>& views, const std::string& search_path,
                               const std::string& description) {
  std::istringstream yaml(display::builtin_config_yaml());
  const auto builtin = OCIO::Config::CreateFromStream(yaml);

  auto config = OCIO::Config::Create();
  config->setMajorVersion(2);
  config->setMinorVersion(1);  // 2.1: colour space aliases (OpenColorIO 2.1, Blender 3.4)
  config->setName("cgtmo");
  config->setDescription(description.c_str());
  config->setSearchPath(search_path.c_str());
  config->setStrictParsingEnabled(true);

  // Colour spaces: the built-in ones (scene_linear first, display encodings, Raw), with the
  // working spaces and the shaper space after scene_linear.
  for (int i = 0; i < builtin->getNumColorSpaces(); ++i) {
    const char* name = builtin->getColorSpaceNameByIndex(i);
    config->addColorSpace(builtin->getColorSpace(name));
    if (std::string(name) != builtin->getColorSpace(OCIO::ROLE_SCENE_LINEAR)->getName()) continue;
    // Derived like the other linear spaces, so naming ACEScg and reading the attribute agree to
    // the last digit (the published matrix differs by up to 5e-7 per element).
    config->addColorSpace(linear_space("ACEScg", "ACES AP1 primaries, linear (ACEScg), Bradford-adapted to D65 Rec.709",
                                       color::to_rec709(color::aces_ap1())));
    config->addColorSpace(linear_space("Linear Rec.2020", "Rec.2020 primaries, D65, linear", rec2020_to_rec709()));
    config->addColorSpace(linear_space("ACES2065-1", "ACES AP0 primaries, linear (the aces_interchange role)", color::aces2065_to_rec709()));
    config->addColorSpace(linear_space("CIE-XYZ-D65", "CIE 1931 XYZ, D65 (the cie_xyz_d65_interchange role)", color::xyz_d65_to_rec709()));
    auto shaper = OCIO::ColorSpace::Create(OCIO::REFERENCE_SPACE_SCENE);
    shaper->setName(kShaperSpaceName);
    shaper->setFamily("Log");
    shaper->setEncoding("log");
    shaper->setDescription(("Process space of the looks and input of the .cube exports: s = (log2(x + 2^" + std::to_string(kShaperSpace.lo) +
                            ") + " + std::to_string(-kShaperSpace.lo) + ") / " + std::to_string(kShaperSpace.hi - kShaperSpace.lo) +
                            ", so 0 is black and 1 is 2^" + std::to_string(kShaperSpace.hi) + " (above 65504)").c_str());
    shaper->setTransform(kShaperSpace.transform(), OCIO::COLORSPACE_DIR_FROM_REFERENCE);
    config->addColorSpace(shaper);
  }
  for (int i = 0; i < builtin->getNumRoles(); ++i) config->setRole(builtin->getRoleName(i), builtin->getRoleColorSpace(i));
  config->setRole("compositing_log", kShaperSpaceName);
  config->setRole("color_timing", kShaperSpaceName);
  config->setRole("rendering", builtin->getColorSpace(OCIO::ROLE_SCENE_LINEAR)->getName());
  config->setRole("matte_paint", "sRGB");
  config->setRole("aces_interchange", "ACES2065-1");
  config->setRole("cie_xyz_d65_interchange", "CIE-XYZ-D65");

  // Displays: Standard (the display encoding alone), then Raw; operator views go in between.
  for (int d = 0; d < builtin->getNumDisplays(); ++d) {
    const char* display = builtin->getDisplay(d);
    for (int v = 0; v < builtin->getNumViews(display); ++v) {
      const char* view = builtin->getView(display, v);
      config->addDisplayView(display, view, builtin->getDisplayViewColorSpaceName(display, view), "");
    }
  }
  config->setActiveDisplays(builtin->getActiveDisplays());
  config->setActiveViews(builtin->getActiveViews());
  for (int stops : kExposureStops)
    config->addLook(make_look(exposure_look_name(kStandardView, stops), stops_text(stops) + " of exposure (Blender lists it under the Standard view)",
                              exposure_look_transform(stops, nullptr)));
  for (const auto& v : views) add_view(config, v);
  config->validate();
  return config;
}

std::string config_text(const OCIO::ConstConfigRcPtr& config, const std::string& header) {
  std::ostringstream s;
  std::istringstream in(header);
  for (std::string line; std::getline(in, line);) s << "# " << line << "\n";
  config->serialize(s);
  return s.str();
}

}  // namespace cgtmo::bake
