// Where linear Rec.709 lies in a config (src/cgtmo/color/working_space.h).
#include <gtest/gtest.h>

#include <filesystem>
#include <sstream>

#include "cgtmo/color/chromaticities.h"
#include "cgtmo/color/working_space.h"
#include "cgtmo/display/display.h"

namespace cgtmo::color {
namespace {

const std::string kShipped = std::string(CGTMO_SOURCE_DIR) + "/ocio_config/config.ocio";
const std::string kBlender = "/usr/share/blender/datafiles/colormanagement/config.ocio";

// A studio config working in ACEScg, with its matrices written to 10 digits as studios do.
OCIO::ConstConfigRcPtr acescg_studio() {
  const Mat3 cg_to_ap0 = to_rec709(aces_ap0()).inverse() * to_rec709(aces_ap1());
  std::ostringstream m;
  m.precision(10);
  for (int r = 0; r < 3; ++r) m << cg_to_ap0.m[r][0] << ", " << cg_to_ap0.m[r][1] << ", " << cg_to_ap0.m[r][2] << ", 0, ";
  std::istringstream yaml("ocio_profile_version: 2\nroles:\n  scene_linear: ACEScg\n  aces_interchange: ACES2065-1\n"
                          "  default: ACES2065-1\n"
                          "displays:\n  sRGB:\n    - !<View> {name: Raw, colorspace: Raw}\n"
                          "colorspaces:\n  - !<ColorSpace>\n    name: ACES2065-1\n"
                          "  - !<ColorSpace>\n    name: ACEScg\n    to_scene_reference: !<MatrixTransform> {matrix: [" +
                          m.str() + "0, 0, 0, 1]}\n"
                          "  - !<ColorSpace>\n    name: Log\n    to_scene_reference: !<LogTransform> {base: 2, direction: inverse}\n"
                          "  - !<ColorSpace>\n    name: Raw\n    isdata: true\n");
  return OCIO::Config::CreateFromStream(yaml);
}

TEST(WorkingSpace, ShippedConfigIsRec709ThroughItsInterchangeRole) {
  const auto w = find_working_space(display::load_config(kShipped));
  EXPECT_EQ(w.basis, "aces_interchange");
  EXPECT_TRUE(w.is_rec709());
}

// Blender's ACES role gives its scene_linear as Rec.709 within 2.4e-4 (another adaptation): taken
// as Rec.709 exactly, so nothing is converted, as in Blender itself.
TEST(WorkingSpace, BlenderConfigIsRec709) {
  if (!std::filesystem::exists(kBlender)) GTEST_SKIP() << "Blender's config is not installed";
  const auto w = find_working_space(display::load_config(kBlender));
  EXPECT_TRUE(w.is_rec709());
  EXPECT_EQ(max_abs_difference(w.scene_linear_to_rec709, Mat3::identity()), 0.0);
}

// The conversion is read from OCIO's matrices in double: measuring through the float32 CPU
// processor is off by ~1e-7 per element (checked below, so this test shows why it matters).
TEST(WorkingSpace, AcescgStudioIsMeasuredInDouble) {
  const auto config = acescg_studio();
  const auto w = find_working_space(config);
  EXPECT_EQ(w.basis, "aces_interchange");
  EXPECT_LT(max_abs_difference(w.scene_linear_to_rec709, to_rec709(aces_ap1())), 1e-9);
  const auto cpu = config->getProcessor("ACEScg", "ACES2065-1")->getDefaultCPUProcessor();
  Mat3 measured;
  for (int c = 0; c < 3; ++c) {
    float v[3] = {0, 0, 0};
    v[c] = 1;
    cpu->applyRGB(v);
    for (int r = 0; r < 3; ++r) measured.m[r][c] = v[r];
  }
  EXPECT_GT(max_abs_difference(aces2065_to_rec709() * measured, to_rec709(aces_ap1())), 1e-9);
}

TEST(WorkingSpace, CurvesAreNotMatrices) {
  const auto config = acescg_studio();
  EXPECT_FALSE(conversion_matrix(config, "Log", "ACEScg"));
  EXPECT_FALSE(conversion_matrix(config, "Raw", "no such space"));
  const auto m = conversion_matrix(config, "ACEScg", "ACES2065-1");
  ASSERT_TRUE(m);
  EXPECT_LT(max_abs_difference(*m, to_rec709(aces_ap0()).inverse() * to_rec709(aces_ap1())), 1e-9);
}

}  // namespace
}  // namespace cgtmo::color
