#include "cgtmo/bake/writers.h"

#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <vector>

#include "cgtmo/errors.h"
#include "cgtmo/util/repro_math.h"
#include "cgtmo/util/test_pause.h"

namespace cgtmo::bake {

namespace fs = std::filesystem;

namespace {

void comment_lines(std::ostringstream& s, const std::string& header) {
  std::istringstream in(header);
  for (std::string line; std::getline(in, line);) s << "# " << line << "\n";
}

void put(std::ostringstream& s, double v, int digits) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.*g", digits, v);
  s << buf;
}

// OpenColorIO writes a CTF's LUT arrays with 8-9 digits in padded columns (5.3 MB for a 49^3
// LUT); with 6 significant digits, one space apart, it is a third smaller. 6 digits on
// log2-encoded values (|v| < 32) and on a [0, 1] pre-curve are 1e-5 at worst, far below the
// interpolation error. Only lines made of numbers alone are rewritten.
std::string compact_number_lines(const std::string& text) {
  std::istringstream in(text);
  std::ostringstream out;
  for (std::string line; std::getline(in, line);) {
    std::istringstream words(line);
    std::vector<double> nums;
    std::string w;
    bool numeric = true;
    while (numeric && words >> w) {
      char* end = nullptr;
      const double v = std::strtod(w.c_str(), &end);
      numeric = end && *end == '\0' && end != w.c_str();
      nums.push_back(v);
    }
    if (!numeric || nums.empty()) {
      out << line << '\n';
      continue;
    }
    for (std::size_t i = 0; i < nums.size(); ++i) {
      if (i) out << ' ';
      put(out, nums[i], 6);
    }
    out << '\n';
  }
  return out.str();
}

}  // namespace

std::string spi1d_text(const BakedLut& lut, const std::string& header) {
  std::ostringstream s;
  comment_lines(s, header);
  const int components = lut.rep.luminance ? 3 : 1;
  s << "Version 1\nFrom 0.0 1.0\nLength " << lut.rep.size << "\nComponents " << components << "\n{\n";
  for (std::size_t i = 0; i < lut.values.size(); i += std::size_t(components)) {
    for (int c = 0; c < components; ++c) {
      s << ' ';
      put(s, lut.values[i + std::size_t(c)], 8);
    }
    s << '\n';
  }
  s << "}\n";
  return s.str();
}

std::string spi3d_text(const BakedLut& lut, const std::string& header) {
  // The format allows no comment before its two header lines; OCIO skips one after them.
  std::ostringstream s;
  const int n = lut.rep.size;
  s << "SPILUT 1.0\n3 3\n" << n << ' ' << n << ' ' << n << '\n';
  comment_lines(s, header);
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j)
      for (int k = 0; k < n; ++k) {
        const float* v = &lut.values[((std::size_t(i) * n + j) * n + k) * 3];
        s << i << ' ' << j << ' ' << k;
        for (int c = 0; c < 3; ++c) {
          s << ' ';
          put(s, v[c], 6);  // log2-encoded: 1e-5 stops, far below the LUT's interpolation error
        }
        s << '\n';
      }
  return s.str();
}

std::string cube_1d_text(const OCIO::ConstCPUProcessorRcPtr& view, int size, const std::string& header) {
  std::ostringstream s;
  comment_lines(s, header);
  std::vector<float> px(std::size_t(size) * 3);
  for (int i = 0; i < size; ++i)
    for (int c = 0; c < 3; ++c) px[std::size_t(i) * 3 + c] = float(kShaperSpace.inverse(double(i) / (size - 1)));
  OCIO::PackedImageDesc desc(px.data(), long(size), 1, 3);
  view->apply(desc);
  s << "LUT_1D_SIZE " << size << "\nLUT_1D_INPUT_RANGE 0.0 1.0\n";
  for (int i = 0; i < size; ++i) {
    for (int c = 0; c < 3; ++c) {
      if (c) s << ' ';
      put(s, px[std::size_t(i) * 3 + c], 6);
    }
    s << '\n';
  }
  return s.str();
}

std::string cube_3d_text(const Representation& rep, const std::vector<float>& warp, const operators::Evaluator& unclamped,
                         const std::string& header) {
  std::ostringstream s;
  comment_lines(s, header);
  const int n = rep.size;
  s << "LUT_1D_SIZE " << kCubeShaperSize << "\nLUT_1D_INPUT_RANGE 0.0 1.0\nLUT_3D_SIZE " << n << "\nLUT_3D_INPUT_RANGE 0.0 1.0\n";
  // The 1D section: the Log2 Shaper value -> the grid coordinate, per channel.
  for (int i = 0; i < kCubeShaperSize; ++i) {
    const double u = std::min(1.0, rep.shaper.forward(kShaperSpace.inverse(double(i) / (kCubeShaperSize - 1))));
    for (int c = 0; c < 3; ++c) {
      if (c) s << ' ';
      put(s, warp_at(rep, warp, c, u), 7);
    }
    s << '\n';
  }
  // The 3D section, red fastest: the unclamped operator at the nodes, sRGB-encoded with the
  // encoding extended beyond [0, 1] (its linear segment below 0, its power law above 1), so that
  // no clamp bends a cell; the reader clips. Clamped values: agx 28 code values at 41^3, 6.8 so.
  std::vector<double> axes[3];
  for (int c = 0; c < 3; ++c) axes[c] = node_axis(rep, warp, c);
  const std::size_t nodes = std::size_t(n) * n * n;
  std::vector<float> px(nodes * 3);
  for (std::size_t q = 0; q < nodes; ++q) {
    px[q * 3] = float(axes[0][q % n]);
    px[q * 3 + 1] = float(axes[1][(q / n) % n]);
    px[q * 3 + 2] = float(axes[2][q / (std::size_t(n) * n)]);
  }
  unclamped.apply(px.data(), nodes, 3);
  char buf[64];
  for (std::size_t q = 0; q < nodes; ++q) {
    // 5 decimals: 5e-6, 0.005 code value at worst.
    double v[3];
    for (int c = 0; c < 3; ++c) {
      const double y = px[q * 3 + c];
      v[c] = y <= 0.0031308 ? 12.92 * y : 1.055 * repro::pow(y, 1.0 / 2.4) - 0.055;
    }
    std::snprintf(buf, sizeof buf, "%.5f %.5f %.5f\n", v[0], v[1], v[2]);
    s << buf;
  }
  return s.str();
}

std::string lut_file_text(const BakedLut& lut, const std::string& header) {
  if (lut.rep.hue_steps || lut.rep.warped) {
    // CTF, not CLF: CLF has no HSV transform (and one file keeps the warped design's two LUTs
    // together). Written unoptimised, as built.
    auto group = view_transform(lut);
    auto& meta = group->getFormatMetadata();
    meta.addAttribute("id", "cgtmo");
    std::istringstream in(header);
    for (std::string line; std::getline(in, line);) meta.addChildElement("Description", line.c_str());
    std::ostringstream s;
    group->write(OCIO::Config::CreateRaw(), "Color Transform Format", s);
    return lut.rep.warped ? compact_number_lines(s.str()) : s.str();
  }
  return lut.rep.dims == 1 ? spi1d_text(lut, header) : spi3d_text(lut, header);
}

std::string clf_text(const OCIO::ConstProcessorRcPtr& view, const std::string& description, bool compact) {
  auto group = view->createGroupTransform();
  auto& meta = group->getFormatMetadata();
  meta.addAttribute("id", "cgtmo");
  meta.addChildElement("Description", description.c_str());
  std::ostringstream s;
  group->write(OCIO::Config::CreateRaw(), "Academy/ASC Common LUT Format", s);
  return compact ? compact_number_lines(s.str()) : s.str();
}

void check_output_folder(const std::string& dir, const std::string& what) {
  if (dir.empty()) throw UsageError("no " + what + " folder named");
  std::error_code ec;
  if (!fs::is_directory(dir, ec)) throw UsageError(what + " folder '" + dir + "' does not exist");
  // Not writable (permissions, a read-only mount) is the filesystem refusing, as for apply: exit 1.
  if (::access(dir.c_str(), W_OK) != 0)
    throw DataError(what + " folder '" + dir + "' is not writable: " + std::strerror(errno));
}

std::string StagedFiles::staging_folder(const std::string& dir) {
  check_output_folder(dir, "output");
  // One staging folder per output folder, however it is spelled ("luts", "luts/", "./luts").
  const std::string key = (fs::path(dir) / "f").lexically_normal().parent_path().string();
  for (const auto& [d, f] : folders_)
    if (d == key) return f.path;
  // A bake killed before its commit left its staging folder here: the first bake after it removes it.
  const io::RemovedLeftovers removed = io::remove_stale_staging_folders(dir);
  if (removed.total() && note_) note_(removed.describe("staging folder") + " in '" + dir + "'");
  folders_.emplace_back(key, io::create_staging_folder(dir));
  return folders_.back().second.path;
}

std::string StagedFiles::stage(const std::string& path, const std::string& content) {
  const fs::path dest(path);
  const fs::path dir = dest.has_parent_path() ? dest.parent_path() : fs::path(".");
  const std::string staged = (fs::path(staging_folder(dir.string())) / dest.filename()).string();
  io::write_new_file(staged, content, path);
  files_.emplace_back(staged, path);
  return staged;
}

void StagedFiles::commit() {
  test_pause_point("commit-start");
  const io::DeferTerminationSignals whole_set_or_nothing;
  for (const auto& [staged, dest] : files_) {
    std::error_code ec;
    fs::rename(staged, dest, ec);
    if (ec) throw DataError("cannot rename '" + staged + "' to '" + dest + "': " + ec.message());
    test_pause_point("commit-renamed");
  }
  files_.clear();
  for (auto& [d, f] : folders_) io::release_staging_folder(f, true);
  folders_.clear();
}

StagedFiles::~StagedFiles() {
  for (auto& [d, f] : folders_) io::release_staging_folder(f, true);
}

}  // namespace cgtmo::bake
