#pragma once
// One function per subcommand; each parses its own arguments and returns the exit code.
// Errors propagate as cgtmo::UsageError (exit 2) or cgtmo::DataError (exit 1) to main().
#include <string>
#include <vector>

namespace cgtmo::cli {

// `cgtmo ARGS...` without the program name: usage, --version or one subcommand. Every error is
// printed as one line on stderr; returns the exit status (0 ok, 1 bad data, 2 bad usage).
int run_command(std::vector<std::string> args);

int run_apply(const std::vector<std::string>& args);
int run_list(const std::vector<std::string>& args);
int run_info(const std::vector<std::string>& args);
int run_bake(const std::vector<std::string>& args);
int run_eval(const std::vector<std::string>& args);

}  // namespace cgtmo::cli
