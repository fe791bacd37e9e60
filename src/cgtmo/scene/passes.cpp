#include "cgtmo/scene/passes.h"

#include <algorithm>
#include <cctype>
#include <map>

#include "cgtmo/errors.h"
#include "cgtmo/util/text.h"

namespace cgtmo::scene {

namespace {

struct PassInfo {
  Pass pass;
  const char* name;
};
constexpr PassInfo kPasses[] = {{Pass::Beauty, "beauty"},     {Pass::Depth, "depth"},
                                {Pass::Position, "position"}, {Pass::Normal, "normal"},
                                {Pass::Albedo, "albedo"},     {Pass::Emission, "emission"},
                                {Pass::LightGroups, "lightgroups"}};

std::string lower(std::string s) {
  std::transform(s.begin(), s.end(), s.begin(), [](unsigned char c) { return char(std::tolower(c)); });
  return s;
}

bool ends_with(const std::string& s, const std::string& suffix) {
  return s.size() >= suffix.size() && s.compare(s.size() - suffix.size(), suffix.size(), suffix) == 0;
}

// Case-insensitive index of the file's names.
class NameIndex {
 public:
  explicit NameIndex(const std::vector<std::string>& names) {
    for (const auto& n : names) by_lower_.emplace(lower(n), n);  // first occurrence wins
  }
  // The file's spelling of `want`, or "".
  std::string find(const std::string& want) const {
    const auto it = by_lower_.find(lower(want));
    return it == by_lower_.end() ? std::string() : it->second;
  }

 private:
  std::map<std::string, std::string> by_lower_;
};

// Bases for a 3-component pass: Blender's first, then the generic spellings under each root.
struct TripleSpec {
  const char* blender;                     // pass name after "<ViewLayer>."
  std::vector<const char*> generic_bases;  // "P", "position", ...
};

const TripleSpec& triple_spec(Pass p) {
  static const TripleSpec position{"Position", {"P", "position", "pos", "worldposition"}};
  static const TripleSpec normal{"Normal", {"N", "normal", "normals"}};
  static const TripleSpec albedo{"DiffCol", {"albedo", "diffcol", "basecolor", "diffuse_color"}};
  static const TripleSpec emission{"Emit", {"emission", "emit"}};
  switch (p) {
    case Pass::Position: return position;
    case Pass::Normal: return normal;
    case Pass::Albedo: return albedo;
    default: return emission;
  }
}

const std::vector<std::vector<const char*>>& component_sets() {
  static const std::vector<std::vector<const char*>> sets = {{"X", "Y", "Z"}, {"R", "G", "B"}};
  return sets;
}

std::vector<std::string> find_triple(const NameIndex& idx, const std::vector<std::string>& bases) {
  for (const auto& base : bases)
    for (const auto& comps : component_sets()) {
      std::vector<std::string> found;
      for (const char* c : comps) {
        const std::string n = idx.find(base + "." + c);
        if (n.empty()) break;
        found.push_back(n);
      }
      if (found.size() == 3) return found;
    }
  return {};
}

// "<ViewLayer>" when the beauty is Blender's "<ViewLayer>.Combined", else "".
std::string blender_view_layer(const std::string& beauty_prefix) {
  const std::string suffix = ".Combined";
  return ends_with(beauty_prefix, suffix) ? beauty_prefix.substr(0, beauty_prefix.size() - suffix.size()) : "";
}

// Roots under which generic names are looked up: beside the beauty layer, then the top level.
std::vector<std::string> generic_roots(const std::string& beauty_prefix) {
  std::vector<std::string> roots;
  if (!beauty_prefix.empty()) {
    const auto dot = beauty_prefix.rfind('.');
    roots.push_back(dot == std::string::npos ? "" : beauty_prefix.substr(0, dot + 1));
    roots.push_back(beauty_prefix + ".");
  }
  roots.push_back("");
  roots.erase(std::unique(roots.begin(), roots.end()), roots.end());
  return roots;
}

std::vector<std::string> triple_bases(Pass p, const std::string& beauty_prefix) {
  const TripleSpec& spec = triple_spec(p);
  std::vector<std::string> bases;
  const std::string vl = blender_view_layer(beauty_prefix);
  if (!vl.empty()) bases.push_back(vl + "." + spec.blender);
  for (const auto& root : generic_roots(beauty_prefix))
    for (const char* b : spec.generic_bases) bases.push_back(root + b);
  return bases;
}

std::vector<std::string> depth_names(const std::string& beauty_prefix) {
  std::vector<std::string> names;
  const std::string vl = blender_view_layer(beauty_prefix);
  if (!vl.empty()) names.push_back(vl + ".Depth.Z");
  for (const auto& root : generic_roots(beauty_prefix))
    for (const char* n : {"Z", "depth", "depth.Z", "zdepth"}) names.push_back(root + n);
  return names;
}

// The three or four channels of one spelling under `prefix`, or empty.
std::vector<std::string> spelled(const NameIndex& idx, const std::string& prefix, const std::vector<const char*>& comps) {
  const std::string p = prefix.empty() ? "" : prefix + ".";
  std::vector<std::string> found;
  for (std::size_t i = 0; i < 3; ++i) {
    const std::string n = idx.find(p + comps[i]);
    if (n.empty()) return {};
    found.push_back(n);
  }
  const std::string a = idx.find(p + comps[3]);
  if (!a.empty()) found.push_back(a);
  return found;
}

std::vector<std::string> beauty_channels_in(const NameIndex& idx, const std::string& prefix) {
  for (const auto& comps : {std::vector<const char*>{"R", "G", "B", "A"}, std::vector<const char*>{"red", "green", "blue", "alpha"}}) {
    auto found = spelled(idx, prefix, comps);
    if (!found.empty()) return found;
  }
  return {};
}

// The file's spelling of the layer of channel `name`.
std::string layer_of(const std::string& name) {
  const auto dot = name.rfind('.');
  return dot == std::string::npos ? "" : name.substr(0, dot);
}

// Layer names that mean the beauty: Nuke's main layer rgba (Arnold names its beauty AOV RGBA),
// RenderMan's Ci, and the generic beauty.
constexpr const char* kBeautyNames[] = {"rgba", "Ci", "beauty"};

}  // namespace

std::vector<std::string> beauty_channels(const std::vector<std::string>& names, const std::string& prefix) {
  return beauty_channels_in(NameIndex(names), prefix);
}

bool beauty_layer(const std::vector<std::string>& names, std::string* prefix) {
  const NameIndex idx(names);
  auto take = [&](const std::string& p) {
    const auto found = beauty_channels_in(idx, p);
    if (found.empty()) return false;
    *prefix = layer_of(found.front());
    return true;
  };
  if (take("")) return true;
  for (const auto& n : names)
    if (ends_with(lower(n), ".combined.r") && take(n.substr(0, n.size() - 2))) return true;
  for (const char* b : kBeautyNames)
    if (take(b)) return true;
  return false;
}

bool names_the_beauty(const std::string& layer) {
  for (const char* b : kBeautyNames)
    if (lower(layer) == lower(b)) return true;
  return false;
}

std::string beauty_conventions() {
  std::string s = "R,G,B; <ViewLayer>.Combined";
  for (const char* b : kBeautyNames) s += std::string("; ") + b;
  return s;
}

std::vector<std::string> rgb_layers(const std::vector<std::string>& names) {
  const NameIndex idx(names);
  std::vector<std::string> layers;
  for (const auto& n : names) {
    const std::string l = layer_of(n);
    const std::string shown = l.empty() ? "(top level)" : l;
    if (std::find(layers.begin(), layers.end(), shown) == layers.end() && !beauty_channels_in(idx, l).empty())
      layers.push_back(shown);
  }
  return layers;
}

const char* pass_name(Pass p) {
  for (const auto& i : kPasses)
    if (i.pass == p) return i.name;
  return "?";
}

std::vector<Pass> passes_in(PassSet s) {
  std::vector<Pass> out;
  for (const auto& i : kPasses)
    if (s.has(i.pass)) out.push_back(i.pass);
  return out;
}

std::string describe(PassSet s) {
  std::string out;
  for (Pass p : passes_in(s)) out += (out.empty() ? "" : ", ") + std::string(pass_name(p));
  return out.empty() ? "none" : out;
}

PassSet parse_passes(const std::string& list) {
  PassSet s;
  std::size_t start = 0;
  while (start <= list.size()) {
    const std::size_t comma = std::min(list.find(',', start), list.size());
    const std::string item = lower(list.substr(start, comma - start));
    start = comma + 1;
    if (item.empty()) continue;
    if (item == "gbuffer") {
      s = s | PassSet::gbuffer();
      continue;
    }
    if (item == "all") {
      s = s | PassSet::all();
      continue;
    }
    bool known = false;
    for (const auto& i : kPasses)
      if (item == i.name) {
        s = s | i.pass;
        known = true;
      }
    if (!known) {
      std::vector<std::string> names{"gbuffer", "all"};
      for (const auto& i : kPasses) names.emplace_back(i.name);
      throw UsageError("unknown pass '" + item + "'" + did_you_mean(item, names) +
                       " (use beauty, depth, position, normal, albedo, emission, lightgroups, gbuffer, all)");
    }
  }
  return s;
}

bool ChannelMap::has(Pass p) const {
  switch (p) {
    case Pass::Beauty: return !beauty.empty();
    case Pass::Depth: return !depth.empty();
    case Pass::Position: return !position.empty();
    case Pass::Normal: return !normal.empty();
    case Pass::Albedo: return !albedo.empty();
    case Pass::Emission: return !emission.empty();
    case Pass::LightGroups: return !light_groups.empty();
  }
  return false;
}

std::vector<std::string> ChannelMap::channels_for(PassSet s) const {
  std::vector<std::string> out;
  auto add = [&](const std::vector<std::string>& v) { out.insert(out.end(), v.begin(), v.end()); };
  if (s.has(Pass::Beauty)) add(beauty);
  if (s.has(Pass::Depth) && !depth.empty()) out.push_back(depth);
  if (s.has(Pass::Position)) add(position);
  if (s.has(Pass::Normal)) add(normal);
  if (s.has(Pass::Albedo)) add(albedo);
  if (s.has(Pass::Emission)) add(emission);
  if (s.has(Pass::LightGroups))
    for (const auto& g : light_groups) add(g.rgb);
  return out;
}

std::string ChannelMap::expected_names(Pass p, const std::string& beauty_prefix) {
  std::vector<std::string> names;
  if (p == Pass::Beauty) return "R,G,B in a layer named by --layer or by convention (" + beauty_conventions() + ")";
  if (p == Pass::Depth) {
    names = depth_names(beauty_prefix);
  } else if (p == Pass::LightGroups) {
    const std::string vl = blender_view_layer(beauty_prefix);
    return (vl.empty() ? std::string() : vl + ".Combined_<group>.R,G,B or ") + "lightgroup.<group>.R,G,B";
  } else {
    for (const auto& b : triple_bases(p, beauty_prefix)) names.push_back(b + ".X,Y,Z");
  }
  std::string s;
  for (const auto& n : names) s += (s.empty() ? "" : ", ") + n;
  return s;
}

ChannelMap map_channels(const std::vector<std::string>& names, const std::string& beauty_prefix) {
  const NameIndex idx(names);
  ChannelMap m;
  const std::string vl = blender_view_layer(beauty_prefix);
  m.scheme = vl.empty() ? "generic" : "blender";
  m.beauty_prefix = beauty_prefix;
  m.beauty = beauty_channels_in(idx, beauty_prefix);
  m.position = find_triple(idx, triple_bases(Pass::Position, beauty_prefix));
  m.normal = find_triple(idx, triple_bases(Pass::Normal, beauty_prefix));
  m.albedo = find_triple(idx, triple_bases(Pass::Albedo, beauty_prefix));
  m.emission = find_triple(idx, triple_bases(Pass::Emission, beauty_prefix));
  for (const auto& n : depth_names(beauty_prefix)) {
    m.depth = idx.find(n);
    if (!m.depth.empty()) break;
  }
  // Light groups: "<beauty>_<group>.R" (Blender: ViewLayer.Combined_<group>) or
  // "lightgroup.<group>.R" under a generic root; G and B must exist too.
  std::vector<std::string> group_prefixes;
  if (!beauty_prefix.empty()) group_prefixes.push_back(lower(beauty_prefix + "_"));
  for (const auto& root : generic_roots(beauty_prefix)) group_prefixes.push_back(lower(root + "lightgroup."));
  for (const auto& n : names) {
    const std::string ln = lower(n);
    if (!ends_with(ln, ".r")) continue;
    const std::string stem = n.substr(0, n.size() - 2);
    const std::string lstem = ln.substr(0, ln.size() - 2);
    for (const auto& gp : group_prefixes) {
      if (lstem.size() <= gp.size() || lstem.compare(0, gp.size(), gp) != 0) continue;
      const std::string g = idx.find(stem + ".G"), b = idx.find(stem + ".B");
      if (g.empty() || b.empty()) continue;
      const std::string group = stem.substr(gp.size());
      const bool dup = std::any_of(m.light_groups.begin(), m.light_groups.end(),
                                   [&](const ChannelMap::Group& x) { return x.name == group; });
      if (!dup) m.light_groups.push_back({group, {n, g, b}});
      break;
    }
  }
  return m;
}

PassOverride parse_pass_override(const std::string& text) {
  const auto eq = text.find('=');
  const std::string role = eq == std::string::npos ? "" : lower(text.substr(0, eq));
  const std::string layer = eq == std::string::npos ? "" : text.substr(eq + 1);
  const bool group = role.rfind("lightgroup:", 0) == 0 && role.size() > 11;
  const bool known = group || role == "position" || role == "normal" || role == "albedo" || role == "emission" || role == "depth";
  if (!known || layer.empty())
    throw UsageError("--pass '" + text + "': use ROLE=LAYER with ROLE position, normal, albedo, emission, depth or lightgroup:NAME");
  // A light group's name keeps the user's spelling.
  return {group ? "lightgroup:" + text.substr(11, eq - 11) : role, layer};
}

void apply_overrides(ChannelMap& m, const std::vector<std::string>& names, const std::vector<PassOverride>& overrides,
                     const std::string& file) {
  const NameIndex idx(names);
  for (const auto& o : overrides) {
    const std::string what = "'" + file + "': --pass " + o.role + "=" + o.layer + ": ";
    if (o.role == "depth") {
      std::string n = idx.find(o.layer);
      if (n.empty()) n = idx.find(o.layer + ".Z");
      if (n.empty()) throw DataError(what + "no channel " + o.layer + " or " + o.layer + ".Z");
      m.depth = n;
      continue;
    }
    const std::vector<std::string> t = find_triple(idx, {o.layer});
    if (t.empty()) throw DataError(what + "no channels " + o.layer + ".X,Y,Z or " + o.layer + ".R,G,B");
    if (o.role == "position") m.position = t;
    else if (o.role == "normal") m.normal = t;
    else if (o.role == "albedo") m.albedo = t;
    else if (o.role == "emission") m.emission = t;
    else {
      const std::string group = o.role.substr(11);
      auto it = std::find_if(m.light_groups.begin(), m.light_groups.end(), [&](const ChannelMap::Group& g) { return g.name == group; });
      if (it != m.light_groups.end()) it->rgb = t;
      else m.light_groups.push_back({group, t});
    }
  }
}

std::vector<std::string> unmapped_channels(const std::vector<std::string>& names, const ChannelMap& m) {
  const std::vector<std::string> used = m.channels_for(PassSet::all());
  std::vector<std::string> out;
  for (const auto& n : names)
    if (std::find(used.begin(), used.end(), n) == used.end()) out.push_back(n);
  return out;
}

}  // namespace cgtmo::scene
