// cgtmo bake: the registry's operators as LUTs, exports, an OCIO config and the accuracy report;
// or, with --scene, the Drago curve of one render as a look added to a copy of the config.
#include <chrono>
#include <cmath>
#include <iomanip>
#include <iostream>
#include <sstream>

#include "cgtmo/bake/bake.h"
#include "cgtmo/bake/merge.h"
#include "cgtmo/errors.h"
#include "cgtmo/io/temp_files.h"
#include "cli_util.h"
#include "commands.h"
#include "shipped_data.h"

namespace cgtmo::cli {

namespace {

const char* kDescription = R"(NAME
    cgtmo bake - bake every operator into LUTs and an OpenColorIO config, and audit their accuracy

SYNOPSIS
    cgtmo bake --out-luts DIR --out-config DIR [--report FILE] [--max-error CV] [-q]
    cgtmo bake --scene RENDER.exr --out-luts DIR --out-config DIR [--name NAME] [--max-error CV]
    cgtmo bake --into STUDIO.ocio -o DIR [--cgtmo-config FILE] [--prefix TEXT]

DESCRIPTION
    For every operator of the registry (see 'cgtmo list'), bake chooses a LUT design, samples the
    operator into it and measures the result through OpenColorIO 2.1 against the analytic
    operator: errors in 10-bit code values after the sRGB display encoding, over every
    non-negative half-float value 0..65504 as greys and pure primaries, random colours and
    saturated hues. Per-channel operators become a 1D LUT (.spi1d) behind a log2 shaper, with
    their matrices kept as matrix transforms. Operators that mix channels: those that scale RGB
    by curve(Y) / Y (luminance mode, saturation 1) become a 1D LUT on Y between XYZ_TO_xyY and
    back (.spi1d, 3 columns); those that keep hue in toe/shoulder/desaturation steps (PBR
    Neutral) become RGB_TO_HSV with four 1D LUTs and back (.ctf); any other becomes a 3D LUT
    (tetrahedral) behind a log2 shaper, holding unclamped log2-encoded values, with a clamp after
    it: .spi3d with nodes uniform in the shaper, or, where it is cheaper for the budget, a .ctf in
    which a per-channel 1D LUT before the 3D LUT moves its nodes to where the operator curves
    (found by probing the operator). See docs/lut-accuracy.md.

    The design is the cheapest that meets the budget: 1D where allowed, then the smallest size,
    then the narrowest shaper. Without --max-error the budgets are the targets (0.1 code value
    for per-channel operators, 1 for the others); an operator that misses its target at every
    size is shipped with the cheapest LUT within 1.5x the error of the most accurate one, and
    named in a warning and in the report. With
    --max-error, the budget is strict: if any operator misses it, bake names it, writes nothing
    and exits 1.

    Outputs: DIR/<operator>.spi1d|.spi3d|.ctf (the config's LUTs), <operator>.cube (Resolve/Iridas:
    the whole sRGB view, input in the config's Log2 Shaper encoding), <operator>.clf (CLF of the
    whole sRGB view, written by OpenColorIO), manifest.json (parameters, designs, error bounds),
    the config (ocio_config/config.ocio: displays sRGB, Rec.1886, Display P3; views Standard, one
    per operator, Raw; looks per operator and exposure looks), and the report. Image-dependent
    parameters are baked for a reference scene (maximum 16, log-average 0.18). Every file is
    written to a staging folder and renamed when all are done: on error nothing changes. An
    interrupted bake (Ctrl-C, SIGTERM, SIGHUP) removes its staging folder; one a killed bake left
    is removed by the next bake writing there.

    --scene bakes the Drago operator with the render's maximum and log-average luminance into
    DIR/drago-NAME.spi1d (or the design --max-error calls for), adds a look and a view
    "drago-NAME" to a copy of the config named
    <out-config>/NAME.ocio, and prints how to use it. In a folder without config.ocio, the copy
    starts from the built-in displays (Standard, Raw) instead.

    --into merges cgtmo into a studio's config: DIR/config.ocio is STUDIO.ocio with every colour
    space, role, display, view, look, view transform and file rule kept, plus one look per
    operator ("cgtmo <op>") and, on every display whose colour space encodes linear Rec.709 as
    sRGB, Rec.1886 (2.4 gamma) or Display P3 within one 10-bit code value, one view per operator
    of the same name. A look converts the studio's scene_linear to linear Rec.709 (a
    ColorSpaceTransform to the studio's own linear Rec.709 space when there is one, else a matrix
    derived through its aces_interchange or cie_xyz_d65_interchange role; scene_linear is taken
    as linear Rec.709 when it has neither), applies the operator's LUTs from --cgtmo-config, and
    converts back. The studio's search-path folders that are real subfolders of its folder, and
    the operators' LUTs, are copied into one set folder, DIR/cgtmo-set-<hash>, that config.ocio
    names; config.ocio is replaced last, in one rename, so DIR always holds a whole merge (the
    previous or the new), and older sets are removed after it. The profile version is kept.
    Refused with nothing written: a config that cannot be parsed or expands too far, a name that
    already exists, a link out of the studio's folder or a file that is not regular in a folder
    to copy, a merged config that ociocheck would reject, a --prefix with OCIO look syntax
    (leading '+', '-' or space, ',' or ':'), and a DIR that is, is inside or contains a folder
    the merge reads.
)";

const char* kExamples = R"(
EXAMPLES
    Regenerate the shipped LUTs, config and report (from the repository root):
        cgtmo bake --out-luts luts --out-config ocio_config --report docs/lut-accuracy.md

    The cheapest LUTs that stay within 2 code values everywhere (with 0.5, reinhard-lum cannot
    meet it: bake names it and writes nothing):
        cgtmo bake --max-error 2 --out-luts /tmp/luts --out-config /tmp/ocio

    A look adapted to one render, then used in Blender and oiiotool:
        mkdir -p shot/luts shot/ocio
        cgtmo bake --scene shot010.exr --name shot010 --out-luts shot/luts --out-config shot/ocio
        OCIO=shot/ocio/shot010.ocio blender shot010.blend
        oiiotool --colorconfig shot/ocio/shot010.ocio shot010.exr --ociodisplay sRGB drago-shot010 -o shot010.png

    Blender's own config with cgtmo's operators added (views "cgtmo agx", ... on sRGB):
        cgtmo bake --into /usr/share/blender/datafiles/colormanagement/config.ocio -o merged
        OCIO=merged/config.ocio blender
)";

// A word as a POSIX shell reads it back.
std::string shell_quote(const std::string& w) {
  if (!w.empty() && w.find_first_not_of("abcdefghijklmnopqrstuvwxyzABCDEFGHIJKLMNOPQRSTUVWXYZ0123456789-_./=:+,") == std::string::npos) return w;
  std::string q = "'";
  for (char c : w) q += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return q + "'";
}

std::string command_line(const std::vector<std::string>& args) {
  std::string s = "cgtmo bake";
  for (const auto& a : args) s += " " + (a.find(' ') == std::string::npos ? a : "'" + a + "'");
  return s;
}

}  // namespace

int run_bake(const std::vector<std::string>& args) {
  CLI::App app{kDescription, "bake"};
  style(app);
  app.footer(kExamples);
  bake::BakeOptions o;
  std::string scene, name, into, merged_dir, cgtmo_config, prefix = "cgtmo ";
  double max_error = 0;
  bool quiet = false;
  app.add_option("--out-luts", o.luts_dir, "folder for the LUT files and exports (must exist; required but with --into)");
  app.add_option("--out-config", o.config_dir, "folder for config.ocio (must exist; required but with --into)");
  app.add_option("--report", o.report_path, "write the accuracy report (Markdown) here");
  auto* max_opt = app.add_option("--max-error", max_error, "strict error budget in 10-bit code values for every operator")
                      ->check(finite_range(0.001, 1023.0));
  app.add_option("--scene", scene, "bake Drago for this render's statistics instead (EXR)");
  app.add_option("--name", name, "name of the scene look (default: the render's file name)");
  app.add_option("--into", into, "merge cgtmo's looks and views into this studio config (OCIO)");
  app.add_option("-o,--out", merged_dir, "with --into: folder for the merged config.ocio and its LUTs (created if missing)");
  const std::string shipped = shipped_config_path();
  app.add_option("--cgtmo-config", cgtmo_config,
                 "with --into: the cgtmo config whose operator looks and LUTs are merged (default: the shipped one, " +
                     (shipped.empty() ? std::string("not found beside this program") : shipped) + ")");
  app.add_option("--prefix", prefix, "with --into: prefix of the added look and view names")->capture_default_str();
  app.add_flag("-q,--quiet", quiet, "print nothing but errors and warnings");
  if (!parse(app, args, {"--prefix"})) return 0;  // --prefix "": the looks without a prefix
  io::remove_temps_on_termination_signals();  // an interrupted bake leaves no staging folder
  if (*max_opt) o.max_error_cv = max_error;
  if (!name.empty() && scene.empty()) throw UsageError("--name needs --scene");
  if (!scene.empty() && !o.report_path.empty()) throw UsageError("--report cannot be combined with --scene");
  // The command that regenerates the outputs, as written into their headers.
  o.command_line = command_line(args);
  const auto t0 = std::chrono::steady_clock::now();
  auto elapsed = [&] { return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count(); };
  if (!quiet)
    o.progress = [&](const std::string& line) {
      std::cerr << "[" << std::fixed << std::setprecision(1) << std::setw(6) << elapsed() << " s] " << line << "\n";
    };

  if (into.empty() && !merged_dir.empty()) throw UsageError("-o is the folder of --into's merged config: use --out-luts / --out-config here");
  if (!into.empty()) {
    if (merged_dir.empty()) throw UsageError("--into needs -o DIR for the merged config");
    if (!scene.empty() || !o.report_path.empty() || *max_opt) throw UsageError("--into cannot be combined with --scene, --report or --max-error");
    if (cgtmo_config.empty()) cgtmo_config = shipped;
    if (cgtmo_config.empty())
      throw UsageError("the shipped cgtmo config is not beside this program (../share/cgtmo/ocio_config): name one with --cgtmo-config");
    bake::MergeOptions m;
    m.studio_config = into;
    m.cgtmo_config = cgtmo_config;
    m.out_dir = merged_dir;
    m.prefix = prefix;
    m.command_line = o.command_line;
    m.progress = o.progress;
    const auto r = bake::merge_into(m);
    if (!quiet) {
      std::cout << "wrote " << r.config_path << ": " << r.looks.size() << " looks";
      for (const auto& d : r.displays)
        if (d.encoding != bake::DisplayEncoding::none) std::cout << ", " << r.looks.size() << " views on '" << d.display << "' (" << bake::encoding_name(d.encoding) << ")";
      std::cout << "\n";
      for (const auto& d : r.displays)
        if (d.encoding == bake::DisplayEncoding::none) std::cout << "no views on display '" << d.display << "': not sRGB, Rec.1886 or Display P3\n";
      for (const auto& p : r.copied_search_paths) std::cout << "copied the studio's LUT folder '" << p << "' into " << r.set_folder << "/\n";
      for (const auto& p : r.absolute_search_paths) std::cout << "search path entry made absolute: " << p << "\n";
      std::cout << "use it:\n    OCIO=" << shell_quote(r.config_path) << " blender\n";
    }
    return 0;
  }

  // Never a default folder: run in a checkout, a bare `cgtmo bake` replaced its shipped LUTs.
  if (o.luts_dir.empty() || o.config_dir.empty())
    throw UsageError("name the output folders: --out-luts DIR --out-config DIR (the shipped set, from the repository root: "
                     "cgtmo bake --out-luts luts --out-config ocio_config --report docs/lut-accuracy.md)");
  if (!scene.empty()) {
    const auto r = bake::bake_scene(scene, name, o);
    if (!quiet) {
      // Each indented line is a command that runs as printed (a test runs every one).
      const std::string cfg = shell_quote(r.config_path), exr = shell_quote(scene), look = shell_quote(r.look_name);
      std::cout << "wrote " << r.lut_path << " and " << r.config_path << " (Drago " << r.subject.params_text() << ", "
                << "max error " << std::setprecision(3) << r.audit.max_cv << " code values)\n"
                << "use it (View Transform " << r.look_name << " in Blender, or the Look " << r.look_name << " over Standard):\n"
                << "    oiiotool --colorconfig " << cfg << " " << exr << " --ociodisplay sRGB " << look << " -o out.png\n"
                << "    oiiotool --colorconfig " << cfg << " " << exr << " --ociolook " << look << " --ociodisplay sRGB Standard -o out.png\n"
                << "    OCIO=" << cfg << " blender\n"
                << "the same image without LUTs:\n"
                << "    cgtmo apply " << exr << " -o out.png --op drago\n";
    }
    return 0;
  }

  const auto res = bake::bake_all(o);
  for (const auto& m : res.missed)
    std::cerr << "cgtmo bake: warning: " << m << " misses its target at every LUT size; shipped with the cheapest LUT within 1.5x the best error (see the report)\n";
  if (!quiet) {
    std::cout << std::left << std::setw(18) << "operator" << std::setw(44) << "representation" << std::right << std::setw(9) << "max CV"
              << std::setw(9) << "p99.9" << std::setw(8) << "target" << std::setw(10) << "Mpix/s" << "\n";
    for (const auto& ob : res.ops)
      std::cout << std::left << std::setw(18) << ob.subject.def->name << std::setw(44) << ob.choice.lut.rep.describe() << std::right
                << std::fixed << std::setprecision(3) << std::setw(9) << ob.shipped.max_cv << std::setw(9) << ob.shipped.p999_cv
                << std::setprecision(2) << std::setw(8) << ob.budget_cv << std::setprecision(1) << std::setw(10) << ob.ocio_mpix << "\n";
    std::cout << "wrote " << res.ops.size() << " operators to " << o.luts_dir << "/ and " << o.config_dir << "/config.ocio"
              << (o.report_path.empty() ? "" : " and " + o.report_path) << " in " << std::setprecision(0) << elapsed() << " s\n";
  }
  return 0;
}

}  // namespace cgtmo::cli
