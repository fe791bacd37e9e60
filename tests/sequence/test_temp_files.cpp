// (mirrors src/cgtmo/io/temp_files.cpp; kept with the sequence tests it serves)
#include "cgtmo/io/temp_files.h"

#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>

namespace fs = std::filesystem;
using namespace cgtmo::io;

TEST(TempFiles, NameSitsBesideTheTargetWithItsExtension) {
  const std::string t = temp_path_for("/a/b/shot.0001.png");
  EXPECT_EQ(fs::path(t).parent_path(), fs::path("/a/b"));
  EXPECT_EQ(fs::path(t).extension(), ".png");
  EXPECT_NE(t.find(".shot.0001.cgtmo-tmp-" + std::to_string(::getpid())), std::string::npos);
}

TEST(TempFiles, SignalSafeUnlinkRemovesRegistered) {
  const fs::path dir = fs::temp_directory_path() / ("cgtmo_tmp_" + std::to_string(::getpid()));
  fs::create_directories(dir);
  const std::string t = temp_path_for((dir / "x.png").string());
  std::ofstream(t) << "partial";
  register_temp(t);
  unlink_registered_temps_signal_safe();
  EXPECT_FALSE(fs::exists(t));
  unregister_temp(t);
  fs::remove_all(dir);
}

TEST(TempFiles, StaleTempsOfDeadProcessesAreRemovedLiveOnesKept) {
  const fs::path dir = fs::temp_directory_path() / ("cgtmo_stale_" + std::to_string(::getpid()));
  fs::create_directories(dir);
  // A child that exits: its PID is dead afterwards (reaped).
  const pid_t child = fork();
  if (child == 0) _exit(0);
  waitpid(child, nullptr, 0);
  const fs::path dead = dir / (".x.cgtmo-tmp-" + std::to_string(child) + ".png");
  const fs::path live = dir / (".x.cgtmo-tmp-1.png");  // PID 1 always runs
  const fs::path other = dir / (".y.cgtmo-tmp-" + std::to_string(child) + ".png");  // another target
  for (const auto& p : {dead, live, other}) std::ofstream(p) << "partial";
  EXPECT_EQ(remove_stale_temps((dir / "x.png").string()), 1);
  EXPECT_FALSE(fs::exists(dead));
  EXPECT_TRUE(fs::exists(live));
  EXPECT_TRUE(fs::exists(other));
  fs::remove_all(dir);
}
