// The committed exports (luts/*.cube, luts/*.clf) read back by OCIO stay within the error the
// manifest states for them, and the committed config's views within theirs.
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <fstream>

#include "cgtmo/bake/bake.h"
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
