// Checks src/cgtmo/bake/lut.cpp: the shaper against hand values and OCIO, LUT sampling against
// the published formulas written out here (not the operators' code).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <fstream>

#include "cgtmo/bake/choose.h"
#include "cgtmo/bake/lut.h"
#include "cgtmo/bake/writers.h"
#include "cgtmo/operators/apply.h"
#include "cgtmo/operators/registry.h"

using namespace cgtmo;
using namespace cgtmo::bake;

TEST(Log2Shaper, HandValues) {
  const Log2Shaper s{-8, 16};
  EXPECT_DOUBLE_EQ(s.forward(0.0), 0.0);
  EXPECT_NEAR(s.forward(1.0 - std::ldexp(1.0, -8)), 8.0 / 24.0, 1e-12);       // log2(1) = 0
  EXPECT_NEAR(s.forward(65536.0 - std::ldexp(1.0, -8)), 1.0, 1e-12);
  EXPECT_NEAR(s.inverse(20.0 / 24.0), 4096.0 - 1.0 / 256.0, 1e-9);            // 2^12 - 2^-8
  EXPECT_DOUBLE_EQ(s.forward(-5.0), 0.0);                                       // negatives are black
}

TEST(Log2Shaper, OcioTransformMatchesFormula) {
  const Log2Shaper s{-12, 16};
  auto cpu = OCIO::Config::CreateRaw()->getProcessor(s.transform())->getDefaultCPUProcessor();
  for (double x : {0.0, 1e-5, 0.18, 1.0, 37.5, 65504.0}) {
    float rgb[3] = {float(x), float(x), float(x)};
    cpu->applyRGB(rgb);
    const double expect = (std::log2(x + std::exp2(-12.0)) + 12.0) / 28.0;
    EXPECT_NEAR(rgb[0], expect, 2e-5) << x;
  }
  auto inv = OCIO::Config::CreateRaw()->getProcessor(s.transform(OCIO::TRANSFORM_DIR_INVERSE))->getDefaultCPUProcessor();
  float rgb[3] = {0.5f, 0.5f, 0.5f};
  inv->applyRGB(rgb);
  EXPECT_NEAR(rgb[0], std::exp2(2.0) - std::exp2(-12.0), 4e-4);  // lo + 0.5 * 28 = 2 stops
}

TEST(SampleLut, OneDimensionalReinhardNodes) {
  const auto ev = operators::make_evaluator(operators::find_operator("reinhard"), {}, nullptr);
  Representation r;
  r.dims = 1;
  r.size = 9;
  r.shaper = {-8, 8};
  const BakedLut lut = sample_lut(*ev, r);
  ASSERT_EQ(lut.values.size(), 9u);
  for (int i = 0; i < 9; ++i) {
    const double x = std::exp2(-8 + 2.0 * i) - std::exp2(-8.0);  // node i: lo + i (hi - lo) / 8
    EXPECT_NEAR(lut.values[i], x / (1 + x), 1e-6) << i;
  }
}

TEST(SampleLut, ThreeDimensionalReinhardLuminanceIsUnclampedAndLogEncoded) {
  // Extended Reinhard on luminance with white 2: Lout = L (1 + L/4) / (1 + L), colour * Lout / L.
  const auto& def = operators::find_operator("reinhard-lum");
  BakeSubject s = make_subject(def, {{"white", "2"}}, reference_scene_stats());
  Representation r;
  r.dims = 3;
  r.size = 3;
  r.shaper = {-4, 4};
  r.out_log2 = -6;
  const BakedLut lut = sample_lut(*s.unclamped, r);
  ASSERT_EQ(lut.values.size(), 27u * 3);
  // Node (2, 0, 1): R = 2^4 - 2^-4, G = 0, B = 2^0 - 2^-4.
  const double R = 16 - 0.0625, G = 0, B = 1 - 0.0625;
  const double L = 0.2126 * R + 0.7152 * G + 0.0722 * B;
  const double k = (1 + L / 4) / (1 + L);
  const float* v = &lut.values[((2 * 3 + 0) * 3 + 1) * 3];
  EXPECT_NEAR(v[0], std::log2(R * k + 1.0 / 64), 1e-5);  // above 1: unclamped
  EXPECT_GT(R * k, 1.0);
  EXPECT_NEAR(v[1], std::log2(0 + 1.0 / 64), 1e-5);
  EXPECT_NEAR(v[2], std::log2(B * k + 1.0 / 64), 1e-5);
}

TEST(ViewTransform, OneDimensionalMatchesOperatorWithinLutError) {
  const auto ev = operators::make_evaluator(operators::find_operator("aces-hill"), {}, nullptr);
  Representation r;
  r.dims = 1;
  r.size = 4096;
  r.shaper = {-16, 16};
  const BakedLut lut = sample_lut(*ev, r);
  ASSERT_TRUE(lut.input_matrix && lut.output_matrix);  // matrices kept as matrices
  auto cpu = OCIO::Config::CreateRaw()->getProcessor(view_transform(lut))->getDefaultCPUProcessor();
  float px[6] = {0.18f, 0.5f, 2.0f, 40.f, 0.01f, 0.f};
  float ref[6];
  std::copy(px, px + 6, ref);
  OCIO::PackedImageDesc desc(px, 2, 1, 3);
  cpu->apply(desc);
  ev->apply(ref, 2, 3);
  for (int i = 0; i < 6; ++i) EXPECT_NEAR(px[i], ref[i], 2e-4) << i;
}

TEST(ScalesByLuminance, RecognisesLuminanceModeWithSaturationOneOnly) {
  const auto stats = reference_scene_stats();
  auto is_lum = [&](const char* op, std::map<std::string, std::string> p) {
    return scales_by_luminance(*make_subject(operators::find_operator(op), p, stats).unclamped);
  };
  EXPECT_TRUE(is_lum("reinhard-lum", {}));
  EXPECT_TRUE(is_lum("drago", {}));
  EXPECT_TRUE(is_lum("reinhard", {{"mode", "luminance"}}));
  EXPECT_FALSE(is_lum("drago", {{"saturation", "0.8"}}));
  EXPECT_FALSE(is_lum("drago", {{"mode", "max-rgb"}}));
  EXPECT_FALSE(is_lum("reinhard", {}));
  EXPECT_FALSE(is_lum("reinhard-jodie", {}));
  EXPECT_FALSE(is_lum("pbr-neutral", {}));
  EXPECT_FALSE(is_lum("aces-hill", {}));  // matrices
}

TEST(ViewTransform, LuminanceDesignKeepsChromaticityAndHandlesEdgeInputs) {
  // Extended Reinhard on luminance, white 2: Lout = L (1 + L/4) / (1 + L), RGB * Lout / L, clamped.
  BakeSubject s = make_subject(operators::find_operator("reinhard-lum"), {{"white", "2"}}, reference_scene_stats());
  Representation r;
  r.dims = 1;
  r.luminance = true;
  r.size = 4096;
  r.shaper = {-16, 16};
  const BakedLut lut = sample_lut(*s.exact, r);
  ASSERT_EQ(lut.values.size(), 4096u * 3);
  EXPECT_FLOAT_EQ(lut.values[3 * 1000], 1000.f / 4095.f);  // chromaticity channels: identity
  auto cpu = OCIO::Config::CreateRaw()->getProcessor(view_transform(lut))->getDefaultCPUProcessor();
  auto hand = [](double R, double G, double B, int c) {
    const double L = 0.2126 * R + 0.7152 * G + 0.0722 * B;
    const double k = L > 0 ? (1 + L / 4) / (1 + L) : 0;
    return std::min(1.0, (c == 0 ? R : c == 1 ? G : B) * k);
  };
  const float in[][3] = {{0.18f, 0.18f, 0.18f}, {0.9f, 0.05f, 0.3f}, {3.f, 0.f, 0.f}, {0.f, 0.02f, 0.f},
                         {1e-6f, 2e-6f, 0.f},  {0.f, 0.f, 0.f},   {65504.f, 0.f, 0.f}, {0.5f, 0.5f, 40.f}};
  for (const auto& p : in) {
    float o[3] = {p[0], p[1], p[2]};
    cpu->applyRGB(o);
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(o[c], hand(p[0], p[1], p[2], c), 2e-5 + 1e-4 * hand(p[0], p[1], p[2], c)) << p[0] << "," << p[1] << "," << p[2];
  }
  // Inputs cgtmo apply sanitises (negative and NaN -> 0, above 65504 -> 65504) are clamped alike.
  const float odd[][3] = {{-1.f, 0.5f, 0.5f}, {NAN, 0.5f, 0.5f}, {1e30f, 0.f, 0.f}};
  const float same[][3] = {{0.f, 0.5f, 0.5f}, {0.f, 0.5f, 0.5f}, {65504.f, 0.f, 0.f}};
  for (int i = 0; i < 3; ++i) {
    float o[3] = {odd[i][0], odd[i][1], odd[i][2]};
    cpu->applyRGB(o);
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(o[c], hand(same[i][0], same[i][1], same[i][2], c), 1e-4) << i << " " << c;
  }
}

// Khronos PBR Neutral as its specification writes it (double), for the hue design's test.
static void pbr_neutral_spec(const double in[3], double out[3]) {
  double c[3] = {std::max(in[0], 0.0), std::max(in[1], 0.0), std::max(in[2], 0.0)};
  const double x = std::min({c[0], c[1], c[2]});
  const double offset = x < 0.08 ? x - 6.25 * x * x : 0.04;
  for (double& v : c) v -= offset;
  const double peak = std::max({c[0], c[1], c[2]});
  const double start = 0.76, d = 0.24;
  if (peak < start) {
    for (int k = 0; k < 3; ++k) out[k] = c[k];
    return;
  }
  const double new_peak = 1 - d * d / (peak + d - start);
  const double g = 1 - 1 / (0.15 * (peak - new_peak) + 1);
  for (int k = 0; k < 3; ++k) out[k] = std::min(1.0, c[k] * new_peak / peak * (1 - g) + new_peak * g);
}

TEST(ViewTransform, HueStepsDesignFollowsThePbrNeutralSpecification) {
  BakeSubject s = make_subject(operators::find_operator("pbr-neutral"), {}, reference_scene_stats());
  ASSERT_TRUE(hue_steps_apply(*s.exact));
  EXPECT_FALSE(hue_steps_apply(*make_subject(operators::find_operator("reinhard-jodie"), {}, reference_scene_stats()).exact));
  Representation r;
  r.dims = 1;
  r.hue_steps = true;
  r.size = 4096;
  const BakedLut lut = sample_lut(*s.exact, r);
  ASSERT_EQ(lut.values.size(), 4096u * 4);
  auto cpu = OCIO::Config::CreateRaw()->getProcessor(view_transform(lut))->getDefaultCPUProcessor();
  const double in[][3] = {{0.18, 0.18, 0.18}, {0.05, 0.02, 0.3},  {0.9, 0.3, 0.01},  {0.0, 0.0, 0.95}, {3.0, 1.0, 0.2},
                          {0.07, 0.5, 0.9},   {200.0, 0.1, 0.0}, {65504, 65504, 0}, {0, 0, 0},        {1e-5, 2e-4, 0}};
  for (const auto& p : in) {
    float o[3] = {float(p[0]), float(p[1]), float(p[2])};
    cpu->applyRGB(o);
    double want[3];
    pbr_neutral_spec(p, want);
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(o[c], want[c], 1e-4 + 2e-4 * want[c]) << p[0] << "," << p[1] << "," << p[2] << " channel " << c;
  }
  // Inputs cgtmo apply sanitises (negative and NaN -> 0, above 65504 -> 65504) are clamped alike.
  float odd[3] = {-1.f, NAN, 0.5f};
  cpu->applyRGB(odd);
  const double same[3] = {0, 0, 0.5};
  double want[3];
  pbr_neutral_spec(same, want);
  for (int c = 0; c < 3; ++c) EXPECT_NEAR(odd[c], want[c], 1e-4) << c;
}

// Reinhard-Jodie as the seed guide writes it (double): per channel lerp(C / (1 + L), C / (1 + C),
// C / (1 + C)), L the Rec.709 luminance, clamped.
static double jodie_spec(const double in[3], int c) {
  const double L = 0.2126 * in[0] + 0.7152 * in[1] + 0.0722 * in[2];
  const double lum = in[c] / (1 + L), tv = in[c] / (1 + in[c]);
  return std::min(1.0, lum + (tv - lum) * tv);
}

// The node-warped 3D design of reinhard-jodie's shipped view at `size` nodes per axis.
static Representation warped_3d(int size) {
  Representation r;
  r.dims = 3;
  r.warped = true;
  r.size = size;
  r.shaper = {-8, 16};
  r.out_log2 = -8;
  return r;
}

TEST(NodeWarp, IncreasingFromZeroToOnePerChannel) {
  BakeSubject s = make_subject(operators::find_operator("reinhard-jodie"), {}, reference_scene_stats());
  const Representation r = warped_3d(17);
  const std::vector<float> w = node_warp(*s.unclamped, r);
  ASSERT_EQ(w.size(), std::size_t(r.warp_size) * 3);
  for (int c = 0; c < 3; ++c) {
    EXPECT_EQ(w[std::size_t(c)], 0.f);
    EXPECT_EQ(w[std::size_t(r.warp_size - 1) * 3 + c], 1.f);
    for (int i = 1; i < r.warp_size; ++i) ASSERT_GT(w[std::size_t(i) * 3 + c], w[std::size_t(i - 1) * 3 + c]) << c << " " << i;
  }
}

TEST(ViewTransform, WarpedDesignIsExactAtItsNodesAndReadsBackFromItsCtf) {
  BakeSubject s = make_subject(operators::find_operator("reinhard-jodie"), {}, reference_scene_stats());
  const Representation r = warped_3d(9);
  const BakedLut lut = sample_lut(*s.unclamped, r);
  ASSERT_EQ(lut.values.size(), 9u * 9 * 9 * 3);
  ASSERT_EQ(lut.warp.size(), std::size_t(r.warp_size) * 3);
  // Node j of channel c: the shaper input where the pre-curve table (linear between entries)
  // reaches j / 8, found here by bisection on the table.
  auto node_input = [&](int c, int j) {
    auto table = [&](double u) {
      const double x = u * (r.warp_size - 1);
      const int i = std::min(int(x), r.warp_size - 2);
      return lut.warp[std::size_t(i) * 3 + c] + (x - i) * (lut.warp[std::size_t(i + 1) * 3 + c] - lut.warp[std::size_t(i) * 3 + c]);
    };
    double a = 0, b = 1;
    for (int it = 0; it < 60; ++it) (table(0.5 * (a + b)) < j / 8.0 ? a : b) = 0.5 * (a + b);
    return r.shaper.inverse(0.5 * (a + b));
  };
  auto inline_cpu = OCIO::Config::CreateRaw()->getProcessor(view_transform(lut))->getDefaultCPUProcessor();
  const std::string path = ::testing::TempDir() + "cgtmo_warped_test.ctf";
  {
    std::ofstream f(path);
    f << lut_file_text(lut, "test");
  }
  auto file_cpu = OCIO::Config::CreateRaw()->getProcessor(view_transform(lut, path))->getDefaultCPUProcessor();
  const int nodes[][3] = {{0, 0, 0}, {3, 5, 1}, {8, 0, 2}, {1, 8, 7}, {4, 4, 4}, {2, 6, 0}, {7, 7, 8}};
  for (const auto& n : nodes) {
    const double in[3] = {node_input(0, n[0]), node_input(1, n[1]), node_input(2, n[2])};
    float a[3] = {float(in[0]), float(in[1]), float(in[2])}, b[3] = {a[0], a[1], a[2]};
    inline_cpu->applyRGB(a);
    file_cpu->applyRGB(b);
    for (int c = 0; c < 3; ++c) {
      const double want = jodie_spec(in, c);
      EXPECT_NEAR(a[c], want, 1e-4 * want + 1e-6) << n[0] << "," << n[1] << "," << n[2] << " channel " << c;
      EXPECT_NEAR(b[c], a[c], 1e-4 * a[c] + 1e-6) << "file vs inline, channel " << c;
    }
  }
  std::remove(path.c_str());
}

TEST(ViewTransform, WarpedReinhardJodieWithinOneCodeValueAt49) {
  // The measured property that makes it the shipped design: 49^3 behind log2 [-8, 16] stays
  // within 1 code value over the whole audit domain (uniform nodes: 1.4 at 57^3).
  BakeSubject s = make_subject(operators::find_operator("reinhard-jodie"), {}, reference_scene_stats());
  const Representation r = warped_3d(49);
  const AuditResult a = audit(encoded_processor(sample_lut(*s.unclamped, r)), *s.exact);
  EXPECT_LT(a.max_cv, 1.0);
}
