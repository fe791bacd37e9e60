// libFuzzer target: the JSON sidecar parser (scene/sidecar.cpp). Any input must either parse or
// raise cgtmo::DataError; a JSON library exception escaping would abort here (a finding).
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <string>

#include "cgtmo/errors.h"
#include "cgtmo/scene/sidecar.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  const std::string in(reinterpret_cast<const char*>(data), size);
  try {
    const auto s = cgtmo::scene::parse_sidecar(in, "fuzz");
    if (s.camera.width < 0 || s.camera.height < 0) std::abort();
    for (const auto& l : s.lights) {
      if (s.light_for_group(l.lightgroup) == nullptr) std::abort();
    }
  } catch (const cgtmo::DataError&) {
  }
  return 0;
}
