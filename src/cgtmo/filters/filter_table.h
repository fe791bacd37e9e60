#pragma once
// Every base-layer filter of the local operators, listed once. The cgtmo operator's `filter`
// choices, `cgtmo apply --help`, `cgtmo-bench --methods`, the tests and the list in docs/cgtmo.md
// all come from this table (tests/filters/test_filter_table.cpp checks the docs against it).
// Adding a filter: its evaluation in its own file (guide.h's signature) and one row in
// filter_table.cpp.
#include <string>
#include <vector>

#include "cgtmo/filters/guide.h"

namespace cgtmo::filters {

struct FilterEntry {
  const char* name;
  // The evaluation; null for wls, which has a solver and parameters of its own (wls.h).
  FilterFunction function;
  // Reads the G-buffer (position, normal, albedo); else log luminance alone.
  bool needs_gbuffer;
  // The operator that runs it: "cgtmo" (a choice of its `filter` parameter), "wls", or "" for a
  // method only measured (`cgtmo-bench`, the tests).
  const char* used_by;
  const char* description;  // one line
  // What the local operator holds at its peak with this filter, beside the planes it read: per
  // pixel, per column (row blocks) and per row (fast's node grid, padded sideways: a frame one
  // pixel wide still fills it); measured on RGB frames of 2 to 54 Mpx, square, 20 to 54 rows high
  // and 1 to 8 columns wide, rounded up (docs/hardening.md). The reader holds a frame to the
  // memory budget with them (io::FrameWork). 0 for a filter no operator runs.
  double work_bytes_per_pixel, work_bytes_per_column, work_bytes_per_row;
};

const std::vector<FilterEntry>& filter_table();

// The entry `name`; UsageError naming the known filters when there is none.
const FilterEntry& find_filter(const std::string& name);

// The names of the entries `op` runs (used_by == op), in table order: offered_filters("cgtmo")
// are the cgtmo operator's `filter` choices.
std::vector<std::string> offered_filters(const std::string& op);

// `names` joined by `separator` ("exact|poisson|fast|bilateral").
std::string join_names(const std::vector<std::string>& names, const std::string& separator);

}  // namespace cgtmo::filters
