// libFuzzer target: EXR files as the reader consumes them (io::read_header, find_beauty,
// io::read_scene with the G-buffer optional). The bytes go to a file in /dev/shm because the
// reader takes paths. Any input must be read or rejected with cgtmo::DataError / UsageError.
//
// The allocation bound: the reader runs under a memory budget of kBudget, and tests/fuzz/run.sh
// limits every single allocation to that plus OpenImageIO's fixed 64 MB scanline conversion buffer
// plus 16 MB (-malloc_limit_mb=96), so a header that makes anything (our reader, OpenImageIO,
// OpenEXR) allocate in proportion to what it declares, beyond the budget, is reported as an
// out-of-memory finding. A file the reader accepts must also declare no more
// than the budget, and its header as parsed by io::read_exr_declaration must agree with OpenEXR's.
// The frame is read on the display window, which no byte of the file bounds (seeds
// huge_display_window*.exr): what the reader holds at once is counted (live_bytes.h) and held to
// the budget too.
#include <unistd.h>

#include <cstdint>
#include <cstdio>
#include <string>

#include "cgtmo/errors.h"
#include "cgtmo/io/image_io.h"
#include "cgtmo/io/input_file.h"
#include "cgtmo/io/scene_reader.h"
#include "live_bytes.h"

namespace {

constexpr std::uint64_t kBudget = 16u << 20;  // bytes of float32 pixels

void require(bool ok) {
  if (!ok) __builtin_trap();
}

}  // namespace

extern "C" int LLVMFuzzerInitialize(int*, char***) {
  cgtmo::io::set_memory_budget(kBudget);
  cgtmo::fuzz::count_live_bytes();
  return 0;
}

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  static const std::string path = "/dev/shm/cgtmo-fuzz-" + std::to_string(::getpid()) + ".exr";
  FILE* f = std::fopen(path.c_str(), "wb");
  if (!f) return 0;
  std::fwrite(data, 1, size, f);
  std::fclose(f);
  try {
    const auto fc = cgtmo::io::read_header(path);
    // Accepted: within the budget, and the header parse agrees with what OpenEXR opened.
    require(double(fc.width) * double(fc.height) * double(fc.names.size()) * sizeof(float) <= double(kBudget));
    cgtmo::io::ExrDeclaration d;
    if (cgtmo::io::read_exr_declaration(path, &d)) {
      double needed = double(d.header_bytes);
      for (const auto& p : d.parts) needed += cgtmo::io::min_stored_bytes(p);
      require(needed <= double(size));
      if (!d.parts.empty() && d.parts[0].valid_window)
        require(d.parts[0].width == fc.width && d.parts[0].height == fc.height &&
                std::size_t(d.parts[0].channels) == fc.names.size());
    }
    cgtmo::io::SceneRequest req;
    req.required = cgtmo::scene::Pass::Beauty;
    req.optional = cgtmo::scene::PassSet::all();
    req.probe = cgtmo::io::Companion::Skip;
    req.sidecar = cgtmo::io::Companion::Skip;
    // On the display window, which the file's bytes do not bound: the frame and all the reader
    // held at once stay within the budget (plus OpenImageIO's conversion buffer and 16 MB).
    const std::int64_t held = cgtmo::fuzz::peak_extra_bytes([&] {
      try {
        const cgtmo::io::Scene s = cgtmo::io::read_scene(path, req);
        require(double(s.frame.beauty.size()) * sizeof(float) <= double(kBudget));
      } catch (const cgtmo::DataError&) {  // refused: then by what it held before refusing
      }
    });
    require(held <= std::int64_t(kBudget + (80u << 20)));
  } catch (const cgtmo::DataError&) {
  } catch (const cgtmo::UsageError&) {
  }
  return 0;
}
