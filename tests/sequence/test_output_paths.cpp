// io::check_outputs_are_not_inputs: the guard a sequence run (and a scene operator's single frame)
// applies before any work, so that no output overwrites a file the run reads.
#include <gtest/gtest.h>

#include <unistd.h>

#include <filesystem>
#include <fstream>

#include "cgtmo/errors.h"
#include "cgtmo/io/image_io.h"

namespace fs = std::filesystem;
using cgtmo::io::check_outputs_are_not_inputs;

namespace {

struct TempDir {
  fs::path path = fs::temp_directory_path() / ("cgtmo-test-output-paths-" + std::to_string(::getpid()));
  TempDir() {
    fs::remove_all(path);
    fs::create_directories(path / "in");
    std::ofstream(path / "in" / "a.exr") << "a";
    std::ofstream(path / "in" / "a.json") << "{}";
  }
  ~TempDir() { fs::remove_all(path); }
  std::string operator()(const std::string& p) const { return (path / p).string(); }
};

}  // namespace

TEST(OutputPaths, DistinctFilesPass) {
  TempDir d;
  EXPECT_NO_THROW(check_outputs_are_not_inputs({d("out.exr"), d("in/b.exr")}, {d("in/a.exr"), d("in/a.json")}));
  EXPECT_NO_THROW(check_outputs_are_not_inputs({}, {d("in/a.exr")}));
}

TEST(OutputPaths, SpellingsOfOneFileAreCaught) {
  TempDir d;
  EXPECT_THROW(check_outputs_are_not_inputs({d("in/./a.exr")}, {d("in/a.exr")}), cgtmo::UsageError);
  EXPECT_THROW(check_outputs_are_not_inputs({d("in/../in/a.json")}, {d("in/a.exr"), d("in/a.json")}), cgtmo::UsageError);
  // A file that does not exist yet is still the same path.
  EXPECT_THROW(check_outputs_are_not_inputs({d("in/./later.exr")}, {d("in/later.exr")}), cgtmo::UsageError);
}

TEST(OutputPaths, LinksAreSeenThrough) {
  TempDir d;
  fs::create_directory_symlink(d.path / "in", d.path / "alias");
  EXPECT_THROW(check_outputs_are_not_inputs({d("alias/a.exr")}, {d("in/a.exr")}), cgtmo::UsageError);
  EXPECT_THROW(check_outputs_are_not_inputs({d("alias/new.exr")}, {d("in/new.exr")}), cgtmo::UsageError);
  fs::create_symlink(d.path / "in" / "a.json", d.path / "json_link.exr");
  EXPECT_THROW(check_outputs_are_not_inputs({d("json_link.exr")}, {d("in/a.json")}), cgtmo::UsageError);
  fs::create_hard_link(d.path / "in" / "a.exr", d.path / "hard.exr");
  try {
    check_outputs_are_not_inputs({d("hard.exr")}, {d("in/a.json"), d("in/a.exr")});
    FAIL() << "no error";
  } catch (const cgtmo::UsageError& e) {
    EXPECT_EQ(std::string(e.what()), "output '" + d("hard.exr") + "' is the input '" + d("in/a.exr") + "': refusing to overwrite it");
  }
}
