// `cgtmo apply --op cgtmo|wls` through its library call, on the committed cornell render: output
// written, fallbacks warned when the companions are missing, nothing written on bad requests.
#include <gtest/gtest.h>

#include <OpenImageIO/imageio.h>

#include <unistd.h>

#include <filesystem>

#include "cgtmo/cgtmo/apply_scene.h"
#include "cgtmo/errors.h"

namespace fs = std::filesystem;
using namespace cgtmo::local;

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
