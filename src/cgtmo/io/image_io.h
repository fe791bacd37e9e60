#pragma once
// Reading renders (only the channels asked for) and writing images atomically, through OIIO.
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "cgtmo/io/input_file.h"
#include "cgtmo/io/read_options.h"
#include "cgtmo/scene/frame.h"

namespace cgtmo::io {

struct FileChannels {
  int width = 0, height = 0;
  std::vector<std::string> names;  // in file order
  std::string format;              // OIIO's format name, e.g. "openexr"
  std::string path;                // the file read ("" for a list built in memory), named in errors
};

// Opens the header only. Throws DataError (missing, unreadable, not an image).
FileChannels read_header(const std::string& path);

// The channel prefix whose R,G,B (and A if present) form the beauty, in any spelling that
// scene::beauty_channels knows: `layer` given: "<layer>" or "<layer>.Combined" (so "ViewLayer"
// works); empty: the layer named by convention (scene::beauty_layer). Returns the four names (A
// empty when absent). Throws DataError naming fc.path and listing what the file has, also when
// its RGB layers are only AOVs under other names: none is taken for the beauty unasked.
struct BeautyChannels {
  std::string prefix, r, g, b, a;
};
BeautyChannels find_beauty(const FileChannels& fc, const std::string& layer);

// The layers of a channel list ("ViewLayer.Combined, ViewLayer.Depth, (top level)"), for messages.
std::string layers_of(const std::vector<std::string>& names);

// Reads the beauty only (no other AOV is decoded where the file layout allows), on the window
// `read` chooses (io/scene_reader.h: by default the display window), held to the memory budget
// with the caller's `work` on it (input_file.h).
scene::Frame read_beauty(const std::string& path, const std::string& layer, const ReadOptions& read = {},
                         const FrameWork& work = {});

// Reads the named channels as float32 planes-interleaved buffer (names.size() values per pixel).
std::vector<float> read_channels(const std::string& path, const FileChannels& fc, const std::vector<std::string>& names);

enum class OutputKind { Png, Tiff, Jpeg, Exr };

// The kind an output path's extension selects (case ignored), or none for an extension cgtmo
// does not write.
std::optional<OutputKind> output_kind_of(const std::string& path);

// Validates an output path before any work: supported extension, existing folder, not the input.
// Throws UsageError. Returns the kind the extension selects.
OutputKind check_output_path(const std::string& out, const std::string& in);

// Refuses (UsageError naming both) when any of `outputs` is any of `inputs`: the same canonical
// path (weakly_canonical, so `./`, `..` and symlinked folders are seen through), or, when both
// exist, the same file (device and inode: symlinks and hard links). Work O(n log n) in the paths.
void check_outputs_are_not_inputs(const std::vector<std::string>& outputs, const std::vector<std::string>& inputs);

// How an output is encoded beyond its extension (docs/outputs.md).
struct OutputFormat {
  // "" = the format's default: 8 for PNG and JPEG, 16 for TIFF, float for EXR. Else "8" (PNG, TIFF,
  // JPEG), "16" (PNG, TIFF), "half" (EXR), "float" (TIFF, EXR).
  std::string bit_depth;
  // EXR only; "" = zip. none, rle, zips, zip, piz, pxr24, b44, b44a, dwaa, dwab.
  std::string compression;
};

// Throws UsageError (one line naming what the format takes) when the extension of `path` cannot
// take `format`. Looks at the extension only (a sequence pattern is fine). A display-encoded
// output holds code values in [0, 1], and a writer cannot clamp what a reader decodes: the DCT
// compressions (dwaa, dwab), whose decoded values ring past [0, 1] at edges, are refused for it
// (docs/outputs.md has the figures); every other compression decodes within the values written.
void check_output_format(const std::string& path, const OutputFormat& format, bool display_encoded);

// The input's attributes that an output carries on (what the camera, renderer or artist said about
// the picture: Software, DateTime, Artist, Copyright, Exif:*, GPS:*, IPTC:*, EXR camera matrices
// such as worldToCamera and worldToNDC, capDate, owner, comments, timecodes, ...). Left out: what
// describes the input's pixels rather than the picture, since the output's differ: channels,
// windows, tiling, compression, bit depth, colour space and chromaticities, ICC profile,
// ImageDescription (cgtmo writes its own), and every format-private attribute (names with a
// format prefix: oiio:, openexr:, tiff:, png:, jpeg:, and Blender's BlenderMultiChannel marker).
// A format that cannot store an attribute drops it (OIIO's writers decide: e.g. a matrix reaches
// only EXR).
struct Metadata;
std::shared_ptr<const Metadata> read_passthrough_metadata(const std::string& path);
std::vector<std::string> metadata_names(const Metadata& m);  // for reports

struct WriteOptions {
  // When not empty, stored as the image's ImageDescription (the one text field that PNG, TIFF, JPEG
  // and EXR all carry through OIIO): cgtmo records there what made the file.
  std::string description;
  OutputFormat format;
  std::vector<unsigned char> icc_profile;        // PNG, TIFF, JPEG: embedded as is; EXR: ignored
  bool linear_rec709 = false;                    // EXR: chromaticities of linear Rec.709, D65
  std::shared_ptr<const Metadata> metadata;      // passed-through attributes (may be null)
};

// What write_image_atomic holds at its peak beside the image it is given, for io::FrameWork:
// the encoder's copy (1.7 bytes a pixel measured for RGB to PNG) and OpenEXR's line buffers, which
// go by the width (1,309 bytes a column measured for RGB float on a 999,999-wide frame); rounded
// up for four channels (docs/hardening.md).
inline constexpr double kWriteBytesPerPixel = 4, kWriteBytesPerColumn = 1800;

// Writes float RGB(A) to `path` (by default PNG/JPEG 8-bit, TIFF 16-bit, EXR float32 with zip),
// via a temporary file in the same folder and a rename, so a failure never leaves a partial file
// or touches an old one.
void write_image_atomic(const std::string& path, const float* px, int width, int height, int channels,
                        const WriteOptions& options);
inline void write_image_atomic(const std::string& path, const float* px, int width, int height, int channels,
                               const std::string& description = {}) {
  WriteOptions o;
  o.description = description;
  write_image_atomic(path, px, width, height, channels, o);
}

// The ImageDescription of an image file, from its header, opened after the checks every input
// gets (input_file.h) by the reader `by` chooses: ReaderBy::Extension for an output cgtmo wrote.
// "" when the file is absent, not a regular file, refused by those checks, unreadable, or has
// none. Never throws.
std::string read_description(const std::string& path, ReaderBy by);

}  // namespace cgtmo::io
