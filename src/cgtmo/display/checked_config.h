#pragma once
// Every OCIO config cgtmo reads from outside (--colorconfig, $OCIO, a studio config, cgtmo's own
// config, a config a bake copies, the text a merge is about to write) is loaded here, after two
// checks OpenColorIO does not make:
//   - its size: a regular file of at most kMaxConfigBytes, read through one descriptor that does
//     not block (a FIFO is refused, not waited on);
//   - what its YAML anchors and aliases expand it to. OpenColorIO walks an aliased node once per
//     alias, so nested aliases multiply: 10 levels of 10 aliases in 9 KB are 1e9 nodes, minutes
//     and gigabytes inside OpenColorIO. The expansion is estimated from the text before
//     OpenColorIO sees it and must stay within kMaxConfigBytes too; an alias inside its own
//     anchor (a cycle) is refused.
#include <OpenColorIO/OpenColorIO.h>

#include <cstdint>
#include <string>

namespace cgtmo::display {

namespace OCIO = OCIO_NAMESPACE;

// The most bytes a config may hold, written out or through its aliases. The largest configs in
// use (ACES studio configs with their inline transforms) are well under 1 MB.
inline constexpr std::uint64_t kMaxConfigBytes = 16u << 20;

// What the anchors and aliases of a YAML text expand it to.
struct YamlExpansion {
  int anchors = 0, aliases = 0;
  double expanded_bytes = 0;  // the text's bytes with every alias replaced by its anchor's node
  std::string cycle;          // the name of an alias used inside its own anchor, or ""
};
YamlExpansion yaml_expansion(const std::string& text);

// Throws DataError "<label>: <reason>" when `text` is larger than kMaxConfigBytes, expands
// beyond it, or holds an alias cycle.
void check_config_text(const std::string& text, const std::string& label);

// A config from text that passed check_config_text; relative search paths resolve in
// `working_dir`. Throws DataError (the checks) or OCIO::Exception (OpenColorIO's parse).
OCIO::ConstConfigRcPtr config_from_checked_text(const std::string& text, const std::string& label,
                                                const std::string& working_dir);

// The config file `path`: read (regular file, at most kMaxConfigBytes), checked, and created from
// that text with the file's folder as working directory, as OpenColorIO's CreateFromFile does.
// Throws DataError "'<path>': <reason>" or OCIO::Exception.
OCIO::ConstConfigRcPtr load_config_checked(const std::string& path);

}  // namespace cgtmo::display
