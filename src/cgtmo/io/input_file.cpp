#include "cgtmo/io/input_file.h"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <map>
#include <thread>

#include "cgtmo/errors.h"
#include "cgtmo/io/image_input.h"
#include "cgtmo/util/allocation.h"
#include "cgtmo/util/parallel.h"

namespace cgtmo::io {

namespace {

constexpr double kMB = 1024.0 * 1024.0;

// What is wrong with a file of this mode as an input, or "".
std::string mode_problem(mode_t mode) {
  if (S_ISREG(mode)) return "";
  if (S_ISDIR(mode)) return "is a folder";
  const char* kind = S_ISCHR(mode)    ? "character device"
                     : S_ISBLK(mode)  ? "block device"
                     : S_ISFIFO(mode) ? "FIFO"
                     : S_ISSOCK(mode) ? "socket"
                     : S_ISLNK(mode)  ? "symbolic link"
                                      : "special file";
  return std::string("not a regular file (") + kind + ")";
}

}  // namespace

std::string human_bytes(double b) {
  char buf[48];
  if (b < 1024) std::snprintf(buf, sizeof buf, "%.0f bytes", b);
  else if (b < kMB) std::snprintf(buf, sizeof buf, "%.1f KB", b / 1024);
  else if (b < 1024 * kMB) std::snprintf(buf, sizeof buf, "%.1f MB", b / kMB);
  else std::snprintf(buf, sizeof buf, "%.1f GB", b / (1024 * kMB));
  return buf;
}

std::string input_file_problem(const std::string& path) {
  struct stat st {};
  if (::stat(path.c_str(), &st) != 0)  // stat follows symlinks: a link to a device is a device
    return errno == ENOENT || errno == ENOTDIR ? "no such file" : std::strerror(errno);
  return mode_problem(st.st_mode);
}

void require_input_file(const std::string& path, const std::string& label) {
  const std::string problem = input_file_problem(path);
  if (!problem.empty()) throw DataError(label + "'" + path + "': " + problem);
}

std::string read_regular_file(const std::string& path, std::uint64_t max_bytes, const std::string& label, bool follow_links) {
  auto refuse = [&](const std::string& problem) { return DataError(label + "'" + path + "': " + problem); };
  const int fd = ::open(path.c_str(), O_RDONLY | O_NONBLOCK | O_CLOEXEC | (follow_links ? 0 : O_NOFOLLOW));
  if (fd < 0) {
    if (errno == ELOOP && !follow_links) throw refuse(mode_problem(S_IFLNK));
    throw refuse(errno == ENOENT || errno == ENOTDIR ? "no such file" : std::strerror(errno));
  }
  struct Closer {
    int fd;
    ~Closer() { ::close(fd); }
  } closer{fd};
  struct stat st {};
  if (::fstat(fd, &st) != 0) throw refuse(std::strerror(errno));
  if (const std::string problem = mode_problem(st.st_mode); !problem.empty()) throw refuse(problem);
  const auto too_big = [&](double bytes) {
    return refuse("is " + human_bytes(bytes) + ", more than the " + human_bytes(double(max_bytes)) + " allowed");
  };
  if (std::uint64_t(st.st_size) > max_bytes) throw too_big(double(st.st_size));
  std::string content(std::size_t(st.st_size), '\0');
  std::size_t done = 0;
  for (;;) {  // to the end of the file, which may have grown since fstat: never past max_bytes
    if (done == content.size()) {
      if (done > max_bytes) throw too_big(double(done));
      content.resize(std::min<std::uint64_t>(max_bytes + 1, std::max<std::uint64_t>(2 * done, 4096)));
    }
    const ssize_t n = ::read(fd, &content[done], content.size() - done);
    if (n < 0 && errno == EINTR) continue;
    if (n < 0) throw refuse(std::strerror(errno));
    if (n == 0) break;
    done += std::size_t(n);
  }
  content.resize(done);
  return content;
}

namespace {

std::atomic<std::uint64_t> g_budget{0};  // 0: the default

// Per OpenEXR compression code: scanlines per chunk, and the largest ratio of raw to stored bytes
// it can reach, so that a file declaring more pixels than its bytes could hold is refused.
//   none: raw bytes stored. rle: a run of 128 bytes in 2 (64:1). zip/zips: deflate, 258 bytes in
//   2 bits at best (1032:1). pxr24: float32 cut to 24 bits, then deflate (4/3 x 1032). piz: Haar
//   wavelet, then Huffman whose run code stores 256 16-bit values in 10 bits (410:1; 512 used).
//   b44/b44a: a 4x4 block of halves (32 bytes) in 14 bytes, or 3 when flat (10.7:1; 11 used).
//   dwaa/dwab: a DCT block's 64 halves give one DC value and an end-of-block code, each then
//   deflated or Huffman-coded (64 x 1032 at most; twice that used, to never refuse a valid file).
struct CompressionLimits {
  const char* name;
  int lines_per_chunk;
  double max_ratio;
};
constexpr CompressionLimits kCompressions[] = {
    {"none", 1, 1},       {"rle", 1, 64},        {"zips", 1, 1032},   {"zip", 16, 1032},
    {"piz", 32, 512},     {"pxr24", 16, 1376},   {"b44", 32, 11},     {"b44a", 32, 11},
    {"dwaa", 32, 132096}, {"dwab", 256, 132096},
};
constexpr int kCompressionCount = int(sizeof kCompressions / sizeof kCompressions[0]);

const CompressionLimits* limits_of(int code) { return code >= 0 && code < kCompressionCount ? &kCompressions[code] : nullptr; }

std::uint64_t file_size_of(const std::string& path) {
  struct stat st {};
  return ::stat(path.c_str(), &st) == 0 ? std::uint64_t(st.st_size) : 0;
}

// Bounded reads of an OpenEXR header: nothing is allocated beyond what the file holds.
class HeaderBytes {
 public:
  HeaderBytes(const std::string& path, std::uint64_t size) : path_(path), size_(size), in_(path, std::ios::binary) {}
  bool ok() const { return bool(in_); }
  std::uint64_t pos() const { return pos_; }
  std::uint64_t left() const { return size_ - pos_; }

  [[noreturn]] void corrupt(const std::string& what) const {
    throw DataError("'" + path_ + "': corrupt OpenEXR header (" + what + ")");
  }
  void read(void* dst, std::uint64_t n, const std::string& what) {
    if (n > left() || !in_.read(static_cast<char*>(dst), std::streamsize(n))) corrupt(what + " runs past the end of the file");
    pos_ += n;
  }
  void skip(std::uint64_t n, const std::string& what) {
    if (n > left() || !in_.seekg(std::streamoff(n), std::ios::cur)) corrupt(what + " runs past the end of the file");
    pos_ += n;
  }
  std::string name(const std::string& what) {  // NUL-terminated, at most 255 characters (long names)
    std::string s;
    for (;;) {
      char c;
      read(&c, 1, what);
      if (c == 0) return s;
      if (s.size() == 255) corrupt(what + " is longer than 255 characters");
      s.push_back(c);
    }
  }
  std::uint32_t u32(const std::string& what) {
    unsigned char b[4];
    read(b, 4, what);
    return std::uint32_t(b[0]) | std::uint32_t(b[1]) << 8 | std::uint32_t(b[2]) << 16 | std::uint32_t(b[3]) << 24;
  }

 private:
  std::string path_;
  std::uint64_t size_, pos_ = 0;
  std::ifstream in_;
};

std::int32_t le_i32(const unsigned char* b) {
  return std::int32_t(std::uint32_t(b[0]) | std::uint32_t(b[1]) << 8 | std::uint32_t(b[2]) << 16 | std::uint32_t(b[3]) << 24);
}

struct ChannelEntry {
  int bytes;  // per sample as stored: 4 (uint, float), 2 (half)
  std::int32_t x_sampling, y_sampling;
};

// The chlist attribute: {name NUL, int32 type, uint8 pLinear, 3 reserved, int32 xSampling,
// int32 ySampling}..., NUL.
// Adds the entries to `out` by name, as OpenEXR does: a second "channels" attribute adds to the
// first rather than replacing it (found by fuzzing), and a repeated name is one channel.
void parse_channel_list(const std::vector<unsigned char>& v, const HeaderBytes& hb, std::map<std::string, ChannelEntry>* out) {
  std::size_t i = 0;
  for (;;) {
    if (i >= v.size()) hb.corrupt("the channel list has no end");
    if (v[i] == 0) {
      // OpenEXR reads up to the terminator, not `size` bytes: they must agree.
      if (i + 1 != v.size()) hb.corrupt("the channel list ends before its declared size");
      return;
    }
    const std::size_t name_at = i;
    while (i < v.size() && v[i] != 0) ++i;  // the name
    if (v.size() - i < 17) hb.corrupt("the channel list has no end");
    const unsigned char* f = &v[i + 1];
    const std::int32_t type = le_i32(f);
    const std::string name(v.begin() + std::ptrdiff_t(name_at), v.begin() + std::ptrdiff_t(i));
    // OpenEXR accepts any type code, OpenImageIO aborts on one it does not know (found by fuzzing).
    if (type < 0 || type > 2) hb.corrupt("channel '" + name + "' has the unknown pixel type " + std::to_string(type));
    (*out)[name] = ChannelEntry{type == 1 ? 2 : 4, le_i32(f + 8), le_i32(f + 12)};
    i += 17;
  }
}

// OpenEXR reads a value of a known type by its type (a box2i is 16 bytes whatever size the
// header gives; a channel list runs to its terminator) and does not skip to the declared end, and
// it allocates what a preview or a string vector declares inside. So a header whose sizes differ
// from what OpenEXR consumes is refused here (a valid file never has one): then this parser and
// OpenEXR read the same attributes, and every allocation is bounded by the file's bytes.
int fixed_value_size(const std::string& type) {
  static const std::map<std::string, int> sizes = {
      {"box2i", 16},   {"box2f", 16},  {"chromaticities", 32}, {"compression", 1}, {"deepImageState", 1},
      {"double", 8},   {"envmap", 1},  {"float", 4},           {"int", 4},         {"keycode", 28},
      {"lineOrder", 1}, {"m33d", 72},  {"m33f", 36},           {"m44d", 128},      {"m44f", 64},
      {"rational", 8}, {"tiledesc", 9}, {"timecode", 8},       {"v2d", 16},        {"v2f", 8},
      {"v2i", 8},      {"v3d", 24},    {"v3f", 12},            {"v3i", 12}};
  const auto it = sizes.find(type);
  return it == sizes.end() ? -1 : it->second;
}

void check_string_vector(const std::vector<unsigned char>& v, const HeaderBytes& hb, const std::string& what) {
  std::size_t at = 0;
  while (at < v.size()) {
    if (v.size() - at < 4) hb.corrupt(what + ": a string length runs past its declared size");
    const std::int32_t n = le_i32(&v[at]);
    at += 4;
    if (n < 0 || std::size_t(n) > v.size() - at) hb.corrupt(what + ": a string runs past its declared size");
    at += std::size_t(n);
  }
}

}  // namespace

std::uint64_t default_memory_budget() { return process_allocation().memory_bytes / 2; }

std::uint64_t memory_budget() {
  const std::uint64_t b = g_budget.load();
  return b ? b : default_memory_budget();
}

void set_memory_budget(std::uint64_t bytes) { g_budget.store(bytes); }

bool read_exr_declaration(const std::string& path, ExrDeclaration* out) {
  HeaderBytes hb(path, file_size_of(path));
  if (!hb.ok() || hb.left() < 8) return false;
  if (hb.u32("the magic number") != 20000630) return false;
  const std::uint32_t version = hb.u32("the version");
  const bool multipart = version & 0x1000, single_tiled = version & 0x200, non_image = version & 0x800;
  ExrDeclaration d;
  for (;;) {
    ExrPartDeclaration p;
    p.tiled = !multipart && single_tiled;
    p.deep = !multipart && non_image;
    // OpenEXR starts every header from its defaults (a 64x64 window, ZIP, no channels: those of
    // ExrPartDeclaration) and keeps those whose attribute is missing: so does this parser.
    bool empty_header = true;
    std::map<std::string, ChannelEntry> channels;
    for (;;) {
      const std::string name = hb.name("an attribute name");
      if (name.empty()) break;
      empty_header = false;
      const std::string type = hb.name("the type of attribute '" + name + "'");
      const std::int32_t size = std::int32_t(hb.u32("the size of attribute '" + name + "'"));
      const std::string what = "attribute '" + name + "'";
      // Checked before any value is read or allocated: OpenEXR allocates what the size says.
      if (size < 0 || std::uint64_t(size) > hb.left())
        hb.corrupt(what + " declares " + std::to_string(size) + " bytes, but " + std::to_string(hb.left()) + " are left in the file");
      const int fixed = fixed_value_size(type);
      if (fixed >= 0 && size != fixed)
        hb.corrupt(what + " of type " + type + " declares " + std::to_string(size) + " bytes instead of " + std::to_string(fixed));
      const bool inspect = fixed >= 0 ? name == "dataWindow" || name == "compression" || name == "tiles"
                                      : type == "chlist" || type == "stringvector" || type == "preview" ||
                                            (name == "type" && type == "string");
      if (!inspect) {
        hb.skip(std::uint64_t(size), what);
        continue;
      }
      std::vector<unsigned char> v(static_cast<std::size_t>(size));  // no more than the file holds
      if (size > 0) hb.read(v.data(), std::uint64_t(size), what);
      if (type == "chlist") {
        std::map<std::string, ChannelEntry> other;
        parse_channel_list(v, hb, name == "channels" ? &channels : &other);
      } else if (type == "stringvector") {
        check_string_vector(v, hb, what);
      } else if (type == "preview") {  // width, height, then 4 bytes per pixel
        if (v.size() < 8 || double(v.size()) != 8 + 4 * double(std::uint32_t(le_i32(&v[0]))) * double(std::uint32_t(le_i32(&v[4]))))
          hb.corrupt(what + ": the preview's size is not what its width and height say");
      } else if (name == "dataWindow" && type == "box2i") {
        p.width = std::int64_t(le_i32(&v[8])) - le_i32(&v[0]) + 1;
        p.height = std::int64_t(le_i32(&v[12])) - le_i32(&v[4]) + 1;
      } else if (name == "compression" && type == "compression") {
        p.compression = v[0];
      } else if (name == "tiles" && type == "tiledesc") {
        p.tile_width = std::uint32_t(le_i32(&v[0]));
        p.tile_height = std::uint32_t(le_i32(&v[4]));
      } else if (name == "type" && type == "string") {
        const std::string t(v.begin(), v.end());
        if (t.rfind("deep", 0) == 0) p.deep = true;
        if (t == "tiledimage" || t == "deeptile") p.tiled = true;
      }
    }
    // A multi-part file's header list ends with an empty header.
    if (multipart && empty_header) break;
    p.channels = int(channels.size());
    for (const auto& [channel_name, c] : channels) {
      p.channel_list.push_back(ExrChannelDeclaration{channel_name, c.x_sampling, c.y_sampling});
      if (c.x_sampling > 1 || c.y_sampling > 1) p.subsampled = true;
      if (c.x_sampling > 0 && c.y_sampling > 0)  // subsampled: at least floor(w/xs) x floor(h/ys) samples
        p.raw_bytes += double(c.bytes) * std::floor(double(p.width) / c.x_sampling) * std::floor(double(p.height) / c.y_sampling);
    }
    p.valid_window = p.width > 0 && p.height > 0;
    d.parts.push_back(p);
    if (!multipart) break;
  }
  d.header_bytes = hb.pos();
  *out = std::move(d);
  return true;
}

bool is_luma_chroma_layout(const ExrPartDeclaration& p) {
  bool y = false, ry = false, by = false;
  for (const auto& c : p.channel_list) {
    const bool full = c.x_sampling == 1 && c.y_sampling == 1, half = c.x_sampling == 2 && c.y_sampling == 2;
    if (c.name == "Y" && full) y = true;
    else if (c.name == "RY" && half) ry = true;
    else if (c.name == "BY" && half) by = true;
    else if (!(c.name == "A" && full)) return false;
  }
  return y && ry && by;
}

double min_stored_bytes(const ExrPartDeclaration& p) {
  if (!p.valid_window) return 0;
  const CompressionLimits* c = limits_of(p.compression);
  double chunks;
  if (p.tiled) {
    if (p.tile_width <= 0 || p.tile_height <= 0) return 0;  // OpenEXR refuses it
    chunks = std::ceil(double(p.width) / double(p.tile_width)) * std::ceil(double(p.height) / double(p.tile_height));
  } else {
    chunks = std::ceil(double(p.height) / (c ? c->lines_per_chunk : 256));
  }
  return 16 * chunks + (c ? p.raw_bytes / c->max_ratio : 0);
}

namespace {

std::string deep_refusal(const std::string& path) { return "'" + path + "': deep images are not supported"; }

// OpenImageIO reads no subsampled channel, and OpenEXR's RGBA interface only its own layout.
std::string subsampling_refusal(const std::string& path, const ExrPartDeclaration& p, std::size_t part) {
  std::string channel;
  for (const auto& c : p.channel_list)
    if (c.x_sampling != 1 || c.y_sampling != 1) {
      channel = "'" + c.name + "' is sampled " + std::to_string(c.x_sampling) + "x" + std::to_string(c.y_sampling);
      break;
    }
  return "'" + path + "': channel " + channel + (part ? " in part " + std::to_string(part) : std::string()) +
         ": subsampled channels are read only as OpenEXR's luminance/chroma layout in the first part (Y; RY, BY at 2x2; A)";
}

// What reading an image costs as float32. OpenImageIO converts scanlines through a buffer of at
// least 64 rows (its chunk is rounded up to a multiple of 64 rows, found by fuzzing: an 8x4 file
// made it allocate 64 MB), so an image of fewer rows costs 64 of them.
double read_cost_bytes(std::int64_t width, std::int64_t height, int channels, bool tiled) {
  const double rows = tiled ? double(height) : std::max(double(height), 64.0);
  return double(width) * rows * channels * sizeof(float);
}

void check_budget(const std::string& path, double cost_bytes, const std::string& declared) {
  const double budget = double(memory_budget());
  if (cost_bytes > budget)
    throw DataError("'" + path + "': " + declared + " need " + human_bytes(cost_bytes) +
                    " to read as float32, more than the memory budget of " + std::to_string(std::uint64_t(budget / kMB)) +
                    " MB (--max-memory)");
}

std::string size_text(std::int64_t w, std::int64_t h, int channels) {
  return std::to_string(w) + "x" + std::to_string(h) + " pixels, " + std::to_string(channels) + " channel" +
         (channels == 1 ? "" : "s");
}

}  // namespace

bool check_exr_declared_size(const std::string& path) {
  ExrDeclaration d;
  if (!read_exr_declaration(path, &d)) return false;
  double decoded = 0, needed = double(d.header_bytes);
  for (std::size_t i = 0; i < d.parts.size(); ++i) {
    const ExrPartDeclaration& p = d.parts[i];
    if (p.deep) throw DataError(deep_refusal(path));
    if (p.subsampled && !(i == 0 && is_luma_chroma_layout(p))) throw DataError(subsampling_refusal(path, p, i));
    if (!p.valid_window) continue;  // OpenEXR refuses it with its own message
    decoded += read_cost_bytes(p.width, p.height, p.channels, p.tiled);
    // OpenEXR allocates a tile's worth of buffer for each of its tile buffers (two per thread) when
    // it opens a tiled file, whatever the window: a 64x64 image declaring 8 x 16,777,480 tiles made
    // it allocate 805 MB (found by fuzzing).
    if (p.tiled && p.tile_width > 0 && p.tile_height > 0)
      decoded += double(p.tile_width) * double(p.tile_height) * p.channels * sizeof(float) * 2 *
                 std::max(1u, std::thread::hardware_concurrency());
    needed += min_stored_bytes(p);
  }
  std::string declared = d.parts.size() == 1 ? size_text(d.parts[0].width, d.parts[0].height, d.parts[0].channels)
                                             : std::to_string(d.parts.size()) + " parts";
  const double have = double(file_size_of(path));
  if (needed > have) {
    const ExrPartDeclaration& first = d.parts[0];
    const CompressionLimits* c = d.parts.size() == 1 ? limits_of(first.compression) : nullptr;
    std::string how = c ? " (" + std::string(c->name) + ", at most " + std::to_string(int(c->max_ratio)) + ":1)" : "";
    throw DataError("'" + path + "': the header declares " + declared + how + ", which need at least " + human_bytes(needed) +
                    ", but the file has " + human_bytes(have) + " (corrupt or truncated)");
  }
  check_budget(path, decoded, declared);
  return true;
}

void check_frame_size(const std::string& path, const FrameWindow& window, const FrameWindow& data, int values_read,
                      const FrameWork& work) {
  const double pixels = double(window.width) * double(window.height);
  const double read = pixels * values_read * sizeof(float);
  const double total = read + pixels * work.bytes_per_pixel + double(window.width) * work.bytes_per_column +
                       double(window.height) * work.bytes_per_row;
  const double budget = double(memory_budget());
  if (total <= budget) return;
  auto rect = [](const FrameWindow& r) {
    return std::to_string(r.width) + "x" + std::to_string(r.height) + " at (" + std::to_string(r.x) + "," + std::to_string(r.y) + ")";
  };
  const bool differs = data.x != window.x || data.y != window.y || data.width != window.width || data.height != window.height;
  std::string text = "'" + path + "': the " + window.window_name + " window " + rect(window) +
                     (differs ? " (data window " + rect(data) + ")" : std::string()) + " needs " + human_bytes(read) +
                     " to read as float32 (" + std::to_string(values_read) + (values_read == 1 ? " value" : " values") + " a pixel)";
  if (total > read) text += " and " + human_bytes(total) + " with the work of " + work.by;
  throw DataError(text + ", more than the memory budget of " + std::to_string(std::uint64_t(budget / kMB)) +
                  " MB (--max-memory)");
}

void check_declared_size(const std::string& path, std::int64_t width, std::int64_t height, int channels, bool tiled,
                         bool deep) {
  if (deep) throw DataError(deep_refusal(path));
  check_budget(path, read_cost_bytes(width, height, channels, tiled), size_text(width, height, channels));
}

std::string first_line(std::string s) {
  s = s.substr(0, s.find('\n'));
  return s.empty() ? "unknown error" : s;
}

std::unique_ptr<OIIO::ImageInput> open_image_input(const std::string& path, ReaderBy by) {
  require_input_file(path);
  const bool exr = check_exr_declared_size(path);  // before OpenEXR allocates its offset tables
  // The reader is the one the content (OpenEXR's magic number) or else the extension names, never
  // whichever of OpenImageIO's formats accepts the file: some decode the whole image in open()
  // (found by fuzzing: a 563-byte file taken for WebP made it allocate 12035x3188x4 bytes),
  // before any declared size can be checked.
  const bool by_content = exr && by == ReaderBy::ContentThenExtension;
  std::string format = by_content ? "openexr" : std::filesystem::path(path).extension().string();
  if (!by_content && !format.empty()) format.erase(0, 1);
  std::transform(format.begin(), format.end(), format.begin(), [](unsigned char c) { return char(std::tolower(c)); });
  auto in = format.empty() ? nullptr : OIIO::ImageInput::create(format);  // unopened: nothing probed
  if (!in)
    throw DataError("'" + path + "': cannot read as an image: not OpenEXR, and " +
                    (format.empty() ? std::string("no extension names another format") : "no image format has the extension '" + format + "'"));
  in->threads(thread_count());  // per file: OIIO's process-wide "threads" is the host's (util/parallel.h)
  OIIO::ImageSpec opened;
  if (!in->open(path, opened)) throw DataError("'" + path + "': cannot read as an image: " + first_line(in->geterror()));
  const OIIO::ImageSpec& s = in->spec();
  check_declared_size(path, s.width, s.height, s.nchannels, s.tile_width > 0, s.deep);
  return in;
}

}  // namespace cgtmo::io
