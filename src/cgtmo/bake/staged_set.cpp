#include "cgtmo/bake/staged_set.h"

#include <fcntl.h>
#include <sys/file.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <random>

#include "cgtmo/bake/writers.h"
#include "cgtmo/display/checked_config.h"
#include "cgtmo/errors.h"
#include "cgtmo/io/input_file.h"
#include "cgtmo/util/test_pause.h"

namespace cgtmo::bake {

namespace fs = std::filesystem;

namespace {

const std::string kSetPrefix = "cgtmo-set-";
constexpr const char* kSetFolder = "set";        // inside the staging folder
constexpr const char* kStagedConfig = "config.ocio";

std::uint64_t fnv1a64(const void* data, std::size_t n, std::uint64_t h = 14695981039346656037ull) {
  const auto* p = static_cast<const unsigned char*>(data);
  for (std::size_t i = 0; i < n; ++i) h = (h ^ p[i]) * 1099511628211ull;
  return h;
}

std::string hex(std::uint64_t v, int digits) {
  char buf[17];
  std::snprintf(buf, sizeof buf, "%0*llx", digits, static_cast<unsigned long long>(v));
  return buf;
}

bool is_hex(const std::string& s) { return !s.empty() && s.find_first_not_of("0123456789abcdef") == std::string::npos; }

bool same_inode(int fd, const fs::path& path) {
  struct stat a {}, b {};
  return ::fstat(fd, &a) == 0 && ::lstat(path.c_str(), &b) == 0 && a.st_dev == b.st_dev && a.st_ino == b.st_ino;
}

// A folder open without following a link, locked; -1 when it cannot be opened or locked now.
int open_locked(const fs::path& folder, int how) {
  const int fd = ::open(folder.c_str(), O_RDONLY | O_DIRECTORY | O_NOFOLLOW | O_CLOEXEC);
  if (fd < 0) return -1;
  if (::flock(fd, how | LOCK_NB) != 0 || !same_inode(fd, folder)) {
    ::close(fd);
    return -1;
  }
  return fd;
}

}  // namespace

bool StagedSet::is_set_name(const std::string& name) {
  if (name.compare(0, kSetPrefix.size(), kSetPrefix) != 0) return false;
  const std::string rest = name.substr(kSetPrefix.size());
  if (rest.size() == 16) return is_hex(rest);
  return rest.size() == 25 && rest[16] == '-' && is_hex(rest.substr(0, 16)) && is_hex(rest.substr(17));
}

StagedSet::StagedSet(const std::string& out_dir, std::function<void(const std::string&)> note)
    : out_dir_(out_dir), note_(std::move(note)) {
  check_output_folder(out_dir_, "merged config");
  const io::RemovedLeftovers removed = io::remove_stale_staging_folders(out_dir_);
  if (removed.total() && note_) note_(removed.describe("staging folder") + " in '" + out_dir_ + "'");
  staging_ = io::create_staging_folder(out_dir_);
  std::error_code ec;
  fs::create_directory(staged_path(), ec);
  if (ec) throw DataError("cannot create '" + staged_path() + "': " + ec.message());
}

StagedSet::~StagedSet() {
  io::release_staging_folder(staging_, true);
  if (set_lock_fd_ >= 0) ::close(set_lock_fd_);
}

std::string StagedSet::staged_path() const { return (fs::path(staging_.path) / kSetFolder).string(); }

void StagedSet::stage(const std::string& relative, const std::string& content) {
  const fs::path rel(relative);
  int parts = 0;
  for (const auto& part : rel) {
    if (part.empty() || part == "." || part == ".." || part == "/") throw DataError("internal: '" + relative + "' is not a plain relative path");
    ++parts;
  }
  if (parts == 0) throw DataError("internal: an empty path staged");
  if (parts > kMaxDepth + 1)
    throw DataError("'" + relative + "' is nested deeper than " + std::to_string(kMaxDepth) + " folders: not copied (nothing written)");
  const fs::path dest = fs::path(staged_path()) / rel;
  std::error_code ec;
  fs::create_directories(dest.parent_path(), ec);
  if (ec) throw DataError("cannot create '" + dest.parent_path().string() + "': " + ec.message());
  io::write_new_file(dest.string(), content, (fs::path(out_dir_) / "<set>" / rel).string());
  staged_[rel.generic_string()] = {content.size(), fnv1a64(content.data(), content.size())};
}

const std::string& StagedSet::settle_name() {
  std::uint64_t h = fnv1a64("cgtmo-set", 9);
  for (const auto& [rel, file] : staged_) {  // sorted by path: the name does not depend on the staging order
    h = fnv1a64(rel.c_str(), rel.size() + 1, h);
    h = fnv1a64(&file, sizeof file, h);
  }
  name_ = kSetPrefix + hex(h, 16);
  const fs::path existing = fs::path(out_dir_) / name_;
  struct stat st {};
  if (::lstat(existing.c_str(), &st) != 0) return name_;
  // Locked shared, so that no other run's clean-up removes it before our config names it.
  const int fd = S_ISDIR(st.st_mode) ? open_locked(existing, LOCK_SH) : -1;
  bool same = fd >= 0;
  std::size_t files = 0;
  std::error_code ec;
  for (auto it = fs::recursive_directory_iterator(existing, ec); same && !ec && it != fs::recursive_directory_iterator();
       it.increment(ec)) {
    const auto status = it->symlink_status(ec);
    if (fs::is_directory(status)) continue;
    const auto want = staged_.find(it->path().lexically_relative(existing).generic_string());
    same = !ec && fs::is_regular_file(status) && want != staged_.end();
    if (!same) break;
    try {
      const std::string content = io::read_regular_file(it->path().string(), want->second.first, "", false);
      same = content.size() == want->second.first && fnv1a64(content.data(), content.size()) == want->second.second;
    } catch (const DataError&) {
      same = false;
    }
    ++files;
  }
  if (same && !ec && files == staged_.size()) {
    reuse_ = true;
    set_lock_fd_ = fd;
    return name_;
  }
  if (fd >= 0) ::close(fd);
  static std::random_device random;
  name_ += "-" + hex(random(), 8);  // a folder of that name that is not this set: never touched
  return name_;
}

void StagedSet::place_set() {
  if (reuse_) return;
  const fs::path dest = fs::path(out_dir_) / name_;
  // Locked before it has its name: another run's clean-up never removes a set that is placed
  // but not yet named by config.ocio.
  set_lock_fd_ = open_locked(staged_path(), LOCK_EX);
  if (set_lock_fd_ < 0) throw DataError("cannot lock '" + staged_path() + "': " + std::strerror(errno));
  if (::rename(staged_path().c_str(), dest.c_str()) != 0)
    throw DataError("cannot rename '" + staged_path() + "' to '" + dest.string() + "': " + std::strerror(errno) + " (nothing changed)");
}

void StagedSet::commit(const std::string& config_text) {
  if (name_.empty()) throw DataError("internal: the set was committed before it was named");
  test_pause_point("merge-commit-start");
  const io::DeferTerminationSignals whole_set;
  const fs::path config = fs::path(out_dir_) / "config.ocio";
  const std::string staged_config = (fs::path(staging_.path) / kStagedConfig).string();
  io::write_new_file(staged_config, config_text, config.string());
  place_set();
  test_pause_point("merge-set-placed");
  if (::rename(staged_config.c_str(), config.c_str()) != 0) {
    const int err = errno;
    std::error_code ec;
    if (!reuse_) fs::remove_all(fs::path(out_dir_) / name_, ec);  // placed by us, named by nothing
    throw DataError("cannot rename '" + staged_config + "' to '" + config.string() + "': " + std::strerror(err) +
                    " (the previous config is kept)");
  }
  test_pause_point("merge-config-renamed");
  io::release_staging_folder(staging_, true);
  remove_unnamed_sets();
  ::close(set_lock_fd_);
  set_lock_fd_ = -1;
}

void StagedSet::remove_unnamed_sets() {
  std::string current;
  try {
    current = io::read_regular_file((fs::path(out_dir_) / "config.ocio").string(), display::kMaxConfigBytes);
  } catch (const DataError&) {
    return;  // replaced meanwhile by something unreadable: remove nothing
  }
  int removed = 0;
  std::error_code ec;
  for (const auto& entry : fs::directory_iterator(out_dir_, ec)) {
    const std::string name = entry.path().filename().string();
    if (!is_set_name(name) || current.find(name) != std::string::npos) continue;
    struct stat marker {};
    if (::lstat((entry.path() / kMarker).c_str(), &marker) != 0 || !S_ISREG(marker.st_mode)) continue;
    const int fd = open_locked(entry.path(), LOCK_EX);  // -1: a link, or a set another run holds
    if (fd < 0) continue;
    std::error_code rm;
    fs::remove_all(entry.path(), rm);
    removed += !rm;
    ::close(fd);
  }
  if (removed && note_)
    note_("removed " + std::to_string(removed) + " earlier set" + (removed == 1 ? "" : "s") + " that config.ocio no longer names");
}

}  // namespace cgtmo::bake
