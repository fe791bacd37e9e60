#pragma once
#include <CLI/CLI.hpp>

#include <string>
#include <vector>

#include "cgtmo/errors.h"

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

// CLI11's formatter with wider columns, so the man-page-like descriptions read well.
inline void style(CLI::App& app) {
  app.get_formatter()->column_width(30);
}

}  // namespace cgtmo::cli
