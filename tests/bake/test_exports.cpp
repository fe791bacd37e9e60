// The committed exports (luts/*.cube, luts/*.clf) read back by OCIO stay within the error the
// manifest states for them, and the committed config's views within theirs.
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <fstream>

#include "cgtmo/bake/audit.h"
#include "cgtmo/bake/bake.h"
#include "cgtmo/color/chromaticities.h"
#include "cgtmo/operators/registry.h"

using namespace cgtmo;
using namespace cgtmo::bake;

namespace {
nlohmann::json manifest() {
  std::ifstream f(std::string(CGTMO_SOURCE_DIR) + "/luts/manifest.json");
  return nlohmann::json::parse(f);
}
}  // namespace

TEST(CommittedExports, EveryRegistryOperatorIsShipped) {
  const auto m = manifest();
  for (const auto& def : operators::operators_of(operators::Scope::Pixel)) EXPECT_TRUE(m["operators"].contains(def.name)) << def.name;
}

TEST(CommittedExports, CubeAndClfReadBackWithinStatedError) {
  const auto m = manifest();
  const std::string luts = std::string(CGTMO_SOURCE_DIR) + "/luts/";
  for (const auto& [name, op] : m["operators"].items()) {
    std::map<std::string, std::string> params;
    for (const auto& [k, v] : op["params"].items()) params[k] = v.is_string() ? v.get<std::string>() : std::to_string(v.get<double>());
    BakeSubject s = make_subject(operators::find_operator(name), params, reference_scene_stats());
    const bool cube_1d = op["cube_dims"].get<int>() == 1;
    const AuditResult cube = audit(export_processor(luts + op["cube"].get<std::string>(), true, cube_1d), *s.exact);
    EXPECT_LE(cube.max_cv, op["cube_max_error_cv"].get<double>() + 0.01) << name;
    const AuditResult clf = audit(export_processor(luts + op["clf"].get<std::string>(), false, false), *s.exact);
    EXPECT_LE(clf.max_cv, op["clf_max_error_cv"].get<double>() + 0.01) << name;
  }
}

TEST(CommittedConfig, ViewsWithinStatedError) {
  const auto m = manifest();
  auto config = OCIO::Config::CreateFromFile((std::string(CGTMO_SOURCE_DIR) + "/ocio_config/config.ocio").c_str());
  for (const auto& [name, op] : m["operators"].items()) {
    std::map<std::string, std::string> params;
    for (const auto& [k, v] : op["params"].items()) params[k] = v.is_string() ? v.get<std::string>() : std::to_string(v.get<double>());
    BakeSubject s = make_subject(operators::find_operator(name), params, reference_scene_stats());
    auto t = OCIO::DisplayViewTransform::Create();
    t->setSrc(OCIO::ROLE_SCENE_LINEAR);
    t->setDisplay("sRGB");
    t->setView(name.c_str());
    const AuditResult a = audit(config->getProcessor(t)->getDefaultCPUProcessor(), *s.exact);
    EXPECT_LE(a.max_cv, op["max_error_cv"].get<double>() + 0.01) << name;
  }
}

namespace {

// Colours of the ACEScg and Rec.2020 gamuts outside Rec.709, as linear Rec.709 (a negative
// component each): the hue circle at full and 70% saturation over 2^-6 .. 2^8.
std::vector<float> outside_rec709() {
  std::vector<float> out;
  for (const color::Mat3& m : {color::to_rec709(color::aces_ap1()), color::to_rec709(color::rec2020())})
    for (int e = -12; e <= 16; ++e)
      for (double sat : {1.0, 0.7})
        for (int h = 0; h < 96; ++h) {
          double rgb[3];
          for (int c = 0; c < 3; ++c) {  // HSV to RGB at value 1
            const double k = std::fmod(h / 16.0 + (c == 0 ? 0.0 : c == 1 ? 4.0 : 2.0), 6.0);
            rgb[c] = std::exp2(e / 2.0) * (1.0 - sat * std::clamp(std::min(k, 4.0 - k), 0.0, 1.0));
          }
          m.apply(rgb[0], rgb[1], rgb[2]);
          if (std::min({rgb[0], rgb[1], rgb[2]}) < 0) out.insert(out.end(), {float(rgb[0]), float(rgb[1]), float(rgb[2])});
        }
  return out;
}

// The largest error, in 10-bit code values, of `encoded` on `in` against cgtmo apply: the
// operator of the colour with its negative components clipped at 0 (scene/sanitize.h).
double worst_against_apply(const OCIO::ConstCPUProcessorRcPtr& encoded, const operators::Evaluator& exact, std::vector<float> in) {
  std::vector<float> want = in;
  for (float& v : want) v = std::max(v, 0.f);
  exact.apply(want.data(), want.size() / 3, 3);
  OCIO::PackedImageDesc desc(in.data(), long(in.size() / 3), 1, 3);
  encoded->apply(desc);
  double worst = 0;
  for (std::size_t i = 0; i < in.size(); ++i) worst = std::max(worst, std::abs(in[i] - srgb_encode(want[i])) * 1023.0);
  return worst;
}

}  // namespace

// What the views, the .clf and the .cube make of a colour outside Rec.709 is what cgtmo apply
// makes of it, within each one's stated error (+1 for inputs the audit does not draw). The
// operators whose input matrix came before any clamp (aces-hill, unreal, agx) spread the negative
// component into the other channels: hundreds of code values off.
TEST(CommittedExports, ColoursOutsideRec709AreClippedAsApplyClipsThem) {
  const auto m = manifest();
  const std::string luts = std::string(CGTMO_SOURCE_DIR) + "/luts/";
  auto config = OCIO::Config::CreateFromFile((std::string(CGTMO_SOURCE_DIR) + "/ocio_config/config.ocio").c_str());
  const std::vector<float> in = outside_rec709();
  ASSERT_GT(in.size(), 3u * 1000u);
  for (const auto& [name, op] : m["operators"].items()) {
    std::map<std::string, std::string> params;
    for (const auto& [k, v] : op["params"].items()) params[k] = v.is_string() ? v.get<std::string>() : std::to_string(v.get<double>());
    BakeSubject s = make_subject(operators::find_operator(name), params, reference_scene_stats());
    auto t = OCIO::DisplayViewTransform::Create();
    t->setSrc(OCIO::ROLE_SCENE_LINEAR);
    t->setDisplay("sRGB");
    t->setView(name.c_str());
    EXPECT_LE(worst_against_apply(config->getProcessor(t)->getDefaultCPUProcessor(), *s.exact, in), op["max_error_cv"].get<double>() + 1)
        << name << " view";
    EXPECT_LE(worst_against_apply(export_processor(luts + op["clf"].get<std::string>(), false, false), *s.exact, in),
              op["clf_max_error_cv"].get<double>() + 1)
        << name << " .clf";
    EXPECT_LE(worst_against_apply(export_processor(luts + op["cube"].get<std::string>(), true, op["cube_dims"].get<int>() == 1), *s.exact, in),
              op["cube_max_error_cv"].get<double>() + 1)
        << name << " .cube";
  }
}
