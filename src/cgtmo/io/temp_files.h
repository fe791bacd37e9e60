#pragma once
// Temporary outputs in flight (image temporaries, bake's staging folders) and atomic writes, so
// that neither an interrupted run nor one running beside it leaves or loses a file.
//
// Names: "<head><marker><boot>-<pid>-<nonce><tail>". <boot> is the start of the kernel's boot id,
// the same in every pid namespace and container of one running kernel; the nonce keeps the names
// of two runs apart when their pids collide (two pid namespaces, two farm nodes).
//
// Liveness: the writer holds an flock on each temporary (taken before the name appears) until
// it is renamed or removed. A later run removes a leftover when
//   - it was made under this running kernel and its lock can be taken: its writer has ended,
//     whatever pid namespace either runs in (the kernel drops the lock when a process dies);
//   - or it has not been modified for 24 h (made on another machine sharing the folder, or
//     before a reboot: that kernel's locks are not visible here, e.g. NFS mounted with
//     local_lock, so only age says it is abandoned).
// A temporary whose lock is held is never removed.
#include <cstddef>
#include <string>
#include <vector>

namespace cgtmo::io {

// A new, unique temporary name for `target`, in the same folder, hidden, ending with `target`'s
// extension: ".<stem>.cgtmo-tmp-<boot>-<pid>-<nonce><ext>". The stem is shortened (and a hash of
// it added) where the name would not fit the folder's NAME_MAX, so that the temporary's name
// fits whenever the target's does.
std::string temp_path_for(const std::string& target);

// Writes `size` bytes to `path` through a locked temporary in the same folder and a rename: an
// existing `path` is replaced only by the complete file. Throws DataError naming `path` and the
// cause ("No space left on device").
void write_file_atomic(const std::string& path, const void* data, std::size_t size);

// Writes a file (one inside a private staging folder). Throws DataError naming `shown_as` (the
// file it stands for; default `path`) and the cause.
void write_new_file(const std::string& path, const std::string& content, const std::string& shown_as = "");

// A staging folder ".cgtmo-staging-<boot>-<pid>-<nonce>" created in `dir`, locked as in use and
// registered for the signal handler until release_staging_folder. Throws DataError. What is
// staged in it may nest folders kMaxStagingDepth deep (the signal handler removes no deeper).
inline constexpr int kMaxStagingDepth = 16;
struct StagingFolder {
  std::string path;
  int lock_fd = -1;
};
StagingFolder create_staging_folder(const std::string& dir);
// Unregisters and unlocks it; removes the folder and its files when `remove`.
void release_staging_folder(StagingFolder& folder, bool remove);

// What a clean-up removed: leftovers of ended runs on this kernel, and old ones from elsewhere.
struct RemovedLeftovers {
  int ended_here = 0;
  int old_elsewhere = 0;
  int total() const { return ended_here + old_elsewhere; }
  // "removed 2 temporary files left by interrupted runs" (and the old ones, if any), for messages.
  std::string describe(const std::string& noun) const;
};

// Removes the leftover temporaries of each target (one listing per folder).
RemovedLeftovers remove_stale_temps(const std::vector<std::string>& targets);
// Removes the leftover staging folders in `dir`.
RemovedLeftovers remove_stale_staging_folders(const std::string& dir);

void register_temp(const std::string& path);
void unregister_temp(const std::string& path);

// Unlinks every registered temporary, and empties and removes every registered staging folder;
// only async-signal-safe calls (for signal handlers).
void unlink_registered_temps_signal_safe();

// For commands without a handler of their own: on SIGINT, SIGTERM or SIGHUP (those not ignored
// when called, so nohup still works), remove the registered temporaries and exit 128 + signal.
void remove_temps_on_termination_signals();

// While one lives, those handlers hold a signal back until it ends, so that a set of renames
// (bake's commit) is never cut in half.
class DeferTerminationSignals {
 public:
  DeferTerminationSignals();
  ~DeferTerminationSignals();
  DeferTerminationSignals(const DeferTerminationSignals&) = delete;
  DeferTerminationSignals& operator=(const DeferTerminationSignals&) = delete;
};

}  // namespace cgtmo::io
