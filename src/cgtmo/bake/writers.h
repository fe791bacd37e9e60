#pragma once
// LUT file writers (.spi1d, .spi3d, Resolve/Iridas .cube, CLF) and staged (atomic) output:
// every file is written to a temporary beside its destination and renamed only when all of a
// run's files were written, so an error leaves existing outputs untouched.
#include <functional>
#include <string>
#include <utility>
#include <vector>

#include "cgtmo/bake/lut.h"
#include "cgtmo/io/temp_files.h"

namespace cgtmo::bake {

// `header` lines are written as '#' comments where the format allows one.
std::string spi1d_text(const BakedLut& lut, const std::string& header);
std::string spi3d_text(const BakedLut& lut, const std::string& header);

// A LUT design's file for the config: .spi1d, .spi3d, or (hue_steps) a CTF of the whole chain
// written by OpenColorIO.
std::string lut_file_text(const BakedLut& lut, const std::string& header);

// .cube files of a whole view for applications outside OCIO (Resolve, Nuke's Vectorfield, ...).
// Their input is kShaperSpace-encoded (the format cannot hold a log shaper: a .cube 1D section is
// indexed linearly, which would leave a handful of nodes below 1.0), their output display-encoded.
// 1D: `size` entries of `view` (scene-linear -> display-encoded), per-channel operators.
std::string cube_1d_text(const OCIO::ConstCPUProcessorRcPtr& view, int size, const std::string& header);
// 1D section + 3D section (Resolve's layout; OCIO 2.1 applies the 1D section, then the 3D LUT):
// the 1D section (kCubeShaperSize entries) maps kShaperSpace to the grid coordinate of `rep`'s 3D
// LUT per channel (its shaper, then its node warp when rep.warped); the 3D section holds
// `unclamped` (the operator without its final clamp) at the grid's nodes, sRGB-encoded with the
// encoding extended beyond [0, 1]: values outside [0, 1] are for the reader to clip (a display
// does), as the view's clamp would.
inline constexpr int kCubeShaperSize = 4096;
std::string cube_3d_text(const Representation& rep, const std::vector<float>& warp, const operators::Evaluator& unclamped,
                         const std::string& header);

// The CLF (Academy/ASC Common LUT Format) of a processor, written by OCIO itself; `compact`:
// lines of numbers alone rewritten with 6 significant digits (a third smaller; for 3D LUTs).
std::string clf_text(const OCIO::ConstProcessorRcPtr& view, const std::string& description, bool compact = false);

// Files written to temporaries, then renamed one by one by commit(), in the order they were
// staged: stage last the file that names the others (a config), so that it is replaced last.
// The staging folders are locked and registered as temporaries (io/temp_files.h): a killed
// run's folder is removed by the next run staging into that folder, an interrupted one's by the
// signal handler. SIGINT, SIGTERM and SIGHUP wait until the renames are done; a SIGKILL between
// two renames leaves the files renamed so far new, the others (the config among them) as they
// were, and the staging folder holding the rest. bake --into commits a whole set instead
// (staged_set.h).
class StagedFiles {
 public:
  // `note` receives messages such as "removed 1 staging folder left by an interrupted run".
  explicit StagedFiles(std::function<void(const std::string&)> note = {}) : note_(std::move(note)) {}
  StagedFiles(const StagedFiles&) = delete;
  StagedFiles& operator=(const StagedFiles&) = delete;
  ~StagedFiles();  // removes temporaries that were not committed

  // Writes `content` to <folder of path>/.cgtmo-staging-<tag>/<file name>. Throws UsageError if
  // the folder is missing, DataError if it is not writable or writing fails (disk full...).
  // Returns the staged file's path (valid until commit).
  std::string stage(const std::string& path, const std::string& content);
  // The staging folder for files destined to `dir` (created on first use).
  std::string staging_folder(const std::string& dir);
  // Renames every staged file to its destination, in the order staged; termination signals
  // wait until it is done.
  void commit();

 private:
  std::function<void(const std::string&)> note_;
  std::vector<std::pair<std::string, std::string>> files_;  // staged, destination
  std::vector<std::pair<std::string, io::StagingFolder>> folders_;  // destination folder, its staging folder
};

// Throws UsageError unless `dir` is an existing folder, DataError (with the cause) unless it is writable.
void check_output_folder(const std::string& dir, const std::string& what);

}  // namespace cgtmo::bake
