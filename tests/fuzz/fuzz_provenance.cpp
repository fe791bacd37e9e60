// libFuzzer target: the provenance record an output carries in its ImageDescription
// (sequence/provenance.cpp), read back on every resume and --dry-run and by `cgtmo info`, and the
// text printed from it (util/text.h). A record is outside input: anyone can write an image whose
// description starts with the magic words. Invariants:
//   - parsing is linear: the bytes allocated while parsing stay within 64 per input byte (the
//     fields' strings and the list of fields), counted by a sanitizer allocation hook (a parser
//     that copied the rest of the record for every field allocated about n^2/8);
//   - a parsed record written back (Provenance::text) parses to the same fields;
//   - what is printed from a record (printable: each field, the difference from a reference
//     record) is one line of valid UTF-8 without a terminal control; json_text never throws,
//     gives valid UTF-8 with every C0 control escaped, and for valid UTF-8 what nlohmann parses
//     back to the same fields.
#include <sanitizer/allocator_interface.h>

#include <algorithm>
#include <cstdint>
#include <cstdlib>
#include <string>

#include <nlohmann/json.hpp>

#include "cgtmo/sequence/provenance.h"
#include "cgtmo/util/text.h"

namespace {

bool g_counting = false;
std::size_t g_allocated = 0;

void on_malloc(const volatile void*, std::size_t size) {
  if (g_counting) g_allocated += size;
}
void on_free(const volatile void*) {}

void require(bool ok) {
  if (!ok) __builtin_trap();
}

// Whether `s` is valid UTF-8, by an oracle other than util/text.cpp's: nlohmann refuses to dump
// anything else.
bool valid_utf8(const std::string& s) {
  try {
    (void)nlohmann::json(s).dump();
    return true;
  } catch (const nlohmann::json::type_error&) {
    return false;
  }
}

// Valid UTF-8 without a C0 control, DEL or a C1 control (U+0080-U+009F): one line, no terminal command.
bool one_safe_line(const std::string& s) {
  for (std::size_t i = 0; i < s.size(); ++i) {
    const unsigned char c = static_cast<unsigned char>(s[i]);
    if (c < 0x20 || c == 0x7f) return false;
    if (c == 0xC2 && i + 1 < s.size() && static_cast<unsigned char>(s[i + 1]) <= 0x9F) return false;
  }
  return valid_utf8(s);
}

}  // namespace

extern "C" int LLVMFuzzerInitialize(int*, char***) {
  __sanitizer_install_malloc_and_free_hooks(on_malloc, on_free);
  return 0;
}

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  using cgtmo::sequence::Provenance;
  const std::string text(reinterpret_cast<const char*>(data), size);
  g_allocated = 0;
  g_counting = true;
  const auto parsed = Provenance::parse(text);
  g_counting = false;
  require(g_allocated <= 64 * size + 4096);
  if (!parsed) return 0;

  const auto again = Provenance::parse(parsed->text());
  require(again && again->fields == parsed->fields);

  nlohmann::json j = nlohmann::json::object();
  bool all_utf8 = true;
  for (const auto& [k, v] : parsed->fields) {
    require(one_safe_line(cgtmo::printable(k)) && one_safe_line(cgtmo::printable(v)));
    all_utf8 = all_utf8 && valid_utf8(k) && valid_utf8(v);
    j[k] = v;
  }
  // Must not throw, whatever the bytes; JSON text is valid UTF-8 with every C0 control escaped
  // (DEL and C1 controls may stay: JSON is read by programs, not terminals).
  const std::string json = cgtmo::json_text(j);
  require(valid_utf8(json) && std::none_of(json.begin(), json.end(), [](char c) { return static_cast<unsigned char>(c) < 0x20; }));
  if (all_utf8) require(nlohmann::json::parse(json) == j);

  Provenance reference;
  reference.fields = {{"version", "0"}, {"op", "drago"}, {"input", "a.exr, 1 bytes"}};
  require(one_safe_line(cgtmo::printable(cgtmo::sequence::provenance_difference(*parsed, reference))));
  return 0;
}
