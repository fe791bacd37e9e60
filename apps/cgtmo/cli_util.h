#pragma once
#include <CLI/CLI.hpp>

#include <string>
#include <vector>

#include "cgtmo/errors.h"
#include "cgtmo/io/input_file.h"

namespace cgtmo::cli {

// Parses `args` (without the program and subcommand names). Returns false after printing help.
// A parse error becomes a one-line UsageError.
inline bool parse(CLI::App& app, std::vector<std::string> args) {
  std::reverse(args.begin(), args.end());  // CLI11 takes a reversed vector
  try {
    app.parse(args);
  } catch (const CLI::CallForHelp&) {
    std::cout << app.help();
    return false;
  } catch (const CLI::ParseError& e) {
    std::string msg = e.what();
    msg = msg.substr(0, msg.find('\n'));
    throw UsageError(msg + " (see 'cgtmo " + app.get_name() + " --help')");
  }
  return true;
}

// --max-memory MB, the same for every command that reads images: the memory budget of the
// readers (io::memory_budget); 0 keeps the default.
inline CLI::Option* add_max_memory_option(CLI::App& app, double& mb, const std::string& extra = "") {
  return app
      .add_option("--max-memory", mb,
                  "memory budget in MB: an input whose pixels take more as float32 is refused" + extra +
                      " (default: half the RAM or cgroup memory limit)")
      ->check(CLI::PositiveNumber);
}
inline void apply_max_memory(double mb) {
  if (mb > 0) io::set_memory_budget(std::uint64_t(mb * 1024 * 1024));
}

// CLI11's formatter with wider columns, so the man-page-like descriptions read well.
inline void style(CLI::App& app) {
  app.get_formatter()->column_width(30);
}

}  // namespace cgtmo::cli
