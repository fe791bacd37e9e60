// src/cgtmo/display/checked_config.cpp: every config cgtmo reads from outside is bounded in size
// and in what its YAML aliases expand to before OpenColorIO sees it, and still loads as
// OpenColorIO's CreateFromFile would (relative search paths from the file's folder).
#include <gtest/gtest.h>

#include <sys/stat.h>
#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <functional>
#include <fstream>
#include <string>

#include "cgtmo/display/checked_config.h"
#include "cgtmo/display/display.h"
#include "cgtmo/errors.h"

namespace cgtmo::display {
namespace {

namespace fs = std::filesystem;

const std::string kShippedConfig = std::string(CGTMO_SOURCE_DIR) + "/ocio_config/config.ocio";
const char* kBlenderConfig = "/usr/share/blender/datafiles/colormanagement/config.ocio";

fs::path fresh_dir(const std::string& name) {
  const fs::path d = fs::temp_directory_path() / ("cgtmo-test-checked-config-" + name + "-" + std::to_string(::getpid()));
  fs::remove_all(d);
  fs::create_directories(d);
  return d;
}

// A config whose colour space c<levels-1> is a GroupTransform of `width` aliases of c<levels-2>'s,
// and so on down to `width` matrices: width^levels transforms for OpenColorIO to build, in a few KB.
std::string nested_alias_config(int levels, int width) {
  std::string s = "ocio_profile_version: 2\nroles:\n  default: c0\n  scene_linear: c0\n"
                  "displays:\n  sRGB:\n    - !<View> {name: Raw, colorspace: c0}\ncolorspaces:\n";
  for (int level = 0; level < levels; ++level) {
    s += "  - !<ColorSpace>\n    name: c" + std::to_string(level) + "\n    to_scene_reference: &g" + std::to_string(level) +
         " !<GroupTransform> {children: [";
    for (int i = 0; i < width; ++i)
      s += std::string(i ? ", " : "") + (level == 0 ? "!<MatrixTransform> {}" : "*g" + std::to_string(level - 1));
    s += "]}\n";
  }
  return s;
}

std::string error_of(const std::function<void()>& f) {
  try {
    f();
  } catch (const DataError& e) {
    return e.what();
  }
  return "";
}

TEST(CheckedConfig, NestedAliasesAreRefusedBeforeOpenColorIOSeesThem) {
  const std::string text = nested_alias_config(10, 10);  // 1e10 matrices through 90 aliases
  EXPECT_LT(text.size(), 4000u);
  const YamlExpansion x = yaml_expansion(text);
  EXPECT_EQ(x.anchors, 10);
  EXPECT_EQ(x.aliases, 90);
  EXPECT_GT(x.expanded_bytes, 1e10);
  const fs::path dir = fresh_dir("laughs");
  { std::ofstream(dir / "laughs.ocio") << text; }
  const std::string path = (dir / "laughs.ocio").string();
  const std::string error = error_of([&] { load_config_checked(path); });
  EXPECT_NE(error.find("'" + path + "'"), std::string::npos) << error;
  EXPECT_NE(error.find("YAML aliases (10 anchors, 90 aliases) expand it to"), std::string::npos) << error;
  EXPECT_EQ(error.find('\n'), std::string::npos) << error;
  // $OCIO and --colorconfig load through the same check.
  ::setenv("OCIO", path.c_str(), 1);
  const std::string from_env = error_of([] { load_config(""); });
  ::unsetenv("OCIO");
  EXPECT_NE(from_env.find("expand it to"), std::string::npos) << from_env;
  EXPECT_NE(from_env.find("($OCIO)"), std::string::npos) << from_env;
  EXPECT_NE(error_of([&] { load_config(path); }).find("(--colorconfig)"), std::string::npos);
  fs::remove_all(dir);
}

TEST(CheckedConfig, AFewAliasesLoadAndAreCountedExactly) {
  // &x's node is "&x [1, 2]" (9 bytes); each "*x" (2 bytes) becomes it.
  const std::string small = "a: &x [1, 2]\nb: [*x, *x]\n";
  const YamlExpansion x = yaml_expansion(small);
  EXPECT_EQ(x.anchors, 1);
  EXPECT_EQ(x.aliases, 2);
  EXPECT_EQ(x.expanded_bytes, double(small.size() + 2 * 7));
  // A block node: from the anchor to the next line as little indented as its key.
  const std::string block = "a: &x\n  - 1\n  - 2\nb: *x\n";
  EXPECT_EQ(yaml_expansion(block).expanded_bytes, double(block.size() + (block.find("b:") - block.find('&')) - 2));
  // Not anchors or aliases: quoted text, comments, block scalars, '*' and '&' inside words.
  const std::string text = "description: |\n  *a &b text\nname: \"*a\"  # *a &b\npattern: 'x*y'\nfamily: R&D\n";
  EXPECT_EQ(yaml_expansion(text).anchors, 0);
  EXPECT_EQ(yaml_expansion(text).aliases, 0);
  // A config with two levels of aliases loads, and OpenColorIO sees the same transforms.
  const fs::path dir = fresh_dir("few");
  { std::ofstream(dir / "few.ocio") << nested_alias_config(2, 3); }
  const auto config = load_config_checked((dir / "few.ocio").string());
  EXPECT_TRUE(config->getColorSpace("c1"));
  fs::remove_all(dir);
}

TEST(CheckedConfig, AnAliasInsideItsOwnAnchorIsRefused) {
  EXPECT_EQ(yaml_expansion("a: &x [1, *x]\n").cycle, "x");
  EXPECT_EQ(yaml_expansion("a: &x\n  - *x\n").cycle, "x");
  EXPECT_NE(error_of([] { check_config_text("a: &x {b: [*x]}\n", "cfg"); }).find("'*x' is used inside its own anchor"), std::string::npos);
  // An alias refers to the latest anchor of its name before it: the enclosing one, when it is
  // being defined (OpenColorIO 2.1 recurses until its stack overflows: SIGSEGV).
  EXPECT_EQ(yaml_expansion("a: &x [1]\nb: &x [*x]\n").cycle, "x");
  const std::string redefined = "a: &x [1]\nb: &x [22]\nc: *x\n";
  EXPECT_EQ(yaml_expansion(redefined).cycle, "");
  EXPECT_EQ(yaml_expansion(redefined).expanded_bytes, double(redefined.size() + 7 - 2));
}

TEST(CheckedConfig, AFifoAnOversizedFileOrAnOversizedTextIsRefused) {
  const fs::path dir = fresh_dir("files");
  ASSERT_EQ(::mkfifo((dir / "fifo.ocio").c_str(), 0600), 0);
  EXPECT_NE(error_of([&] { load_config_checked((dir / "fifo.ocio").string()); }).find("not a regular file (FIFO)"), std::string::npos);
  { std::ofstream(dir / "big.ocio"); }
  fs::resize_file(dir / "big.ocio", kMaxConfigBytes + 1);  // sparse: nothing is written
  EXPECT_NE(error_of([&] { load_config_checked((dir / "big.ocio").string()); }).find("more than the 16.0 MB allowed"), std::string::npos);
  EXPECT_NE(error_of([] { check_config_text(std::string(kMaxConfigBytes + 1, '#'), "cfg"); }).find("more than the 16.0 MB"), std::string::npos);
  fs::remove_all(dir);
}

TEST(CheckedConfig, RelativeSearchPathsResolveFromTheFilesFolder) {
  const fs::path elsewhere = fresh_dir("cwd");
  const fs::path cwd = fs::current_path();
  fs::current_path(elsewhere);
  const auto shipped = load_config_checked(kShippedConfig);
  EXPECT_NO_THROW(shipped->getCurrentContext()->resolveFileLocation("agx.spi1d"));
  EXPECT_EQ(fs::path(shipped->getWorkingDir()), fs::path(kShippedConfig).parent_path());
  if (fs::exists(kBlenderConfig)) {
    const auto blender = load_config_checked(kBlenderConfig);
    EXPECT_NO_THROW(blender->getProcessor("Linear", "sRGB")->getDefaultCPUProcessor());  // a LUT in its luts/ folder
  }
  fs::current_path(cwd);
  fs::remove_all(elsewhere);
}

}  // namespace
}  // namespace cgtmo::display
