// libFuzzer target: OpenEXR files whose windows come from the fuzzer's bytes. A mutation of a
// header's bytes rarely gives a display window millions of pixels wide around a valid file, so
// this target builds the file instead: one or two parts, each with its own small data window at
// any origin, one display window of any size and place (int32 corners), RGB or RGBA with an
// optional depth part, scanline or tiled, any compression. Every path that sizes a frame by a
// window then runs on it under a 16 MB memory budget: the header and parts (`cgtmo info`), the
// scene reader on the display and the data window, the per-pixel pipeline (apply --op drago) and
// the scene pipeline (apply --op cgtmo).
//
// Invariants: only DataError/UsageError leave a call; an accepted frame is within the budget;
// and, counted by sanitizer allocation hooks, the bytes live at once during any call stay under
// the budget plus a fixed allowance (kFixedBytes: OpenImageIO's 64 MB scanline conversion buffer,
// reserved and never touched, OpenColorIO's processors, thread stacks), so a path that allocates
// by the display window beyond what it held to the budget is a finding.
#include <fuzzer/FuzzedDataProvider.h>
#include <unistd.h>

#include <OpenImageIO/imageio.h>

#include <algorithm>
#include <cstdint>
#include <string>
#include <vector>

#include "cgtmo/errors.h"
#include "cgtmo/io/exr_parts.h"
#include "cgtmo/io/image_io.h"
#include "cgtmo/io/input_file.h"
#include "cgtmo/io/scene_reader.h"
#include "cgtmo/local/apply_scene.h"
#include "cgtmo/pipeline/apply_file.h"
#include "cgtmo/util/parallel.h"
#include "live_bytes.h"

namespace {

constexpr std::uint64_t kBudget = 16u << 20;
constexpr std::uint64_t kFixedBytes = 96u << 20;

void require(bool ok) {
  if (!ok) __builtin_trap();
}

// Runs `f`; a library error is an answer, anything else escapes (a finding). The bytes held at
// once during the call must stay within the budget and the fixed allowance.
template <typename F>
void bounded(F&& f) {
  const std::int64_t extra = cgtmo::fuzz::peak_extra_bytes([&] {
    try {
      f();
    } catch (const cgtmo::DataError&) {
    } catch (const cgtmo::UsageError&) {
    }
  });
  require(extra <= std::int64_t(kBudget + kFixedBytes));
}

struct PartPlan {
  int x, y, width, height;
  std::vector<std::string> names;
};

// Writes the file; false when OpenImageIO or OpenEXR refuse the windows (not a finding).
bool write_file(const std::string& path, const std::vector<PartPlan>& parts, int full_x, int full_y, int full_w,
                int full_h, bool tiled, const std::string& compression) {
  std::vector<OIIO::ImageSpec> specs;
  for (const auto& p : parts) {
    OIIO::ImageSpec s(p.width, p.height, int(p.names.size()), OIIO::TypeDesc::HALF);
    s.x = p.x;
    s.y = p.y;
    s.full_x = full_x;
    s.full_y = full_y;
    s.full_width = full_w;
    s.full_height = full_h;
    s.channelnames = p.names;
    s.attribute("compression", compression);
    if (tiled) s.tile_width = s.tile_height = 16;
    specs.push_back(s);
  }
  auto out = OIIO::ImageOutput::create("openexr");
  if (!out || !out->open(path, int(specs.size()), specs.data())) return false;
  for (std::size_t i = 0; i < specs.size(); ++i) {
    if (i && !out->open(path, specs[i], OIIO::ImageOutput::AppendSubimage)) return false;
    const std::vector<float> px(std::size_t(specs[i].width) * std::size_t(specs[i].height) * specs[i].channelnames.size(), 0.25f);
    if (!out->write_image(OIIO::TypeDesc::FLOAT, px.data())) return false;
  }
  return out->close();
}

}  // namespace

extern "C" int LLVMFuzzerInitialize(int*, char***) {
  cgtmo::io::set_memory_budget(kBudget);
  cgtmo::set_threads(1);
  cgtmo::fuzz::count_live_bytes();
  return 0;
}

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  static const std::string stem = "/dev/shm/cgtmo-fuzz-windows-" + std::to_string(::getpid());
  static const std::string path = stem + ".exr", png = stem + ".png";
  FuzzedDataProvider in(data, size);
  static const char* const kCompressions[] = {"none", "rle", "zips", "zip", "piz", "pxr24", "b44", "dwaa"};
  const std::string compression = kCompressions[in.ConsumeIntegralInRange<int>(0, 7)];
  const bool tiled = in.ConsumeBool(), alpha = in.ConsumeBool(), depth_part = in.ConsumeBool();
  std::vector<PartPlan> parts;
  for (int i = 0; i < (depth_part ? 2 : 1); ++i) {
    PartPlan p{in.ConsumeIntegral<std::int32_t>() >> in.ConsumeIntegralInRange<int>(0, 31),
               in.ConsumeIntegral<std::int32_t>() >> in.ConsumeIntegralInRange<int>(0, 31),
               in.ConsumeIntegralInRange<int>(1, 128), in.ConsumeIntegralInRange<int>(1, 128), {}};
    p.names = i ? std::vector<std::string>{"Z"} : alpha ? std::vector<std::string>{"R", "G", "B", "A"} : std::vector<std::string>{"R", "G", "B"};
    parts.push_back(p);
  }
  // The display window: any origin, any extent that keeps its far corner (origin + extent - 1) in
  // int32; at the origin INT32_MAX that is an extent of 1.
  const int full_x = in.ConsumeIntegral<std::int32_t>() >> in.ConsumeIntegralInRange<int>(0, 31);
  const int full_y = in.ConsumeIntegral<std::int32_t>() >> in.ConsumeIntegralInRange<int>(0, 31);
  const int full_w = int(in.ConsumeIntegralInRange<std::int64_t>(1, std::int64_t(INT32_MAX) - std::max<std::int64_t>(std::int64_t(full_x) - 1, 0)));
  const int full_h = int(in.ConsumeIntegralInRange<std::int64_t>(1, std::int64_t(INT32_MAX) - std::max<std::int64_t>(std::int64_t(full_y) - 1, 0)));
  if (!write_file(path, parts, full_x, full_y, full_w, full_h, tiled, compression)) {
    (void)OIIO::geterror();
    return 0;
  }

  bounded([&] { (void)cgtmo::io::read_header(path); });
  bounded([&] { (void)cgtmo::io::read_parts(path); });
  for (const auto window : {cgtmo::io::Window::Display, cgtmo::io::Window::Data}) {
    bounded([&] {
      cgtmo::io::SceneRequest req;
      req.optional = cgtmo::scene::PassSet::all();
      req.probe = req.sidecar = cgtmo::io::Companion::Skip;
      req.read.window = window;
      const cgtmo::io::Scene s = cgtmo::io::read_scene(path, req);
      require(double(s.frame.pixel_count()) * double(s.frame.channels) * sizeof(float) <= double(kBudget));
    });
  }
  bounded([&] {
    cgtmo::pipeline::ApplyOptions o;
    o.op = "drago";
    cgtmo::pipeline::Applier(o).apply_file(path, png);
  });
  bounded([&] {
    cgtmo::local::SceneApplyOptions o;
    o.op = "cgtmo";
    (void)cgtmo::local::apply_scene_file(o, path, png);
  });
  return 0;
}
