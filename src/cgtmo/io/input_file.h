#pragma once
// Checks on an input file before anything reads it, in one place for every reader of the library
// (renders, probes, sidecars, eval's images, camera tables, OCIO configs):
//   - it must be a regular file once symlinks are followed: a FIFO blocks in open and /dev/zero
//     never ends, so a format probe would wait or spin forever;
//   - an image must not declare more pixels than the memory budget holds, and an OpenEXR file
//     must be large enough for what its header declares (every compression has a maximum ratio),
//     so that a 33 KB file cannot make the reader allocate gigabytes. For OpenEXR this is decided
//     from the header bytes alone, before OpenEXR allocates its chunk offset tables.
// image_input.h opens images through OpenImageIO after these checks.
#include <cstdint>
#include <string>
#include <vector>

namespace cgtmo::io {

// Why `path` cannot be read as an input, or "" when it can: "no such file", "is a folder",
// "not a regular file (character device)" (FIFO, socket, block device).
std::string input_file_problem(const std::string& path);

// Throws DataError "<label>'<path>': <problem>" when input_file_problem(path) is not empty
// (label e.g. "sidecar ", "" for an image).
void require_input_file(const std::string& path, const std::string& label = "");

// Which reader opens an image: an input's is OpenEXR's when the content starts with OpenEXR's
// magic number, else its extension's; a file cgtmo wrote is read only as the format its extension
// names (what cgtmo wrote there), so another format under that name is not taken for an output.
// Never whichever of OpenImageIO's formats accepts the bytes (image_input.h).
enum class ReaderBy { ContentThenExtension, Extension };

// "849 bytes", "2.3 MB", "9.3 GB", for messages.
std::string human_bytes(double bytes);

// The whole of a regular file of at most `max_bytes`, read through one descriptor: the check and
// the read are of the same file (nothing swapped in between), and the open does not block, so a
// FIFO is refused, not waited on. `follow_links` false: a symlink itself is refused. Throws
// DataError "<label>'<path>': <problem>" ("not a regular file (FIFO)", "is 300.0 MB, more than
// the 256.0 MB allowed", or the system's error).
std::string read_regular_file(const std::string& path, std::uint64_t max_bytes, const std::string& label = "",
                              bool follow_links = true);

// The memory budget for reading one image: its pixels as float32, every channel of every part,
// and at least 64 rows of a scanline image (OpenImageIO converts 64 rows at a time). An image
// declaring more is refused before any pixel is allocated. The default is half of the memory this
// process is allotted (util/allocation.h: the least of the RAM, the cgroup memory limit and
// Slurm's memory request); the other half is left to the operators' work buffers, which peak at
// about 2x the channels read.
std::uint64_t default_memory_budget();
std::uint64_t memory_budget();
void set_memory_budget(std::uint64_t bytes);  // 0: back to the default

// A channel as the header declares it.
struct ExrChannelDeclaration {
  std::string name;
  int x_sampling = 1, y_sampling = 1;
};

// What one part of an OpenEXR file declares, read from the header bytes (OpenEXR's defaults for
// attributes it lacks: a 64x64 window, ZIP).
struct ExrPartDeclaration {
  std::int64_t width = 64, height = 64;
  int channels = 0;
  double raw_bytes = 0;   // the pixel data as stored uncompressed (a lower bound with subsampling)
  int compression = 3;    // OpenEXR's code: 0 none, 1 rle, 2 zips, 3 zip, 4 piz, 5 pxr24, 6 b44, 7 b44a, 8 dwaa, 9 dwab
  bool tiled = false, deep = false;
  std::int64_t tile_width = 0, tile_height = 0;
  bool valid_window = false;  // width and height above 0 (else OpenEXR refuses the file)
  bool subsampled = false;    // a channel with x or y sampling above 1 (luminance/chroma)
  std::vector<ExrChannelDeclaration> channel_list;  // by name, as OpenEXR orders them
};

// Whether a part's channels are OpenEXR's luminance/chroma layout, the only subsampled one
// cgtmo reads (through OpenEXR's RGBA interface, exr_luma_chroma.h): Y at full resolution, RY
// and BY at 2x2, optionally A at full resolution, nothing else.
bool is_luma_chroma_layout(const ExrPartDeclaration& part);

struct ExrDeclaration {
  std::vector<ExrPartDeclaration> parts;
  std::uint64_t header_bytes = 0;  // where the headers end (the offset tables begin)
};

// Parses the headers of an OpenEXR file. Returns false when the file does not start with the
// OpenEXR magic number; throws DataError when a header runs past the end of the file.
bool read_exr_declaration(const std::string& path, ExrDeclaration* out);

// The fewest bytes a complete file needs for a part: an 8-byte offset-table entry and an 8-byte
// chunk header per chunk, and its raw pixel bytes at the compression's maximum ratio.
double min_stored_bytes(const ExrPartDeclaration& part);

// Refuses (DataError naming the file, the declared size and the reason) a deep image, an image
// whose decoded size exceeds memory_budget(), an OpenEXR file smaller than its header requires,
// and subsampled channels other than the first part's luminance/chroma layout (no reader takes
// them: reporting the file as readable would be a promise the pixel read then breaks).
// Returns false for a file that is not OpenEXR (checked from its OpenImageIO spec on open).
bool check_exr_declared_size(const std::string& path);

// The same budget and deep checks for an image of any format, from what its header says.
void check_declared_size(const std::string& path, std::int64_t width, std::int64_t height, int channels, bool tiled,
                         bool deep);

// What a caller will hold at its peak beside the planes it reads, per pixel of the frame, per
// column (buffers of a fixed number of rows: OpenEXR's line buffers, a filter's row blocks) and
// per row (a grid padded sideways, which a frame one pixel wide still fills), measured
// (docs/hardening.md). The frame is held to the memory budget with them, so that a
// window far larger than the file's pixels (a display window no byte of the file bounds) is
// refused before the pipeline that would allocate by it starts.
struct FrameWork {
  double bytes_per_pixel = 0, bytes_per_column = 0, bytes_per_row = 0;
  std::string by;  // who needs them, for the message: "--op cgtmo (filter fast)"
};

// Refuses (one-line DataError naming the file, the window, the bytes and --max-memory) a frame of
// `window` (the display or the data window, as `window_name` says; `data` the beauty's data
// window, named when it differs) whose `values_read` float32 planes plus `work` exceed
// memory_budget().
struct FrameWindow {
  std::string window_name;  // "display", "data"
  std::int64_t x = 0, y = 0, width = 0, height = 0;
};
void check_frame_size(const std::string& path, const FrameWindow& window, const FrameWindow& data, int values_read,
                      const FrameWork& work);

}  // namespace cgtmo::io
