#include "cgtmo/io/temp_files.h"

#include <dirent.h>
#include <fcntl.h>
#include <signal.h>
#include <sys/file.h>
#include <sys/stat.h>
#include <unistd.h>

#include <array>
#include <atomic>
#include <cctype>
#include <cerrno>
#include <climits>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <ctime>
#include <filesystem>
#include <fstream>
#include <map>
#include <random>
#include <set>

#include "cgtmo/errors.h"
#include "cgtmo/util/test_pause.h"

namespace cgtmo::io {

namespace fs = std::filesystem;

namespace {

const std::string kTempMarker = ".cgtmo-tmp-";
const std::string kStagingMarker = ".cgtmo-staging-";
// A leftover made elsewhere (its kernel's locks are not visible here) is removed once untouched
// this long: cgtmo keeps a temporary named for microseconds, a staging folder for a bake's length.
constexpr std::time_t kAbandonedAfterSeconds = 24 * 3600;
// The longest tag: 8 hex digits of boot id, a pid (pid_max is at most 4194304), 8 hex digits.
constexpr std::size_t kMaxTagLength = 8 + 1 + 7 + 1 + 8;

std::string errno_text(int err) { return std::strerror(err); }

std::string hex32(std::uint32_t v) {
  char b[9];
  std::snprintf(b, sizeof b, "%08x", v);
  return b;
}

std::uint64_t splitmix64(std::uint64_t x) {
  x += 0x9e3779b97f4a7c15ULL;
  x = (x ^ (x >> 30)) * 0xbf58476d1ce4e5b9ULL;
  x = (x ^ (x >> 27)) * 0x94d049bb133111ebULL;
  return x ^ (x >> 31);
}

// The first 8 hex digits of this kernel's boot id: every process of one running kernel (any pid
// namespace, any container) reads the same, and each boot draws a new one. Unreadable: a random
// tag of this process, so that every other run's leftovers count as made elsewhere.
const std::string& boot_tag() {
  static const std::string tag = [] {
    std::ifstream f("/proc/sys/kernel/random/boot_id");
    std::string id, hex;
    std::getline(f, id);
    for (char c : id)
      if (std::isxdigit(static_cast<unsigned char>(c))) hex += char(std::tolower(static_cast<unsigned char>(c)));
    return hex.size() >= 8 ? hex.substr(0, 8) : hex32(std::uint32_t(std::random_device{}()));
  }();
  return tag;
}

// "<boot>-<pid>-<nonce>": unique per call, even between runs whose pids collide.
std::string unique_tag() {
  static const std::uint64_t seed = (std::uint64_t(std::random_device{}()) << 32) ^ std::random_device{}();
  static std::atomic<std::uint64_t> count{0};
  const std::uint64_t pid = std::uint64_t(::getpid());
  const auto nonce = std::uint32_t(splitmix64(seed ^ (pid << 40) ^ count.fetch_add(1)));
  return boot_tag() + "-" + std::to_string(pid) + "-" + hex32(nonce);
}

std::uint32_t fnv1a32(const std::string& s) {
  std::uint32_t h = 2166136261u;
  for (unsigned char c : s) h = (h ^ c) * 16777619u;
  return h;
}

fs::path folder_of(const std::string& target) {
  const fs::path dir = fs::path(target).parent_path();
  return dir.empty() ? fs::path(".") : dir;
}

// The temporary's name is "<head><marker><tag><tail>": head "." + the target's stem, tail its
// extension (OIIO and viewers go by it). Where that would not fit the folder's NAME_MAX, the stem
// is cut (at a UTF-8 character boundary) and a hash of the whole stem appended, so that every
// name that fits as a target has a temporary that fits too.
struct TempName {
  std::string head, tail;
};
TempName temp_name_parts(const std::string& target) {
  const fs::path t(target);
  std::string stem = t.stem().string(), ext = t.extension().string();
  if (ext.size() > 16) {  // not an image extension: keep the name budget for the stem
    stem += ext;
    ext.clear();
  }
  long name_max = ::pathconf(folder_of(target).c_str(), _PC_NAME_MAX);
  if (name_max <= 0) name_max = NAME_MAX;
  const std::size_t fixed = 1 + kTempMarker.size() + kMaxTagLength + ext.size();
  const std::size_t room = std::size_t(name_max) > fixed ? std::size_t(name_max) - fixed : 0;
  if (stem.size() > room) {
    const std::string hash = "~" + hex32(fnv1a32(stem));
    std::size_t keep = room > hash.size() ? room - hash.size() : 0;
    while (keep > 0 && (static_cast<unsigned char>(stem[keep]) & 0xC0) == 0x80) --keep;  // not inside a character
    stem = stem.substr(0, keep) + hash;
  }
  return {"." + stem, ext};
}

bool same_file(const struct stat& a, const struct stat& b) { return a.st_dev == b.st_dev && a.st_ino == b.st_ino; }

// Whether `path` still names the file open as `fd` (a clean-up may have removed it meanwhile).
bool still_named(int fd, const std::string& path) {
  struct stat by_fd {}, by_name {};
  return ::fstat(fd, &by_fd) == 0 && ::lstat(path.c_str(), &by_name) == 0 && same_file(by_fd, by_name);
}

// The lock that says "in use": held until the process closes its last descriptor of the file,
// which the kernel does when the process dies however it dies. Where the filesystem refuses locks
// (ENOLCK), nothing is held, and clean-ups, refused too, go by age alone.
void hold_in_use_lock(int fd) {
  while (::flock(fd, LOCK_EX) != 0 && errno == EINTR) {
  }
}

bool write_all(int fd, const void* data, std::size_t size) {
  const auto* p = static_cast<const unsigned char*>(data);
  std::size_t done = 0;
  while (done < size) {
    const ssize_t n = ::write(fd, p + done, size - done);
    if (n < 0) {
      if (errno == EINTR) continue;
      return false;
    }
    done += std::size_t(n);
  }
  return true;
}

// Registered temporaries, in fixed storage so that a signal handler may read them without
// allocating or locking. A slot is claimed (kWriting) before its path is written and published
// (kFile, kFolder) after, so neither a concurrent registration nor a handler sees a torn path.
constexpr int kSlots = 256;
constexpr std::size_t kPathMax = 4096;
enum SlotState : int { kFree, kWriting, kFile, kFolder };
std::array<std::atomic<int>, kSlots> g_state{};
std::array<std::array<char, kPathMax>, kSlots> g_paths{};

void register_path(const std::string& path, SlotState kind) {
  if (path.size() >= kPathMax) return;
  for (int i = 0; i < kSlots; ++i) {
    int expected = kFree;
    if (!g_state[i].compare_exchange_strong(expected, kWriting)) continue;
    std::memcpy(g_paths[i].data(), path.c_str(), path.size() + 1);
    g_state[i].store(kind);
    return;
  }
}

// Empties the folder open as `fd`, its subfolders first (kMaxStagingDepth deep at most), without
// following links; async-signal-safe (no allocation: a 1 KB listing buffer per level).
void empty_folder_signal_safe(int fd, int depth) {
  alignas(8) char buf[1024];
  for (bool removed_some = true; removed_some;) {  // listing while unlinking may skip names: list again
    removed_some = false;
    ::lseek(fd, 0, SEEK_SET);
    for (ssize_t n; (n = ::getdents64(fd, buf, sizeof buf)) > 0;)
      for (ssize_t at = 0; at < n;) {
        const auto* d = reinterpret_cast<const struct dirent64*>(buf + at);
        at += d->d_reclen;
        if (std::strcmp(d->d_name, ".") == 0 || std::strcmp(d->d_name, "..") == 0) continue;
        if (::unlinkat(fd, d->d_name, 0) == 0) {
          removed_some = true;
        } else if (errno == EISDIR && depth < kMaxStagingDepth) {
          const int sub = ::openat(fd, d->d_name, O_RDONLY | O_DIRECTORY | O_NOFOLLOW | O_CLOEXEC);
          if (sub >= 0) {
            empty_folder_signal_safe(sub, depth + 1);
            ::close(sub);
          }
          if (::unlinkat(fd, d->d_name, AT_REMOVEDIR) == 0) removed_some = true;
        }
      }
  }
}

void remove_folder_signal_safe(const char* path) {
  // Another thread may still be writing into it (the handler runs on any thread): empty it
  // again while that adds files.
  for (int attempt = 0; attempt < 8; ++attempt) {
    const int fd = ::open(path, O_RDONLY | O_DIRECTORY | O_NOFOLLOW | O_CLOEXEC);
    if (fd < 0) return;
    empty_folder_signal_safe(fd, 1);
    ::close(fd);
    if (::rmdir(path) == 0 || errno != ENOTEMPTY) return;
  }
}

// The deferring sections open, and kExiting once a handler has decided to end the process, in
// one atomic word: a handler on one thread and a commit starting on another never both go on
// (the handler removing a staging folder while the commit renames out of it: a mixed set).
constexpr int kExiting = 1 << 30;
std::atomic<int> g_defer{0};
std::atomic<int> g_deferred_signal{0};

// Ends the process for the pending signal unless a deferring section is open (its end comes
// back here). Async-signal-safe.
void end_unless_deferred() {
  int s = g_defer.load();
  do {
    if (s & kExiting) return;  // another thread is ending the process
    if (s > 0) return;
  } while (!g_defer.compare_exchange_weak(s, kExiting));
  const int sig = g_deferred_signal.load();
  unlink_registered_temps_signal_safe();
  ::_exit(128 + sig);
}

extern "C" void remove_temps_and_exit(int sig) {
  g_deferred_signal.store(sig);  // before the check: a section ending meanwhile sees it
  end_unless_deferred();
}

enum class Verdict { Keep, EndedHere, OldElsewhere };

// Removes the leftover `path` (a temporary file, or a staging folder when `folder`) whose name
// holds `tag`, if it is abandoned (see temp_files.h); never one whose lock is held.
Verdict remove_if_abandoned(const fs::path& path, const std::string& tag, bool folder) {
  struct stat st {};
  if (::lstat(path.c_str(), &st) != 0 || (folder ? !S_ISDIR(st.st_mode) : !S_ISREG(st.st_mode))) return Verdict::Keep;
  // Opened for writing where allowed: NFS grants an exclusive lock only on a file open for writing.
  const int flags = O_NOFOLLOW | O_CLOEXEC | O_NONBLOCK;
  int fd = folder ? ::open(path.c_str(), O_RDONLY | O_DIRECTORY | flags) : ::open(path.c_str(), O_RDWR | flags);
  if (fd < 0 && !folder) fd = ::open(path.c_str(), O_RDONLY | flags);
  bool locked = false;
  if (fd >= 0) {
    if (::flock(fd, LOCK_EX | LOCK_NB) == 0) {
      locked = true;
    } else if (errno == EWOULDBLOCK) {
      ::close(fd);
      return Verdict::Keep;  // its writer is alive, in whatever pid namespace
    }
  }
  const bool made_here = tag.compare(0, boot_tag().size() + 1, boot_tag() + "-") == 0;
  Verdict v = Verdict::Keep;
  if (made_here && locked) v = Verdict::EndedHere;
  else if (std::time(nullptr) - st.st_mtime > kAbandonedAfterSeconds) v = Verdict::OldElsewhere;
  if (v != Verdict::Keep) {
    // Only if the name still is the file judged (removed while our lock is held, if we hold it).
    struct stat now {};
    const bool same = fd >= 0 ? still_named(fd, path.string()) : ::lstat(path.c_str(), &now) == 0 && same_file(st, now);
    std::error_code ec;
    if (!same) v = Verdict::Keep;
    else if (folder) fs::remove_all(path, ec);
    else fs::remove(path, ec);
    if (ec) v = Verdict::Keep;
  }
  if (fd >= 0) ::close(fd);
  return v;
}

void count(RemovedLeftovers& r, Verdict v) {
  if (v == Verdict::EndedHere) ++r.ended_here;
  if (v == Verdict::OldElsewhere) ++r.old_elsewhere;
}

}  // namespace

std::string temp_path_for(const std::string& target) {
  const TempName n = temp_name_parts(target);
  return (folder_of(target) / (n.head + kTempMarker + unique_tag() + n.tail)).string();
}

void write_file_atomic(const std::string& path, const void* data, std::size_t size) {
  const fs::path dir = folder_of(path);
  std::string tmp;     // the temporary's name, once this call has made one
  bool named = false;  // whether `tmp` exists and is ours: never unlink another run's name
  struct Unregister {
    std::string& p;
    ~Unregister() {
      if (!p.empty()) unregister_temp(p);
    }
  } unregister{tmp};
  auto fail = [&](int err, int fd) {
    if (fd >= 0) ::close(fd);
    if (named) ::unlink(tmp.c_str());
    throw DataError("cannot write '" + path + "': " + errno_text(err));
  };
  // An unnamed file (O_TMPFILE) vanishes if the process dies; it is locked before it gets a name,
  // so no clean-up can see it unlocked. Where O_TMPFILE is unsupported (NFS), a named temporary is
  // created, locked, and checked to be still ours: a clean-up may have taken it in between.
  int fd = ::open(dir.c_str(), O_TMPFILE | O_WRONLY | O_CLOEXEC, 0666);
  const bool unnamed = fd >= 0;
  if (unnamed) {
    hold_in_use_lock(fd);
  } else {
    if (errno == EACCES || errno == EROFS || errno == ENOSPC || errno == ENOENT) fail(errno, -1);
    for (int attempt = 0; !named; ++attempt) {
      if (!tmp.empty()) unregister_temp(tmp);
      tmp = temp_path_for(path);
      register_temp(tmp);
      fd = ::open(tmp.c_str(), O_CREAT | O_EXCL | O_WRONLY | O_CLOEXEC, 0666);
      if (fd < 0) fail(errno, -1);
      hold_in_use_lock(fd);
      named = still_named(fd, tmp);
      if (!named) {
        ::close(fd);
        if (attempt == 8) fail(EAGAIN, -1);
      }
    }
  }
  if (!write_all(fd, data, size)) fail(errno, fd);
  if (unnamed) {
    tmp = temp_path_for(path);
    register_temp(tmp);
    const std::string self = "/proc/self/fd/" + std::to_string(fd);
    if (::linkat(AT_FDCWD, self.c_str(), AT_FDCWD, tmp.c_str(), AT_SYMLINK_FOLLOW) != 0) fail(errno, fd);
    named = true;
  }
  // close() reports delayed write errors (NFS) and must succeed before the rename; a duplicate
  // descriptor keeps the lock until the temporary has been renamed.
  const int lock_fd = ::dup(fd);
  if (::close(fd) != 0) fail(errno, lock_fd);
  if (::rename(tmp.c_str(), path.c_str()) != 0) fail(errno, lock_fd);
  if (lock_fd >= 0) ::close(lock_fd);
}

void write_new_file(const std::string& path, const std::string& content, const std::string& shown_as) {
  const std::string& name = shown_as.empty() ? path : shown_as;
  const int fd = ::open(path.c_str(), O_CREAT | O_TRUNC | O_WRONLY | O_CLOEXEC, 0666);
  if (fd < 0) throw DataError("cannot write '" + name + "': " + errno_text(errno));
  const bool written = write_all(fd, content.data(), content.size());
  const int err = errno;
  if (::close(fd) != 0 || !written) throw DataError("cannot write '" + name + "': " + errno_text(written ? errno : err));
}

StagingFolder create_staging_folder(const std::string& dir) {
  // Made, locked, then checked to be still ours: a clean-up may have taken it before the lock.
  // From mkdir to its registration a termination signal waits: the handler removes only
  // registered folders, so one arriving in between would leave this one behind.
  const DeferTerminationSignals until_registered;
  for (int attempt = 0;; ++attempt) {
    const std::string path = (fs::path(dir) / (kStagingMarker + unique_tag())).string();
    if (::mkdir(path.c_str(), 0777) != 0) throw DataError("cannot create '" + path + "': " + errno_text(errno));
    test_pause_point("staging-folder-made");
    const int fd = ::open(path.c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC);
    if (fd >= 0) {
      hold_in_use_lock(fd);
      if (still_named(fd, path)) {
        register_path(path, kFolder);
        return {path, fd};
      }
      ::close(fd);
    }
    if (attempt == 8) throw DataError("cannot create '" + path + "': removed by another run as it was made");
  }
}

void release_staging_folder(StagingFolder& folder, bool remove) {
  if (folder.path.empty()) return;
  unregister_temp(folder.path);
  std::error_code ec;
  if (remove) fs::remove_all(folder.path, ec);
  if (folder.lock_fd >= 0) ::close(folder.lock_fd);
  folder = {};
}

std::string RemovedLeftovers::describe(const std::string& noun) const {
  std::string s;
  if (ended_here)
    s = "removed " + std::to_string(ended_here) + " " + noun + (ended_here == 1 ? " left by an interrupted run" : "s left by interrupted runs");
  if (old_elsewhere)
    s += (s.empty() ? "removed " : "; and ") + std::to_string(old_elsewhere) + " " + noun + (old_elsewhere == 1 ? "" : "s") +
         " untouched for over 24 h (left on another machine or before a reboot)";
  return s;
}

RemovedLeftovers remove_stale_temps(const std::vector<std::string>& targets) {
  // Per folder, the (head, tail) of each target's temporaries; then one listing per folder.
  std::map<fs::path, std::set<std::pair<std::string, std::string>>> wanted;
  for (const auto& t : targets) {
    const TempName n = temp_name_parts(t);
    wanted[folder_of(t)].emplace(n.head, n.tail);
  }
  RemovedLeftovers removed;
  for (const auto& [dir, names] : wanted) {
    // The tag in `name` if it is a temporary of one of the targets, else "".
    auto tag_of = [&names = names](const std::string& name) -> std::string {
      for (auto at = name.find(kTempMarker, 1); at != std::string::npos; at = name.find(kTempMarker, at + 1)) {
        const std::string head = name.substr(0, at), rest = name.substr(at + kTempMarker.size());
        for (auto n = names.lower_bound({head, ""}); n != names.end() && n->first == head; ++n) {
          const std::string& tail = n->second;
          if (rest.size() > tail.size() && rest.compare(rest.size() - tail.size(), tail.size(), tail) == 0)
            return rest.substr(0, rest.size() - tail.size());
        }
      }
      return "";
    };
    std::error_code ec;
    for (const auto& entry : fs::directory_iterator(dir, ec)) {
      const std::string name = entry.path().filename().string();
      if (name.empty() || name[0] != '.') continue;
      const std::string tag = tag_of(name);
      if (!tag.empty()) count(removed, remove_if_abandoned(entry.path(), tag, false));
    }
  }
  return removed;
}

RemovedLeftovers remove_stale_staging_folders(const std::string& dir) {
  RemovedLeftovers removed;
  std::error_code ec;
  for (const auto& entry : fs::directory_iterator(dir, ec)) {
    const std::string name = entry.path().filename().string();
    if (name.size() > kStagingMarker.size() && name.compare(0, kStagingMarker.size(), kStagingMarker) == 0)
      count(removed, remove_if_abandoned(entry.path(), name.substr(kStagingMarker.size()), true));
  }
  return removed;
}

void register_temp(const std::string& path) { register_path(path, kFile); }

void unregister_temp(const std::string& path) {
  for (int i = 0; i < kSlots; ++i) {
    const int s = g_state[i].load();
    if ((s == kFile || s == kFolder) && path == g_paths[i].data()) {
      g_state[i].store(kFree);
      return;
    }
  }
}

void unlink_registered_temps_signal_safe() {
  for (int i = 0; i < kSlots; ++i) {
    const int s = g_state[i].load();
    if (s == kFile) ::unlink(g_paths[i].data());
    if (s == kFolder) remove_folder_signal_safe(g_paths[i].data());
  }
}

void remove_temps_on_termination_signals() {
  struct sigaction sa {};
  sa.sa_handler = remove_temps_and_exit;
  sigemptyset(&sa.sa_mask);
  for (int sig : {SIGINT, SIGTERM, SIGHUP}) sigaddset(&sa.sa_mask, sig);  // one handler at a time per thread
  for (int sig : {SIGINT, SIGTERM, SIGHUP}) {
    struct sigaction old {};
    if (sigaction(sig, nullptr, &old) == 0 && old.sa_handler == SIG_IGN) continue;  // nohup, background jobs
    sigaction(sig, &sa, nullptr);
  }
}

DeferTerminationSignals::DeferTerminationSignals() {
  int s = g_defer.load();
  do {
    while (s & kExiting) {  // a handler on another thread is ending the process: start nothing
      ::pause();
      s = g_defer.load();
    }
  } while (!g_defer.compare_exchange_weak(s, s + 1));
}

DeferTerminationSignals::~DeferTerminationSignals() {
  g_defer.fetch_sub(1);
  if (g_deferred_signal.load()) end_unless_deferred();
}

}  // namespace cgtmo::io
