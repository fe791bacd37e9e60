#pragma once
// The colour space of an input render and its conversion into cgtmo's working space (linear
// Rec.709, D65), done once, right after reading, on the radiometric planes (beauty, light groups,
// albedo, probe), never on position, normal or depth.
//
// Which space a file is in:
//   1. the OCIO colour space named by the user (--colorspace, colorspace=...), when given;
//   2. else the file's `chromaticities` attribute, when it has one;
//   3. else, for a display-referred file (integer pixels: an 8- or 16-bit PNG, JPEG or TIFF),
//      sRGB-encoded Rec.709, decoded to linear light with a warning that says so;
//   4. else the OCIO config's scene_linear role;
//   5. else linear Rec.709 (nothing to convert).
// A named space is converted by OCIO into the config's scene_linear role and from there to linear
// Rec.709 by the matrix measured through the config's interchange roles (color/working_space.h;
// without them scene_linear is taken to be linear Rec.709, as in cgtmo's and Blender's). When both a
// name and the attribute are there and they disagree, the name wins with a one-line warning.
#include <OpenColorIO/OpenColorIO.h>

#include <cstddef>
#include <optional>
#include <string>
#include <vector>

#include "cgtmo/color/chromaticities.h"
#include "cgtmo/color/matrix.h"

namespace cgtmo::color {

namespace OCIO = OCIO_NAMESPACE;

// What a file says about its colour.
struct FileColour {
  std::optional<Chromaticities> chromaticities;  // the OpenEXR attribute
  // Set when the pixels are display-referred (integers, as 8- and 16-bit PNG, JPEG and TIFF
  // store them): what the file is ("an 8-bit PNG"), for the warning. "": linear light.
  std::string display_referred;
};

class InputSpace {
 public:
  // Linear Rec.709: no conversion.
  InputSpace();

  // Resolves as above. `name` must be a colour space (or role or alias) of `config` (check with
  // check_colorspace_name first for a usage error). `warning`, when given, receives the
  // disagreement line ("" when none). Throws DataError for degenerate chromaticities.
  static InputSpace resolve(const OCIO::ConstConfigRcPtr& config, const std::string& name,
                            const std::optional<Chromaticities>& attribute, std::string* warning = nullptr);
  // With all the file says: a display-referred file without a name is decoded from sRGB, and
  // `warning` says so.
  static InputSpace resolve(const OCIO::ConstConfigRcPtr& config, const std::string& name, const FileColour& file,
                            std::string* warning = nullptr);

  // What was resolved, for records and messages: "chromaticities attribute (ACEScg (AP1)
  // primaries, ACES white (D60))", "OCIO colour space 'ACEScg'", "scene_linear role
  // ('Linear Rec.709')", "Linear Rec.709".
  const std::string& description() const { return description_; }
  bool identity() const { return identity_; }
  // The conversion as a matrix when it is linear (always, except for a named non-linear space).
  const std::optional<Mat3>& matrix() const { return matrix_; }

  // In place over interleaved pixels whose first three channels are RGB (alpha and any further
  // channel untouched). A pixel with a non-finite value is left as it is, for the non-finite
  // policy (scene/sanitize.h) to count and replace. A converted component within 1e-5 of the sum
  // of its terms' magnitudes is rounding residue and becomes 0. Parallel over chunks.
  void apply(float* px, std::size_t count, int channels) const;
  void apply(std::vector<float>& rgb, int channels) const { apply(rgb.data(), rgb.size() / std::size_t(channels), channels); }

 private:
  std::string description_ = "Linear Rec.709";
  bool identity_ = true;
  std::optional<Mat3> matrix_;
  OCIO::ConstCPUProcessorRcPtr cpu_;  // named non-linear space only, then post_ (XYZ -> Rec.709)
  std::optional<Mat3> post_;
};

// The OCIO config that input colour spaces are resolved in: display::load_config(path) (path,
// else $OCIO, else built-in). With no `name`, a config that cannot be loaded is no error: nullptr,
// and files go by their attribute, else linear Rec.709 (as before colour spaces were read, a run
// without display encoding needs no config). `origin` as in load_config.
OCIO::ConstConfigRcPtr config_for_input(const std::string& path, const std::string& name, std::string* origin = nullptr);

// Throws UsageError when `name` is not a colour space, role or alias of `config`: one line naming
// the config (`origin`) and a few of its colour spaces.
void check_colorspace_name(const OCIO::ConstConfigRcPtr& config, const std::string& name, const std::string& origin);

// The conversion of a named space of `config` into linear Rec.709 as a matrix, found by sending
// test colours through OCIO; nullopt when the conversion is not linear (a log or display space).
std::optional<Mat3> named_space_matrix(const OCIO::ConstConfigRcPtr& config, const std::string& name);

}  // namespace cgtmo::color
