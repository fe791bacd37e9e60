#include "cgtmo/bake/merge.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <optional>
#include <set>
#include <tuple>
#include <sstream>

#include "cgtmo/bake/config_writer.h"
#include "cgtmo/bake/writers.h"
#include "cgtmo/color/chromaticities.h"
#include "cgtmo/color/working_space.h"
#include "cgtmo/display/display.h"
#include "cgtmo/errors.h"
#include "cgtmo/operators/registry.h"

namespace cgtmo::bake {

namespace fs = std::filesystem;

namespace {

constexpr const char* kLutFolder = "cgtmo-luts";
// A colour space is linear Rec.709 when its matrix from scene_linear is within this of the derived
// one per element: room for the chromatic adaptation a studio chose (Bradford, CAT02) and for
// matrices written with 4 to 6 digits, far below any difference of primaries.
constexpr double kMatrixTolerance = 2e-3;

std::string first_line(const std::string& s) { return s.substr(0, s.find('\n')); }

OCIO::ConstConfigRcPtr load(const std::string& path, const char* what) {
  if (!fs::is_regular_file(path)) throw UsageError(std::string("no ") + what + " config at '" + path + "'");
  try {
    return OCIO::Config::CreateFromFile(path.c_str());
  } catch (const OCIO::Exception& e) {
    throw DataError("cannot parse " + std::string(what) + " config '" + path + "': " + first_line(e.what()));
  }
}

OCIO::ConstCPUProcessorRcPtr processor(const OCIO::ConstConfigRcPtr& config, const std::string& src, const std::string& dst) {
  try {
    return config->getProcessor(src.c_str(), dst.c_str())->getDefaultCPUProcessor();
  } catch (const OCIO::Exception&) {
    return nullptr;  // no conversion between them (display-referred without a view transform, a missing LUT, ...)
  }
}

std::vector<std::string> colour_space_names(const OCIO::ConstConfigRcPtr& config) {
  std::vector<std::string> names;
  const int n = config->getNumColorSpaces(OCIO::SEARCH_REFERENCE_SPACE_ALL, OCIO::COLORSPACE_ALL);
  for (int i = 0; i < n; ++i) names.push_back(config->getColorSpaceNameByIndex(OCIO::SEARCH_REFERENCE_SPACE_ALL, OCIO::COLORSPACE_ALL, i));
  return names;
}

std::vector<std::string> display_names(const OCIO::ConstConfigRcPtr& config) {
  std::vector<std::string> names;
  for (int i = 0; i < config->getNumDisplaysAll(); ++i) names.push_back(config->getDisplayAll(i));
  return names;
}

// Every view of a display, its own first, then the shared ones it uses.
std::vector<std::string> view_names(const OCIO::ConstConfigRcPtr& config, const std::string& display) {
  std::vector<std::string> names;
  for (auto type : {OCIO::VIEW_DISPLAY_DEFINED, OCIO::VIEW_SHARED})
    for (int i = 0; i < config->getNumViews(type, display.c_str()); ++i) names.push_back(config->getView(type, display.c_str(), i));
  return names;
}

std::string view_colour_space(const OCIO::ConstConfigRcPtr& config, const std::string& display, const std::string& view) {
  std::string cs = config->getDisplayViewColorSpaceName(display.c_str(), view.c_str());
  if (cs == OCIO::OCIO_VIEW_USE_DISPLAY_NAME) cs = display;
  return cs;
}

template <class T>
std::string text_of(const T& object) {
  std::ostringstream s;
  s << object;
  return s.str();
}

void collect_files(const OCIO::TransformRcPtr& t, std::vector<OCIO::FileTransformRcPtr>& out) {
  if (auto g = OCIO::DynamicPtrCast<OCIO::GroupTransform>(t)) {
    for (int i = 0; i < g->getNumTransforms(); ++i) collect_files(g->getTransform(i), out);
  } else if (auto f = OCIO::DynamicPtrCast<OCIO::FileTransform>(t)) {
    out.push_back(f);
  }
}

std::string read_binary(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  if (!in) throw DataError("cannot read '" + p.string() + "'");
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

// Stages `content` at `path`, creating the folders it needs.
void stage_into(StagedFiles& staged, const fs::path& path, const std::string& content) {
  std::error_code ec;
  fs::create_directories(path.parent_path(), ec);
  if (ec) throw DataError("cannot create '" + path.parent_path().string() + "': " + ec.message());
  staged.stage(path.string(), content);
}

// Text-level editing of a config file. OpenColorIO 2.1 writes some numbers with fewer digits than
// it read (an AllocationTransform's vars: -12.473931188 comes back as -12.47393), so serializing
// a studio config through it would change its transforms slightly. The merge therefore edits the
// studio's own text: it replaces the search_path and active_views entries, and inserts the looks
// and the views; every other line stays byte for byte.
using Lines = std::vector<std::string>;

Lines split_lines(const std::string& text) {
  Lines v;
  std::istringstream in(text);
  for (std::string l; std::getline(in, l);) v.push_back(l);
  return v;
}

std::size_t indent_of(const std::string& l) { return l.find_first_not_of(' '); }
bool is_blank_or_comment(const std::string& l) {
  const auto i = l.find_first_not_of(" \t\r");
  return i == std::string::npos || l[i] == '#';
}

// The key of a mapping line at column `indent` ("sRGB:" or "'sRGB':"), else empty.
std::string key_at(const std::string& l, std::size_t indent) {
  if (is_blank_or_comment(l) || indent_of(l) != indent || l[indent] == '-') return "";
  std::string k;
  std::size_t i = indent;
  if (l[i] == '"' || l[i] == '\'') {
    const char q = l[i];
    const auto e = l.find(q, i + 1);
    if (e == std::string::npos || e + 1 >= l.size() || l[e + 1] != ':') return "";
    return l.substr(i + 1, e - i - 1);
  }
  const auto c = l.find(": ", i) != std::string::npos ? l.find(": ", i) : (l.back() == ':' ? l.size() - 1 : std::string::npos);
  if (c == std::string::npos) return "";
  k = l.substr(i, c - i);
  while (!k.empty() && k.back() == ' ') k.pop_back();
  return k;
}

// [first, end) of the block of the top-level key: its line and the lines up to the next top-level
// key; end is moved back over trailing blank and comment lines.
std::pair<std::size_t, std::size_t> block(const Lines& v, const std::string& key) {
  for (std::size_t i = 0; i < v.size(); ++i) {
    if (key_at(v[i], 0) != key) continue;
    std::size_t e = i + 1;
    while (e < v.size() && (is_blank_or_comment(v[e]) || indent_of(v[e]) > 0 || v[e][0] == '-')) ++e;
    while (e > i + 1 && is_blank_or_comment(v[e - 1])) --e;
    return {i, e};
  }
  return {std::string::npos, std::string::npos};
}

std::string yaml_quoted(const std::string& s) {
  std::string q = "\"";
  for (char c : s) {
    if (c == '"' || c == '\\') q += '\\';
    q += c;
  }
  return q + "\"";
}

std::string after_colon(const std::string& l) {
  const auto c = l.find(':');
  const auto rest = l.find_first_not_of(' ', c + 1);
  return rest == std::string::npos ? "" : l.substr(rest);
}

}  // namespace

const char* encoding_name(DisplayEncoding e) {
  switch (e) {
    case DisplayEncoding::srgb: return "sRGB";
    case DisplayEncoding::rec1886: return "Rec.1886";
    case DisplayEncoding::display_p3: return "Display P3";
    default: return "none";
  }
}

DisplayEncoding detect_encoding(const OCIO::ConstConfigRcPtr& config, const std::string& colour_space,
                                const color::Mat3& rec709_to_scene_linear) {
  const auto cs = config->getColorSpace(colour_space.c_str());
  const auto sl = config->getColorSpace(OCIO::ROLE_SCENE_LINEAR);
  if (!cs || !sl || cs->isData()) return DisplayEncoding::none;
  const auto cpu = processor(config, sl->getName(), cs->getName());
  if (!cpu) return DisplayEncoding::none;
  // The references: the built-in config's display encodings of linear Rec.709 (one definition).
  std::istringstream yaml(display::builtin_config_yaml());
  const auto builtin = OCIO::Config::CreateFromStream(yaml);
  const std::pair<DisplayEncoding, const char*> encodings[] = {
      {DisplayEncoding::srgb, "sRGB"}, {DisplayEncoding::rec1886, "Rec.1886"}, {DisplayEncoding::display_p3, "Display P3"}};
  std::vector<std::array<float, 3>> inputs;
  for (int i = 0; i <= 64; ++i) {
    const float g = float(i) / 64;
    inputs.push_back({g, g, g});
  }
  // No zero channel in the colours: a studio's matrices round a zero to +-1e-7, which a pure 2.4
  // gamma (infinite slope at 0) lifts to a code value; greys are exact (0 stays 0).
  const float levels[] = {0.01f, 0.05f, 0.2f, 0.5f, 0.8f, 1};
  for (float r : levels)
    for (float g : levels)
      for (float b : levels) inputs.push_back({r, g, b});
  for (const auto& [e, name] : encodings) {
    const auto ref = builtin->getProcessor("Linear Rec.709", name)->getDefaultCPUProcessor();
    double worst = 0;
    for (const auto& in : inputs) {
      float want[3] = {in[0], in[1], in[2]};
      ref->applyRGB(want);
      double s[3] = {in[0], in[1], in[2]};
      rec709_to_scene_linear.apply(s[0], s[1], s[2]);
      float got[3] = {float(s[0]), float(s[1]), float(s[2])};
      cpu->applyRGB(got);
      for (int c = 0; c < 3; ++c) worst = std::max(worst, std::isfinite(got[c]) ? std::abs(double(got[c]) - want[c]) : 1e9);
    }
    if (worst <= 1.0 / 1023) return e;
  }
  return DisplayEncoding::none;
}

WorkingSpace find_working_space(const OCIO::ConstConfigRcPtr& config) {
  const color::WorkingSpace measured = color::find_working_space(config);
  const auto sl = config->getColorSpace(OCIO::ROLE_SCENE_LINEAR);
  WorkingSpace w;
  w.scene_linear_to_rec709 = measured.scene_linear_to_rec709;
  w.basis = measured.basis;
  // A colour space of the studio that already is linear Rec.709 from scene_linear: scene_linear
  // itself first, then in the config's order.
  std::vector<std::string> names = colour_space_names(config);
  names.insert(names.begin(), sl->getName());
  for (const auto& name : names) {
    const auto cs = config->getColorSpace(name.c_str());
    if (!cs || cs->isData()) continue;
    const auto m = color::conversion_matrix(config, sl->getName(), name);
    if (m && color::max_abs_difference(*m, w.scene_linear_to_rec709) <= kMatrixTolerance) {
      w.rec709_space = name;
      break;
    }
  }
  return w;
}

std::vector<std::string> kept_differences(const OCIO::ConstConfigRcPtr& studio, const OCIO::ConstConfigRcPtr& merged) {
  std::vector<std::string> diffs;
  for (const auto& name : colour_space_names(studio)) {
    const auto m = merged->getColorSpace(name.c_str());
    if (!m || std::string(m->getName()) != name) diffs.push_back("colour space '" + name + "' missing");
    else if (text_of(*m) != text_of(*studio->getColorSpace(name.c_str()))) diffs.push_back("colour space '" + name + "' changed");
  }
  if (std::string(studio->getInactiveColorSpaces()) != merged->getInactiveColorSpaces()) diffs.push_back("inactive colour spaces changed");
  for (int i = 0; i < studio->getNumRoles(); ++i) {
    const std::string role = studio->getRoleName(i);
    if (!merged->hasRole(role.c_str())) {
      diffs.push_back("role '" + role + "' missing");
      continue;
    }
    bool same = false;
    for (int j = 0; j < merged->getNumRoles(); ++j)
      same = same || (role == merged->getRoleName(j) && std::string(studio->getRoleColorSpace(i)) == merged->getRoleColorSpace(j));
    if (!same) diffs.push_back("role '" + role + "' changed");
  }
  for (const auto& display : display_names(studio)) {
    const auto merged_views = view_names(merged, display);
    for (const auto& view : view_names(studio, display)) {
      const std::string where = "view '" + display + "/" + view + "'";
      if (std::find(merged_views.begin(), merged_views.end(), view) == merged_views.end()) {
        diffs.push_back(where + " missing");
        continue;
      }
      const char* d = display.c_str();
      const char* v = view.c_str();
      if (std::string(studio->getDisplayViewColorSpaceName(d, v)) != merged->getDisplayViewColorSpaceName(d, v) ||
          std::string(studio->getDisplayViewTransformName(d, v)) != merged->getDisplayViewTransformName(d, v) ||
          std::string(studio->getDisplayViewLooks(d, v)) != merged->getDisplayViewLooks(d, v) ||
          std::string(studio->getDisplayViewRule(d, v)) != merged->getDisplayViewRule(d, v) ||
          std::string(studio->getDisplayViewDescription(d, v)) != merged->getDisplayViewDescription(d, v))
        diffs.push_back(where + " changed");
    }
  }
  for (int i = 0; i < studio->getNumLooks(); ++i) {
    const std::string name = studio->getLookNameByIndex(i);
    const auto m = merged->getLook(name.c_str());
    if (!m) diffs.push_back("look '" + name + "' missing");
    else if (text_of(*m) != text_of(*studio->getLook(name.c_str()))) diffs.push_back("look '" + name + "' changed");
  }
  for (int i = 0; i < studio->getNumViewTransforms(); ++i) {
    const std::string name = studio->getViewTransformNameByIndex(i);
    const auto m = merged->getViewTransform(name.c_str());
    if (!m) diffs.push_back("view transform '" + name + "' missing");
    else if (text_of(*m) != text_of(*studio->getViewTransform(name.c_str()))) diffs.push_back("view transform '" + name + "' changed");
  }
  for (int i = 0; i < studio->getNumNamedTransforms(OCIO::NAMEDTRANSFORM_ALL); ++i) {
    const std::string name = studio->getNamedTransformNameByIndex(OCIO::NAMEDTRANSFORM_ALL, i);
    const auto m = merged->getNamedTransform(name.c_str());
    if (!m) diffs.push_back("named transform '" + name + "' missing");
    else if (text_of(*m) != text_of(*studio->getNamedTransform(name.c_str()))) diffs.push_back("named transform '" + name + "' changed");
  }
  if (text_of(*studio->getFileRules()) != text_of(*merged->getFileRules())) diffs.push_back("file rules changed");
  if (std::string(studio->getActiveDisplays()) != merged->getActiveDisplays()) diffs.push_back("active displays changed");
  const std::string active = studio->getActiveViews();
  if (std::string(merged->getActiveViews()).rfind(active, 0) != 0) diffs.push_back("active views changed");
  if (std::string(studio->getDefaultViewTransformName()) != merged->getDefaultViewTransformName()) diffs.push_back("default view transform changed");
  for (int i = 0; i < studio->getNumEnvironmentVars(); ++i) {
    const std::string var = studio->getEnvironmentVarNameByIndex(i);
    if (std::string(studio->getEnvironmentVarDefault(var.c_str())) != merged->getEnvironmentVarDefault(var.c_str()))
      diffs.push_back("environment variable '" + var + "' changed");
  }
  return diffs;
}

MergeResult merge_into(const MergeOptions& o) {
  const auto studio = load(o.studio_config, "studio");
  const auto ours = load(o.cgtmo_config, "cgtmo");
  MergeResult r;
  r.working = find_working_space(studio);
  const std::string scene_linear = studio->getColorSpace(OCIO::ROLE_SCENE_LINEAR)->getName();
  if (o.progress)
    o.progress("scene_linear '" + scene_linear + "' to linear Rec.709: " +
               (r.working.rec709_space == scene_linear ? std::string("the same space")
                : !r.working.rec709_space.empty()      ? "the studio's colour space '" + r.working.rec709_space + "'"
                                                       : "a derived matrix") +
               " (basis: " + r.working.basis + ")");

  // Names: prefix + operator name, for the look and the view alike; none may exist already.
  std::vector<std::pair<std::string, std::string>> ops;  // operator, merged name
  for (const auto& def : operators::operators_of(operators::Scope::Pixel)) ops.emplace_back(def.name, o.prefix + def.name);
  std::set<std::string> taken;
  for (const auto& n : colour_space_names(studio)) taken.insert(n);
  for (int i = 0; i < studio->getNumLooks(); ++i) taken.insert(studio->getLookNameByIndex(i));
  for (int i = 0; i < studio->getNumViewTransforms(); ++i) taken.insert(studio->getViewTransformNameByIndex(i));
  for (int i = 0; i < studio->getNumNamedTransforms(OCIO::NAMEDTRANSFORM_ALL); ++i)
    taken.insert(studio->getNamedTransformNameByIndex(OCIO::NAMEDTRANSFORM_ALL, i));
  for (int i = 0; i < studio->getNumRoles(); ++i) taken.insert(studio->getRoleName(i));
  for (const auto& d : display_names(studio)) {
    taken.insert(d);
    for (const auto& v : view_names(studio, d)) taken.insert(v);
  }
  for (const auto& [op, name] : ops) {
    bool clash = taken.count(name) > 0 || studio->getColorSpace(name.c_str()) != nullptr;  // aliases too
    if (clash) throw DataError("'" + name + "' already exists in '" + o.studio_config + "': cannot add cgtmo's look and view under that name");
    if (!ours->getLook(op.c_str()))
      throw DataError("'" + o.cgtmo_config + "' has no look '" + op + "': not a current cgtmo config (re-run 'cgtmo bake')");
  }

  auto merged = studio->createEditableCopy();
  if (merged->getMajorVersion() < 2) {
    merged->setMajorVersion(2);
    merged->setMinorVersion(0);
  }

  // scene_linear -> linear Rec.709 and back, around each operator.
  OCIO::TransformRcPtr to_rec709, from_rec709;
  if (r.working.rec709_space.empty()) {
    to_rec709 = color::matrix_transform(r.working.scene_linear_to_rec709);
    from_rec709 = color::matrix_transform(r.working.scene_linear_to_rec709.inverse());
  } else if (r.working.rec709_space != scene_linear) {
    auto t = OCIO::ColorSpaceTransform::Create();
    t->setSrc(scene_linear.c_str());
    t->setDst(r.working.rec709_space.c_str());
    to_rec709 = t;
    auto f = OCIO::ColorSpaceTransform::Create();
    f->setSrc(r.working.rec709_space.c_str());
    f->setDst(scene_linear.c_str());
    from_rec709 = f;
  }

  std::error_code ec;
  fs::create_directories(o.out_dir, ec);
  check_output_folder(o.out_dir, "merged config");
  if (fs::exists(fs::path(o.out_dir) / "config.ocio") && fs::equivalent(o.studio_config, fs::path(o.out_dir) / "config.ocio"))
    throw UsageError("the merged config would overwrite the studio config '" + o.studio_config + "': choose another folder");
  StagedFiles staged(o.progress);
  const fs::path out(o.out_dir);
  std::set<std::string> staged_luts;
  for (const auto& [op, name] : ops) {
    const auto look = ours->getLook(op.c_str());
    auto g = OCIO::DynamicPtrCast<OCIO::GroupTransform>(look->getTransform()->createEditableCopy());
    const auto is_log = [](const OCIO::ConstTransformRcPtr& t) { return OCIO::DynamicPtrCast<const OCIO::LogAffineTransform>(t) != nullptr; };
    if (!g || g->getNumTransforms() < 3 || !is_log(g->getTransform(0)) || !is_log(g->getTransform(g->getNumTransforms() - 1)))
      throw DataError("look '" + op + "' of '" + o.cgtmo_config + "' is not shaper, operator, shaper: not a cgtmo config");
    // Without the shaper in and out: linear Rec.709 (scene) -> display-linear Rec.709.
    auto chain = OCIO::GroupTransform::Create();
    if (to_rec709) chain->appendTransform(to_rec709->createEditableCopy());
    for (int i = 1; i + 1 < g->getNumTransforms(); ++i) chain->appendTransform(g->getTransform(i)->createEditableCopy());
    if (from_rec709) chain->appendTransform(from_rec709->createEditableCopy());
    // The LUT files, found through cgtmo's config, copied under kLutFolder.
    std::vector<OCIO::FileTransformRcPtr> files;
    collect_files(chain, files);
    for (auto& f : files) {
      const std::string src = f->getSrc();
      if (!staged_luts.count(src)) {
        std::string path;
        try {
          path = ours->getCurrentContext()->resolveFileLocation(src.c_str());
        } catch (const OCIO::Exception& e) {
          throw DataError("'" + o.cgtmo_config + "': " + first_line(e.what()));
        }
        stage_into(staged, out / kLutFolder / src, read_binary(path));
        staged_luts.insert(src);
      }
      f->setSrc((std::string(kLutFolder) + "/" + src).c_str());
    }
    auto l = OCIO::Look::Create();
    l->setName(name.c_str());
    l->setProcessSpace(scene_linear.c_str());
    l->setDescription(("cgtmo: " + std::string(look->getDescription()) + "; from scene_linear '" + scene_linear + "' as linear Rec.709").c_str());
    l->setTransform(chain);
    merged->addLook(l);
    r.looks.push_back(name);
  }

  // Views on the displays whose encoding is one the operators are audited for.
  const color::Mat3 rec709_to_sl = r.working.scene_linear_to_rec709.inverse();
  std::string active = merged->getActiveViews();
  for (const auto& display : display_names(studio)) {
    MergedDisplay md;
    md.display = display;
    std::vector<std::string> candidates;
    for (const auto& v : view_names(studio, display)) candidates.push_back(view_colour_space(studio, display, v));
    candidates.push_back(display);
    for (const auto& cs : candidates) {
      md.encoding = detect_encoding(studio, cs, rec709_to_sl);
      if (md.encoding != DisplayEncoding::none) {
        md.colour_space = studio->getColorSpace(cs.c_str())->getName();
        break;
      }
    }
    if (md.encoding != DisplayEncoding::none)
      for (const auto& [op, name] : ops) merged->addDisplayView(display.c_str(), name.c_str(), md.colour_space.c_str(), name.c_str());
    r.displays.push_back(md);
  }
  if (!active.empty()) {
    for (const auto& [op, name] : ops) active += ", " + name;
    merged->setActiveViews(active.c_str());
  }

  // Search path: the studio's relative folders are copied beside the merged config (same relative
  // names); other entries (absolute, environment variables, outside the studio's folder) become
  // absolute; then "." for kLutFolder/<file>.
  const fs::path studio_dir = fs::absolute(o.studio_config).parent_path();
  std::vector<std::string> entries;
  for (int i = 0; i < studio->getNumSearchPaths(); ++i) entries.push_back(studio->getSearchPath(i));
  if (entries.empty()) entries.push_back(studio_dir.string());
  merged->clearSearchPaths();
  for (const auto& e : entries) {
    const fs::path p(e);
    const fs::path norm = p.lexically_normal();
    const bool plain_subfolder = e.find('$') == std::string::npos && p.is_relative() && !norm.empty() && norm != "." &&
                                 *norm.begin() != ".." && fs::is_directory(studio_dir / norm);
    if (plain_subfolder) {
      for (const auto& f : fs::recursive_directory_iterator(studio_dir / norm))
        if (f.is_regular_file()) stage_into(staged, out / norm / fs::relative(f.path(), studio_dir / norm), read_binary(f.path()));
      merged->addSearchPath(norm.string().c_str());
      r.copied_search_paths.push_back(norm.string());
    } else if (e.find('$') == std::string::npos && p.is_relative()) {
      const std::string abs = (studio_dir / norm).lexically_normal().string();
      merged->addSearchPath(abs.c_str());
      r.absolute_search_paths.push_back(abs);
    } else {
      merged->addSearchPath(e.c_str());
    }
  }
  merged->addSearchPath(".");
  merged->setDescription((std::string(studio->getDescription()) + (studio->getDescription()[0] ? "\n" : "") +
                          "With cgtmo's operators as looks and views, merged by `" + o.command_line + "`.").c_str());

  // The text: the studio's own, edited (a version 1 config is written by OpenColorIO as version 2).
  const std::string header = "# The studio config '" + fs::path(o.studio_config).filename().string() +
                             "' with cgtmo's operators as looks and views.\n# Generated by `" + o.command_line +
                             "`; do not edit, re-run it.\n";
  std::string text;
  if (studio->getMajorVersion() < 2) {
    text = config_text(merged, header.substr(2));
  } else {
    Lines v = split_lines(read_binary(o.studio_config));
    // search_path
    std::string search;
    for (int i = 0; i < merged->getNumSearchPaths(); ++i) search += (i ? ":" : "") + std::string(merged->getSearchPath(i));
    auto [sp, sp_end] = block(v, "search_path");
    if (sp == std::string::npos) {
      const auto [ver, ver_end] = block(v, "ocio_profile_version");
      v.insert(v.begin() + (ver == std::string::npos ? 0 : ver_end), "search_path: " + yaml_quoted(search));
    } else {
      v.erase(v.begin() + sp, v.begin() + sp_end);
      v.insert(v.begin() + sp, "search_path: " + yaml_quoted(search));
    }
    // views, at the end of each display's list
    auto [ds, ds_end] = block(v, "displays");
    std::size_t display_indent = std::string::npos;
    for (std::size_t i = ds + 1; ds != std::string::npos && i < ds_end && display_indent == std::string::npos; ++i)
      if (!is_blank_or_comment(v[i])) display_indent = indent_of(v[i]);
    for (auto it = r.displays.rbegin(); it != r.displays.rend(); ++it) {
      if (it->encoding == DisplayEncoding::none) continue;
      std::tie(ds, ds_end) = block(v, "displays");
      if (ds == std::string::npos) throw DataError("cannot find the displays of '" + o.studio_config + "' in its text (nothing written)");
      std::size_t at = std::string::npos, end = ds_end;
      for (std::size_t i = ds + 1; i < ds_end; ++i)
        if (key_at(v[i], display_indent) == it->display) {
          at = i;
          for (end = i + 1; end < ds_end && (is_blank_or_comment(v[end]) || indent_of(v[end]) > display_indent); ++end) {}
          while (end > at + 1 && is_blank_or_comment(v[end - 1])) --end;
          break;
        }
      if (at == std::string::npos || !after_colon(v[at]).empty())
        throw DataError("cannot find display '" + it->display + "' as a block list in '" + o.studio_config + "' (nothing written)");
      std::string item_indent(display_indent + 2, ' ');
      for (std::size_t i = at + 1; i < end; ++i)
        if (!is_blank_or_comment(v[i])) {
          item_indent = std::string(indent_of(v[i]), ' ');
          break;
        }
      Lines add;
      for (const auto& [op, name] : ops)
        add.push_back(item_indent + "- !<View> {name: " + yaml_quoted(name) + ", colorspace: " + yaml_quoted(it->colour_space) + ", looks: " + yaml_quoted(name) + "}");
      v.insert(v.begin() + end, add.begin(), add.end());
    }
    // active_views, when the studio lists them
    if (!active.empty()) {
      const auto [av, av_end] = block(v, "active_views");
      std::string list;
      std::istringstream names(merged->getActiveViews());
      for (std::string n; std::getline(names, n, ',');) {
        n.erase(0, n.find_first_not_of(' '));
        while (!n.empty() && n.back() == ' ') n.pop_back();
        list += (list.empty() ? "" : ", ") + yaml_quoted(n);
      }
      if (av == std::string::npos) throw DataError("cannot find active_views in '" + o.studio_config + "' (nothing written)");
      v.erase(v.begin() + av, v.begin() + av_end);
      v.insert(v.begin() + av, "active_views: [" + list + "]");
    }
    // looks: OpenColorIO's own text of the new looks, appended to the looks list (or a new one)
    auto only_looks = OCIO::Config::Create();
    for (const auto& name : r.looks) only_looks->addLook(merged->getLook(name.c_str()));
    Lines look_lines;
    {
      std::ostringstream t;
      only_looks->serialize(t);
      const Lines all = split_lines(t.str());
      const auto [lk, lk_end] = block(all, "looks");
      if (lk == std::string::npos) throw DataError("internal: no looks written");
      look_lines.assign(all.begin() + lk + 1, all.begin() + lk_end);
    }
    const auto [lk, lk_end] = block(v, "looks");
    if (lk == std::string::npos) {
      v.push_back("");
      v.push_back("looks:");
      v.insert(v.end(), look_lines.begin(), look_lines.end());
    } else {
      // Re-indent to the studio's list indentation.
      std::size_t studio_indent = std::string::npos, ours = indent_of(look_lines.front());
      for (std::size_t i = lk + 1; i < lk_end && studio_indent == std::string::npos; ++i)
        if (!is_blank_or_comment(v[i])) studio_indent = indent_of(v[i]);
      if (studio_indent == std::string::npos) studio_indent = ours;
      for (auto& l : look_lines)
        if (!l.empty()) l = studio_indent >= ours ? std::string(studio_indent - ours, ' ') + l : l.substr(ours - studio_indent);
      if (!after_colon(v[lk]).empty() && after_colon(v[lk]) != "[]")
        throw DataError("the looks of '" + o.studio_config + "' are a flow list: cannot add to them (nothing written)");
      if (!after_colon(v[lk]).empty()) v[lk] = "looks:";
      look_lines.insert(look_lines.begin(), "");
      v.insert(v.begin() + lk_end, look_lines.begin(), look_lines.end());
    }
    text = header;
    for (const auto& l : v) text += l + "\n";
  }

  // Reload the text that will be written and check that everything of the studio is kept.
  OCIO::ConstConfigRcPtr back;
  try {
    std::istringstream in(text);
    back = OCIO::Config::CreateFromStream(in);
  } catch (const OCIO::Exception& e) {
    throw DataError("the merged config does not load back: " + first_line(e.what()) + " (nothing written)");
  }
  for (const auto& name : r.looks)
    if (!back->getLook(name.c_str())) throw DataError("the merged config lost the look '" + name + "' (nothing written)");
  for (const auto& d : r.displays)
    if (d.encoding != DisplayEncoding::none && std::string(back->getDisplayViewLooks(d.display.c_str(), r.looks.front().c_str())) != r.looks.front())
      throw DataError("the merged config lost the views on '" + d.display + "' (nothing written)");
  const auto diffs = kept_differences(studio, back);
  if (!diffs.empty()) throw DataError("the merged config would not keep the studio's " + diffs.front() + " (nothing written)");
  r.config_path = (out / "config.ocio").string();
  stage_into(staged, r.config_path, text);
  staged.commit();
  return r;
}

}  // namespace cgtmo::bake
