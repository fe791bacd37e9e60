#pragma once
// `cgtmo apply --op cgtmo|wls` as one library call (the CLI and the Python module share it):
//   validate (operator, parameters, display, output path) -> read the render with the passes the
//   operator needs, its probe and sidecar -> sanitise -> exposure -> local Drago -> OpenColorIO
//   display encoding -> atomic write.
// Nothing is read or written when the request is wrong.
#include <functional>
#include <map>
#include <string>

#include "cgtmo/local/local_drago.h"
#include "cgtmo/operators/operator.h"
#include "cgtmo/pipeline/apply_file.h"
#include "cgtmo/scene/sanitize.h"

namespace cgtmo::local {

struct SceneApplyOptions {
  std::string op = "cgtmo";
  std::map<std::string, std::string> params;  // key=value, validated against the scene operator's specs
  double exposure_ev = 0.0;                   // multiplies the beauty before the operator
  std::string layer;
  bool encode_display = true;
  std::string colorconfig, display, view;
  std::string colorspace;                     // input colour space (pipeline::ApplyOptions::colorspace)
  std::string probe_path, sidecar_path;       // "" = beside the render; missing or foreign: warned
  io::OutputFormat output;                    // bit depth, EXR compression (pipeline::ApplyOptions)
  io::ReadOptions read;                       // window (display or data) and EXR view of the input
  std::function<void(const std::string&)> warn;
};

struct SceneApplyReport {
  int width = 0, height = 0, channels = 0;
  operators::ParamValues params;
  Explain explain;
  std::vector<std::string> notes;  // what the reader found missing
  scene::SanitizeReport sanitized;
  std::string display, view, config_origin;
  std::string colour_tag;             // as pipeline::ApplyReport
  std::vector<std::string> metadata;  // the input's attributes carried to the output
  std::string input_space;  // the render's colour space as resolved
  std::string alpha;        // as pipeline::ApplyReport
};

// Throws UsageError when `options.op` is not a scene operator or a parameter is wrong.
// Stages: read, statistics, filter, encode, write.
SceneApplyReport apply_scene_file(const SceneApplyOptions& options, const std::string& in, const std::string& out,
                                  const pipeline::FileHooks& hooks = {});

}  // namespace cgtmo::local
