#pragma once
// LUT file writers (.spi1d, .spi3d, Resolve/Iridas .cube, CLF) and staged (atomic) output:
// every file is written to a temporary beside its destination and renamed only when all of a
// run's files were written, so an error leaves existing outputs untouched.
#include <string>
#include <utility>
#include <vector>

#include "cgtmo/bake/lut.h"

namespace cgtmo::bake {

// `header` lines are written as '#' comments where the format allows one.
std::string spi1d_text(const BakedLut& lut, const std::string& header);
std::string spi3d_text(const BakedLut& lut, const std::string& header);

// A LUT design's file for the config: .spi1d, .spi3d, or (hue_steps) a CTF of the whole chain
// written by OpenColorIO.
std::string lut_file_text(const BakedLut& lut, const std::string& header);

// A .cube of a whole view for applications outside OCIO (Resolve, Nuke's Vectorfield, ...).
// Its input is kShaperSpace-encoded (the format cannot hold a log shaper: a .cube 1D "shaper" is
// indexed linearly, which would leave a handful of nodes below 1.0), its output display-encoded.
// `view` maps scene-linear to display-encoded values. 1D when `per_channel`; else a Resolve 1D
// shaper section (kShaperSpace -> `grid_shaper`, 4096 entries) followed by a 3D LUT of `size`
// whose nodes are uniform in `grid_shaper`.
std::string cube_text(const OCIO::ConstCPUProcessorRcPtr& view, bool per_channel, int size, const Log2Shaper& grid_shaper,
                      const std::string& header);

// The CLF (Academy/ASC Common LUT Format) of a processor, written by OCIO itself.
std::string clf_text(const OCIO::ConstProcessorRcPtr& view, const std::string& description);

// Files written to temporaries, then renamed together by commit().
class StagedFiles {
 public:
  StagedFiles() = default;
  StagedFiles(const StagedFiles&) = delete;
  StagedFiles& operator=(const StagedFiles&) = delete;
  ~StagedFiles();  // removes temporaries that were not committed

  // Writes `content` to <folder of path>/.cgtmo-staging-<pid>/<file name>. Throws UsageError if
  // the folder is missing or not writable. Returns the staged file's path (valid until commit).
  std::string stage(const std::string& path, const std::string& content);
  // The staging folder for files destined to `dir` (created on first use).
  std::string staging_folder(const std::string& dir);
  void commit();

 private:
  std::vector<std::pair<std::string, std::string>> files_;  // staged, destination
  std::vector<std::string> folders_;                         // staging folders
};

// Throws UsageError unless `dir` is an existing, writable folder.
void check_output_folder(const std::string& dir, const std::string& what);

}  // namespace cgtmo::bake
