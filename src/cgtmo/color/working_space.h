#pragma once
// Where linear Rec.709 (D65), cgtmo's working space, lies in an OCIO config: the conversion from
// the config's scene_linear role, measured through its interchange roles. One answer for the
// readers (input colour spaces), the display encoder and the config merge.
#include <OpenColorIO/OpenColorIO.h>

#include <optional>
#include <string>

#include "cgtmo/color/matrix.h"

namespace cgtmo::color {

namespace OCIO = OCIO_NAMESPACE;

// ACES2065-1 (AP0, D60) -> linear Rec.709 and CIE XYZ (D65) -> linear Rec.709, from the primaries
// (Bradford adaptation of the white; color/chromaticities.h).
Mat3 aces2065_to_rec709();
Mat3 xyz_d65_to_rec709();

// A 3x3 colour matrix as an OCIO transform.
OCIO::MatrixTransformRcPtr matrix_transform(const Mat3& m);

// The 3x3 matrix of OCIO's conversion from `src` to `dst` (colour spaces, roles or aliases): its
// columns from the unit vectors, then checked on colours from 0.001 to 200 (relative 1e-4), so a
// curve is never taken for a matrix. nullopt when OCIO has no such conversion or it is not linear.
std::optional<Mat3> conversion_matrix(const OCIO::ConstConfigRcPtr& config, const std::string& src,
                                      const std::string& dst);
// The same for a processor followed by an optional matrix. When the processor's operations are all
// matrices (OCIO's own list, GroupTransform of the processor), their product is taken in double:
// measuring through the CPU processor gives float32 (about 1e-7 per element), which leaves colour
// in the other channels of a very bright primary.
std::optional<Mat3> processor_matrix(const OCIO::ConstProcessorRcPtr& processor, const std::optional<Mat3>& post);

struct WorkingSpace {
  Mat3 scene_linear_to_rec709;  // identity when assumed or within kRec709Tolerance of it
  // "aces_interchange" or "cie_xyz_d65_interchange" when measured through that role; "assumed"
  // when the config has neither (Blender's convention: scene_linear is linear Rec.709).
  std::string basis = "assumed";
  bool is_rec709() const { return scene_linear_to_rec709.m == Mat3::identity().m; }
};

// A measured scene_linear within this of the identity (per element) is linear Rec.709 written
// with another chromatic adaptation or fewer digits (Blender's: 2.4e-4 through its ACES role).
inline constexpr double kRec709Tolerance = 2e-3;

// Throws DataError when the config has no scene_linear role.
WorkingSpace find_working_space(const OCIO::ConstConfigRcPtr& config);

}  // namespace cgtmo::color
