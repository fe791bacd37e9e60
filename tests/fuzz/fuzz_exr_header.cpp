// libFuzzer target: EXR files as the reader consumes them (io::read_header, find_beauty,
// io::read_scene with the G-buffer optional). The bytes go to a file in /dev/shm because the
// reader takes paths. Any input must be read or rejected with cgtmo::DataError / UsageError.
#include <unistd.h>

#include <cstdint>
#include <cstdio>
#include <string>

#include "cgtmo/errors.h"
#include "cgtmo/io/image_io.h"
#include "cgtmo/io/scene_reader.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  static const std::string path = "/dev/shm/cgtmo-fuzz-" + std::to_string(::getpid()) + ".exr";
  FILE* f = std::fopen(path.c_str(), "wb");
  if (!f) return 0;
  std::fwrite(data, 1, size, f);
  std::fclose(f);
  try {
    const auto fc = cgtmo::io::read_header(path);
    if (std::size_t(fc.width) * std::size_t(fc.height) > (1u << 22)) return 0;  // keep runs fast
    cgtmo::io::SceneRequest req;
    req.required = cgtmo::scene::Pass::Beauty;
    req.optional = cgtmo::scene::PassSet::all();
    req.probe = cgtmo::io::Companion::Skip;
    req.sidecar = cgtmo::io::Companion::Skip;
    (void)cgtmo::io::read_scene(path, req);
  } catch (const cgtmo::DataError&) {
  } catch (const cgtmo::UsageError&) {
  }
  return 0;
}
