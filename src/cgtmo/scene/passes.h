#pragma once
// Which passes a reader should decode, and how channel names map onto them.
//
// Two naming schemes are recognised (component letters are case-insensitive):
//   Blender multilayer:  <ViewLayer>.Combined.R/G/B[/A]   beauty
//                        <ViewLayer>.Position.X/Y/Z       position
//                        <ViewLayer>.Normal.X/Y/Z         normal
//                        <ViewLayer>.DiffCol.R/G/B        albedo
//                        <ViewLayer>.Depth.Z              depth
//                        <ViewLayer>.Emit.R/G/B           emission
//                        <ViewLayer>.Combined_<group>.R/G/B   one light group
//   Generic:             R,G,B[,A]                        beauty (beauty_layer: conventions)
//                        P.x | position.x | pos.x         position (also .X, .r, .R)
//                        N.x | normal.x                   normal
//                        albedo.r | diffcol.r | basecolor.r   albedo
//                        Z | depth | depth.z              depth
//                        emission.r | emit.r              emission
//                        lightgroup.<group>.r             one light group
// Generic names are looked up at the top level and beside the beauty layer (<layer>.P.x).
#include <cstdint>
#include <string>
#include <vector>

namespace cgtmo::scene {

enum class Pass : std::uint32_t {
  Beauty = 1u << 0,
  Depth = 1u << 1,  // also yields the background mask
  Position = 1u << 2,
  Normal = 1u << 3,
  Albedo = 1u << 4,
  Emission = 1u << 5,
  LightGroups = 1u << 6,
};

// A set of passes: PassSet{Pass::Beauty} | Pass::Normal.
class PassSet {
 public:
  constexpr PassSet() = default;
  constexpr PassSet(Pass p) : bits_(std::uint32_t(p)) {}  // NOLINT: implicit on purpose
  friend constexpr PassSet operator|(PassSet a, PassSet b) { return PassSet(a.bits_ | b.bits_); }
  friend constexpr PassSet operator-(PassSet a, PassSet b) { return PassSet(a.bits_ & ~b.bits_); }
  constexpr bool has(Pass p) const { return (bits_ & std::uint32_t(p)) != 0; }
  constexpr bool empty() const { return bits_ == 0; }
  constexpr std::uint32_t bits() const { return bits_; }

  static constexpr PassSet gbuffer();  // depth, position, normal, albedo
  static constexpr PassSet all();

 private:
  constexpr explicit PassSet(std::uint32_t b) : bits_(b) {}
  std::uint32_t bits_ = 0;
};

constexpr PassSet operator|(Pass a, Pass b) { return PassSet(a) | PassSet(b); }
constexpr PassSet PassSet::gbuffer() { return Pass::Depth | Pass::Position | Pass::Normal | Pass::Albedo; }
constexpr PassSet PassSet::all() { return gbuffer() | Pass::Beauty | Pass::Emission | Pass::LightGroups; }

const char* pass_name(Pass p);                      // "position", ...
std::vector<Pass> passes_in(PassSet s);             // in enum order
std::string describe(PassSet s);                    // "beauty, depth, normal"
// Parses "position,normal" (names as pass_name, plus "gbuffer" and "all"). Throws UsageError.
PassSet parse_passes(const std::string& list);

// Where each pass lives in one file's channel list. A missing pass has empty names.
struct ChannelMap {
  std::string scheme;            // "blender" or "generic"
  std::string beauty_prefix;     // as io::find_beauty, "" for top-level R,G,B
  std::vector<std::string> beauty;   // R, G, B (and A when present)
  std::vector<std::string> position, normal, albedo, emission;  // 3 names each, or empty
  std::string depth;                 // one name, or empty
  struct Group {
    std::string name;
    std::vector<std::string> rgb;
  };
  std::vector<Group> light_groups;   // in file order

  bool has(Pass p) const;
  // Every channel name the given passes use (the beauty's alpha included).
  std::vector<std::string> channels_for(PassSet s) const;
  // A line listing the names tried for a pass, for error messages.
  static std::string expected_names(Pass p, const std::string& beauty_prefix);
};

// The beauty's channels in layer `prefix` ("" = the top level): R, G, B, then A when present, in
// the spellings renderers and compositors write: R/G/B/A in either case (RenderMan's r, g, b, a)
// or Nuke's red/green/blue/alpha (layer names match in any case). Empty when one of the three is
// missing.
std::vector<std::string> beauty_channels(const std::vector<std::string>& names, const std::string& prefix);

// The layer that holds the beauty by convention, in this order: the top level; Blender's
// "<ViewLayer>.Combined"; a layer named rgba (Nuke's main layer, Arnold's beauty AOV RGBA), Ci
// (RenderMan's beauty) or beauty, in any case. Returns the file's spelling of the prefix, or false
// when none has R, G and B: another RGB layer (an AOV such as diffuse) is never taken for it.
bool beauty_layer(const std::vector<std::string>& names, std::string* prefix);

// Whether `layer` is one of the names beauty_layer takes for the beauty (rgba, Ci, beauty; any
// case). Nuke and Arnold write their rgba / RGBA beauty as top-level R, G, B, A, so such a name
// given by the user also means the top level when the file has no layer of that name.
bool names_the_beauty(const std::string& layer);

// The conventions beauty_layer follows, for messages.
std::string beauty_conventions();

// The layers holding R, G and B (beauty_channels), in file order; "(top level)" for "".
std::vector<std::string> rgb_layers(const std::vector<std::string>& names);

// Maps the file's channel names (in file order) given the beauty's prefix (io::find_beauty).
// Never throws: what is not found stays empty.
ChannelMap map_channels(const std::vector<std::string>& names, const std::string& beauty_prefix);

// The user's choice of the layer that fills a role, for renderers whose AOV names the automatic
// mapping does not know (`--pass role=LAYER`). Roles: position, normal, albedo, emission, depth,
// lightgroup:<name>. LAYER names channels as the file spells them: a vector role takes
// LAYER.X,Y,Z or LAYER.R,G,B (any case); depth takes the channel LAYER itself, else LAYER.Z.
struct PassOverride {
  std::string role, layer;
};
// Parses "role=LAYER". Throws UsageError naming the roles.
PassOverride parse_pass_override(const std::string& text);
// Points `m` at the overrides' channels, among the file's `names` (a light group of the same name
// is replaced, a new one added). Throws DataError naming `file`, the option and what was looked for.
void apply_overrides(ChannelMap& m, const std::vector<std::string>& names, const std::vector<PassOverride>& overrides,
                     const std::string& file);

// Channel names that belong to no known pass (reported by `cgtmo info`).
std::vector<std::string> unmapped_channels(const std::vector<std::string>& names, const ChannelMap& m);

}  // namespace cgtmo::scene
