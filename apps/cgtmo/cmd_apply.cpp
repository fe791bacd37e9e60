// cgtmo apply: read a render, tone-map it with one registry operator, display-encode, write.
#include <algorithm>
#include <chrono>
#include <cstdlib>
#include <filesystem>
#include <iostream>
#include <map>

#include "cgtmo/color/input_space.h"
#include "cgtmo/errors.h"
#include "cgtmo/filters/filter_table.h"
#include "cgtmo/io/chromaticities.h"
#include "cgtmo/io/temp_files.h"
#include "cgtmo/pipeline/apply_file.h"
#include "cgtmo/util/parallel.h"
#include "cgtmo/local/scene_operators.h"
#include "cgtmo/operators/registry.h"
#include "cmd_apply_scene.h"
#include "apply_sequence.h"
#include "cgtmo/sequence/frame_pattern.h"
#include "cgtmo/local/apply_scene.h"
#include "cgtmo/display/display.h"
#include "cgtmo/display/encode.h"
#include "cgtmo/pipeline/request.h"
#include "cli_util.h"
#include "apply_json.h"
#include "cgtmo/io/image_io.h"
#include "commands.h"
#include "stage_progress.h"

namespace cgtmo::cli {

namespace {

const char* kSynopsis = R"(NAME
    cgtmo apply - tone-map an OpenEXR render with one operator and write a display-ready image

SYNOPSIS
    cgtmo apply IN -o OUT [--op NAME] [-p key=value]... [--exposure EV] [--layer NAME]
                [--colorspace NAME] [--colorconfig FILE] [--display NAME] [--view NAME]
                [--no-display] [--threads N] [--max-memory MB] [--bit-depth 8|16|half|float]
                [--compression NAME] [--allow-double] [--json] [--window display|data]
                [--exr-view NAME] [--pass ROLE=LAYER]... [--probe FILE] [--sidecar FILE]
)";

// After the options: what a reader looks up once the synopsis and examples did not answer.
const char* kProse = R"(
DESCRIPTION
    IN is an OpenEXR file: plain R,G,B(,A) channels, or a Blender multilayer EXR, where the
    beauty is taken from <ViewLayer>.Combined (or from the layer --layer names). Only the beauty
    channels are read. Non-finite and out-of-range input follows one policy, reported as a
    warning: NaN and -Inf become 0, negatives 0, +Inf and values above 65504 become 65504.
    An input that is not a regular file (a FIFO, a device) is refused, and so is one whose
    header declares more pixels than --max-memory holds as float32 (default: half of the RAM
    or of the cgroup memory limit) or than its size in bytes could hold.

    Input colour space: cgtmo works in linear Rec.709 (D65), and converts the input into it once,
    right after reading (the beauty, and for scene operators the light groups, albedo and probe;
    never position, normal or depth). The input's space is --colorspace NAME, any colour space
    (or role) of the OCIO config in use; else the file's OpenEXR chromaticities attribute (an
    RGB->XYZ matrix from its primaries, Bradford-adapted to D65); else the config's scene_linear
    role; else linear Rec.709. When NAME and the attribute disagree, NAME is used and a warning
    names both. An unknown NAME is a usage error that lists some of the config's spaces.

    The exposure (in stops) multiplies the input first; then the operator maps it to
    display-linear [0, 1]; then OpenColorIO encodes it for the display (default: the sRGB
    display's Standard view, i.e. the sRGB transfer function). The OCIO config is --colorconfig,
    else $OCIO, else a built-in one with sRGB, Rec.1886 and Display P3 displays.

    OUT is chosen by extension: .png and .jpg (8 bit), .tif (16 bit), .exr (float, zip); or
    --bit-depth: 8 or 16 for .png, 8, 16 or float for .tif, half or float for .exr, and
    --compression for .exr (none, rle, zips, zip, piz, pxr24, b44, b44a, dwaa, dwab; dwaa and
    dwab are lossy DCT codecs whose decoded values ring past [0, 1] at edges, so they are refused
    for a display-encoded EXR and take --no-display, whose linear values may decode past 1 too;
    pxr24 and b44 are lossy within [0, 1]). It is
    written to a temporary file in the same folder and renamed, so an existing OUT is replaced
    only by a complete image; a temporary that a killed run left is removed by the next run
    writing OUT. Alpha passes through (not to JPEG).

    Colour tags: a display-encoded .png, .tif or .jpg embeds an ICC profile of the display
    encoded (primaries, white and curve, read off the OCIO colour space of the view: sRGB,
    Display P3, Rec.1886's 2.4 gamma...); when that colour space is not a matrix and an sRGB or
    power-law curve, no profile is written and one warning says so. With --no-display, .exr gets
    the chromaticities of linear Rec.709 (D65) and other formats a linear Rec.709 profile.
    The input's descriptive attributes (Software, DateTime, Artist, Exif, camera matrices...)
    are carried to OUT where its format can hold them; its channels, windows, compression and
    colour tags are not (docs/outputs.md).

    A view of the config that applies a cgtmo operator itself (views named after an operator,
    as in ocio_config/) after --op would tone-map twice: refused unless --allow-double.

    --json prints, instead of the 'wrote' line, one JSON object: input, output, size, operator
    and resolved parameters, exposure, layer, display/view/config, format, colour tag, metadata
    carried, sanitised counts, stage timings, and for cgtmo/wls the scene statistics and guide
    decisions. For a sequence, at the end: the patterns, operator, parameters, how many frames
    ran at once and why, the done/skipped/failed counts and each frame's input, output, status,
    time or error (not with --dry-run or --list-frames).

    Sequences: when IN holds a frame token (#### or @@@@: one digit each; %04d), every frame
    of --frames (default: every matching input on disk) is tone-mapped to OUT's pattern,
    several frames at a time within --threads and --max-memory. Every output records what made
    it (operator, parameters, exposure, colour management, version, and the size and time of
    each file read; 'cgtmo info OUT' shows it). A frame whose output records exactly what this
    run would write is skipped (--force redoes it), so an interrupted run resumes where it
    stopped and a run with other settings or re-rendered inputs redoes what changed. --dry-run
    prints todo (and what changed), skip or missing per frame. Ctrl-C, SIGTERM or SIGHUP
    finishes the frames in flight and leaves no partial file. A failing frame is reported and
    the others go on (--fail-fast stops); the run ends with a summary and exits 1 if any frame
    failed, 130 if interrupted. Progress: a bar with the current frame's stage on a terminal,
    else a line per frame and per stage on stdout.

    OpenEXR layouts (docs/exr-inputs.md): the image is the beauty's display window (--window
    data: its data window, overscan included); every pass is placed by its part's data window,
    and pixels a part does not store read as 0 (depth: background). Multi-part files, passes in
    parts of other sizes, luminance/chroma (Y, RY, BY) files and multi-view files (--exr-view;
    default the first view) are read; deep files are refused.

    Scene operators: --op cgtmo (CG-TMO; -p filter=@FILTER_CHOICES@) and --op wls
    are local: they also read the G-buffer and light-group passes of IN, the sidecar (--sidecar,
    else NAME.json beside IN) and the probe (--probe, else NAME.probe.exr beside IN, else the
    file the sidecar's probe.file names); a missing one, or a sidecar that is JSON of another
    kind, is a warning and the statistics fall back to the image.
    --pass ROLE=LAYER points a role (position, normal, albedo, emission, depth,
    lightgroup:NAME) at a layer the automatic mapping does not know. --explain prints their
    statistics and guide decisions (docs/cgtmo.md). For them --exposure scales the whole scene:
    the beauty, the light groups, the sidecar's light luminances and the probe, so Lw_max and
    Lw_a scale with it (values given with -p lw_max=, lw_a= are used as given).
    With cgtmo, -p detail=illumination tone-maps beauty / albedo and multiplies the albedo back
    (Monte Carlo noise is compressed as lighting). With either, -p output=scene-linear
    compresses the base layer's range around Lw_a, its top to -p stops= above scene-linear 0.18
    (default 6), its shadows into -p shadows= stops under Lw_a (default 3.5), and writes
    scene-linear values for a display transform to finish: --no-display to an EXR, or --colorconfig/--view (Filmic, AgX) to apply
    it here (a view that clips is warned about). Their base-layer filters:
@FILTER_TABLE@

    'cgtmo list' shows every operator and its parameters.
)";

const char* kExamples = R"(
EXAMPLES
    Tone-map a Blender render with the ACES fit and write an sRGB PNG:
        cgtmo apply render.exr -o render.png --op aces-narkowicz

    Drago with a brighter bias, one stop up, for a Display P3 monitor:
        cgtmo apply render.exr -o p3.png --op drago -p b=0.75 --exposure 1 --display "Display P3"

    The operator's linear output, for checking values (no display encoding):
        cgtmo apply render.exr -o linear.exr --op reinhard --no-display

    A shot, frames 1001 to 1240, resumable, with a progress bar on a terminal:
        cgtmo apply 'renders/shot.####.exr' -o 'out/shot.####.png' --frames 1001-1240 --op agx

    A 16-bit Display P3 PNG (tagged with its ICC profile), and what was done as JSON:
        cgtmo apply render.exr -o p3.png --op agx --display "Display P3" --bit-depth 16 --json

    Half-float linear EXR with DWAA compression (tagged linear Rec.709):
        cgtmo apply render.exr -o lin.exr --op agx --no-display --bit-depth half --compression dwaa

    An ACEScg render whose header lacks the chromaticities attribute, with the shipped config:
        cgtmo apply acescg.exr -o out.png --colorconfig ocio_config/config.ocio --colorspace ACEScg

    A light-group pass of a multilayer file instead of the beauty:
        cgtmo apply render.exr -o key.png --layer ViewLayer.Combined_key
)";

// The prose of the help with the filter table filled in (filters/filter_table.h).
std::string prose() {
  std::string d = kProse;
  auto fill = [&d](const std::string& key, const std::string& value) { d.replace(d.find(key), key.size(), value); };
  fill("@FILTER_CHOICES@", filters::join_names(filters::offered_filters("cgtmo"), "|"));
  std::string table;
  for (const auto& f : filters::filter_table()) {
    std::string name = f.name;
    name.resize(std::max<std::size_t>(name.size(), 10), ' ');
    table += "        " + name + " " + f.description + "\n";
  }
  table.pop_back();
  fill("@FILTER_TABLE@", table);
  return d;
}

std::map<std::string, std::string> parse_params(const std::vector<std::string>& kv) {
  std::map<std::string, std::string> out;
  for (const auto& s : kv) {
    const auto eq = s.find('=');
    if (eq == std::string::npos || eq == 0) throw UsageError("parameter '" + s + "' is not key=value");
    out[s.substr(0, eq)] = s.substr(eq + 1);
  }
  return out;
}

// The input colour space for the provenance record, as resolved for `in` (a usage error for an
// unknown name comes first). For a sequence (`in` empty) the rule, as the attribute may vary.
std::string input_space_record(const std::string& config_path, const std::string& name, const std::string& in) {
  std::string origin;
  const auto config = color::config_for_input(config_path, name, &origin);
  if (!name.empty()) color::check_colorspace_name(config, name, origin);
  color::FileColour file;
  if (!in.empty() && name.empty()) {
    try {
      file = io::read_file_colour(in);
    } catch (const DataError&) {
      // Unreadable: reading it fails next, with the reader's message.
    }
  }
  const std::string resolved = color::InputSpace::resolve(config, name, file).description();
  if (in.empty() && name.empty()) return "chromaticities attribute, else " + resolved;
  return resolved;
}

}  // namespace

int run_apply(const std::vector<std::string>& args) {
  // Synopsis and examples first, then the options, then the prose (as a man page reads).
  CLI::App app{std::string(kSynopsis) + kExamples, "apply"};
  style(app);
  app.footer(prose());
  std::string in, out, op = "drago", layer, config, display_name, view_name, colorspace;
  std::vector<std::string> params;
  double exposure = 0.0;
  bool no_display = false, quiet = false;
  int threads = 0;
  app.add_option("IN", in, "input OpenEXR render")->required();
  app.add_option("-o,--output", out, "output image (.png, .tif, .jpg, .exr)")->required();
  app.add_option("--op", op, "operator name (see 'cgtmo list')")->capture_default_str();
  app.add_option("-p,--param", params, "operator parameter key=value (repeatable)");
  app.add_option("--exposure", exposure, "exposure in stops (EV), applied before the operator")
      ->capture_default_str()
      ->check(finite_range(-pipeline::kMaxExposureStops, pipeline::kMaxExposureStops));
  app.add_option("--layer", layer, "beauty layer prefix, e.g. ViewLayer or ViewLayer.Combined_key");
  app.add_option("--colorspace", colorspace,
                 "input colour space, a space of the OCIO config (default: the file's chromaticities, else scene_linear)");
  app.add_option("--colorconfig", config, "OCIO config (default: $OCIO, else built-in)");
  app.add_option("--display", display_name, "OCIO display (default: the config's default)");
  app.add_option("--view", view_name, "OCIO view (default: Standard, else the display's default)");
  app.add_flag("--no-display", no_display, "write the operator's linear output, no display encoding");
  app.add_option("--threads", threads, "worker threads (0: the CPUs this process is allotted: affinity, cgroup quota, SLURM_CPUS_PER_TASK)")->capture_default_str()->check(CLI::Range(0, kMaxThreads));
  app.add_flag("-q,--quiet", quiet, "print nothing but errors and warnings");
  io::OutputFormat format;
  bool allow_double = false, json = false;
  app.add_option("--bit-depth", format.bit_depth, "8 or 16 (png), 8 (jpg), 8, 16 or float (tif), half or float (exr); default 8, 8, 16, float");
  app.add_option("--compression", format.compression, "EXR compression: none, rle, zips, zip (default), piz, pxr24, b44, b44a, dwaa, dwab (dwaa and dwab: --no-display only, their decoded values leave [0, 1])");
  app.add_flag("--allow-double", allow_double, "allow --op before a view that applies an operator itself (two tone curves)");
  app.add_flag("--json", json, "print what was done as one JSON object on stdout (for a sequence: the run and each frame)");
  bool explain = false;
  // How IN is read (docs/exr-inputs.md), and the scene operators' companions.
  io::ReadOptions read;
  std::string window = "display", probe, sidecar;
  std::vector<std::string> pass_args;
  app.add_option("--window", window, "display: the display window (default; a pass outside its data window reads 0, depth background); data: the beauty's data window")
      ->capture_default_str();
  app.add_option("--exr-view", read.view, "multi-view (stereo) EXR: the view to read (default: the file's first view)");
  app.add_option("--pass", pass_args, "cgtmo, wls: ROLE=LAYER, the layer for a role (position, normal, albedo, emission, depth, lightgroup:NAME); repeatable");
  app.add_option("--probe", probe, "cgtmo, wls: adaptation probe (default: IN.probe.exr); missing: a warning, Lw_a from the image");
  app.add_option("--sidecar", sidecar, "cgtmo, wls: JSON sidecar (default: IN.json); missing or of another kind: a warning, Lw_max from the passes or the image");
  app.add_flag("--explain", explain, "cgtmo, wls: print the scene statistics and what the guide used or dropped, and why");
  SequenceOptions seq;
  add_max_memory_option(app, seq.max_memory_mb, "; a sequence runs as many frames at once as it holds");
  auto* g = app.add_option_group("Sequences", "IN and OUT with a frame token (####, @@@@, %04d)");
  g->add_option("--frames", seq.frames, "frames to do: 1-240, 1-240x2, 1-10,20,30-40 (default: every IN found)");
  g->add_flag("--force", seq.force, "redo frames whose output records the same settings and inputs");
  g->add_flag("--fail-fast", seq.fail_fast, "stop at the first failing frame");
  g->add_flag("--dry-run", seq.dry_run, "print 'todo' (and what changed), 'skip' or 'missing' for each frame; change nothing");
  g->add_flag("--list-frames", seq.list_frames, "print the frame numbers a run would do and exit; refused as the run would be");
  g->add_option("--temporal", seq.temporal,
                "hold image/scene statistics steady: Gaussian sigma in frames (0: per-frame statistics)")
      ->capture_default_str()
      ->check(finite_range(0.0, 1000.0));
  if (!parse(app, args)) return 0;
  apply_max_memory(seq.max_memory_mb);
  read.window = io::parse_window(window);
  for (const auto& p : pass_args) read.passes.push_back(scene::parse_pass_override(p));
  // One registry: the operator's scope chooses the pipeline (scene operators read the passes).
  const operators::OperatorDef& def = operators::find_operator(op);
  const bool scene_op = def.scope == operators::Scope::Scene;
  if ((!probe.empty() || !sidecar.empty()) && !scene_op)
    throw UsageError("--probe and --sidecar are read by the scene operators (cgtmo, wls) only, not by '" + op + "'");
  const bool sequence_mode = sequence::FramePattern::is_pattern(in) || !seq.frames.empty();
  // The library's check, before anything is read; the message starts with the option it is about.
  with_option("--no-display", [&] { display::check_display_choice(!no_display, display_name, view_name); });
  io::check_output_format(out, format, !no_display);
  if (json && (seq.dry_run || seq.list_frames))
    throw UsageError(std::string("--json cannot be combined with ") + (seq.dry_run ? "--dry-run" : "--list-frames") +
                     ", which print their own lines");
  if (json) quiet = true;  // stdout holds the JSON object alone
  // The request as both pipelines take it (pipeline::ApplyOptions, local::SceneApplyOptions).
  const auto given = parse_params(params);
  auto fill_request = [&](auto& o) {
    o.op = op;
    o.params = given;
    o.exposure_ev = exposure;
    o.layer = layer;
    o.encode_display = !no_display;
    o.colorconfig = config;
    o.display = display_name;
    o.view = view_name;
    o.output = format;
    o.colorspace = colorspace;
    o.read = read;
  };
  // What every output records about how it was made (sequence/provenance.h): the request with the
  // display and view resolved, so spelling out a default does not count as a change.
  sequence::ProvenanceRequest record;
  record.op = op;
  record.params = given;
  record.exposure_ev = exposure;
  record.layer = layer;
  record.encode_display = !no_display;
  record.bit_depth = format.bit_depth;
  record.compression = format.compression;
  record.colorspace = input_space_record(config, colorspace, sequence_mode ? std::string() : in);
  record.read = read;
  if (!no_display) {
    // By absolute path: a farm script that makes paths absolute must not count as a change.
    record.config = !config.empty() ? config : std::getenv("OCIO") ? std::string(std::getenv("OCIO")) : std::string();
    std::error_code ec;
    if (!record.config.empty()) {
      const auto absolute = std::filesystem::weakly_canonical(record.config, ec);
      if (!ec) record.config = absolute.string();
    }
    // The encoder the pipeline will build, by the same call (pipeline/request.h).
    const pipeline::ColourSetup colour = pipeline::setup_colour(true, config, colorspace, display_name, view_name);
    const display::DisplayEncoder& enc = *colour.encoder;
    record.display = enc.display();
    record.view = enc.view();
    // output=scene-linear is made for a tone-mapping view to finish: not a second tone map.
    const auto output_param = std::find_if(given.begin(), given.end(), [](const auto& kv) { return kv.first == "output"; });
    const bool scene_linear_output = output_param != given.end() && output_param->second == "scene-linear";
    const std::string twice = enc.view_operator();
    if (!twice.empty() && twice != "linear" && op != "linear" && !scene_linear_output && !allow_double)
      throw UsageError("view '" + enc.view() + "' applies operator '" + twice + "' itself: --op " + op +
                       " before it tone-maps twice (choose the Standard view, or --allow-double)");
    if (scene_linear_output) {
      // The highlights are left for the view to roll off: a view that clips scene-linear 4 (a
      // little over 4 stops above the grey) burns them.
      float probe_px[3] = {4.f, 4.f, 4.f};
      enc.apply(probe_px, 1, 1, 3);
      if (!(probe_px[1] < 0.999f))
        std::cerr << "cgtmo apply: warning: -p output=scene-linear through view '" << enc.view()
                  << "', which clips scene-linear 4.0: the highlights burn; choose a view that rolls them off "
                     "(Filmic, AgX) or --no-display for an EXR\n";
    }
    std::string ext = std::filesystem::path(out).extension().string();
    for (auto& c : ext) c = char(std::tolower(static_cast<unsigned char>(c)));
    if (ext != ".exr" && !enc.profile().known)
      std::cerr << "cgtmo apply: warning: no colour profile written for " << enc.display() << "/" << enc.view() << ": "
                << enc.profile().why << "\n";
  }
  if (sequence_mode) {
    if (!probe.empty() || !sidecar.empty())
      throw UsageError("--probe and --sidecar name one file: not for a sequence (each frame reads NAME.probe.exr and NAME.json beside it)");
    set_threads(threads);
    seq.in_pattern = in;
    seq.out_pattern = out;
    seq.quiet = quiet;
    seq.json = json;
    seq.threads = threads;
    seq.reads_companions = scene_op;
    auto plan = sequence::plan_statistics(op, given, exposure, layer);
    plan.colorspace = colorspace;
    plan.colorconfig = config;
    plan.read = read;
    if (!plan.smoothed_params.empty()) record.temporal_sigma = seq.temporal;
    seq.provenance = record;
    if (scene_op) {
      local::SceneApplyOptions so;
      fill_request(so);
      // The request is validated before any frame is touched.
      local::options_from(def, operators::resolve_params(def, given, nullptr));
      prefer_mapped_frame_buffers();
      return run_apply_sequence([&](const sequence::FrameJob& j, const std::map<std::string, std::string>& overrides,
                                    const pipeline::FileHooks& hooks) {
        local::SceneApplyOptions f = so;
        for (const auto& [k, v] : overrides) f.params[k] = v;
        local::apply_scene_file(f, j.input, j.output, hooks);  // warnings: hooks.warn, grouped over frames
      }, plan, seq);
    }
    pipeline::ApplyOptions po;
    fill_request(po);
    const pipeline::Applier fixed(po);  // validates the request before any frame is touched
    return run_apply_sequence([&](const sequence::FrameJob& j, const std::map<std::string, std::string>& overrides,
                                  const pipeline::FileHooks& hooks) {
      // Warnings go to hooks.warn, grouped over the frames.
      if (overrides.empty()) {
        fixed.apply_file(j.input, j.output, hooks);
      } else {
        pipeline::ApplyOptions f = po;
        for (const auto& [k, v] : overrides) f.params[k] = v;
        pipeline::Applier(f).apply_file(j.input, j.output, hooks);
      }
    }, plan, seq);
  }
  // One file: a killed run's temporary of OUT (named only between link and rename) goes now, and
  // an interrupted one leaves none.
  io::remove_temps_on_termination_signals();
  const io::RemovedLeftovers stale = io::remove_stale_temps({out});
  if (stale.total() && !quiet) std::cerr << "cgtmo apply: " << stale.describe("temporary file") << "\n";
  // Scene operators are not per-pixel: they read passes, probe and sidecar (cmd_apply_scene.cpp).
  StageProgress progress("cgtmo apply", quiet);
  StageTimer timer;
  pipeline::FileHooks hooks;
  hooks.on_stage = [&timer, cb = progress.callback()](const Stage& s) {
    timer.mark(s);
    if (cb) cb(s);
  };
  if (scene_op) {
    set_threads(threads);
    hooks.description = sequence::make_provenance(record, files_read_by(in, true, probe, sidecar)).text();
    SceneApplyArgs sa{in, out, op, layer, config, display_name, view_name, parse_params(params), exposure, no_display, quiet, explain,
                      format, json ? &timer : nullptr, colorspace, probe, sidecar, read};
    return run_apply_scene(sa, hooks);
  }

  // The pipeline (validate -> read -> sanitise -> tone-map -> encode -> atomic write) is one
  // library call shared with the Python module: no output is created on error.
  const auto t0 = std::chrono::steady_clock::now();
  set_threads(threads);
  pipeline::ApplyOptions opts;
  fill_request(opts);
  opts.warn = [&in](const std::string& msg) { std::cerr << "cgtmo apply: warning: " << in << ": " << msg << "\n"; };
  const pipeline::Applier applier(opts);
  hooks.description = sequence::make_provenance(record, files_read_by(in, false)).text();
  const pipeline::ApplyReport rep = applier.apply_file(in, out, hooks);
  progress.finish();
  const auto& result = rep.tonemap;
  if (json) {
    nlohmann::json j = apply_json({in, out, op, exposure, format}, rep);
    j["timings_ms"] = timer.durations();
    std::cout << json_text(j) << "\n";  // never throws: any file name is written (util/text.h)
    return 0;
  }

  if (!quiet) {
    const double ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
    std::cout << "wrote " << out << " (" << rep.width << "x" << rep.height << ", " << op;
    for (const auto& [k, v] : result.params.numbers()) std::cout << " " << k << "=" << v;
    for (const auto& [k, v] : result.params.texts()) std::cout << " " << k << "=" << (v.empty() ? "\"\"" : v);
    std::cout << ", layer " << (rep.layer.empty() ? "R,G,B" : rep.layer);
    if (!rep.display.empty()) std::cout << ", " << rep.display << "/" << rep.view << " via " << rep.config_origin;
    else std::cout << ", linear";
    std::cout << ", " << int(ms + 0.5) << " ms)\n";
  }
  return 0;
}

}  // namespace cgtmo::cli
