// libFuzzer target: channel-name mapping (io::find_beauty, scene::map_channels). Input: one
// channel name per line, as an EXR header would list them. Checks that every name the mapping
// hands out exists in the file and that known and unmapped names partition the list.
#include <algorithm>
#include <cstdint>
#include <cstdlib>
#include <set>
#include <string>
#include <vector>

#include "cgtmo/errors.h"
#include "cgtmo/io/image_io.h"
#include "cgtmo/scene/passes.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  const std::string in(reinterpret_cast<const char*>(data), size);
  cgtmo::io::FileChannels fc;
  fc.width = fc.height = 1;
  std::size_t start = 0;
  while (start <= in.size() && fc.names.size() < 4096) {
    const std::size_t nl = in.find('\n', start);
    fc.names.push_back(in.substr(start, nl == std::string::npos ? std::string::npos : nl - start));
    if (nl == std::string::npos) break;
    start = nl + 1;
  }
  const std::set<std::string> all(fc.names.begin(), fc.names.end());
  std::string prefix;
  try {
    const auto b = cgtmo::io::find_beauty(fc, "");
    for (const auto& n : {b.r, b.g, b.b})
      if (!all.count(n)) std::abort();
    prefix = b.prefix;
  } catch (const cgtmo::DataError&) {
  }
  const auto map = cgtmo::scene::map_channels(fc.names, prefix);
  for (const auto& n : map.channels_for(cgtmo::scene::PassSet::all()))
    if (!all.count(n)) std::abort();
  const auto unmapped = cgtmo::scene::unmapped_channels(fc.names, map);
  for (const auto& n : unmapped)
    if (!all.count(n)) std::abort();
  return 0;
}
