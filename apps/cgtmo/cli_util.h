#pragma once
#include <CLI/CLI.hpp>

#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <optional>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include "cgtmo/errors.h"
#include "cgtmo/io/image_io.h"
#include "cgtmo/io/input_file.h"
#include "cgtmo/util/text.h"

namespace cgtmo::cli {

// What a user most likely meant by the words CLI11 could not place, which it reports only after
// a missing required option: an output given as a second positional names -o, and an unknown
// option gets the closest option names. Empty when every word was placed.
inline std::optional<std::string> unexpected_words_hint(const CLI::App& app) {
  for (const std::string& word : app.remaining(false)) {
    if (word.size() > 1 && word[0] == '-') {
      std::vector<std::string> names;
      for (const CLI::Option* o : app.get_options()) {
        for (const auto& l : o->get_lnames()) names.push_back("--" + l);
        for (const auto& sn : o->get_snames()) names.push_back("-" + sn);
      }
      const std::string flag = word.substr(0, word.find('='));
      return "unknown option '" + printable(flag) + "'" + did_you_mean(flag, names);
    }
    const CLI::Option* out = app.get_option_no_throw("--output");
    if (out && out->count() == 0 && io::output_kind_of(word))
      return "'" + printable(word) + "' looks like the output: name it with -o (-o " + printable(word) + ")";
    return "unexpected argument '" + printable(word) + "'";
  }
  return std::nullopt;
}

// Refuses an option given with an empty value (`--bit-depth ""`, `--compression=`): the library
// reads "" as "not given", so an empty value would silently mean the default. Option groups are
// nameless sub-apps, looked into too. `may_be_empty`: options for which "" is a value of its own
// (bake's --prefix: no prefix), not the default.
inline void check_no_empty_values(const CLI::App& app, const std::string& command, const std::set<std::string>& may_be_empty) {
  for (const CLI::Option* opt : app.get_options()) {
    if (opt->get_items_expected_max() == 0 || opt->count() == 0 || may_be_empty.count(opt->get_name())) continue;
    for (const auto& value : opt->results())
      if (value.empty())
        throw UsageError(opt->get_name() + " is given an empty value (leave the option out for its default; see 'cgtmo " +
                         command + " --help')");
  }
  for (const CLI::App* group : app.get_subcommands([](const CLI::App* a) { return a->get_name().empty(); }))
    check_no_empty_values(*group, command, may_be_empty);
}

// Parses `args` (without the program and subcommand names). Returns false after printing help.
// A parse error, or an option given an empty value (check_no_empty_values), becomes a one-line UsageError.
inline bool parse(CLI::App& app, std::vector<std::string> args, const std::set<std::string>& may_be_empty = {}) {
  // CLI11 2.1 takes an empty word that is not an option's value for the name of an option group
  // (groups have empty names) and then loops forever: `cgtmo apply in.exr "" -o x.png` hung.
  for (std::size_t i = 0; i < args.size(); ++i) {
    if (!args[i].empty()) continue;
    const CLI::Option* prev = i > 0 && args[i - 1].size() > 1 && args[i - 1][0] == '-' ? app.get_option_no_throw(args[i - 1]) : nullptr;
    if (!prev || prev->get_items_expected_max() == 0)
      throw UsageError("argument " + std::to_string(i + 1) + " is empty (see 'cgtmo " + app.get_name() + " --help')");
  }
  std::reverse(args.begin(), args.end());  // CLI11 takes a reversed vector
  try {
    app.parse(args);
  } catch (const CLI::CallForHelp&) {
    std::cout << app.help();
    return false;
  } catch (const CLI::ParseError& e) {
    std::string msg = e.what();
    msg = msg.substr(0, msg.find('\n'));
    throw UsageError(unexpected_words_hint(app).value_or(msg) + " (see 'cgtmo " + app.get_name() + " --help')");
  }
  check_no_empty_values(app, app.get_name(), may_be_empty);
  return true;
}

// Runs a library check of one option's value; its UsageError comes back prefixed with the option
// ("--no-display: a display or view cannot be ..."), as CLI11's own errors name the option first.
template <typename Check>
void with_option(const char* option, Check&& check) {
  try {
    check();
  } catch (const UsageError& e) {
    throw UsageError(std::string(option) + ": " + e.what());
  }
}

// A number within [lo, hi]. Unlike CLI::Range it refuses NaN (which passes every comparison-based
// range test) and infinities, and it reads the text the way the option will be converted.
inline CLI::Validator finite_range(double lo, double hi) {
  std::ostringstream desc;
  desc << "in [" << lo << ", " << hi << "]";
  return CLI::Validator(
      [lo, hi, range = desc.str()](std::string& text) -> std::string {
        const char* s = text.c_str();
        char* end = nullptr;
        errno = 0;
        const double v = std::strtod(s, &end);
        if (end == s || *end != '\0' || errno == ERANGE || !std::isfinite(v)) return "'" + text + "' is not a finite number";
        if (v < lo || v > hi) return "'" + text + "' is not " + range;
        return "";
      },
      "NUMBER " + desc.str());
}

// --max-memory MB, the same for every command that reads images: the memory budget of the
// readers (io::memory_budget); 0 keeps the default.
inline CLI::Option* add_max_memory_option(CLI::App& app, double& mb, const std::string& extra = "") {
  return app
      .add_option("--max-memory", mb,
                  "memory budget in MB: an input whose pixels take more as float32 is refused" + extra +
                      " (default: half the memory this process is allotted: the least of the RAM, the cgroup memory limit, SLURM_MEM_PER_NODE, SLURM_MEM_PER_CPU x CPUs)")
      ->check(finite_range(1, 1e9));
}
inline void apply_max_memory(double mb) {
  if (mb > 0) io::set_memory_budget(std::uint64_t(mb * 1024 * 1024));
}

// CLI11's formatter with wider columns, so the man-page-like descriptions read well.
inline void style(CLI::App& app) {
  app.get_formatter()->column_width(30);
}

}  // namespace cgtmo::cli
