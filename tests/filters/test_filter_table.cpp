// filters/filter_table.h: the one list of filters, and the copy of it in docs/cgtmo.md.
#include "cgtmo/filters/filter_table.h"

#include <gtest/gtest.h>

#include <fstream>
#include <set>
#include <sstream>
#include <string>

#include "cgtmo/errors.h"

namespace cgtmo::filters {
namespace {

TEST(FilterTable, NamesAreUniqueAndFoundAndUnknownOnesListTheKnown) {
  std::set<std::string> names;
  for (const auto& f : filter_table()) {
    EXPECT_TRUE(names.insert(f.name).second) << f.name;
    EXPECT_EQ(&find_filter(f.name), &f);
    // Only wls, with a solver of its own, has no FilterFunction.
    EXPECT_EQ(f.function == nullptr, std::string(f.name) == "wls") << f.name;
    EXPECT_TRUE(*f.description) << f.name;
  }
  try {
    find_filter("gaussian");
    FAIL();
  } catch (const UsageError& e) {
    EXPECT_NE(std::string(e.what()).find("gaussian"), std::string::npos);
    EXPECT_NE(std::string(e.what()).find("separable"), std::string::npos);
  }
}

TEST(FilterTable, CgtmoOffersItsFiltersWithTheDefaultAmongThem) {
  const auto offered = offered_filters("cgtmo");
  EXPECT_EQ(offered, (std::vector<std::string>{"exact", "poisson", "fast", "bilateral"}));
  EXPECT_EQ(offered_filters("wls"), std::vector<std::string>{"wls"});
  EXPECT_EQ(join_names(offered, "|"), "exact|poisson|fast|bilateral");
}

// docs/cgtmo.md lists the filters in a table whose rows are these lines, in table order.
std::string docs_rows() {
  std::ostringstream s;
  for (const auto& f : filter_table())
    s << "| `" << f.name << "` | " << (*f.used_by ? f.used_by : "-") << " | " << (f.needs_gbuffer ? "yes" : "no")
      << " | " << f.description << " |\n";
  return s.str();
}

TEST(FilterTable, DocsListMatchesTheTable) {
  std::ifstream in(std::string(CGTMO_SOURCE_DIR) + "/docs/cgtmo.md");
  ASSERT_TRUE(in) << "docs/cgtmo.md";
  const std::string header = "| filter | operator | G-buffer | what it is |";
  std::string line, rows;
  bool inside = false;
  while (std::getline(in, line)) {
    if (line == header) {
      inside = true;
      std::getline(in, line);  // |---|...
      continue;
    }
    if (inside && line.rfind("| ", 0) != 0) break;
    if (inside) rows += line + "\n";
  }
  EXPECT_EQ(rows, docs_rows()) << "docs/cgtmo.md's filter table should read, under '" << header << "':\n"
                               << docs_rows();
}

}  // namespace
}  // namespace cgtmo::filters
