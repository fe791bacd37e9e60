// src/cgtmo/sequence/provenance.cpp: reading a record costs in proportion to its size. Every
// resume and --dry-run parses each output's record, and a parser that copied the rest of the record
// for every field allocated 138 GB for this record (3 s a --dry-run). The bytes it allocates are counted
// by replacing the global operator new, so this binary holds nothing else (the other tests keep
// the sanitizers' own operator new).
#include <gtest/gtest.h>

#include <atomic>
#include <cstdlib>
#include <new>
#include <string>

#include "cgtmo/sequence/provenance.h"

namespace {
std::atomic<bool> g_counting{false};
std::atomic<std::size_t> g_allocated{0};
}  // namespace

void* operator new(std::size_t size) {
  if (g_counting) g_allocated += size;
  if (void* p = std::malloc(size ? size : 1)) return p;
  throw std::bad_alloc();
}
void operator delete(void* p) noexcept { std::free(p); }
void operator delete(void* p, std::size_t) noexcept { std::free(p); }

TEST(ProvenanceAllocation, ParsingAllocatesInProportionToTheRecord) {
  cgtmo::sequence::Provenance record;
  for (int i = 0; i < 200000; ++i) record.fields.emplace_back("k" + std::to_string(i % 100), "v");
  const std::string text = record.text();
  ASSERT_GT(text.size(), 1000000u);
  g_allocated = 0;
  g_counting = true;
  const auto parsed = cgtmo::sequence::Provenance::parse(text);
  g_counting = false;
  ASSERT_TRUE(parsed.has_value());
  EXPECT_EQ(parsed->fields, record.fields);
  // The fields and their list: 64 bytes of list per field, twice over while it grows. Copying the
  // rest of the record per field allocated 138 GB here.
  EXPECT_LT(g_allocated.load(), 64 * text.size()) << g_allocated.load() << " bytes allocated for a record of " << text.size();
}
