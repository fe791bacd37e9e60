#include "cgtmo/display/display.h"

#include <cstdlib>
#include <sstream>
#include <vector>

#include "cgtmo/color/working_space.h"
#include "cgtmo/display/checked_config.h"
#include "cgtmo/errors.h"
#include "cgtmo/io/input_file.h"
#include "cgtmo/operators/registry.h"
#include "cgtmo/util/parallel.h"
#include "cgtmo/util/text.h"

namespace cgtmo::display {

OCIO::ConstConfigRcPtr load_config(const std::string& path, std::string* origin) {
  std::string chosen = path;
  std::string how = "--colorconfig";
  if (chosen.empty()) {
    const char* env = std::getenv("OCIO");
    if (env && *env) {
      chosen = env;
      how = "$OCIO";
    }
  }
  try {
    if (chosen.empty()) {
      if (origin) *origin = "built-in config";
      std::istringstream s(builtin_config_yaml());
      return OCIO::Config::CreateFromStream(s);
    }
    if (origin) *origin = chosen + " (" + how + ")";
    // A FIFO or device would block OCIO's read or never end.
    if (const std::string why = io::input_file_problem(chosen); !why.empty())
      throw UsageError("cannot load OCIO config '" + chosen + "' (" + how + "): " + why);
    try {
      return load_config_checked(chosen);
    } catch (const DataError& e) {
      throw DataError(e.what() + (" (" + how + ")"));
    }
  } catch (const OCIO::Exception& e) {
    std::string msg = e.what();
    msg = msg.substr(0, msg.find('\n'));
    throw UsageError("cannot load OCIO config '" + chosen + "' (" + how + "): " + msg);
  }
}

static std::string list_views(const OCIO::ConstConfigRcPtr& c, const std::string& display) {
  std::string s;
  for (int i = 0; i < c->getNumViews(display.c_str()); ++i) s += (s.empty() ? "" : ", ") + std::string(c->getView(display.c_str(), i));
  return s;
}

// Names a view may carry for an operator: the view's own name, its looks (comma or space separated
// in OCIO; an exposure look of cgtmo's config is "<op> - <stops>").
static std::string operator_named_by(const std::string& view, const std::string& looks) {
  std::vector<std::string> names = {view};
  std::string word;
  for (char ch : looks + ",") {
    if (ch == ',') {
      const auto b = word.find_first_not_of(" +-");
      const auto e = word.find_last_not_of(' ');
      if (b != std::string::npos) names.push_back(word.substr(b, e - b + 1));
      word.clear();
    } else {
      word += ch;
    }
  }
  std::vector<std::string> ops;
  for (const auto& def : operators::operators_of(operators::Scope::Pixel)) ops.push_back(def.name);
  for (const auto& name : names)
    for (const auto& op : ops)
      if (name == op || name.rfind(op + " - ", 0) == 0) return op;
  return {};
}

DisplayEncoder::DisplayEncoder(OCIO::ConstConfigRcPtr config, std::string display, std::string view)
    : display_(std::move(display)), view_(std::move(view)) {
  if (display_.empty()) display_ = config->getDefaultDisplay();
  bool found = false;
  std::string displays;
  std::vector<std::string> known;
  for (int i = 0; i < config->getNumDisplays(); ++i) {
    const std::string d = config->getDisplay(i);
    found = found || d == display_;
    displays += (displays.empty() ? "" : ", ") + d;
    known.push_back(d);
  }
  if (!found)
    throw UsageError("display '" + display_ + "' is not in the OCIO config" + did_you_mean(display_, known) + " (displays: " + displays + ")");
  if (view_.empty()) {
    for (int i = 0; i < config->getNumViews(display_.c_str()); ++i)
      if (std::string(config->getView(display_.c_str(), i)) == "Standard") view_ = "Standard";
    if (view_.empty()) view_ = config->getDefaultView(display_.c_str());
  } else {
    bool ok = false;
    std::vector<std::string> views;
    for (int i = 0; i < config->getNumViews(display_.c_str()); ++i) {
      views.emplace_back(config->getView(display_.c_str(), i));
      ok = ok || views.back() == view_;
    }
    if (!ok)
      throw UsageError("view '" + view_ + "' is not offered by display '" + display_ + "'" + did_you_mean(view_, views) +
                       " (views: " + list_views(config, display_) + ")");
  }
  view_operator_ = operator_named_by(view_, config->getDisplayViewLooks(display_.c_str(), view_.c_str()));
  try {
    auto t = OCIO::DisplayViewTransform::Create();
    t->setSrc(OCIO::ROLE_SCENE_LINEAR);
    t->setDisplay(display_.c_str());
    t->setView(view_.c_str());
    // The operators' output is linear Rec.709: into the config's scene_linear first when that is
    // another space (a studio config working in ACEScg).
    const color::WorkingSpace w = color::find_working_space(config);
    if (w.is_rec709()) {
      cpu_ = config->getProcessor(t)->getDefaultCPUProcessor();
    } else {
      auto g = OCIO::GroupTransform::Create();
      g->appendTransform(color::matrix_transform(w.scene_linear_to_rec709.inverse()));
      g->appendTransform(t);
      cpu_ = config->getProcessor(g)->getDefaultCPUProcessor();
    }
    profile_ = describe_display(config, display_, view_);
  } catch (const OCIO::Exception& e) {
    std::string msg = e.what();
    throw UsageError("OCIO cannot build " + display_ + "/" + view_ + ": " + msg.substr(0, msg.find('\n')));
  }
}

void DisplayEncoder::apply(float* px, int width, int height, int channels) const {
  parallel_rows(height, [&](int64_t y0, int64_t y1) {
    OCIO::PackedImageDesc desc(px + std::size_t(y0) * width * channels, width, long(y1 - y0), channels);
    cpu_->apply(desc);
  });
}

}  // namespace cgtmo::display
