// local/filter_input: the filters' input is the reader's masks applied to the pipeline's signal,
// a hand-built scene gets the same masks by derivation, and the benchmark's wrapper
// (bench/scene_guide.h) hands the filters exactly what `cgtmo apply` filters.
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <filesystem>
#include <string>
#include <vector>

#include "cgtmo/io/scene_reader.h"
#include "cgtmo/local/filter_input.h"
#include "cgtmo/local/scene_load.h"
#include "cgtmo/local/scene_operators.h"
#include "scene_guide.h"

using namespace cgtmo;
using namespace cgtmo::local;

namespace {

const std::string kCornell =
    (std::filesystem::path(CGTMO_SOURCE_DIR) / "tests" / "scenes" / "cornell" / "cornell.exr").string();

// The scene as `cgtmo apply --op cgtmo` loads it: G-buffer, light groups, probe and sidecar.
scene::Frame load_as_apply(const std::string& path) {
  LoadRequest req;
  req.path = path;
  return load_scene(req).scene;
}

LocalOptions cgtmo_defaults() {
  const operators::OperatorDef& op = find_scene_operator("cgtmo");
  return options_from(op, operators::resolve_params(op, {}, nullptr));
}

// Bitwise equality of a plane the input points to (null on both sides counts as equal).
void expect_same_channel(const filters::Channel& a, const filters::Channel& b, std::size_t n, const char* what) {
  ASSERT_EQ(bool(a), bool(b)) << what;
  if (!a) return;
  for (std::size_t i = 0; i < n; ++i)
    ASSERT_EQ(std::memcmp(&a.data[i * a.stride], &b.data[i * b.stride], sizeof(float)), 0) << what << " at " << i;
}

void expect_same_input(const filters::GuidedInput& a, const filters::GuidedInput& b) {
  ASSERT_EQ(a.width, b.width);
  ASSERT_EQ(a.height, b.height);
  const std::size_t n = a.pixel_count();
  expect_same_channel(a.log_lum, b.log_lum, n, "log_lum");
  expect_same_channel(a.mask, b.mask, n, "mask");
  expect_same_channel(a.footprint, b.footprint, n, "footprint");
  for (int k = 0; k < 3; ++k) {
    expect_same_channel(a.position[k], b.position[k], n, "position");
    expect_same_channel(a.normal[k], b.normal[k], n, "normal");
    expect_same_channel(a.albedo[k], b.albedo[k], n, "albedo");
  }
}

}  // namespace

TEST(FilterInput, MaskIsTheReadersBackgroundAndNormalValidity) {
  io::SceneRequest req;
  req.required = scene::Pass::Beauty | scene::Pass::Depth | scene::Pass::Normal;
  req.probe = req.sidecar = io::Companion::Skip;
  const io::Scene read = io::read_scene(kCornell, req);
  const scene::Frame& f = read.frame;
  const std::size_t n = f.pixel_count();
  ASSERT_EQ(f.background.size(), n);
  ASSERT_EQ(f.normal_valid.size(), n);

  const scene::Frame s = load_as_apply(kCornell);
  ASSERT_EQ(s.background, f.background);  // kept, not recomputed
  ASSERT_EQ(s.normal_valid, f.normal_valid);
  const FilterInput fi = luminance_filter_input(s, cgtmo_defaults());
  ASSERT_TRUE(fi.input.mask);
  std::size_t background = 0, invalid = 0;
  for (std::size_t i = 0; i < n; ++i) {
    const bool geometry = !f.background[i] && f.normal_valid[i];
    ASSERT_EQ(fi.mask[i], geometry ? 1.f : 0.f) << "pixel " << i;
    background += f.background[i];
    invalid += !f.background[i] && !f.normal_valid[i];
  }
  EXPECT_EQ(fi.background, background);
  EXPECT_EQ(fi.invalid_normals, invalid);
  EXPECT_EQ(fi.invalid_normals, read.invalid_normals);
  EXPECT_EQ(fi.available, filters::kGuideAll);
  EXPECT_TRUE(fi.normal.empty()) << "the reader's unit normals are used in place";
}

TEST(FilterInput, HandBuiltSceneDerivesTheReadersMasks) {
  const scene::Frame loaded = load_as_apply(kCornell);
  const FilterInput expected = luminance_filter_input(loaded, cgtmo_defaults());

  // Without the masks: derived from depth and the normals by the reader's rules.
  scene::Frame bare = loaded;
  bare.background.clear();
  bare.normal_valid.clear();
  FilterInput derived = luminance_filter_input(bare, cgtmo_defaults());
  expect_same_input(derived.input, expected.input);
  EXPECT_EQ(derived.invalid_normals, expected.invalid_normals);

  // Unnormalised normals (Blender's silhouette lengths) are renormalised into a copy.
  scene::Frame shrunk = bare;
  for (float& v : shrunk.normal) v *= 0.25f;
  const FilterInput renormalised = luminance_filter_input(shrunk, cgtmo_defaults());
  ASSERT_FALSE(renormalised.normal.empty());
  expect_same_channel(renormalised.input.mask, expected.input.mask, loaded.pixel_count(), "mask");
  for (std::size_t i = 0; i < loaded.normal.size(); ++i)
    ASSERT_NEAR(renormalised.normal[i], loaded.normal[i], 1e-6f) << i;

  // A depth of -inf or NaN is background, as in the reader.
  scene::Frame odd = bare;
  odd.depth[0] = -INFINITY;
  odd.depth[1] = NAN;
  const FilterInput odd_input = luminance_filter_input(odd, cgtmo_defaults());
  EXPECT_EQ(odd_input.mask[0], 0.f);
  EXPECT_EQ(odd_input.mask[1], 0.f);
}

TEST(FilterInput, NoDepthNoMaskUnlessANormalHasNoDirection) {
  scene::Frame s;
  s.width = 3, s.height = 1;
  s.beauty.assign(9, 0.5f);
  s.normal = {0, 0, 1, 0, 0, 2, 0, 0, 0};
  std::vector<float> sig(3, -0.3f);
  FilterInput fi = build_filter_input(s, sig);
  ASSERT_TRUE(fi.input.mask);
  EXPECT_EQ(fi.mask, (std::vector<float>{1, 1, 0}));
  EXPECT_EQ(fi.invalid_normals, 1u);
  EXPECT_EQ(fi.normal[5], 1.f);  // renormalised copy
  s.normal = {0, 0, 1, 0, 1, 0, 1, 0, 0};
  fi = build_filter_input(s, sig);
  EXPECT_FALSE(fi.input.mask);
  EXPECT_TRUE(fi.normal.empty());
  EXPECT_EQ(fi.lines.front(), "background: no depth pass, every pixel is treated as geometry");
}

TEST(FilterInput, BenchWrapperFiltersWhatApplyFilters) {
  bench::GuideFrame frame;
  bench::load_guide_frame(kCornell, frame);
  const scene::Frame s = load_as_apply(kCornell);
  double lw_a = 0;
  const FilterInput fi = luminance_filter_input(s, cgtmo_defaults(), &lw_a);
  EXPECT_EQ(frame.lw_a, lw_a);
  expect_same_input(frame.input, fi.input);
  EXPECT_EQ(bench::available_groups(frame.input), fi.available);

  // The floor is tone_map_local's: the same Lw_a from the same scene.
  const LocalResult r = tone_map_local(s, cgtmo_defaults());
  EXPECT_EQ(r.explain.log_floor, log_floor_of(lw_a));
  EXPECT_EQ(r.explain.background_fraction, fi.background_fraction);
  EXPECT_EQ(r.explain.invalid_normals, fi.invalid_normals);
}
