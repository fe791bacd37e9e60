#pragma once
// A set of files that one config names, committed whole (`cgtmo bake --into`). The output
// folder DIR holds config.ocio and the set folder it names, cgtmo-set-<hash of the content>/.
// A new set is staged whole in a staging folder of DIR, renamed to its name, and only then is
// config.ocio replaced, by one rename: at every moment, a SIGKILL included, DIR's config.ocio
// names a whole set, the previous one or the new one. After the rename, the sets of ours that
// config.ocio no longer names are removed: only folders named cgtmo-set-<hash> that hold our
// marker file and whose lock no other run holds.
#include <functional>
#include <map>
#include <string>

#include "cgtmo/io/temp_files.h"

namespace cgtmo::bake {

class StagedSet {
 public:
  // The marker file in every set: the clean-up removes no folder without it.
  static constexpr const char* kMarker = ".cgtmo-set";
  // Folders a staged path may nest (the staging folder and the set take two of the levels the
  // signal handler's clean-up reaches).
  static constexpr int kMaxDepth = io::kMaxStagingDepth - 2;

  // Stages into a new staging folder of `out_dir` (an existing folder), after removing the
  // staging folders that killed runs left there. `note` gets messages ("removed 1 earlier set").
  explicit StagedSet(const std::string& out_dir, std::function<void(const std::string&)> note = {});
  StagedSet(const StagedSet&) = delete;
  StagedSet& operator=(const StagedSet&) = delete;
  ~StagedSet();  // removes what was not committed

  // Stages `content` as <set>/<relative>: a relative path without "." or "..", at most kMaxDepth
  // folders deep. Throws DataError.
  void stage(const std::string& relative, const std::string& content);
  // Where the set lies while staged (to check the config against it before the commit).
  std::string staged_path() const;
  // The set's name from what was staged: "cgtmo-set-<16 hex>". An identical set of that name
  // already in DIR is reused; a different folder of that name (edited by hand) makes it
  // "cgtmo-set-<hash>-<8 hex>". Call after the last stage().
  const std::string& settle_name();
  // Renames the set into place, then `config_text` to DIR/config.ocio; then removes the sets
  // of ours that config.ocio no longer names. Termination signals wait until it is done.
  void commit(const std::string& config_text);

  // Whether a file name is one a set of ours may have.
  static bool is_set_name(const std::string& name);

 private:
  void place_set();
  void remove_unnamed_sets();

  std::string out_dir_;
  std::function<void(const std::string&)> note_;
  io::StagingFolder staging_;
  std::map<std::string, std::pair<std::uint64_t, std::uint64_t>> staged_;  // relative -> size, content hash
  std::string name_;
  bool reuse_ = false;  // an identical set of that name is already in place
  int set_lock_fd_ = -1;
};

}  // namespace cgtmo::bake
