#include "cgtmo/io/image_io.h"

#include <OpenImageIO/imageio.h>
#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <OpenImageIO/filesystem.h>
#include <cerrno>
#include <cstring>

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <map>
#include <unordered_map>

#include "cgtmo/errors.h"
#include "cgtmo/io/exr_luma_chroma.h"
#include "cgtmo/io/image_input.h"
#include "cgtmo/io/input_file.h"
#include "cgtmo/io/scene_reader.h"
#include "cgtmo/io/temp_files.h"
#include "cgtmo/scene/passes.h"
#include "cgtmo/util/parallel.h"

namespace cgtmo::io {

namespace fs = std::filesystem;

FileChannels read_header(const std::string& path) {
  if (is_luma_chroma_exr(path)) {
    const Part p = luma_chroma_part(path);
    return FileChannels{p.width, p.height, p.names, "openexr (luminance/chroma, read as RGB)", path};
  }
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

static BeautyChannels make(const std::vector<std::string>& channels) {
  const auto dot = channels[0].rfind('.');
  BeautyChannels b{dot == std::string::npos ? "" : channels[0].substr(0, dot), channels[0], channels[1], channels[2],
                   channels.size() > 3 ? channels[3] : ""};
  return b;
}

BeautyChannels find_beauty(const FileChannels& fc, const std::string& layer) {
  const std::string file = fc.path.empty() ? "" : "'" + fc.path + "': ";
  if (!layer.empty()) {
    for (const std::string& l : {layer, layer + ".Combined"}) {
      const auto found = scene::beauty_channels(fc.names, l);
      if (!found.empty()) return make(found);
    }
    if (scene::names_the_beauty(layer)) {
      const auto top = scene::beauty_channels(fc.names, "");
      if (!top.empty()) return make(top);
    }
    throw DataError(file + "no RGB layer '" + layer + "' (layers: " + layers_of(fc.names) + ")");
  }
  std::string prefix;
  if (scene::beauty_layer(fc.names, &prefix)) return make(scene::beauty_channels(fc.names, prefix));
  const auto rgb = scene::rgb_layers(fc.names);
  if (rgb.empty()) throw DataError(file + "no RGB layer found (layers: " + layers_of(fc.names) + ")");
  // An RGB layer under another name is an AOV as often as not (diffuse, specular): never guessed.
  std::string list;
  for (const auto& l : rgb) list += (list.empty() ? "" : ", ") + l;
  throw DataError(file + "no layer is the beauty by name (" + scene::beauty_conventions() + "): name it with --layer (RGB layers: " +
                  list + "; layers: " + layers_of(fc.names) + ")");
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

scene::Frame read_beauty(const std::string& path, const std::string& layer, const ReadOptions& read, const FrameWork& work) {
  SceneRequest req;
  req.layer = layer;
  req.needed_by = "the beauty";
  req.probe = req.sidecar = Companion::Skip;
  req.read = read;
  req.work = work;
  return std::move(read_scene(path, req).frame);
}

static std::string lower_ext(const std::string& path) {
  std::string e = fs::path(path).extension().string();
  std::transform(e.begin(), e.end(), e.begin(), [](unsigned char c) { return char(std::tolower(c)); });
  return e;
}

std::optional<OutputKind> output_kind_of(const std::string& path) {
  static const std::map<std::string, OutputKind> kinds = {
      {".png", OutputKind::Png}, {".tif", OutputKind::Tiff}, {".tiff", OutputKind::Tiff},
      {".jpg", OutputKind::Jpeg}, {".jpeg", OutputKind::Jpeg}, {".exr", OutputKind::Exr}};
  const auto it = kinds.find(lower_ext(path));
  if (it == kinds.end()) return std::nullopt;
  return it->second;
}

OutputKind check_output_path(const std::string& out, const std::string& in) {
  const std::optional<OutputKind> kind = output_kind_of(out);
  if (!kind)
    throw UsageError("output '" + out + "': unsupported extension '" + lower_ext(out) + "' (use .png, .tif, .jpg or .exr)");
  fs::path dir = fs::path(out).parent_path();
  if (dir.empty()) dir = ".";
  std::error_code ec;
  if (!fs::is_directory(dir, ec)) throw UsageError("output folder '" + dir.string() + "' does not exist");
  if (fs::is_directory(out, ec)) throw UsageError("output '" + out + "' is a folder");
  if (!in.empty() && fs::exists(out, ec) && fs::equivalent(out, in, ec))
    throw UsageError("output '" + out + "' is the input file: refusing to overwrite it");
  return *kind;
}

void check_outputs_are_not_inputs(const std::vector<std::string>& outputs, const std::vector<std::string>& inputs) {
  // Canonical path: the folder resolved once per folder (a sequence has one or two), the name
  // appended; a name that is itself a symlink is caught by the inode check below.
  std::map<std::string, std::string> folders;
  auto canonical = [&folders](const std::string& p) {
    const fs::path normal = fs::path(p).lexically_normal();
    const std::string name = normal.filename().string();
    std::error_code ec;
    if (name.empty() || name == "." || name == "..") {
      const fs::path c = fs::weakly_canonical(normal, ec);
      return ec ? normal.string() : c.string();
    }
    const std::string dir = normal.parent_path().string();
    auto it = folders.find(dir);
    if (it == folders.end()) {
      const fs::path c = fs::weakly_canonical(dir.empty() ? fs::path(".") : fs::path(dir), ec);
      it = folders.emplace(dir, ec ? dir : c.string()).first;
    }
    return (fs::path(it->second) / name).string();
  };
  auto identity = [](const std::string& p, std::pair<dev_t, ino_t>* id) {
    struct stat st {};
    if (::stat(p.c_str(), &st) != 0) return false;
    *id = {st.st_dev, st.st_ino};
    return true;
  };
  std::unordered_map<std::string, const std::string*> by_path;
  by_path.reserve(inputs.size());
  for (const auto& in : inputs) by_path.emplace(canonical(in), &in);
  // Inputs by inode, looked up only when an output exists (a file that does not exist is no
  // link to anything), so a fresh run does not stat every input.
  std::map<std::pair<dev_t, ino_t>, const std::string*> by_file;
  bool by_file_built = false;
  for (const auto& out : outputs) {
    const std::string* in = nullptr;
    const auto p = by_path.find(canonical(out));
    std::pair<dev_t, ino_t> id;
    if (p != by_path.end()) {
      in = p->second;
    } else if (identity(out, &id)) {
      if (!by_file_built) {
        for (const auto& i : inputs) {
          std::pair<dev_t, ino_t> input_id;
          if (identity(i, &input_id)) by_file.emplace(input_id, &i);
        }
        by_file_built = true;
      }
      const auto f = by_file.find(id);
      if (f != by_file.end()) in = f->second;
    }
    if (in) throw UsageError("output '" + out + "' is the input '" + *in + "': refusing to overwrite it");
  }
}

static OIIO::TypeDesc pixel_type(OutputKind kind, const std::string& depth, const std::string& path) {
  static const std::map<OutputKind, std::pair<const char*, std::vector<std::string>>> allowed = {
      {OutputKind::Png, {"PNG", {"8", "16"}}},
      {OutputKind::Jpeg, {"JPEG", {"8"}}},
      {OutputKind::Tiff, {"TIFF", {"8", "16", "float"}}},
      {OutputKind::Exr, {"EXR", {"half", "float"}}}};
  const auto& [name, depths] = allowed.at(kind);
  if (depth.empty()) {
    return kind == OutputKind::Exr ? OIIO::TypeDesc::FLOAT : kind == OutputKind::Tiff ? OIIO::TypeDesc::UINT16 : OIIO::TypeDesc::UINT8;
  }
  if (std::find(depths.begin(), depths.end(), depth) == depths.end()) {
    std::string list;
    for (const auto& d : depths) list += (list.empty() ? "" : ", ") + d;
    throw UsageError("output '" + path + "': bit depth '" + depth + "' is not one " + name + " takes (" + list + ")");
  }
  if (depth == "8") return OIIO::TypeDesc::UINT8;
  if (depth == "16") return OIIO::TypeDesc::UINT16;
  if (depth == "half") return OIIO::TypeDesc::HALF;
  return OIIO::TypeDesc::FLOAT;
}

static const std::vector<std::string>& exr_compressions() {
  static const std::vector<std::string> names = {"none", "rle", "zips", "zip", "piz", "pxr24", "b44", "b44a", "dwaa", "dwab"};
  return names;
}

static OutputKind kind_of_extension(const std::string& path) {
  const std::string ext = lower_ext(path);
  if (ext == ".png") return OutputKind::Png;
  if (ext == ".tif" || ext == ".tiff") return OutputKind::Tiff;
  if (ext == ".jpg" || ext == ".jpeg") return OutputKind::Jpeg;
  if (ext == ".exr") return OutputKind::Exr;
  throw UsageError("output '" + path + "': unsupported extension '" + ext + "' (use .png, .tif, .jpg or .exr)");
}

void check_output_format(const std::string& path, const OutputFormat& format, bool display_encoded) {
  const OutputKind kind = kind_of_extension(path);
  (void)pixel_type(kind, format.bit_depth, path);
  if (format.compression.empty()) return;
  if (kind != OutputKind::Exr)
    throw UsageError("output '" + path + "': --compression applies to .exr outputs only");
  const auto& names = exr_compressions();
  if (std::find(names.begin(), names.end(), format.compression) == names.end()) {
    std::string list;
    for (const auto& n : names) list += (list.empty() ? "" : ", ") + n;
    throw UsageError("output '" + path + "': unknown EXR compression '" + format.compression + "' (" + list + ")");
  }
  if (display_encoded && (format.compression == "dwaa" || format.compression == "dwab"))
    throw UsageError("output '" + path + "': --compression " + format.compression +
                     " is lossy and decodes display-encoded values outside [0, 1] at edges: choose another "
                     "compression (pxr24 and b44 are lossy too, but decode within it), or --no-display for linear values");
}

struct Metadata {
  OIIO::ParamValueList attributes;
};

// Whether an input attribute describes the picture (kept) rather than the input's pixels or file.
static bool passes_through(const std::string& name) {
  std::string lower = name;
  std::transform(lower.begin(), lower.end(), lower.begin(), [](unsigned char c) { return char(std::tolower(c)); });
  for (const char* prefix : {"oiio:", "iccprofile:", "openexr:", "tiff:", "png:", "jpeg:", "exr:", "dpx:", "heif:", "webp:"})
    if (lower.rfind(prefix, 0) == 0) return false;
  static const char* const dropped[] = {
      "imagedescription", "iccprofile", "compression", "planarconfig", "chromaticities", "whiteluminance",
      "adoptedneutral", "datawindow", "displaywindow", "name", "type", "version", "chunkcount", "tiles",
      "view", "multiview", "lineorder", "blendermultichannel", "bitspersample", "sampleformat", "extrasamples",
      "exif:colorspace", "exif:pixelxdimension", "exif:pixelydimension", "photometricinterpretation",
      "deepimagestate", "dwacompressionlevel"};
  for (const char* d : dropped)
    if (lower == d) return false;
  return true;
}

std::shared_ptr<const Metadata> read_passthrough_metadata(const std::string& path) {
  auto m = std::make_shared<Metadata>();
  if (is_luma_chroma_exr(path)) {  // OpenImageIO cannot open these: their string attributes
    for (const auto& [name, value] : luma_chroma_string_attributes(path))
      // comments is OpenEXR's name for the ImageDescription that cgtmo writes.
      if (passes_through(name) && name != "comments") m->attributes.push_back(OIIO::ParamValue(name, value));
    return m;
  }
  auto in = open_image_input(path);
  for (const auto& p : in->spec().extra_attribs)
    if (passes_through(p.name().string())) m->attributes.push_back(p);
  return m;
}

std::vector<std::string> metadata_names(const Metadata& m) {
  std::vector<std::string> names;
  for (const auto& p : m.attributes) names.push_back(p.name().string());
  return names;
}

void write_image_atomic(const std::string& path, const float* px, int width, int height, int channels,
                        const WriteOptions& options) {
  const OutputKind kind = check_output_path(path, "");
  check_output_format(path, options.format, false);  // the request's check (display-encoded or not) came first
  const OIIO::TypeDesc format = pixel_type(kind, options.format.bit_depth, path);
  const int out_channels = kind == OutputKind::Jpeg ? 3 : channels;  // JPEG has no alpha
  OIIO::ImageSpec spec(width, height, out_channels, format);
  if (channels == 4 && out_channels == 4) spec.alpha_channel = 3;
  // The input's attributes first, so that nothing cgtmo sets below can be overridden by them.
  if (options.metadata)
    for (const auto& p : options.metadata->attributes) spec.extra_attribs.push_back(p);
  if (kind == OutputKind::Exr) {
    spec.attribute("compression", options.format.compression.empty() ? "zip" : options.format.compression);
    if (options.linear_rec709) {
      const float chroma[8] = {0.64f, 0.33f, 0.30f, 0.60f, 0.15f, 0.06f, 0.3127f, 0.3290f};
      spec.attribute("chromaticities", OIIO::TypeDesc(OIIO::TypeDesc::FLOAT, 8), chroma);
    }
  } else if (!options.icc_profile.empty()) {
    spec.attribute("ICCProfile", OIIO::TypeDesc(OIIO::TypeDesc::UINT8, int(options.icc_profile.size())),
                   options.icc_profile.data());
  }
  if (!options.description.empty()) spec.attribute("ImageDescription", options.description);

  // 1. Encode in memory: no file exists until the image is complete.
  std::vector<unsigned char> bytes;
  {
    OIIO::Filesystem::IOVecOutput vec(bytes);
    auto out = OIIO::ImageOutput::create(path, &vec);
    if (!out) throw DataError("cannot write '" + path + "': " + first_line(OIIO::geterror()));
    out->threads(thread_count());  // per file: OIIO's process-wide "threads" is the host's (util/parallel.h)
    const OIIO::stride_t xstride = OIIO::stride_t(channels * sizeof(float));
    if (!out->open(path, spec) || !out->write_image(OIIO::TypeDesc::FLOAT, px, xstride) || !out->close())
      throw DataError("cannot write '" + path + "': " + first_line(out->geterror()));
  }

  // 2. Write them through a locked temporary in the target folder and rename it over the target.
  write_file_atomic(path, bytes.data(), bytes.size());
}

std::string read_description(const std::string& path, ReaderBy by) {
  try {
    // The checks every input gets: a header declaring more than the file holds or the budget
    // allows is refused before OpenEXR allocates it.
    auto in = open_image_input(path, by);
    std::string text = in->spec().get_string_attribute("ImageDescription");
    in->close();
    return text;
  } catch (const std::exception&) {
    (void)OIIO::geterror();  // clear the thread's error: an unreadable output is simply redone
    return {};
  }
}

}  // namespace cgtmo::io
