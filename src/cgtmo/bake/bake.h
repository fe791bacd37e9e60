#pragma once
// `cgtmo bake`: every registry operator -> LUT files, exports, the OCIO config, the accuracy
// report and a manifest, all staged and renamed together (an error leaves old outputs as they were).
#include <optional>
#include <string>
#include <vector>

#include "cgtmo/bake/audit.h"
#include "cgtmo/bake/choose.h"

namespace cgtmo::bake {

struct BakeOptions {
  // Named by the caller, never a default: a bake run in a checkout must not overwrite its shipped
  // set unasked (the shipped set is regenerated with --out-luts luts --out-config ocio_config).
  std::string luts_dir;
  std::string config_dir;
  std::string report_path;                // empty: no report
  std::optional<double> max_error_cv;     // strict budget for every operator; unset: the targets
  std::string command_line;               // written into every generated file's header
  Progress progress;
};

struct OperatorBake {
  BakeSubject subject;
  Choice choice;
  double budget_cv = 0;
  std::string lut_file, cube_file, clf_file;  // file names inside luts_dir
  std::size_t lut_bytes = 0, cube_bytes = 0, clf_bytes = 0;
  int cube_dims = 1;          // 1: a 1D .cube; 3: 1D shaper section + 3D
  std::string cube_design, clf_design;  // for the report
  AuditResult shipped;       // through the written config's sRGB view
  AuditResult cube, clf;     // OCIO reading the exports back
  double ocio_mpix = 0;      // the shipped view, one thread
};

struct BakeResult {
  std::vector<OperatorBake> ops;
  std::vector<std::string> missed;  // operators whose best LUT misses its target (targets mode)
};

// Throws UsageError (missing or unwritable folder) or DataError (an operator cannot meet
// --max-error at any size: named, nothing written).
BakeResult bake_all(const BakeOptions& options);

// Sizes of the 3D LUT in .cube and CLF exports, each tried with uniform then node-warped nodes
// (the cheapest that meets the operator's target, else the most accurate). 41^3 keeps a .cube
// at 1.7 MB and a CLF under 2 MB.
inline constexpr int kExport3DSizes[] = {25, 33, 41};
inline constexpr int kExport1DSizes[] = {4096, 8192, 16384};  // .cube of per-channel curves: first that meets

// The audit's encoded processor for an exported file read back through OCIO.
OCIO::ConstCPUProcessorRcPtr export_processor(const std::string& path, bool cube, bool per_channel);

// `cgtmo bake --scene`: the drago operator with a render's statistics, as a LUT in luts_dir and a
// look + view added to a copy of <config_dir>/config.ocio named <config_dir>/<name>.ocio.
struct SceneBakeResult {
  std::string lut_path, config_path, look_name;
  operators::ImageStats stats;
  BakeSubject subject;
  AuditResult audit;
};
SceneBakeResult bake_scene(const std::string& render, const std::string& name, const BakeOptions& options);

}  // namespace cgtmo::bake
