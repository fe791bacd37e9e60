// Scene statistics (src/cgtmo/local/stats.cpp) against values worked out by hand.
#include <gtest/gtest.h>

#include <cmath>

#include "cgtmo/local/stats.h"
#include "scene_builder.h"

using namespace cgtmo::local;
namespace scene = cgtmo::scene;
using cgtmo::local::test::plane_scene;

namespace {

std::vector<float> lum_of(const scene::Frame& s) {
  std::vector<float> l(s.pixel_count());
  for (std::size_t i = 0; i < l.size(); ++i) l[i] = s.beauty[3 * i];  // grey scenes: R = G = B = Y
  return l;
}

bool has_warning(const SceneStats& st, const std::string& part) {
  for (const auto& w : st.warnings)
    if (w.find(part) != std::string::npos) return true;
  return false;
}

// 8x4 frame lit by two groups: "lamp" everywhere at 0.5, "hidden" only in column 0 at 0.1
// (so it never wins M) plus the sidecar's emitted luminances.
scene::Frame two_group_scene() {
  scene::Frame s = plane_scene(8, 4, [](int x, int) { return x == 3 ? 2.0f : 0.6f; });
  scene::LightGroupPlane lamp = test::light_group("lamp", std::vector<float>(32, 0.5f));
  scene::LightGroupPlane hidden = test::light_group("hidden", std::vector<float>(32, 0.0f));
  for (int y = 0; y < 4; ++y) hidden.luminance[y * 8] = 0.1f;
  s.light_groups = {lamp, hidden};
  s.has_sidecar = true;
  s.lights = {{"lamp", "AREA", "lamp", 40.0}, {"hidden", "POINT", "hidden", 900.0}};
  return s;
}

}  // namespace

TEST(SceneStats, LwMaxIsTheBrightestLightInM) {
  const scene::Frame s = two_group_scene();
  const SceneStats st = compute_scene_stats(s, lum_of(s), Adaptation::LogAverage);
  EXPECT_TRUE(st.light_analysis);
  EXPECT_DOUBLE_EQ(st.lw_max, 40.0);  // 'hidden' (900) never contributes most
  EXPECT_DOUBLE_EQ(st.image_max, 2.0);
  ASSERT_EQ(st.groups.size(), 2u);
  EXPECT_EQ(st.groups[0].pixels_in_m, 32u);
  EXPECT_EQ(st.groups[1].pixels_in_m, 0u);
}

TEST(SceneStats, AGroupThatWinsOnePixelCounts) {
  scene::Frame s = two_group_scene();
  s.light_groups[1].luminance[5] = 0.7f;  // beats the lamp's 0.5 at one pixel
  const SceneStats st = compute_scene_stats(s, lum_of(s), Adaptation::LogAverage);
  EXPECT_DOUBLE_EQ(st.lw_max, 900.0);
  EXPECT_EQ(st.groups[1].pixels_in_m, 1u);
}

TEST(SceneStats, MissingSidecarLuminanceIsMeasuredFromThePass) {
  scene::Frame s = two_group_scene();
  s.lights[0].luminance = std::nan("");
  s.light_groups[0].luminance[7] = 3.5f;
  const SceneStats st = compute_scene_stats(s, lum_of(s), Adaptation::LogAverage);
  EXPECT_DOUBLE_EQ(st.lw_max, 3.5);
  EXPECT_TRUE(has_warning(st, "'lamp'"));
}

TEST(SceneStats, OneLightSkipsTheAnalysis) {
  scene::Frame s = two_group_scene();
  s.lights = {{"sun", "SUN", "sun", 12345.0}, {"world", "WORLD", "world", 0.0}};  // black world
  const SceneStats st = compute_scene_stats(s, lum_of(s), Adaptation::LogAverage);
  EXPECT_FALSE(st.light_analysis);
  EXPECT_DOUBLE_EQ(st.lw_max, 12345.0);
  EXPECT_NE(st.light_analysis_note.find("one"), std::string::npos);
}

TEST(SceneStats, NoLightsFallsBackToTheImageWithAWarning) {
  scene::Frame s = plane_scene(6, 3, [](int x, int y) { return 0.1f * float(x + y); });
  const SceneStats st = compute_scene_stats(s, lum_of(s), Adaptation::LogAverage);
  EXPECT_NEAR(st.lw_max, 0.7, 1e-6);
  EXPECT_TRUE(has_warning(st, "no sidecar"));
  EXPECT_TRUE(has_warning(st, "image maximum"));
  EXPECT_TRUE(has_warning(st, "no adaptation probe"));
}

TEST(SceneStats, ProbeMeansBySolidAngle) {
  // 4 rows: latitudes 67.5, 22.5, -22.5, -67.5 degrees; weights cos(lat).
  scene::Frame s = plane_scene(4, 4, [](int, int) { return 1.0f; });
  const float rows[4] = {8.f, 1.f, 1.f, 2.f};
  s.probe = test::probe(8, 4, [&](int y) { return rows[y]; });
  const double wp = std::cos(67.5 * M_PI / 180), we = std::cos(22.5 * M_PI / 180);
  const double W = 2 * wp + 2 * we;
  const double harm = W / (wp / 8 + we / 1 + we / 1 + wp / 2);
  const double loga = std::exp((wp * std::log(8.0) + wp * std::log(2.0)) / W);
  const SceneStats h = compute_scene_stats(s, lum_of(s), Adaptation::Harmonic);
  const SceneStats g = compute_scene_stats(s, lum_of(s), Adaptation::LogAverage);
  EXPECT_NEAR(h.lw_a, harm, 1e-6);
  EXPECT_NEAR(g.lw_a, loga, 1e-6);
  EXPECT_NEAR(h.probe_log_average, loga, 1e-6);
  EXPECT_NE(h.lw_a_source.find("probe"), std::string::npos);
}

TEST(SceneStats, BlackDirectionsOfTheProbeAreLeftOut) {
  // Rows 0-1 black (a black world); rows 2 and 3 at 2 and 8 sit at -22.5 and -67.5 degrees.
  scene::Frame s = plane_scene(4, 4, [](int, int) { return 1.0f; });
  const float rows[4] = {0.f, 0.f, 2.f, 8.f};
  s.probe = test::probe(8, 4, [&](int y) { return rows[y]; });
  const double w2 = std::cos(22.5 * M_PI / 180), w3 = std::cos(67.5 * M_PI / 180);
  const SceneStats g = compute_scene_stats(s, lum_of(s), Adaptation::LogAverage);
  EXPECT_NEAR(g.lw_a, std::exp((w2 * std::log(2.0) + w3 * std::log(8.0)) / (w2 + w3)), 1e-6);
  EXPECT_NEAR(g.probe_dark_fraction, 0.5, 1e-6);
  const SceneStats h = compute_scene_stats(s, lum_of(s), Adaptation::Harmonic);
  EXPECT_NEAR(h.lw_a, (w2 + w3) / (w2 / 2 + w3 / 8), 1e-6);
}

TEST(SceneStats, BlackProbeFallsBackToTheImage) {
  scene::Frame s = plane_scene(4, 2, [](int x, int) { return x < 2 ? 1.0f : 4.0f; });
  s.probe = test::probe(8, 4, [](int) { return 0.0f; });
  const SceneStats st = compute_scene_stats(s, lum_of(s), Adaptation::Harmonic);
  EXPECT_NEAR(st.lw_a, 2.0 / (1.0 + 0.25), 1e-6);  // the image's harmonic mean of {1, 4}
  EXPECT_TRUE(has_warning(st, "all black"));
  const SceneStats lg = compute_scene_stats(s, lum_of(s), Adaptation::LogAverage);
  EXPECT_NEAR(lg.lw_a, 2.0, 1e-6);
}

TEST(SceneStats, ZeroLuminanceIsFlooredInBothMeans) {
  const float l[4] = {0.f, 0.f, 1.f, 1.f};
  EXPECT_NEAR(harmonic_mean(l, nullptr, 4), 4.0 / (2 / kMeanFloor + 2), 1e-12);
  EXPECT_NEAR(log_average(l, nullptr, 4), std::sqrt(kMeanFloor), 1e-12);
}

TEST(SceneStats, LwMaxBelowLwAIsWarned) {
  scene::Frame s = plane_scene(4, 2, [](int, int) { return 1.0f; });
  s.has_sidecar = true;
  s.lights = {{"dim", "POINT", "dim", 0.5}};
  s.probe = test::probe(8, 4, [](int) { return 10.0f; });
  const SceneStats st = compute_scene_stats(s, lum_of(s), Adaptation::LogAverage);
  EXPECT_DOUBLE_EQ(st.lw_max, 0.5);
  EXPECT_NEAR(st.lw_a, 10.0, 1e-6);
  EXPECT_TRUE(has_warning(st, "below Lw_a"));
}

// ---- View-weighted adaptation -------------------------------------------------------------

namespace {

// A level camera looking along +X (Blender: right = -Y when looking along +X with Z up), frame
// 60 x 40 degrees; the probe's centre column looks along +X too.
scene::CameraView camera_along_x() {
  scene::CameraView c;
  c.known = true;
  const double f[3] = {1, 0, 0}, r[3] = {0, -1, 0}, u[3] = {0, 0, 1};
  std::copy(f, f + 3, c.forward), std::copy(r, r + 3, c.right), std::copy(u, u + 3, c.up);
  c.fov_x = 60.0 * M_PI / 180.0;
  c.fov_y = 40.0 * M_PI / 180.0;
  return c;
}

double deg(double d) { return d * M_PI / 180.0; }

}  // namespace

TEST(ViewWeights, InsideTheFrameOnlySolidAngleOutsideAGaussianOfTheAngleBeyondTheEdge) {
  // 360x180: pixel centres every degree, at half degrees. Column x looks at azimuth
  // 180 - (x + 0.5) degrees (left of the heading is positive), row y at latitude 90 - (y + 0.5).
  const scene::CameraView cam = camera_along_x();
  const std::vector<float> w = view_weights(360, 180, cam, 20.0);
  ASSERT_EQ(w.size(), 360u * 180u);
  auto at = [&](int x, int y) { return double(w[std::size_t(y) * 360 + x]); };
  const int row = 89;  // latitude +0.5 degrees, inside the frame's vertical extent
  const double solid = std::cos(deg(0.5));
  EXPECT_NEAR(at(179, row), solid, 1e-6);       // azimuth +0.5: the frame's centre
  EXPECT_NEAR(at(151, row), solid, 1e-6);       // azimuth +28.5: inside the 30-degree half width
  // Azimuth +50.5 (x = 129) and -50.5 (x = 230): 20.5 degrees beyond the edge, one sigma and a bit.
  const double g = solid * std::exp(-0.5 * (20.5 / 20.0) * (20.5 / 20.0));
  EXPECT_NEAR(at(129, row), g, 1e-5);
  EXPECT_NEAR(at(230, row), g, 1e-5);
  EXPECT_LT(at(0, row), 1e-10);                // straight behind the camera
  // Straight up: 70 degrees above the frame's top edge (20 degrees up).
  EXPECT_NEAR(at(179, 0) / std::cos(deg(89.5)), std::exp(-0.5 * (69.5 / 20.0) * (69.5 / 20.0)), 1e-4);
  EXPECT_TRUE(view_weights(360, 180, scene::CameraView{}, 20.0).empty());  // unknown camera
}

TEST(ViewWeights, TheProbeHeadingTurnsTheLobe) {
  // The probe's centre looks along +Y (heading 90 degrees) while the camera looks along +X: the
  // frame sits 90 degrees to the right of the probe's centre, at azimuth -90 (x = 269).
  scene::CameraView cam = camera_along_x();
  cam.probe_heading = M_PI / 2;
  const std::vector<float> w = view_weights(360, 180, cam, 20.0);
  EXPECT_NEAR(w[89 * 360 + 269], std::cos(deg(0.5)), 1e-6);
  // The probe's centre column (azimuth 90.5 degrees in the world) is 60.5 degrees beyond the
  // frame's 30-degree half width: three sigmas.
  EXPECT_NEAR(w[89 * 360 + 179], std::cos(deg(0.5)) * std::exp(-0.5 * (60.5 / 20) * (60.5 / 20)), 1e-4);
}

TEST(ViewWeights, BlendKeepsAShareOfTheLogDifferenceBeyondTheFactor) {
  EXPECT_DOUBLE_EQ(blend_towards_image(1.5, 1.0, 2.0, 0.5), 1.5);          // within the factor
  EXPECT_NEAR(blend_towards_image(16.0, 1.0, 2.0, 0.5), std::pow(2.0, 2.5), 1e-12);  // 2 * 8^0.5
  EXPECT_NEAR(blend_towards_image(1.0 / 16, 1.0, 2.0, 0.5), std::pow(2.0, -2.5), 1e-12);
  EXPECT_NEAR(blend_towards_image(16.0, 1.0, 2.0, 1.0), 2.0, 1e-12);       // clamp to the factor
  EXPECT_NEAR(blend_towards_image(16.0, 1.0, 2.0, 0.0), 16.0, 1e-12);      // no blend
  EXPECT_NEAR(blend_towards_image(0.3, 0.1, 2.0, 0.5), 0.2 * std::sqrt(1.5), 1e-12);
}

TEST(SceneStats, ViewRegionSeesTheBrightFrameTheSphereDoesNot) {
  // The probe is 10 within 30 degrees of the camera's heading (the frame's width, every row) and
  // 0.5 elsewhere; the image's log-average is 4.
  scene::Frame s = plane_scene(8, 4, [](int, int) { return 4.0f; });
  s.probe.width = 72;
  s.probe.height = 36;
  s.probe.luminance.assign(72 * 36, 0.5f);
  for (int y = 0; y < 36; ++y)
    for (int x = 30; x < 42; ++x) s.probe.luminance[y * 72 + x] = 10.0f;
  s.camera = camera_along_x();
  const std::vector<float> lum = lum_of(s);
  AdaptationOptions o;
  o.region = AdaptationRegion::Sphere;
  const SceneStats sphere = compute_scene_stats(s, lum, o);
  o.region = AdaptationRegion::Image;
  const SceneStats image = compute_scene_stats(s, lum, o);
  o.region = AdaptationRegion::View;
  o.factor = 1e6;  // no blend: the view's own value
  const SceneStats view = compute_scene_stats(s, lum, o);
  EXPECT_NEAR(image.lw_a, 4.0, 1e-5);
  EXPECT_LT(sphere.lw_a, 1.0);                          // a sixth of the sphere is bright
  EXPECT_GT(view.lw_a, 2.0);                            // the frame is the bright band, the lobe more
  EXPECT_LT(view.lw_a, 10.0);
  EXPECT_DOUBLE_EQ(view.lw_a, view.view_log_average);
  EXPECT_FALSE(view.view_blended);
  EXPECT_GT(view.view_in_frame_share, 0.2);
  EXPECT_LT(view.view_in_frame_share, 0.5);
  // The defaults (factor 1, blend 0.5): the geometric mean of the view's and the image's values.
  const SceneStats blended = compute_scene_stats(s, lum, AdaptationOptions{});
  EXPECT_TRUE(blended.view_blended);
  EXPECT_NEAR(blended.lw_a, std::sqrt(view.lw_a * 4.0), 1e-5);
  EXPECT_NE(blended.adaptation_note.find("agree within 2x"), std::string::npos) << blended.adaptation_note;
  // An image 10 times brighter than the view: --explain says they disagree.
  scene::Frame bright = s;
  for (float& v : bright.beauty) v = 40.0f;
  const SceneStats apart = compute_scene_stats(bright, lum_of(bright), AdaptationOptions{});
  EXPECT_NEAR(apart.lw_a, std::sqrt(view.lw_a * 40.0), 1e-4);
  EXPECT_NE(apart.adaptation_note.find("disagree"), std::string::npos) << apart.adaptation_note;
  // --exposure scales the whole scene (the probe and the image alike): Lw_a scales with it.
  scene::Frame exposed = s;
  for (float& v : exposed.probe.luminance) v *= 4;
  std::vector<float> lum4(lum);
  for (float& v : lum4) v *= 4;
  EXPECT_NEAR(compute_scene_stats(exposed, lum4, AdaptationOptions{}).lw_a, 4 * blended.lw_a, 4e-5);
  // Without a camera, the view region falls back to the whole sphere with a warning.
  s.camera = scene::CameraView{};
  const SceneStats blind = compute_scene_stats(s, lum, AdaptationOptions{});
  EXPECT_DOUBLE_EQ(blind.lw_a, sphere.lw_a);
  EXPECT_TRUE(has_warning(blind, "camera is unknown"));
}
