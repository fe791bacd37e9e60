#pragma once
// The whole `cgtmo apply` pipeline as one library call, so that the CLI and the Python module
// (plugins/python) produce the same pixels:
//   validate (operator, parameters, display, colour space, output path) -> read the beauty
//   -> convert to linear Rec.709 (color/input_space.h) -> sanitise -> exposure + operator -> OpenColorIO display encoding -> atomic write.
// Everything that can be checked without reading pixels is checked first: on a bad request
// nothing is read and nothing is written.
#include <functional>
#include <map>
#include <memory>
#include <string>

#include "cgtmo/color/input_space.h"
#include "cgtmo/display/display.h"
#include "cgtmo/io/image_io.h"
#include "cgtmo/io/read_options.h"
#include "cgtmo/operators/apply.h"
#include "cgtmo/pipeline/request.h"
#include "cgtmo/scene/sanitize.h"
#include "cgtmo/util/progress.h"

namespace cgtmo::pipeline {

struct ApplyOptions {
  std::string op = "drago";
  std::map<std::string, std::string> params;  // user-given key=value, validated by the registry
  double exposure_ev = 0.0;                   // stops, before the operator; |EV| <= 64
  std::string layer;                          // beauty layer prefix (io::find_beauty); "" = automatic
  bool encode_display = true;                 // false: the operator's display-linear output
  std::string colorconfig;                    // OCIO config file; "" = $OCIO, else built-in
  std::string display, view;                  // "" = the config's default display, Standard view
  io::OutputFormat output;                    // bit depth, EXR compression ("" = the format's default)
  // The input's colour space, an OCIO colour space of the config; "" = the file's chromaticities
  // attribute, else the config's scene_linear role, else linear Rec.709 (color/input_space.h).
  std::string colorspace;
  io::ReadOptions read;                       // window (display or data) and EXR view of the input
  // Called with a one-line message when the input needed the non-finite policy (scene/sanitize.h)
  // or when the named colour space disagrees with the file's chromaticities attribute.
  std::function<void(const std::string&)> warn;
};

struct ApplyReport {
  int width = 0, height = 0, channels = 0;
  std::string layer;                  // channel prefix read ("" for plain R,G,B or in-memory input)
  operators::ToneMapResult tonemap;   // resolved parameters, image statistics
  scene::SanitizeReport sanitized;    // what the non-finite policy changed
  std::string display, view;          // empty when not display-encoded
  std::string config_origin;          // which OCIO config was used, empty when not encoded
  // What the output file says about its colour: the ICC profile embedded (PNG, TIFF, JPEG), or the
  // linear Rec.709 chromaticities (EXR without display encoding). See write_options().
  std::string colour_tag;             // e.g. "ICC: Display P3 primaries, sRGB curve"; "" when none
  std::vector<std::string> metadata;  // the input's attributes carried to the output
  std::string input_space;            // the input colour space as resolved (InputSpace::description)
  std::string alpha;                  // the alpha rule's warning when it dropped the alpha, else ""
};

// The write options of one output (io::WriteOptions) for an output of `out`'s extension: the
// request's format, the display profile when the encoder knows it (PNG/TIFF/JPEG), the linear
// Rec.709 tag when there is no encoder (EXR: chromaticities; else a linear ICC profile), the
// metadata read from the input. `colour_tag` says in words what was tagged.
io::WriteOptions write_options(const std::string& out, const io::OutputFormat& format, const display::DisplayEncoder* encoder,
                               std::shared_ptr<const io::Metadata> metadata, const std::string& description,
                               std::string* colour_tag);

// What one file's run adds to a request: the text recorded as the output's ImageDescription
// (cgtmo writes its provenance record there, sequence/provenance.h), a callback as each stage
// of the file starts, and where this file's warnings go (set: instead of the request's `warn`, so
// a sequence learns which frame warned while its frames share one request).
struct FileHooks {
  std::string description;
  StageCallback on_stage;
  std::function<void(const std::string&)> warn;
};

// A validated request: operator and parameters checked, the OCIO processor built. Reusable over
// many buffers or files (a Blender animation builds it once).
class Applier {
 public:
  // Throws UsageError (unknown operator or parameter, value out of range, unknown display/view
  // or colour space).
  explicit Applier(ApplyOptions options);
  const ApplyOptions& options() const { return options_; }

  // In place over interleaved float RGB (3) or RGBA (4) pixels: convert from the colour space
  // (the named one, else the config's scene_linear role: pixels in memory carry no attribute),
  // sanitise, tone-map, encode.
  ApplyReport apply_pixels(float* px, int width, int height, int channels) const;

  // Reads `in`, applies, writes `out` atomically (.png/.jpg 8 bit, .tif 16 bit, .exr float).
  // The output path is checked before the input is read. Stages: read, tone-map, write.
  // The file's chromaticities attribute takes part in choosing its colour space.
  ApplyReport apply_file(const std::string& in, const std::string& out, const FileHooks& hooks = {}) const;

 private:
  ApplyReport process(float* px, int width, int height, int channels, const color::InputSpace& space,
                      const std::function<void(const std::string&)>& warn) const;

  ApplyOptions options_;
  ColourSetup colour_;
};

}  // namespace cgtmo::pipeline
