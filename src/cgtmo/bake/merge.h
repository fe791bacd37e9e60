#pragma once
// `cgtmo bake --into STUDIO.ocio`: a studio's OCIO config with cgtmo's operators added as looks
// and as views on the studio's sRGB, Rec.1886 and Display P3 displays, everything of the studio
// kept (see docs/ocio.md, "Merging into a studio config").
#include <OpenColorIO/OpenColorIO.h>

#include <string>
#include <vector>

#include "cgtmo/bake/choose.h"
#include "cgtmo/color/matrix.h"

namespace cgtmo::bake {

namespace OCIO = OCIO_NAMESPACE;

// The display encodings an operator view is added for (they are what the operators' LUTs and the
// audit assume: display-linear Rec.709 in, one of these encodings out).
enum class DisplayEncoding { none, srgb, rec1886, display_p3 };
const char* encoding_name(DisplayEncoding e);

// What a colour space of `config` does to linear Rec.709 values given in `scene_linear` (through
// `to_scene_linear`, linear Rec.709 -> the config's scene_linear): the encoding it matches within
// one 10-bit code value on greys and colours inside [0, 1], or none.
DisplayEncoding detect_encoding(const OCIO::ConstConfigRcPtr& config, const std::string& colour_space,
                                const color::Mat3& rec709_to_scene_linear);

// How scene_linear values of a config become linear Rec.709, cgtmo's working space.
struct WorkingSpace {
  color::Mat3 scene_linear_to_rec709;  // measured through the config's interchange role, or identity
  std::string basis;                   // "aces_interchange", "cie_xyz_d65_interchange" or "assumed"
  std::string rec709_space;            // a colour space of the config equal to linear Rec.709 from
                                       // scene_linear (may be scene_linear itself), or empty
};
WorkingSpace find_working_space(const OCIO::ConstConfigRcPtr& config);

struct MergeOptions {
  std::string studio_config;  // STUDIO.ocio
  std::string cgtmo_config;   // cgtmo's own config (its operator looks and LUT files)
  std::string out_dir;        // DIR: the merged config.ocio and its set folder
  std::string prefix = "cgtmo ";
  std::string command_line;
  Progress progress;
};

struct MergedDisplay {
  std::string display, colour_space;
  DisplayEncoding encoding = DisplayEncoding::none;
};

struct MergeResult {
  std::string config_path;
  std::string set_folder;  // DIR/<set_folder>: the copied studio folders and cgtmo's LUTs (staged_set.h)
  WorkingSpace working;
  std::vector<MergedDisplay> displays;  // every display of the studio; encoding none: no views added
  std::vector<std::string> looks;       // the added look (and view) names
  std::vector<std::string> copied_search_paths, absolute_search_paths;
};

// Writes DIR/config.ocio and the set folder it names (staged_set.h), nothing else: the set
// holds copies of the studio's search-path folders that are real subfolders of its folder
// (regular files, and links to regular files inside that folder) and cgtmo's LUTs. Throws
// UsageError (a --prefix OpenColorIO would read as look syntax; an output folder that is, is
// inside or contains a folder the merge reads) or DataError (a config that cannot be read, is too
// large or expands too far; a name that would collide; no scene_linear role; a link out of the
// studio's folder or a file that is not regular in a folder to copy; a merged config that does
// not load back, keep the studio's definitions, validate or build its views). On any error DIR
// is as it was.
MergeResult merge_into(const MergeOptions& options);

// The differences between what `studio` defines and what `merged` keeps of it: every colour
// space (transforms as text), role, display / view (colour space, view transform, looks), look,
// view transform, named transform, file rule, active display and view. Empty: all kept.
std::vector<std::string> kept_differences(const OCIO::ConstConfigRcPtr& studio, const OCIO::ConstConfigRcPtr& merged);

}  // namespace cgtmo::bake
