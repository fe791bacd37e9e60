#pragma once
// What made an output: the request (operator, the parameters given, exposure, layer, colour
// management, temporal smoothing, cgtmo's version) and the identity of every file the frame read
// (name, size, modification time). cgtmo records it in each output's ImageDescription; a resumed
// sequence redoes a frame whose record is missing or differs from what the run would write now.
#include <map>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "cgtmo/io/read_options.h"
#include "cgtmo/sequence/batch.h"

namespace cgtmo::sequence {

struct ProvenanceRequest {
  std::string op;
  std::map<std::string, std::string> params;  // as given (-p); defaults belong to the version
  double exposure_ev = 0.0;
  std::string layer;
  bool encode_display = true;
  std::string config;          // the OCIO config file in use; "" = the built-in one
  std::string display, view;   // as resolved (the config's defaults filled in); "" when not encoded
  double temporal_sigma = 0.0; // frames; 0 when no statistic is smoothed over time
  std::string bit_depth, compression;  // as given; "" = the format's default (then not recorded)
  // The input colour space as resolved (color::InputSpace::description): an OCIO colour space,
  // the file's chromaticities attribute, the config's scene_linear role or linear Rec.709.
  std::string colorspace;
  io::ReadOptions read;        // recorded only where it differs from the default
};

// Ordered key=value fields.
struct Provenance {
  std::vector<std::pair<std::string, std::string>> fields;

  // "cgtmo provenance 1; key=value; key=value; ..." with '%', ';', '=' and control characters of
  // keys and values percent-encoded, so any path or parameter value survives the round trip.
  std::string text() const;
  // nullopt when `text` is not a cgtmo record (another tool's description, an older format).
  static std::optional<Provenance> parse(const std::string& text);
};

// The record of one frame. `files_read`: the beauty, and for scene operators the probe and the
// sidecar (an absent file is recorded as absent, so adding it later redoes the frame).
Provenance make_provenance(const ProvenanceRequest& request, const std::vector<std::string>& files_read);

// "" when equal; else what differs, e.g. "op agx -> drago, exposure 0 -> 2" (at most three fields
// named, then "and N more").
std::string provenance_difference(const Provenance& recorded, const Provenance& wanted);

// "NAME, SIZE bytes, modified YYYY-MM-DDTHH:MM:SS.NNNNNNNNNZ" or "NAME absent" (NAME: the file name).
std::string file_identity(const std::string& path);

enum class FrameState {
  Missing,   // the input does not exist: the frame cannot be done
  Todo,      // no output yet
  Stale,     // an output exists, but made otherwise (or not by cgtmo): `reason` says how
  UpToDate,  // the output's record equals `wanted`
};
const char* state_name(FrameState s);  // "missing", "todo", "stale", "skip"

struct FrameCheck {
  FrameState state = FrameState::Todo;
  std::string reason;  // for Stale
};

// Reads only the output's header.
FrameCheck check_frame(const FrameJob& job, const Provenance& wanted);

}  // namespace cgtmo::sequence
