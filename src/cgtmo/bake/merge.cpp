#include "cgtmo/bake/merge.h"

#include <sys/stat.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <functional>
#include <optional>
#include <set>
#include <tuple>
#include <sstream>

#include "cgtmo/bake/config_writer.h"
#include "cgtmo/bake/staged_set.h"
#include "cgtmo/color/chromaticities.h"
#include "cgtmo/color/working_space.h"
#include "cgtmo/display/checked_config.h"
#include "cgtmo/display/display.h"
#include "cgtmo/errors.h"
#include "cgtmo/io/input_file.h"
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


namespace {

// The largest file a merge copies (a 65^3 .spi3d is 10 MB): a LUT that is a link to /dev/zero
// or a growing file stops here.
constexpr std::uint64_t kMaxCopiedFileBytes = 256u << 20;

// A config as read: its text (read once: the text edited is the text checked) and its folder.
struct LoadedConfig {
  std::string path, text;
  fs::path folder;  // canonical
  OCIO::ConstConfigRcPtr config;
};

LoadedConfig load(const std::string& path, const std::string& what) {
  if (!fs::is_regular_file(path)) throw UsageError("no " + what + " config at '" + path + "'");
  LoadedConfig c;
  c.path = path;
  c.text = io::read_regular_file(path, display::kMaxConfigBytes, what + " config ");
  c.folder = fs::canonical(fs::absolute(path).parent_path());
  try {
    c.config = display::config_from_checked_text(c.text, what + " config '" + path + "'", fs::absolute(path).parent_path().string());
  } catch (const OCIO::Exception& e) {
    throw DataError("cannot parse " + what + " config '" + path + "': " + first_line(e.what()));
  }
  return c;
}

// OpenColorIO reads a view's looks as a list: ',' and ':' separate looks, and a leading '+' or
// '-' applies one forward or inverse (a leading space is trimmed): a name with them cannot be
// used as a look.
void check_prefix(const std::string& prefix) {
  for (unsigned char c : prefix)
    if (c < 0x20 || c == 0x7f) throw UsageError("--prefix holds a control character");
  if (!prefix.empty() && std::string("+- \t").find(prefix[0]) != std::string::npos)
    throw UsageError("--prefix '" + prefix + "' starts with '" + prefix.substr(0, 1) +
                     "', which OpenColorIO reads as look-list syntax: choose a prefix starting with a letter or digit");
  if (prefix.find_first_of(",:") != std::string::npos)
    throw UsageError("--prefix '" + prefix + "' holds ',' or ':', which separate looks in OpenColorIO: choose another prefix");
}

using OperatorNames = std::vector<std::pair<std::string, std::string>>;  // operator, merged name

// Prefix + operator name, for the look and the view alike; none may exist in the studio already.
OperatorNames operator_names(const LoadedConfig& studio, const LoadedConfig& ours, const std::string& prefix) {
  OperatorNames ops;
  for (const auto& def : operators::operators_of(operators::Scope::Pixel)) ops.emplace_back(def.name, prefix + def.name);
  const auto& s = studio.config;
  std::set<std::string> taken;
  for (const auto& n : colour_space_names(s)) taken.insert(n);
  for (int i = 0; i < s->getNumLooks(); ++i) taken.insert(s->getLookNameByIndex(i));
  for (int i = 0; i < s->getNumViewTransforms(); ++i) taken.insert(s->getViewTransformNameByIndex(i));
  for (int i = 0; i < s->getNumNamedTransforms(OCIO::NAMEDTRANSFORM_ALL); ++i)
    taken.insert(s->getNamedTransformNameByIndex(OCIO::NAMEDTRANSFORM_ALL, i));
  for (int i = 0; i < s->getNumRoles(); ++i) taken.insert(s->getRoleName(i));
  for (const auto& d : display_names(s)) {
    taken.insert(d);
    for (const auto& v : view_names(s, d)) taken.insert(v);
  }
  for (const auto& [op, name] : ops) {
    const bool clash = taken.count(name) > 0 || s->getColorSpace(name.c_str()) != nullptr;  // aliases too
    if (clash) throw DataError("'" + name + "' already exists in '" + studio.path + "': cannot add cgtmo's look and view under that name");
    if (!ours.config->getLook(op.c_str()))
      throw DataError("'" + ours.path + "' has no look '" + op + "': not a current cgtmo config (re-run 'cgtmo bake')");
  }
  return ops;
}

// Whether `inner` is `outer` or below it (both absolute and normal).
bool is_within(const fs::path& inner, const fs::path& outer) {
  const fs::path rel = inner.lexically_relative(outer);
  return !rel.empty() && *rel.begin() != "..";
}

// The search path: the studio's entries that are real subfolders of its folder (no link on the
// way, so that nothing outside it is copied) are copied into the set, once each; other relative
// entries become absolute; absolute ones and those with environment variables are kept.
struct SearchPlan {
  struct Entry {
    std::string path;  // relative to the set when copied
    bool copied, made_absolute;
  };
  std::vector<Entry> entries;
  std::vector<fs::path> copied;  // folders copied, relative to the studio's folder; none inside another
};

bool real_subfolder(const fs::path& base, const fs::path& rel) {
  fs::path p = base;
  for (const auto& part : rel) {
    p /= part;
    struct stat st {};
    if (::lstat(p.c_str(), &st) != 0 || !S_ISDIR(st.st_mode)) return false;
  }
  return true;
}

SearchPlan plan_search_path(const LoadedConfig& studio) {
  std::vector<std::string> entries;
  for (int i = 0; i < studio.config->getNumSearchPaths(); ++i) entries.push_back(studio.config->getSearchPath(i));
  if (entries.empty()) entries.push_back(studio.folder.string());
  SearchPlan plan;
  for (const auto& e : entries) {
    fs::path norm = fs::path(e).lexically_normal();
    if (!norm.empty() && norm.filename().empty()) norm = norm.parent_path();  // "luts/"
    const bool relative = e.find('$') == std::string::npos && fs::path(e).is_relative();
    if (relative && !norm.empty() && norm != "." && *norm.begin() != ".." && real_subfolder(studio.folder, norm)) {
      plan.entries.push_back({norm.generic_string(), true, false});
      plan.copied.push_back(norm);
    } else {
      plan.entries.push_back({relative ? (studio.folder / norm).lexically_normal().string() : e, false, relative});
    }
  }
  // Each folder once (luts:filmic:luts), and none that another copied folder holds.
  std::sort(plan.copied.begin(), plan.copied.end());
  plan.copied.erase(std::unique(plan.copied.begin(), plan.copied.end()), plan.copied.end());
  std::vector<fs::path> outermost;
  for (const auto& c : plan.copied)
    if (outermost.empty() || !is_within(c, outermost.back())) outermost.push_back(c);
  plan.copied = outermost;
  return plan;
}

// A file of the set: its path in the set and the file it is read from.
struct SetFile {
  std::string relative, source;
  bool follow_links;  // cgtmo's LUTs: wherever its config finds them
};

// The files of the copied folders: regular files, and links to regular files inside the studio's
// folder. Anything else (a link out of it, a FIFO, a device) is refused, before OpenColorIO
// reads any file of those folders (a FIFO would block it).
std::vector<SetFile> studio_files(const LoadedConfig& studio, const SearchPlan& plan) {
  std::vector<SetFile> files;
  const auto refuse = [&](const fs::path& p, const std::string& why) {
    return DataError("'" + p.string() + "' in the studio's folder '" + studio.folder.string() + "': " + why + ": not copied (nothing written)");
  };
  for (const auto& folder : plan.copied) {
    const fs::path root = studio.folder / folder;
    std::error_code ec;
    for (auto it = fs::recursive_directory_iterator(root, ec); !ec && it != fs::recursive_directory_iterator(); it.increment(ec)) {
      const fs::path rel = folder / it->path().lexically_relative(root);
      const auto status = it->symlink_status(ec);
      if (ec || fs::is_directory(status)) continue;
      if (fs::is_regular_file(status)) {
        files.push_back({rel.generic_string(), it->path().string(), false});
      } else if (fs::is_symlink(status)) {
        std::error_code broken;
        const fs::path target = fs::canonical(it->path(), broken);
        if (broken) throw refuse(it->path(), "a link to nothing");
        if (!is_within(target, studio.folder) || !fs::is_regular_file(fs::symlink_status(target)))
          throw refuse(it->path(), "a link to '" + target.string() + "', not to a file in that folder");
        files.push_back({rel.generic_string(), target.string(), false});
      } else {
        throw refuse(it->path(), io::input_file_problem(it->path().string()));
      }
    }
    if (ec) throw DataError("cannot list '" + root.string() + "': " + ec.message() + " (nothing written)");
  }
  return files;
}

void collect_file_names(const OCIO::ConstTransformRcPtr& t, std::set<std::string>& out) {
  if (!t) return;
  if (auto g = OCIO::DynamicPtrCast<const OCIO::GroupTransform>(t)) {
    for (int i = 0; i < g->getNumTransforms(); ++i) collect_file_names(g->getTransform(i), out);
  } else if (auto f = OCIO::DynamicPtrCast<const OCIO::FileTransform>(t)) {
    out.insert(f->getSrc());
  }
}

// The files the studio's config names, where OpenColorIO finds them (in folders kept in place
// too, which studio_files does not list): regular files only, checked before OpenColorIO reads
// any, so that measuring the display encodings cannot wait on a FIFO or read /dev/zero without end.
void check_named_files(const LoadedConfig& studio) {
  const auto& c = studio.config;
  std::set<std::string> names;
  for (int i = 0; i < c->getNumColorSpaces(); ++i) {
    const auto cs = c->getColorSpace(c->getColorSpaceNameByIndex(i));
    for (auto dir : {OCIO::COLORSPACE_DIR_TO_REFERENCE, OCIO::COLORSPACE_DIR_FROM_REFERENCE}) collect_file_names(cs->getTransform(dir), names);
  }
  for (int i = 0; i < c->getNumLooks(); ++i) {
    const auto look = c->getLook(c->getLookNameByIndex(i));
    collect_file_names(look->getTransform(), names);
    collect_file_names(look->getInverseTransform(), names);
  }
  for (int i = 0; i < c->getNumViewTransforms(); ++i) {
    const auto vt = c->getViewTransform(c->getViewTransformNameByIndex(i));
    for (auto dir : {OCIO::VIEWTRANSFORM_DIR_TO_REFERENCE, OCIO::VIEWTRANSFORM_DIR_FROM_REFERENCE}) collect_file_names(vt->getTransform(dir), names);
  }
  for (const auto& name : names) {
    std::string path;
    try {
      path = c->getCurrentContext()->resolveFileLocation(name.c_str());
    } catch (const OCIO::Exception&) {
      continue;  // not found: OpenColorIO's own error where the file is needed
    }
    const std::string problem = io::input_file_problem(path);
    if (!problem.empty())
      throw DataError("'" + path + "', the file '" + name + "' of the studio config '" + studio.path + "': " + problem + " (nothing written)");
  }
}

// scene_linear -> linear Rec.709 and back, around each operator (none when they are the same).
std::pair<OCIO::TransformRcPtr, OCIO::TransformRcPtr> rec709_conversions(const WorkingSpace& w, const std::string& scene_linear) {
  if (w.rec709_space.empty())
    return {color::matrix_transform(w.scene_linear_to_rec709), color::matrix_transform(w.scene_linear_to_rec709.inverse())};
  if (w.rec709_space == scene_linear) return {};
  auto to = OCIO::ColorSpaceTransform::Create();
  to->setSrc(scene_linear.c_str());
  to->setDst(w.rec709_space.c_str());
  auto from = OCIO::ColorSpaceTransform::Create();
  from->setSrc(w.rec709_space.c_str());
  from->setDst(scene_linear.c_str());
  return {to, from};
}

// One look per operator: cgtmo's look without its shaper, between the conversions. Returns the
// LUT files the looks name, to be copied under kLutFolder.
std::vector<SetFile> add_looks(const OCIO::ConfigRcPtr& merged, const LoadedConfig& ours, const OperatorNames& ops,
                               const std::string& scene_linear, MergeResult& r) {
  const auto [to_rec709, from_rec709] = rec709_conversions(r.working, scene_linear);
  std::vector<SetFile> luts;
  std::set<std::string> seen;
  for (const auto& [op, name] : ops) {
    const auto look = ours.config->getLook(op.c_str());
    auto g = OCIO::DynamicPtrCast<OCIO::GroupTransform>(look->getTransform()->createEditableCopy());
    const auto is_log = [](const OCIO::ConstTransformRcPtr& t) { return OCIO::DynamicPtrCast<const OCIO::LogAffineTransform>(t) != nullptr; };
    if (!g || g->getNumTransforms() < 3 || !is_log(g->getTransform(0)) || !is_log(g->getTransform(g->getNumTransforms() - 1)))
      throw DataError("look '" + op + "' of '" + ours.path + "' is not shaper, operator, shaper: not a cgtmo config");
    // Without the shaper in and out: linear Rec.709 (scene) -> display-linear Rec.709.
    auto chain = OCIO::GroupTransform::Create();
    if (to_rec709) chain->appendTransform(to_rec709->createEditableCopy());
    for (int i = 1; i + 1 < g->getNumTransforms(); ++i) chain->appendTransform(g->getTransform(i)->createEditableCopy());
    if (from_rec709) chain->appendTransform(from_rec709->createEditableCopy());
    std::vector<OCIO::FileTransformRcPtr> files;
    collect_files(chain, files);
    for (auto& f : files) {
      const std::string src = f->getSrc();
      const fs::path rel = fs::path(src).lexically_normal();
      if (rel.empty() || rel.is_absolute() || *rel.begin() == ".." || rel.filename().empty())
        throw DataError("'" + ours.path + "': the LUT '" + src + "' of look '" + op + "' is not a file name inside its search path");
      if (seen.insert(src).second) {
        try {
          luts.push_back({std::string(kLutFolder) + "/" + rel.generic_string(), ours.config->getCurrentContext()->resolveFileLocation(src.c_str()), true});
        } catch (const OCIO::Exception& e) {
          throw DataError("'" + ours.path + "': " + first_line(e.what()));
        }
      }
      f->setSrc((std::string(kLutFolder) + "/" + rel.generic_string()).c_str());
    }
    auto l = OCIO::Look::Create();
    l->setName(name.c_str());
    l->setProcessSpace(scene_linear.c_str());
    l->setDescription(("cgtmo: " + std::string(look->getDescription()) + "; from scene_linear '" + scene_linear + "' as linear Rec.709").c_str());
    l->setTransform(chain);
    merged->addLook(l);
    r.looks.push_back(name);
  }
  return luts;
}

// -o may not be, be inside, or contain a folder the merge reads: the merge writes DIR/config.ocio
// and DIR/cgtmo-set-*, and removes DIR's older sets; a staging folder inside a folder it copies
// would be copied into the set.
void check_output_apart(const fs::path& out, const std::vector<std::pair<fs::path, std::string>>& read) {
  // The closest relation is named: "is" before "is inside" before "contains".
  const std::pair<const char*, std::function<bool(const fs::path&)>> relations[] = {
      {"is", [&](const fs::path& f) { return out == f; }},
      {"is inside", [&](const fs::path& f) { return is_within(out, f); }},
      {"contains", [&](const fs::path& f) { return is_within(f, out); }}};
  for (const auto& [how, holds] : relations)
    for (const auto& [folder, what] : read)
      if (holds(folder))
        throw UsageError("-o '" + out.string() + "' " + how + " " + what + " '" + folder.string() +
                         "', which the merge reads: choose an output folder apart from it");
}

// Views on the displays whose encoding is one the operators are audited for. Returns the new
// active_views ("" when the studio lists none).
std::string add_views(const OCIO::ConfigRcPtr& merged, const LoadedConfig& studio, const OperatorNames& ops, MergeResult& r) {
  const color::Mat3 rec709_to_sl = r.working.scene_linear_to_rec709.inverse();
  for (const auto& display : display_names(studio.config)) {
    MergedDisplay md;
    md.display = display;
    std::vector<std::string> candidates;
    for (const auto& v : view_names(studio.config, display)) candidates.push_back(view_colour_space(studio.config, display, v));
    candidates.push_back(display);
    for (const auto& cs : candidates) {
      md.encoding = detect_encoding(studio.config, cs, rec709_to_sl);
      if (md.encoding != DisplayEncoding::none) {
        md.colour_space = studio.config->getColorSpace(cs.c_str())->getName();
        break;
      }
    }
    if (md.encoding != DisplayEncoding::none)
      for (const auto& [op, name] : ops) merged->addDisplayView(display.c_str(), name.c_str(), md.colour_space.c_str(), name.c_str());
    r.displays.push_back(md);
  }
  std::string active = merged->getActiveViews();
  if (!active.empty()) {
    for (const auto& [op, name] : ops) active += ", " + name;
    merged->setActiveViews(active.c_str());
  }
  return active;
}

// The search path entries of the merged config: copied folders inside the set, then the set
// itself (for kLutFolder/<file>).
void set_search_path(const OCIO::ConfigRcPtr& merged, const SearchPlan& plan, const std::string& set, MergeResult& r) {
  merged->clearSearchPaths();
  for (const auto& e : plan.entries) {
    merged->addSearchPath(e.copied ? (set + "/" + e.path).c_str() : e.path.c_str());
    auto& list = e.copied ? r.copied_search_paths : r.absolute_search_paths;
    if ((e.copied || e.made_absolute) && std::find(list.begin(), list.end(), e.path) == list.end()) list.push_back(e.path);
  }
  merged->addSearchPath(set.c_str());
}

}  // namespace

namespace {

void replace_search_path(Lines& v, const OCIO::ConstConfigRcPtr& merged) {
  std::string search;
  for (int i = 0; i < merged->getNumSearchPaths(); ++i) search += (i ? ":" : "") + std::string(merged->getSearchPath(i));
  const auto [sp, sp_end] = block(v, "search_path");
  if (sp == std::string::npos) {
    const auto [ver, ver_end] = block(v, "ocio_profile_version");
    v.insert(v.begin() + std::ptrdiff_t(ver == std::string::npos ? 0 : ver_end), "search_path: " + yaml_quoted(search));
  } else {
    v.erase(v.begin() + std::ptrdiff_t(sp), v.begin() + std::ptrdiff_t(sp_end));
    v.insert(v.begin() + std::ptrdiff_t(sp), "search_path: " + yaml_quoted(search));
  }
}

// The operator views, at the end of each chosen display's list.
void insert_views(Lines& v, const MergeResult& r, const OperatorNames& ops, const std::string& studio_path) {
  auto [ds, ds_end] = block(v, "displays");
  std::size_t display_indent = std::string::npos;
  for (std::size_t i = ds + 1; ds != std::string::npos && i < ds_end && display_indent == std::string::npos; ++i)
    if (!is_blank_or_comment(v[i])) display_indent = indent_of(v[i]);
  for (auto it = r.displays.rbegin(); it != r.displays.rend(); ++it) {
    if (it->encoding == DisplayEncoding::none) continue;
    std::tie(ds, ds_end) = block(v, "displays");
    if (ds == std::string::npos) throw DataError("cannot find the displays of '" + studio_path + "' in its text (nothing written)");
    std::size_t at = std::string::npos, end = ds_end;
    for (std::size_t i = ds + 1; i < ds_end; ++i)
      if (key_at(v[i], display_indent) == it->display) {
        at = i;
        for (end = i + 1; end < ds_end && (is_blank_or_comment(v[end]) || indent_of(v[end]) > display_indent); ++end) {}
        while (end > at + 1 && is_blank_or_comment(v[end - 1])) --end;
        break;
      }
    if (at == std::string::npos || !after_colon(v[at]).empty())
      throw DataError("cannot find display '" + it->display + "' as a block list in '" + studio_path + "' (nothing written)");
    std::string item_indent(display_indent + 2, ' ');
    for (std::size_t i = at + 1; i < end; ++i)
      if (!is_blank_or_comment(v[i])) {
        item_indent = std::string(indent_of(v[i]), ' ');
        break;
      }
    Lines add;
    for (const auto& [op, name] : ops)
      add.push_back(item_indent + "- !<View> {name: " + yaml_quoted(name) + ", colorspace: " + yaml_quoted(it->colour_space) +
                    ", looks: " + yaml_quoted(name) + "}");
    v.insert(v.begin() + std::ptrdiff_t(end), add.begin(), add.end());
  }
}

void replace_active_views(Lines& v, const std::string& active, const std::string& studio_path) {
  const auto [av, av_end] = block(v, "active_views");
  if (av == std::string::npos) throw DataError("cannot find active_views in '" + studio_path + "' (nothing written)");
  std::string list;
  std::istringstream names(active);
  for (std::string n; std::getline(names, n, ',');) {
    n.erase(0, n.find_first_not_of(' '));
    while (!n.empty() && n.back() == ' ') n.pop_back();
    list += (list.empty() ? "" : ", ") + yaml_quoted(n);
  }
  v.erase(v.begin() + std::ptrdiff_t(av), v.begin() + std::ptrdiff_t(av_end));
  v.insert(v.begin() + std::ptrdiff_t(av), "active_views: [" + list + "]");
}

// OpenColorIO's own text of the new looks, appended to the studio's looks list (or a new one).
void append_looks(Lines& v, const OCIO::ConstConfigRcPtr& merged, const std::vector<std::string>& looks, const std::string& studio_path) {
  auto only_looks = OCIO::Config::Create();
  for (const auto& name : looks) only_looks->addLook(merged->getLook(name.c_str()));
  Lines look_lines;
  {
    std::ostringstream t;
    only_looks->serialize(t);
    const Lines all = split_lines(t.str());
    const auto [lk, lk_end] = block(all, "looks");
    if (lk == std::string::npos) throw DataError("internal: no looks written");
    look_lines.assign(all.begin() + std::ptrdiff_t(lk + 1), all.begin() + std::ptrdiff_t(lk_end));
  }
  const auto [lk, lk_end] = block(v, "looks");
  if (lk == std::string::npos) {
    v.push_back("");
    v.push_back("looks:");
    v.insert(v.end(), look_lines.begin(), look_lines.end());
    return;
  }
  // Re-indented to the studio's list indentation.
  std::size_t studio_indent = std::string::npos, ours = indent_of(look_lines.front());
  for (std::size_t i = lk + 1; i < lk_end && studio_indent == std::string::npos; ++i)
    if (!is_blank_or_comment(v[i])) studio_indent = indent_of(v[i]);
  if (studio_indent == std::string::npos) studio_indent = ours;
  for (auto& l : look_lines)
    if (!l.empty()) l = studio_indent >= ours ? std::string(studio_indent - ours, ' ') + l : l.substr(ours - studio_indent);
  if (!after_colon(v[lk]).empty() && after_colon(v[lk]) != "[]")
    throw DataError("the looks of '" + studio_path + "' are a flow list: cannot add to them (nothing written)");
  if (!after_colon(v[lk]).empty()) v[lk] = "looks:";
  look_lines.insert(look_lines.begin(), "");
  v.insert(v.begin() + std::ptrdiff_t(lk_end), look_lines.begin(), look_lines.end());
}

// The text to write: the studio's own, edited (a version 1 config is written by OpenColorIO as
// version 2).
std::string merged_text(const LoadedConfig& studio, const OCIO::ConstConfigRcPtr& merged, const MergeResult& r,
                        const OperatorNames& ops, const std::string& active, const std::string& command_line) {
  const std::string header = "# The studio config '" + fs::path(studio.path).filename().string() +
                             "' with cgtmo's operators as looks and views.\n# Generated by `" + command_line +
                             "`; do not edit, re-run it.\n";
  if (studio.config->getMajorVersion() < 2) return config_text(merged, header.substr(2));
  Lines v = split_lines(studio.text);
  replace_search_path(v, merged);
  insert_views(v, r, ops, studio.path);
  if (!active.empty()) replace_active_views(v, merged->getActiveViews(), studio.path);
  append_looks(v, merged, r.looks, studio.path);
  std::string text = header;
  for (const auto& l : v) text += l + "\n";
  return text;
}

// What ociocheck checks, on the text about to be written, its set read where it is staged:
// the config loads, keeps everything of the studio, validates (unless the studio's own config
// does not), and every added view builds its processor, LUTs read.
void check_merged(const std::string& text, const LoadedConfig& studio, const MergeResult& r, const std::string& set,
                  const std::string& staged_set, const std::string& out_dir) {
  OCIO::ConstConfigRcPtr back;
  try {
    back = display::config_from_checked_text(text, "the merged config", out_dir);
  } catch (const OCIO::Exception& e) {
    throw DataError("the merged config does not load back: " + first_line(e.what()) + " (nothing written)");
  }
  for (const auto& name : r.looks)
    if (!back->getLook(name.c_str())) throw DataError("the merged config lost the look '" + name + "' (nothing written)");
  for (const auto& d : r.displays)
    if (d.encoding != DisplayEncoding::none && std::string(back->getDisplayViewLooks(d.display.c_str(), r.looks.front().c_str())) != r.looks.front())
      throw DataError("the merged config lost the views on '" + d.display + "' (nothing written)");
  const auto diffs = kept_differences(studio.config, back);
  if (!diffs.empty()) throw DataError("the merged config would not keep the studio's " + diffs.front() + " (nothing written)");
  auto staged = back->createEditableCopy();
  staged->clearSearchPaths();
  for (int i = 0; i < back->getNumSearchPaths(); ++i) {
    const std::string e = back->getSearchPath(i);
    staged->addSearchPath(e.compare(0, set.size(), set) == 0 && (e.size() == set.size() || e[set.size()] == '/')
                              ? (staged_set + e.substr(set.size())).c_str() : e.c_str());
  }
  try {
    staged->validate();
  } catch (const OCIO::Exception& e) {
    bool studio_valid = true;
    try {
      studio.config->validate();
    } catch (const OCIO::Exception&) {
      studio_valid = false;
    }
    if (studio_valid) throw DataError("the merged config is not valid: " + first_line(e.what()) + " (nothing written)");
  }
  for (const auto& d : r.displays) {
    if (d.encoding == DisplayEncoding::none) continue;
    for (const auto& name : r.looks) {
      try {
        auto t = OCIO::DisplayViewTransform::Create();
        t->setSrc(OCIO::ROLE_SCENE_LINEAR);
        t->setDisplay(d.display.c_str());
        t->setView(name.c_str());
        staged->getProcessor(t)->getDefaultCPUProcessor();
      } catch (const OCIO::Exception& e) {
        throw DataError("the merged view '" + d.display + "/" + name + "' does not build: " + first_line(e.what()) + " (nothing written)");
      }
    }
  }
}

// The output folder, created with its missing parents; unless kept, those of them that are still
// empty are removed again (a merge that fails leaves no folder it made).
class FoldersMade {
 public:
  explicit FoldersMade(const fs::path& folder) {
    for (fs::path p = folder; !p.empty() && !fs::exists(p); p = p.parent_path()) made_.push_back(p);
    std::error_code ec;
    fs::create_directories(folder, ec);
  }
  FoldersMade(const FoldersMade&) = delete;
  FoldersMade& operator=(const FoldersMade&) = delete;
  ~FoldersMade() {
    for (const auto& p : made_) {  // innermost first; fs::remove leaves a folder that is not empty
      std::error_code ec;
      fs::remove(p, ec);
    }
  }
  void keep() { made_.clear(); }

 private:
  std::vector<fs::path> made_;
};

// The folders the merge reads, for check_output_apart.
std::vector<std::pair<fs::path, std::string>> folders_read(const LoadedConfig& studio, const SearchPlan& plan, const LoadedConfig& ours,
                                                          const std::vector<SetFile>& luts) {
  std::vector<std::pair<fs::path, std::string>> read;
  for (const auto& c : plan.copied) read.emplace_back(studio.folder / c, "the studio's LUT folder");
  for (const auto& e : plan.entries) {  // those kept in place: OpenColorIO reads them to check the merge
    std::error_code ec;
    const fs::path folder = fs::weakly_canonical(e.path, ec);
    if (!e.copied && e.path.find('$') == std::string::npos && !ec) read.emplace_back(folder, "a folder on the studio's search path");
  }
  read.emplace_back(studio.folder, "the studio config's folder");
  read.emplace_back(ours.folder, "the cgtmo config's folder");
  for (const auto& l : luts) {
    std::error_code ec;
    const fs::path folder = fs::weakly_canonical(fs::absolute(l.source).parent_path(), ec);
    if (!ec) read.emplace_back(folder, "cgtmo's LUT folder");
  }
  return read;
}

}  // namespace

MergeResult merge_into(const MergeOptions& o) {
  check_prefix(o.prefix);
  const LoadedConfig studio = load(o.studio_config, "studio");
  const LoadedConfig ours = load(o.cgtmo_config, "cgtmo");
  // Every file to copy is checked before OpenColorIO reads any of them.
  const SearchPlan plan = plan_search_path(studio);
  const std::vector<SetFile> copies = studio_files(studio, plan);
  check_named_files(studio);
  MergeResult r;
  r.working = find_working_space(studio.config);
  const std::string scene_linear = studio.config->getColorSpace(OCIO::ROLE_SCENE_LINEAR)->getName();
  if (o.progress)
    o.progress("scene_linear '" + scene_linear + "' to linear Rec.709: " +
               (r.working.rec709_space == scene_linear ? std::string("the same space")
                : !r.working.rec709_space.empty()      ? "the studio's colour space '" + r.working.rec709_space + "'"
                                                       : "a derived matrix") +
               " (basis: " + r.working.basis + ")");
  const OperatorNames ops = operator_names(studio, ours, o.prefix);
  auto merged = studio.config->createEditableCopy();
  if (merged->getMajorVersion() < 2) {
    merged->setMajorVersion(2);
    merged->setMinorVersion(0);
  }
  const std::vector<SetFile> luts = add_looks(merged, ours, ops, scene_linear, r);
  const fs::path out = fs::weakly_canonical(fs::absolute(o.out_dir));
  check_output_apart(out, folders_read(studio, plan, ours, luts));
  const std::string active = add_views(merged, studio, ops, r);

  FoldersMade made(out);  // before the set: removed after its staging folder
  StagedSet set(out.string(), o.progress);
  set.stage(StagedSet::kMarker, "A set of files of the config.ocio beside it, made by `" + o.command_line +
                                    "`. The next merge into this folder removes it once config.ocio no longer names it.\n");
  for (const auto* list : {&copies, &luts})
    for (const auto& f : *list)
      set.stage(f.relative, io::read_regular_file(f.source, kMaxCopiedFileBytes, f.follow_links ? "cgtmo LUT " : "studio file ", f.follow_links));
  r.set_folder = set.settle_name();
  set_search_path(merged, plan, r.set_folder, r);
  merged->setDescription((std::string(studio.config->getDescription()) + (studio.config->getDescription()[0] ? "\n" : "") +
                          "With cgtmo's operators as looks and views, merged by `" + o.command_line + "`.").c_str());
  const std::string text = merged_text(studio, merged, r, ops, active, o.command_line);
  check_merged(text, studio, r, r.set_folder, set.staged_path(), out.string());
  r.config_path = (fs::path(o.out_dir) / "config.ocio").string();
  set.commit(text);
  made.keep();
  return r;
}

}  // namespace cgtmo::bake
