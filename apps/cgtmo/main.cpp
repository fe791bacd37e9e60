// cgtmo: tone mapping for CG renders. Dispatches to one file per subcommand.
#include <OpenImageIO/imageio.h>

#include <cstring>
#include <iostream>
#include <new>
#include <string>
#include <vector>

#include "cgtmo/errors.h"
#include "commands.h"

namespace {

const char* kUsage = R"(NAME
    cgtmo - tone mapping for CG and VFX renders (OpenEXR in, display-ready images out)

SYNOPSIS
    cgtmo <command> [options]
    cgtmo <command> --help

COMMANDS
    apply    tone-map an EXR render (plain RGB(A) or Blender multilayer) to PNG, TIFF, JPEG or EXR
    list     the operators, their kinds and parameters with defaults and ranges
    info     the layers and AOVs a file holds and which operators can run on it
    bake     every operator as LUTs and an OpenColorIO config, with the LUT accuracy report
    eval     TMQI of a tone-mapped image against its HDR render, or of every operator on the scenes
    bench    speed against error of the CG-TMO filters and their peers (docs/speed-vs-error.md)

EXIT STATUS
    0 success, 1 bad data (unreadable, corrupt or truncated file, missing channels),
    2 bad usage (unknown command, operator or parameter, value out of range, bad output path).

EXAMPLES
    cgtmo apply tests/scenes/cornell/cornell.exr -o cornell.png --op aces-narkowicz
    cgtmo list
    cgtmo apply --help
)";

}  // namespace

int main(int argc, char** argv) {
  std::vector<std::string> args(argv + 1, argv + argc);
  if (args.empty() || args[0] == "-h" || args[0] == "--help" || args[0] == "help") {
    std::cout << kUsage;
    return args.empty() ? 2 : 0;
  }
  if (args[0] == "--version") {
    std::cout << "cgtmo 0.1.0 (OpenImageIO " << OIIO::openimageio_version() / 10000 << "." << OIIO::openimageio_version() / 100 % 100 << ")\n";
    return 0;
  }
  const std::string cmd = args[0];
  args.erase(args.begin());
  try {
    if (cmd == "apply") return cgtmo::cli::run_apply(args);
    if (cmd == "list") return cgtmo::cli::run_list(args);
    if (cmd == "info") return cgtmo::cli::run_info(args);
    if (cmd == "bake") return cgtmo::cli::run_bake(args);
    if (cmd == "eval") return cgtmo::cli::run_eval(args);
    if (cmd == "bench") return cgtmo::cli::run_bench(args);
    throw cgtmo::UsageError("unknown command '" + cmd + "' (commands: apply, list, info, eval, bake, bench; see 'cgtmo --help')");
  } catch (const cgtmo::UsageError& e) {
    std::cerr << "cgtmo " << cmd << ": error: " << e.what() << "\n";
    return 2;
  } catch (const cgtmo::DataError& e) {
    std::cerr << "cgtmo " << cmd << ": error: " << e.what() << "\n";
    return 1;
  } catch (const std::bad_alloc&) {
    // The last resort: the readers refuse files declaring more than the budget before allocating.
    std::cerr << "cgtmo " << cmd << ": error: out of memory (apply and info take --max-memory to refuse such input up front)\n";
    return 1;
  } catch (const std::exception& e) {
    std::cerr << "cgtmo " << cmd << ": error: " << e.what() << "\n";
    return 1;
  }
}
