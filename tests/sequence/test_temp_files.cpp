// (mirrors src/cgtmo/io/temp_files.cpp; kept with the sequence tests it serves)
#include "cgtmo/io/temp_files.h"

#include <fcntl.h>
#include <gtest/gtest.h>
#include <sys/file.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <ctime>
#include <filesystem>
#include <fstream>
#include <thread>
#include <vector>

#include "cgtmo/errors.h"

namespace fs = std::filesystem;
using namespace cgtmo::io;

namespace {

struct TempDir {
  fs::path path;
  explicit TempDir(const std::string& name) : path(fs::temp_directory_path() / (name + "_" + std::to_string(::getpid()))) {
    fs::remove_all(path);
    fs::create_directories(path);
  }
  ~TempDir() { fs::remove_all(path); }
};

void touch(const fs::path& p) { std::ofstream(p) << "partial"; }

// The same name with another boot tag: as made under another kernel.
std::string with_foreign_boot(const std::string& temp_name) {
  std::string n = temp_name;
  const auto at = n.find(".cgtmo-tmp-") + std::string(".cgtmo-tmp-").size();
  n[at] = n[at] == '0' ? '1' : '0';
  return n;
}

}  // namespace

TEST(TempFiles, NameSitsBesideTheTargetWithItsExtension) {
  const std::string t = temp_path_for("/a/b/shot.0001.png");
  EXPECT_EQ(fs::path(t).parent_path(), fs::path("/a/b"));
  EXPECT_EQ(fs::path(t).extension(), ".png");
  EXPECT_EQ(fs::path(t).filename().string().rfind(".shot.0001.cgtmo-tmp-", 0), 0u);
  EXPECT_NE(t.find("-" + std::to_string(::getpid()) + "-"), std::string::npos);
}

// Two runs whose pids collide (pid namespaces, farm nodes) must not share a temporary.
TEST(TempFiles, EveryTemporaryOfOneTargetHasItsOwnName) {
  EXPECT_NE(temp_path_for("/a/shot.png"), temp_path_for("/a/shot.png"));
}

TEST(TempFiles, TemporaryOfTheLongestTargetNameFits) {
  const TempDir dir("cgtmo_long");
  for (const std::string& stem : {std::string(251, 'a'), std::string(240, 'a')}) {
    const std::string target = (dir.path / (stem + ".png")).string();
    const std::string t = temp_path_for(target);
    EXPECT_LE(fs::path(t).filename().string().size(), 255u);
    EXPECT_EQ(fs::path(t).extension(), ".png");
    const float px[3] = {0.1f, 0.2f, 0.3f};
    ASSERT_NO_THROW(write_file_atomic(target, px, sizeof px));
    EXPECT_EQ(fs::file_size(target), sizeof px);
  }
  EXPECT_EQ(std::distance(fs::directory_iterator(dir.path), fs::directory_iterator()), 2);
}

TEST(TempFiles, ShortenedStemIsCutBetweenCharacters) {
  std::string stem;
  for (int i = 0; i < 120; ++i) stem += "\xc3\xa9";  // 'é', two bytes each
  const std::string name = fs::path(temp_path_for("/x/" + stem + ".png")).filename().string();
  EXPECT_LE(name.size(), 255u);
  EXPECT_EQ(std::count(name.begin(), name.end(), '\xc3'), std::count(name.begin(), name.end(), '\xa9'));
}

TEST(TempFiles, WriteFileAtomicReplacesTheTargetAndLeavesNothingElse) {
  const TempDir dir("cgtmo_atomic");
  const std::string target = (dir.path / "out.txt").string();
  touch(target);
  write_file_atomic(target, "complete", 8);
  std::ifstream in(target);
  std::string s;
  std::getline(in, s);
  EXPECT_EQ(s, "complete");
  EXPECT_EQ(std::distance(fs::directory_iterator(dir.path), fs::directory_iterator()), 1);
}

TEST(TempFiles, WriteErrorsAreDataErrorsNamingTheCause) {
  try {
    write_new_file("/dev/full", "x", "out.ocio");
    FAIL() << "no error";
  } catch (const cgtmo::DataError& e) {
    EXPECT_STREQ(e.what(), "cannot write 'out.ocio': No space left on device");
  }
  try {
    write_file_atomic("/nonexistent-cgtmo-folder/out.png", "x", 1);
    FAIL() << "no error";
  } catch (const cgtmo::DataError& e) {
    EXPECT_STREQ(e.what(), "cannot write '/nonexistent-cgtmo-folder/out.png': No such file or directory");
  }
}

TEST(TempFiles, SignalSafeUnlinkRemovesRegisteredFilesAndStagingFolders) {
  const TempDir dir("cgtmo_tmp");
  const std::string t = temp_path_for((dir.path / "x.png").string());
  touch(t);
  register_temp(t);
  StagingFolder staging = create_staging_folder(dir.path.string());
  touch(fs::path(staging.path) / "a.spi1d");
  touch(fs::path(staging.path) / "b.ocio");
  unlink_registered_temps_signal_safe();
  EXPECT_FALSE(fs::exists(t));
  EXPECT_FALSE(fs::exists(staging.path));
  unregister_temp(t);
  release_staging_folder(staging, true);
}

// Threads register their frames' temporaries at once: every path must be registered whole.
TEST(TempFiles, ConcurrentRegistrationsKeepEveryPath) {
  const TempDir dir("cgtmo_reg");
  constexpr int kThreads = 8, kRounds = 300;
  std::vector<std::string> last(kThreads);
  std::atomic<bool> go{false};
  std::vector<std::thread> threads;
  for (int i = 0; i < kThreads; ++i)
    threads.emplace_back([&, i] {
      while (!go.load()) {
      }
      for (int r = 0; r < kRounds; ++r) {
        const std::string p = (dir.path / ("f" + std::to_string(i) + "_" + std::to_string(r) + std::string(200, 'x'))).string();
        register_temp(p);
        if (r + 1 < kRounds) unregister_temp(p);
        else last[std::size_t(i)] = p;
      }
    });
  go = true;
  for (auto& t : threads) t.join();
  for (const auto& p : last) touch(p);
  unlink_registered_temps_signal_safe();
  for (const auto& p : last) {
    EXPECT_FALSE(fs::exists(p)) << p;
    unregister_temp(p);
  }
}

TEST(TempFiles, LeftoversOfEndedWritersGoLockedOnesStay) {
  const TempDir dir("cgtmo_stale");
  const std::string target = (dir.path / "x.png").string();
  const fs::path ended = temp_path_for(target);
  const fs::path live = temp_path_for(target);
  const fs::path other_target = temp_path_for((dir.path / "y.png").string());
  for (const auto& p : {ended, live, other_target}) touch(p);
  // A live writer holds the lock (flock conflicts between two opens, even in one process).
  const int holder = ::open(live.c_str(), O_RDONLY | O_CLOEXEC);
  ASSERT_EQ(::flock(holder, LOCK_EX), 0);
  const RemovedLeftovers r = remove_stale_temps({target});
  EXPECT_EQ(r.ended_here, 1);
  EXPECT_EQ(r.old_elsewhere, 0);
  EXPECT_FALSE(fs::exists(ended));
  EXPECT_TRUE(fs::exists(live));
  EXPECT_TRUE(fs::exists(other_target));
  ::close(holder);
  EXPECT_EQ(remove_stale_temps({target}).ended_here, 1);
  EXPECT_FALSE(fs::exists(live));
}

// Made under another kernel (another machine, or before a reboot): its locks are not visible
// here, so age decides: kept while younger than 24 h, removed after. A pid-only name likewise.
TEST(TempFiles, LeftoversFromElsewhereGoOnlyWhenOld) {
  const TempDir dir("cgtmo_foreign");
  const std::string target = (dir.path / "x.png").string();
  const fs::path young = dir.path / with_foreign_boot(fs::path(temp_path_for(target)).filename().string());
  const fs::path old = dir.path / with_foreign_boot(fs::path(temp_path_for(target)).filename().string());
  const fs::path by_pid = dir.path / ".x.cgtmo-tmp-1.png";
  const fs::path link = dir.path / with_foreign_boot(fs::path(temp_path_for(target)).filename().string());
  for (const auto& p : {young, old, by_pid}) touch(p);
  fs::create_symlink(young, link);
  const std::time_t day_ago = std::time(nullptr) - 25 * 3600;
  const struct timespec times[2] = {{day_ago, 0}, {day_ago, 0}};
  ASSERT_EQ(::utimensat(AT_FDCWD, old.c_str(), times, 0), 0);
  ASSERT_EQ(::utimensat(AT_FDCWD, link.c_str(), times, AT_SYMLINK_NOFOLLOW), 0);
  const RemovedLeftovers r = remove_stale_temps({target});
  EXPECT_EQ(r.ended_here, 0);
  EXPECT_EQ(r.old_elsewhere, 1);
  EXPECT_TRUE(fs::exists(young));
  EXPECT_FALSE(fs::exists(old));
  EXPECT_TRUE(fs::exists(by_pid));
  EXPECT_TRUE(fs::is_symlink(link));  // not a file cgtmo made: never touched
  EXPECT_EQ(r.describe("temporary file"),
            "removed 1 temporary file untouched for over 24 h (left on another machine or before a reboot)");
}

TEST(TempFiles, StagingFolderStaysWhileHeldAndGoesOnceReleased) {
  const TempDir dir("cgtmo_staging");
  StagingFolder s = create_staging_folder(dir.path.string());
  EXPECT_EQ(fs::path(s.path).filename().string().rfind(".cgtmo-staging-", 0), 0u);
  touch(fs::path(s.path) / "a.cube");
  EXPECT_EQ(remove_stale_staging_folders(dir.path.string()).total(), 0);
  EXPECT_TRUE(fs::exists(s.path));
  const std::string path = s.path;
  release_staging_folder(s, false);  // as a killed run leaves it: unlocked
  const RemovedLeftovers r = remove_stale_staging_folders(dir.path.string());
  EXPECT_EQ(r.ended_here, 1);
  EXPECT_FALSE(fs::exists(path));
  EXPECT_EQ(r.describe("staging folder"), "removed 1 staging folder left by an interrupted run");
}
