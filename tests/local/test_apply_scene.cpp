// `cgtmo apply --op cgtmo|wls` through its library call, on the committed cornell render: output
// written, fallbacks warned when the companions are missing, nothing written on bad requests.
#include <gtest/gtest.h>

#include <OpenImageIO/imagebuf.h>
#include <OpenImageIO/imagebufalgo.h>
#include <OpenImageIO/imageio.h>

#include <unistd.h>

#include <algorithm>
#include <filesystem>
#include <map>
#include <sstream>

#include "cgtmo/local/apply_scene.h"
#include "cgtmo/local/scene_load.h"
#include "cgtmo/local/scene_operators.h"
#include "cgtmo/errors.h"

namespace fs = std::filesystem;
using namespace cgtmo::local;
namespace scene = cgtmo::scene;

namespace {

const fs::path kScene = fs::path(CGTMO_SOURCE_DIR) / "tests" / "scenes" / "cornell" / "cornell.exr";

fs::path temp_dir(const std::string& name) {
  const fs::path d = fs::temp_directory_path() / ("cgtmo-test-apply-scene-" + name + "-" + std::to_string(::getpid()));
  fs::remove_all(d);
  fs::create_directories(d);
  return d;
}

}  // namespace

TEST(ApplyScene, WritesTheImageWithSceneStatistics) {
  if (!fs::exists(kScene)) GTEST_SKIP() << "no committed cornell scene";
  const fs::path d = temp_dir("ok");
  std::vector<std::string> warnings;
  SceneApplyOptions o;
  o.op = "cgtmo";
  o.warn = [&](const std::string& w) { warnings.push_back(w); };
  const SceneApplyReport r = apply_scene_file(o, kScene.string(), (d / "out.png").string());
  auto in = OIIO::ImageInput::open((d / "out.png").string());
  ASSERT_TRUE(in);
  EXPECT_EQ(in->spec().width, r.width);
  EXPECT_NE(r.explain.stats.lw_a_source.find("probe"), std::string::npos);
  EXPECT_NE(r.explain.stats.lw_max_source.find("sidecar"), std::string::npos);
  EXPECT_TRUE(warnings.empty()) << warnings.front();
  fs::remove_all(d);
}

TEST(ApplyScene, WithoutCompanionsFallsBackAndWarns) {
  if (!fs::exists(kScene)) GTEST_SKIP() << "no committed cornell scene";
  const fs::path d = temp_dir("alone");
  fs::copy_file(kScene, d / "alone.exr");
  std::vector<std::string> warnings;
  SceneApplyOptions o;
  o.op = "wls";
  o.warn = [&](const std::string& w) { warnings.push_back(w); };
  const SceneApplyReport r = apply_scene_file(o, (d / "alone.exr").string(), (d / "out.png").string());
  EXPECT_TRUE(fs::exists(d / "out.png"));
  std::string all;
  for (const auto& w : warnings) all += w + "\n";
  EXPECT_NE(all.find("no adaptation probe"), std::string::npos) << all;
  EXPECT_NE(r.explain.stats.lw_a_source.find("image"), std::string::npos);
  // Light groups are in the EXR: M is still built, with luminances measured from the passes.
  EXPECT_NE(all.find("maximum of its pass"), std::string::npos) << all;
  fs::remove_all(d);
}

// A render with the beauty alone (no Position, Normal or DiffCol pass): the operator still runs,
// with a spatial blur as its base layer, and says so.
TEST(ApplyScene, WithoutTheGBufferWarnsThatTheBaseIsUnguided) {
  if (!fs::exists(kScene)) GTEST_SKIP() << "no committed cornell scene";
  const fs::path d = temp_dir("no-gbuffer");
  const OIIO::ImageBuf full(kScene.string());
  std::vector<int> order;
  for (const char* name : {"ViewLayer.Combined.R", "ViewLayer.Combined.G", "ViewLayer.Combined.B", "ViewLayer.Combined.A"})
    order.push_back(full.spec().channelindex(name));
  ASSERT_GE(*std::min_element(order.begin(), order.end()), 0);
  const OIIO::ImageBuf beauty = OIIO::ImageBufAlgo::channels(full, 4, order);
  ASSERT_TRUE(beauty.write((d / "beauty.exr").string()));
  std::vector<std::string> warnings;
  SceneApplyOptions o;
  o.op = "cgtmo";
  o.warn = [&](const std::string& w) { warnings.push_back(w); };
  const SceneApplyReport r = apply_scene_file(o, (d / "beauty.exr").string(), (d / "out.png").string());
  EXPECT_TRUE(fs::exists(d / "out.png"));
  EXPECT_EQ(r.explain.guide_used, 0u);
  std::string all;
  for (const auto& w : warnings) all += w + "\n";
  EXPECT_NE(all.find("not guided by the G-buffer"), std::string::npos) << all;
  fs::remove_all(d);
}

// The alpha rule holds for the scene operators too: the beauty alone with its alpha set to 0.
TEST(ApplyScene, AnAlphaCoveringNothingIsDroppedWithAWarning) {
  if (!fs::exists(kScene)) GTEST_SKIP() << "no committed cornell scene";
  const fs::path d = temp_dir("empty-alpha");
  const OIIO::ImageBuf full(kScene.string());
  std::vector<int> order;
  for (const char* name : {"ViewLayer.Combined.R", "ViewLayer.Combined.G", "ViewLayer.Combined.B"})
    order.push_back(full.spec().channelindex(name));
  order.push_back(-1);  // alpha: the value below
  const float values[4] = {0, 0, 0, 0};
  const std::string names[4] = {"R", "G", "B", "A"};
  const OIIO::ImageBuf beauty = OIIO::ImageBufAlgo::channels(full, 4, order, values, names);
  ASSERT_TRUE(beauty.write((d / "beauty.exr").string()));
  std::vector<std::string> warnings;
  SceneApplyOptions o;
  o.op = "cgtmo";
  o.warn = [&](const std::string& w) { warnings.push_back(w); };
  const SceneApplyReport r = apply_scene_file(o, (d / "beauty.exr").string(), (d / "out.png").string());
  EXPECT_EQ(r.channels, 3);
  EXPECT_EQ(OIIO::ImageInput::open((d / "out.png").string())->spec().nchannels, 3);
  std::string all;
  for (const auto& w : warnings) all += w + "\n";
  EXPECT_NE(all.find("alpha is 0 at every pixel while the colour is not: alpha dropped"), std::string::npos) << all;
  fs::remove_all(d);
}

TEST(ApplyScene, BadRequestsWriteNothing) {
  if (!fs::exists(kScene)) GTEST_SKIP() << "no committed cornell scene";
  const fs::path d = temp_dir("bad");
  SceneApplyOptions o;
  o.op = "cgtmo";
  o.params = {{"filter", "nope"}};
  EXPECT_THROW(apply_scene_file(o, kScene.string(), (d / "a.png").string()), cgtmo::UsageError);
  o.params = {{"sigma_s", "-1"}};
  EXPECT_THROW(apply_scene_file(o, kScene.string(), (d / "b.png").string()), cgtmo::UsageError);
  o.params = {};
  o.op = "drago";  // a per-pixel operator is not a scene operator
  EXPECT_THROW(apply_scene_file(o, kScene.string(), (d / "c.png").string()), cgtmo::UsageError);
  o.op = "cgtmo";
  EXPECT_THROW(apply_scene_file(o, (d / "missing.exr").string(), (d / "d.png").string()), cgtmo::DataError);
  EXPECT_TRUE(fs::is_empty(d));
  fs::remove_all(d);
}

// The loader completes the reader's frame in place (no copy into another model) and frees each
// light group's RGB after its luminance: the beauty and its alpha must still be the file's.
TEST(ApplyScene, LoadedBeautyAndAlphaAreTheFiles) {
  if (!fs::exists(kScene)) GTEST_SKIP() << "no committed cornell scene";
  LoadRequest req;
  req.path = kScene.string();
  const LoadResult loaded = load_scene(req);
  const scene::Frame& s = loaded.scene;
  auto in = OIIO::ImageInput::open(kScene.string());
  ASSERT_TRUE(in);
  const OIIO::ImageSpec spec = in->spec();
  const int r = spec.channelindex("ViewLayer.Combined.R"), a = spec.channelindex("ViewLayer.Combined.A");
  ASSERT_GE(r, 0);
  ASSERT_GE(a, 0);
  std::vector<float> px(std::size_t(spec.width) * spec.height * spec.nchannels);
  ASSERT_TRUE(in->read_image(0, 0, 0, spec.nchannels, OIIO::TypeDesc::FLOAT, px.data()));
  ASSERT_EQ(s.channels, 4);
  ASSERT_EQ(s.beauty.size(), s.pixel_count() * 4);
  for (std::size_t i = 0; i < s.pixel_count(); i += 7) {
    for (int c = 0; c < 3; ++c) ASSERT_EQ(s.beauty[4 * i + c], px[i * spec.nchannels + r + c]) << "pixel " << i;
    ASSERT_EQ(s.beauty[4 * i + 3], px[i * spec.nchannels + a]) << "pixel " << i;
  }
  EXPECT_FALSE(s.light_groups.empty());
  for (const auto& g : s.light_groups) EXPECT_EQ(g.luminance.size(), s.pixel_count()) << g.name;
}

// apply_scene_file releases the light groups once the statistics exist and the G-buffer after the
// filter (peak memory): the image it writes is the library's on the same scene, released nothing.
TEST(ApplyScene, ReleasingPlanesEarlyChangesNothing) {
  if (!fs::exists(kScene)) GTEST_SKIP() << "no committed cornell scene";
  const fs::path d = temp_dir("release");
  SceneApplyOptions o;
  o.op = "cgtmo";
  o.encode_display = false;
  apply_scene_file(o, kScene.string(), (d / "out.exr").string());
  LoadRequest req;
  req.path = kScene.string();
  const LoadResult loaded = load_scene(req);
  bool called = false;
  const cgtmo::operators::OperatorDef& op = find_scene_operator("cgtmo");
  const LocalOptions lo = options_from(op, cgtmo::operators::resolve_params(op, {}, nullptr));
  const LocalResult lib = tone_map_local(loaded.scene, lo, [&] { called = true; });
  EXPECT_TRUE(called);
  auto in = OIIO::ImageInput::open((d / "out.exr").string());
  ASSERT_TRUE(in);
  const OIIO::ImageSpec spec = in->spec();
  ASSERT_EQ(spec.width, loaded.scene.width);
  std::vector<float> px(std::size_t(spec.width) * spec.height * spec.nchannels);
  ASSERT_TRUE(in->read_image(0, 0, 0, spec.nchannels, OIIO::TypeDesc::FLOAT, px.data()));
  for (std::size_t i = 0; i < loaded.scene.pixel_count(); ++i)
    for (int c = 0; c < 3; ++c)
      ASSERT_NEAR(px[i * spec.nchannels + c], lib.rgb[3 * i + c], 1e-3f * (1.0f + lib.rgb[3 * i + c])) << "pixel " << i;
  fs::remove_all(d);
}

// The rule documented in docs/cgtmo.md ("Exposure"): --exposure makes the scene k = 2^EV times
// brighter, the lights and the probe included, so Lw_max and Lw_a scale with it (and --explain
// says so). cgtmo at +2 EV equals cgtmo on the beauty scaled by 4 with both statistics given at 4
// times the unexposed ones.
TEST(ApplyScene, ExposureScalesTheSceneStatistics) {
  if (!fs::exists(kScene)) GTEST_SKIP() << "no committed cornell scene";
  const fs::path d = temp_dir("exposure");
  SceneApplyOptions o;
  o.op = "cgtmo";
  o.encode_display = false;
  const SceneApplyReport at0 = apply_scene_file(o, kScene.string(), (d / "ev0.exr").string());
  o.exposure_ev = 2.0;
  const SceneApplyReport at2 = apply_scene_file(o, kScene.string(), (d / "ev2.exr").string());
  EXPECT_NEAR(at2.explain.stats.lw_max, 4 * at0.explain.stats.lw_max, 1e-6 * at2.explain.stats.lw_max);
  EXPECT_NEAR(at2.explain.stats.lw_a, 4 * at0.explain.stats.lw_a, 1e-6 * at2.explain.stats.lw_a);
  std::string explained;
  for (const auto& l : describe(at2.explain)) explained += l + "\n";
  EXPECT_NE(explained.find("exposure: x4 (2 EV)"), std::string::npos) << explained;
  std::ostringstream lw_a;
  lw_a.precision(5);
  lw_a << "Lw_a = " << at2.explain.stats.lw_a;
  EXPECT_NE(explained.find(lw_a.str()), std::string::npos) << explained;

  LoadRequest req;
  req.path = kScene.string();
  scene::Frame scaled = load_scene(req).scene;
  for (std::size_t i = 0; i < scaled.beauty.size(); ++i)
    if (i % std::size_t(scaled.channels) < 3) scaled.beauty[i] *= 4.f;  // colour, not alpha
  const cgtmo::operators::OperatorDef* op = &find_scene_operator("cgtmo");
  auto exact = [](double v) {
    std::ostringstream t;
    t.precision(17);
    t << v;
    return t.str();
  };
  const std::map<std::string, std::string> given = {{"lw_max", exact(4 * at0.explain.stats.lw_max)},
                                                    {"lw_a", exact(4 * at0.explain.stats.lw_a)}};
  const LocalResult lib = tone_map_local(scaled, options_from(*op, cgtmo::operators::resolve_params(*op, given, nullptr)));
  auto in = OIIO::ImageInput::open((d / "ev2.exr").string());
  ASSERT_TRUE(in);
  const OIIO::ImageSpec spec = in->spec();
  std::vector<float> px(std::size_t(spec.width) * spec.height * spec.nchannels);
  ASSERT_TRUE(in->read_image(0, 0, 0, spec.nchannels, OIIO::TypeDesc::FLOAT, px.data()));
  for (std::size_t i = 0; i < scaled.pixel_count(); ++i)
    for (int c = 0; c < 3; ++c)
      ASSERT_NEAR(px[i * spec.nchannels + c], lib.rgb[3 * i + c], 1e-3f * (1.0f + lib.rgb[3 * i + c])) << "pixel " << i;
  fs::remove_all(d);
}

// The probe and the sidecar are inputs: an output naming either, however spelled (symlink, hard
// link, `./`), is refused before anything is read or written. So is the probe a sidecar names.
TEST(ApplyScene, AnOutputOverTheProbeOrSidecarIsRefused) {
  if (!fs::exists(kScene)) GTEST_SKIP() << "no committed cornell scene";
  const fs::path d = temp_dir("companions");
  const fs::path dir = kScene.parent_path();
  fs::copy_file(kScene, d / "s.exr");
  fs::copy_file(dir / "cornell.probe.exr", d / "s.probe.exr");
  fs::copy_file(dir / "cornell.json", d / "s.json");
  auto bytes = [](const fs::path& p) { return fs::file_size(p); };
  const auto probe_size = bytes(d / "s.probe.exr"), sidecar_size = bytes(d / "s.json");
  SceneApplyOptions o;
  o.op = "cgtmo";
  o.encode_display = false;
  const std::string in = (d / "s.exr").string();
  EXPECT_THROW(apply_scene_file(o, in, (d / "." / "s.probe.exr").string()), cgtmo::UsageError);
  fs::create_symlink(d / "s.json", d / "sidecar_link.exr");
  EXPECT_THROW(apply_scene_file(o, in, (d / "sidecar_link.exr").string()), cgtmo::UsageError);
  fs::create_hard_link(d / "s.probe.exr", d / "probe_link.exr");
  EXPECT_THROW(apply_scene_file(o, in, (d / "probe_link.exr").string()), cgtmo::UsageError);
  // The committed sidecar names cornell.probe.exr: beside s.exr, that is the probe it reads.
  fs::copy_file(dir / "cornell.probe.exr", d / "cornell.probe.exr");
  fs::remove(d / "s.probe.exr");
  EXPECT_THROW(apply_scene_file(o, in, (d / "cornell.probe.exr").string()), cgtmo::UsageError);
  EXPECT_EQ(bytes(d / "cornell.probe.exr"), probe_size);
  EXPECT_EQ(bytes(d / "s.json"), sidecar_size);
  EXPECT_EQ(bytes(d / "probe_link.exr"), probe_size);
  fs::remove_all(d);
}

// Both scene operators take the output modes, read by one options_from into the same fields
// (tone_map_local applies them after either base layer).
TEST(SceneOperators, WlsAndCgtmoShareTheOutputModes) {
  const std::map<std::string, std::string> given = {{"output", "scene-linear"}, {"stops", "4"}, {"shadows", "2"}};
  for (const char* name : {"cgtmo", "wls"}) {
    const cgtmo::operators::OperatorDef& op = find_scene_operator(name);
    const LocalOptions lo = options_from(op, cgtmo::operators::resolve_params(op, given, nullptr));
    EXPECT_EQ(lo.output, LocalOptions::Output::SceneLinear) << name;
    EXPECT_EQ(lo.target_stops, 4) << name;
    EXPECT_EQ(lo.shadow_stops, 2) << name;
    const LocalOptions d = options_from(op, cgtmo::operators::resolve_params(op, {}, nullptr));
    EXPECT_EQ(d.output, LocalOptions::Output::Display) << name;
  }
  EXPECT_EQ(options_from(find_scene_operator("wls"), cgtmo::operators::resolve_params(find_scene_operator("wls"), given, nullptr)).filter,
            "wls");
}
