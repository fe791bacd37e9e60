// libFuzzer target: the command line end to end (cli::run_command, the same code as the `cgtmo`
// binary): argument parsing, validation and the work it starts, on tiny files in a private folder.
// Input: one argument per line. Invariants, checked after every run:
//   - the exit status is 0, 1 or 2 (no other exception, no crash, no abort);
//   - no file the run reads was changed: a file named by an argument that is not an output option's
//     value, the frames of a pattern argument, and the probe and sidecar of a scene operator's input;
//   - no temporary (.cgtmo-tmp-*, .cgtmo-staging-*) is left behind.
// A run may legitimately overwrite another file of the folder (`-o s.0002.exr`): it is restored.
// Left out: `bake` with arguments that pass parsing runs for minutes by design; it is
// kept to its parsing (a line "--help" is appended to it), and '/' is refused in any
// argument so that nothing outside the private folder is read or written.
#include <fcntl.h>
#include <unistd.h>

#include <OpenImageIO/imageio.h>

#include <cstdint>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include "commands.h"

namespace fs = std::filesystem;

namespace {

void write_exr(const std::string& path, int w, int h, float scale) {
  OIIO::ImageSpec spec(w, h, 4, OIIO::TypeDesc::HALF);
  spec.channelnames = {"ViewLayer.Combined.R", "ViewLayer.Combined.G", "ViewLayer.Combined.B", "ViewLayer.Combined.A"};
  std::vector<float> px(std::size_t(w) * h * 4);
  for (std::size_t i = 0; i < px.size(); ++i) px[i] = (i % 4 == 3) ? 1.f : scale * float((i * 37) % 101) / 10.f;
  auto out = OIIO::ImageOutput::create(path);
  if (!out || !out->open(path, spec) || !out->write_image(OIIO::TypeDesc::FLOAT, px.data()) || !out->close()) std::abort();
}

void write_png(const std::string& path, int w, int h) {
  OIIO::ImageSpec spec(w, h, 3, OIIO::TypeDesc::UINT8);
  std::vector<unsigned char> px(std::size_t(w) * h * 3);
  for (std::size_t i = 0; i < px.size(); ++i) px[i] = (unsigned char)((i * 53) % 256);
  auto out = OIIO::ImageOutput::create(path);
  if (!out || !out->open(path, spec) || !out->write_image(OIIO::TypeDesc::UINT8, px.data()) || !out->close()) std::abort();
}

std::string contents(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  return std::string(std::istreambuf_iterator<char>(in), {});
}

// The private folder with its inputs, made once; the fuzzer runs inside it (so libFuzzer must be
// given absolute corpus and artifact paths, as tests/fuzz/run.sh does).
const std::map<std::string, std::string>& inputs() {
  static const std::map<std::string, std::string> files = [] {
    char dir[] = "/tmp/cgtmo-fuzz-cli-XXXXXX";
    if (!::mkdtemp(dir) || ::chdir(dir) != 0) std::abort();
    write_exr("in.exr", 8, 6, 1.f);
    write_exr("in.probe.exr", 16, 8, 0.5f);
    std::ofstream("in.json") << R"({"camera": {"world_matrix": [[1,0,0,0],[0,1,0,0],[0,0,1,2],[0,0,0,1]], "fov_x_rad": 1.0,
      "resolution": [8, 6]}, "lights": [{"name": "key", "type": "AREA", "lightgroup": "key", "luminance": 25.0}]})";
    for (int f = 1; f <= 3; ++f) write_exr("s.000" + std::to_string(f) + ".exr", 6, 4, float(f));
    write_png("ldr.png", 8, 6);
    std::map<std::string, std::string> m;
    for (const auto& e : fs::directory_iterator(".")) m[e.path().filename().string()] = contents(e.path());
    // Stdout carries listings and reports: not needed here, and slow at the fuzzer's rate.
    const int null = ::open("/dev/null", O_WRONLY);
    if (null < 0 || ::dup2(null, 1) < 0) std::abort();
    return m;
  }();
  return files;
}

bool is_output_option(const std::string& a) {
  for (const char* o : {"-o", "--output", "--write", "--json", "--report", "--doc", "--plot"})
    if (a == o) return true;
  return false;
}

// Whether the run with `args` reads `name` (one of the folder's inputs), judged from the arguments
// alone; outputs are the values of output options (separate, `--opt=value` or `-oVALUE`).
bool read_by_the_run(const std::string& name, const std::vector<std::string>& args) {
  bool scene_op = false;
  for (std::size_t i = 0; i + 1 < args.size(); ++i)
    if (args[i] == "--op" && (args[i + 1] == "cgtmo" || args[i + 1] == "wls")) scene_op = true;
  for (const auto& a : args) scene_op = scene_op || a == "--op=cgtmo" || a == "--op=wls";
  for (std::size_t i = 0; i < args.size(); ++i) {
    const std::string& a = args[i];
    if (is_output_option(a)) {
      ++i;  // its value is an output
      continue;
    }
    if (a.rfind("-o", 0) == 0 && a.rfind("--", 0) != 0) continue;  // -oVALUE
    const auto eq = a.find('=');
    if (a.rfind("--", 0) == 0 && eq != std::string::npos && is_output_option(a.substr(0, eq))) continue;
    const std::string value = a.rfind("--", 0) == 0 && eq != std::string::npos ? a.substr(eq + 1) : a;
    if (value == name) return true;
    const bool pattern = value.find_first_of("#@%") != std::string::npos;
    if (pattern && name.rfind("s.", 0) == 0) return true;  // the frames of a sequence
    const std::string stem = value.size() > 4 && value.compare(value.size() - 4, 4, ".exr") == 0 ? value.substr(0, value.size() - 4) : "";
    if ((scene_op || args[0] == "info") && !stem.empty() && (name == stem + ".probe.exr" || name == stem + ".json")) return true;
  }
  return false;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  const auto& originals = inputs();
  std::vector<std::string> args;
  std::istringstream lines(std::string(reinterpret_cast<const char*>(data), size));
  for (std::string a; std::getline(lines, a);) {
    if (a.find('/') != std::string::npos || a.size() > 256 || args.size() >= 24) return 0;
    args.push_back(a);
  }
  if (!args.empty() && args[0] == "bake") args.push_back("--help");

  // The tool's own error lines would flood the fuzzer's log: stderr is muted during the run.
  const int saved_err = ::dup(2), null = ::open("/dev/null", O_WRONLY);
  ::dup2(null, 2);
  const int rc = cgtmo::cli::run_command(args);
  ::dup2(saved_err, 2);
  ::close(saved_err);
  ::close(null);
  if (rc != 0 && rc != 1 && rc != 2) std::abort();

  for (const auto& [name, bytes] : originals) {
    if (contents(name) == bytes) continue;
    if (read_by_the_run(name, args)) std::abort();  // an input was written (or removed)
    std::ofstream(name, std::ios::binary | std::ios::trunc) << bytes;
  }
  for (const auto& e : fs::directory_iterator(".")) {
    const std::string name = e.path().filename().string();
    if (originals.count(name)) continue;
    if (name.find(".cgtmo-tmp-") != std::string::npos || name.find(".cgtmo-staging-") != std::string::npos) std::abort();
    std::error_code ec;
    fs::remove_all(e.path(), ec);  // an output of this run: the next starts from the same folder
  }
  return 0;
}
