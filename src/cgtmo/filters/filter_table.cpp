#include "cgtmo/filters/filter_table.h"

#include "cgtmo/errors.h"
#include "cgtmo/util/text.h"

namespace cgtmo::filters {

const std::vector<FilterEntry>& filter_table() {
  static const std::vector<FilterEntry> table = {
      {"exact", &cross_bilateral_exact, true, "cgtmo",
       "the definition (guide.h), double accumulation over a 3 sigma_g window: the reference, slow", 16, 0, 0},
      {"poisson", &cross_bilateral_poisson, true, "cgtmo",
       "the paper's approximation: S offsets Poisson-disk distributed with Gaussian density (-p samples)", 18, 0, 0},
      {"fast", &cross_bilateral_fast, true, "cgtmo",
       "two scales: the filter between cell representatives, a G-buffer-guided upsampling, and the "
       "definition where the nodes do not describe a pixel (the default)", 28, 3000, 1400},
      {"separable", &cross_bilateral_separable, true, "",
       "horizontal then vertical 1-D passes in homogeneous coordinates (measured against fast by cgtmo-bench; no operator runs it)", 0, 0, 0},
      {"bilateral", &cross_bilateral_bilateral, false, "cgtmo",
       "the classic bilateral of log luminance alone, no G-buffer (the paper's Figure 3(a))", 16, 0, 0},
      {"wls", nullptr, false, "wls",
       "Farbman et al.'s weighted least squares on log luminance, no G-buffer (the wls operator)", 256, 0, 0},
  };
  return table;
}

const FilterEntry& find_filter(const std::string& name) {
  std::vector<std::string> names;
  for (const auto& f : filter_table()) {
    if (name == f.name) return f;
    names.emplace_back(f.name);
  }
  throw UsageError("unknown filter '" + name + "'" + did_you_mean(name, names) + " (filters: " + join_names(names, ", ") + ")");
}

std::vector<std::string> offered_filters(const std::string& op) {
  std::vector<std::string> out;
  for (const auto& f : filter_table())
    if (op == f.used_by) out.emplace_back(f.name);
  return out;
}

std::string join_names(const std::vector<std::string>& names, const std::string& separator) {
  std::string out;
  for (const auto& n : names) out += (out.empty() ? "" : separator) + n;
  return out;
}

}  // namespace cgtmo::filters
