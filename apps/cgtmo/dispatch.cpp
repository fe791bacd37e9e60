// The subcommand dispatch of `cgtmo`: usage, --version, and the one place where errors become
// one line on stderr and an exit status. A library (cgtmo_cli) so the argument fuzzer runs it too.
#include <OpenImageIO/imageio.h>

#include <iostream>
#include <new>
#include <string>
#include <vector>

#include "cgtmo/errors.h"
#include "cgtmo/util/text.h"
#include "cgtmo/util/version.h"
#include "commands.h"

namespace cgtmo::cli {

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

EXIT STATUS
    0 success, 1 bad data (unreadable, corrupt or truncated file, missing channels),
    2 bad usage (unknown command, operator or parameter, value out of range, bad output path).

EXAMPLES
    cgtmo apply tests/scenes/cornell/cornell.exr -o cornell.png --op aces-narkowicz
    cgtmo list
    cgtmo apply --help
)";

}  // namespace

int run_command(std::vector<std::string> args) {
  if (args.empty() || args[0] == "-h" || args[0] == "--help" || args[0] == "help") {
    std::cout << kUsage;
    return args.empty() ? 2 : 0;
  }
  if (args[0] == "--version") {
    std::cout << "cgtmo " << cgtmo::version() << " (OpenImageIO " << OIIO::openimageio_version() / 10000 << "." << OIIO::openimageio_version() / 100 % 100 << ")\n";
    return 0;
  }
  const std::string cmd = args[0];
  args.erase(args.begin());
  try {
    if (cmd == "apply") return run_apply(args);
    if (cmd == "list") return run_list(args);
    if (cmd == "info") return run_info(args);
    if (cmd == "bake") return run_bake(args);
    if (cmd == "eval") return run_eval(args);
    throw UsageError("unknown command '" + printable(cmd) + "'" + did_you_mean(cmd, {"apply", "list", "info", "eval", "bake"}) +
                     " (commands: apply, list, info, eval, bake; see 'cgtmo --help')");
  } catch (const UsageError& e) {
    std::cerr << "cgtmo " << cmd << ": error: " << e.what() << "\n";
    return 2;
  } catch (const DataError& e) {
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

}  // namespace cgtmo::cli
