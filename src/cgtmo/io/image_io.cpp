#include "cgtmo/io/image_io.h"

#include <OpenImageIO/imageio.h>
#include <fcntl.h>
#include <unistd.h>

#include <OpenImageIO/filesystem.h>
#include <cerrno>
#include <cstring>

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <map>

#include "cgtmo/errors.h"
#include "cgtmo/io/image_input.h"
#include "cgtmo/io/temp_files.h"

namespace cgtmo::io {

namespace fs = std::filesystem;

FileChannels read_header(const std::string& path) {
  auto in = open_image_input(path);
  const OIIO::ImageSpec& s = in->spec();
  FileChannels fc;
  fc.width = s.width;
  fc.height = s.height;
  fc.names = s.channelnames;
  fc.format = in->format_name();
  fc.path = path;
  if (fc.width <= 0 || fc.height <= 0) throw DataError("'" + path + "': empty image");
  return fc;
}

static bool has(const FileChannels& fc, const std::string& n) {
  return std::find(fc.names.begin(), fc.names.end(), n) != fc.names.end();
}

static bool rgb_at(const FileChannels& fc, const std::string& prefix) {
  const std::string p = prefix.empty() ? "" : prefix + ".";
  return has(fc, p + "R") && has(fc, p + "G") && has(fc, p + "B");
}

static BeautyChannels make(const FileChannels& fc, const std::string& prefix) {
  const std::string p = prefix.empty() ? "" : prefix + ".";
  BeautyChannels b{prefix, p + "R", p + "G", p + "B", has(fc, p + "A") ? p + "A" : ""};
  return b;
}

std::string layers_of(const std::vector<std::string>& names) {
  std::vector<std::string> layers;
  for (const auto& n : names) {
    const auto dot = n.rfind('.');
    const std::string l = dot == std::string::npos ? "(top level)" : n.substr(0, dot);
    if (std::find(layers.begin(), layers.end(), l) == layers.end()) layers.push_back(l);
  }
  std::string s;
  for (const auto& l : layers) s += (s.empty() ? "" : ", ") + l;
  return s;
}

BeautyChannels find_beauty(const FileChannels& fc, const std::string& layer) {
  const std::string file = fc.path.empty() ? "" : "'" + fc.path + "': ";
  if (!layer.empty()) {
    if (rgb_at(fc, layer)) return make(fc, layer);
    if (rgb_at(fc, layer + ".Combined")) return make(fc, layer + ".Combined");
    throw DataError(file + "no RGB layer '" + layer + "' (layers: " + layers_of(fc.names) + ")");
  }
  if (rgb_at(fc, "")) return make(fc, "");
  for (const auto& n : fc.names) {
    const std::string suffix = ".Combined.R";
    if (n.size() > suffix.size() && n.compare(n.size() - suffix.size(), suffix.size(), suffix) == 0) {
      const std::string prefix = n.substr(0, n.size() - 2);
      if (rgb_at(fc, prefix)) return make(fc, prefix);
    }
  }
  for (const auto& n : fc.names)
    if (n.size() > 2 && n.compare(n.size() - 2, 2, ".R") == 0 && rgb_at(fc, n.substr(0, n.size() - 2)))
      return make(fc, n.substr(0, n.size() - 2));
  throw DataError(file + "no RGB layer found (layers: " + layers_of(fc.names) + ")");
}

std::vector<float> read_channels(const std::string& path, const FileChannels& fc, const std::vector<std::string>& names) {
  std::vector<int> idx;
  for (const auto& n : names) {
    const auto it = std::find(fc.names.begin(), fc.names.end(), n);
    if (it == fc.names.end()) throw DataError("'" + path + "': no channel '" + n + "'");
    idx.push_back(int(it - fc.names.begin()));
  }
  auto in = open_image_input(path);
  const std::size_t npx = std::size_t(fc.width) * std::size_t(fc.height);
  const int k = int(names.size());
  std::vector<float> out(npx * k);
  // Read contiguous runs of wanted channels straight into place (strided), so no AOV that is
  // not asked for is decoded into memory.
  std::size_t i = 0;
  while (i < idx.size()) {
    std::size_t j = i + 1;
    while (j < idx.size() && idx[j] == idx[j - 1] + 1) ++j;
    const OIIO::stride_t xstride = OIIO::stride_t(k * sizeof(float));
    if (!in->read_image(0, 0, idx[i], idx[j - 1] + 1, OIIO::TypeDesc::FLOAT, out.data() + i, xstride))
      throw DataError("'" + path + "': corrupt or truncated: " + first_line(in->geterror()));
    i = j;
  }
  return out;
}

scene::Frame read_beauty(const std::string& path, const std::string& layer) {
  const FileChannels fc = read_header(path);
  const BeautyChannels b = find_beauty(fc, layer);
  std::vector<std::string> names = {b.r, b.g, b.b};
  if (!b.a.empty()) names.push_back(b.a);
  scene::Frame f;
  f.width = fc.width;
  f.height = fc.height;
  f.channels = int(names.size());
  f.beauty = read_channels(path, fc, names);
  f.source = path;
  f.layer = b.prefix;
  return f;
}

static std::string lower_ext(const std::string& path) {
  std::string e = fs::path(path).extension().string();
  std::transform(e.begin(), e.end(), e.begin(), [](unsigned char c) { return char(std::tolower(c)); });
  return e;
}

OutputKind check_output_path(const std::string& out, const std::string& in) {
  const std::string ext = lower_ext(out);
  static const std::map<std::string, OutputKind> kinds = {
      {".png", OutputKind::Png}, {".tif", OutputKind::Tiff}, {".tiff", OutputKind::Tiff},
      {".jpg", OutputKind::Jpeg}, {".jpeg", OutputKind::Jpeg}, {".exr", OutputKind::Exr}};
  const auto it = kinds.find(ext);
  if (it == kinds.end())
    throw UsageError("output '" + out + "': unsupported extension '" + ext + "' (use .png, .tif, .jpg or .exr)");
  fs::path dir = fs::path(out).parent_path();
  if (dir.empty()) dir = ".";
  std::error_code ec;
  if (!fs::is_directory(dir, ec)) throw UsageError("output folder '" + dir.string() + "' does not exist");
  if (fs::is_directory(out, ec)) throw UsageError("output '" + out + "' is a folder");
  if (!in.empty() && fs::exists(out, ec) && fs::equivalent(out, in, ec))
    throw UsageError("output '" + out + "' is the input file: refusing to overwrite it");
  return it->second;
}

namespace {

// Writes all of `bytes` to `fd`; false with errno set on failure (ENOSPC: disk full).
bool write_all(int fd, const std::vector<unsigned char>& bytes) {
  std::size_t done = 0;
  while (done < bytes.size()) {
    const ssize_t n = ::write(fd, bytes.data() + done, bytes.size() - done);
    if (n < 0) {
      if (errno == EINTR) continue;
      return false;
    }
    done += std::size_t(n);
  }
  return true;
}

std::string errno_text() { return std::strerror(errno); }

}  // namespace

void write_image_atomic(const std::string& path, const float* px, int width, int height, int channels) {
  const OutputKind kind = check_output_path(path, "");
  const fs::path target(path);
  const OIIO::TypeDesc format = kind == OutputKind::Exr    ? OIIO::TypeDesc::FLOAT
                                : kind == OutputKind::Tiff ? OIIO::TypeDesc::UINT16
                                                           : OIIO::TypeDesc::UINT8;
  const int out_channels = kind == OutputKind::Jpeg ? 3 : channels;  // JPEG has no alpha
  OIIO::ImageSpec spec(width, height, out_channels, format);
  if (channels == 4 && out_channels == 4) spec.alpha_channel = 3;
  if (kind == OutputKind::Exr) spec.attribute("compression", "zip");

  // 1. Encode in memory: no file exists until the image is complete.
  std::vector<unsigned char> bytes;
  {
    OIIO::Filesystem::IOVecOutput vec(bytes);
    auto out = OIIO::ImageOutput::create(path, &vec);
    if (!out) throw DataError("cannot write '" + path + "': " + first_line(OIIO::geterror()));
    const OIIO::stride_t xstride = OIIO::stride_t(channels * sizeof(float));
    if (!out->open(path, spec) || !out->write_image(OIIO::TypeDesc::FLOAT, px, xstride) || !out->close())
      throw DataError("cannot write '" + path + "': " + first_line(out->geterror()));
  }

  // 2. Put the bytes in an unnamed file in the target folder (O_TMPFILE: if the process dies
  //    now, nothing is left), give it a hidden temporary name, and rename it over the target.
  //    Where O_TMPFILE is unsupported, a named hidden temporary is written instead.
  fs::path dir = target.parent_path();
  if (dir.empty()) dir = ".";
  const std::string tmp = temp_path_for(path);
  register_temp(tmp);
  struct Unregister {
    std::string p;
    ~Unregister() { unregister_temp(p); }
  } unregister{tmp};
  auto fail = [&](const std::string& why, int fd) {
    if (fd >= 0) ::close(fd);
    ::unlink(tmp.c_str());
    throw DataError("cannot write '" + path + "': " + why);
  };
  int fd = ::open(dir.c_str(), O_TMPFILE | O_WRONLY | O_CLOEXEC, 0666);
  const bool unnamed = fd >= 0;
  if (!unnamed) {
    if (errno == EACCES || errno == EROFS || errno == ENOSPC) fail(errno_text(), -1);
    fd = ::open(tmp.c_str(), O_CREAT | O_EXCL | O_WRONLY | O_CLOEXEC, 0666);
    if (fd < 0) fail(errno_text(), -1);
  }
  if (!write_all(fd, bytes)) fail(errno_text(), fd);
  if (unnamed) {
    const std::string self = "/proc/self/fd/" + std::to_string(fd);
    if (::linkat(AT_FDCWD, self.c_str(), AT_FDCWD, tmp.c_str(), AT_SYMLINK_FOLLOW) != 0) fail(errno_text(), fd);
  }
  if (::close(fd) != 0) fail(errno_text(), -1);
  if (::rename(tmp.c_str(), path.c_str()) != 0) fail(errno_text(), -1);
}

}  // namespace cgtmo::io
