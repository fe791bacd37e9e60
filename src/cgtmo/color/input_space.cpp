#include "cgtmo/color/input_space.h"

#include <algorithm>
#include <cmath>

#include "cgtmo/display/display.h"
#include "cgtmo/errors.h"
#include "cgtmo/util/parallel.h"

namespace cgtmo::color {

namespace {

constexpr const char* kXyzRole = "cie_xyz_d65_interchange";
// A matrix this close to the identity (element-wise) converts nothing worth the pass.
constexpr double kIdentityTolerance = 1e-5;
// A named space and the file's attribute agree when their matrices to Rec.709 differ by less
// than this, element-wise (independent derivations of the same primaries differ by ~1e-4).
constexpr double kAgreementTolerance = 2e-3;

bool has_space(const OCIO::ConstConfigRcPtr& config, const char* name) {
  return config && config->getColorSpace(name) != nullptr;
}

// The conversion from `source` to linear Rec.709 as OCIO evaluates it: the processor into the XYZ
// role (then `post` is XYZ -> Rec.709), else into scene_linear (then no `post`).
OCIO::ConstCPUProcessorRcPtr processor_to_working(const OCIO::ConstConfigRcPtr& config, const std::string& source,
                                                  std::optional<Mat3>* post) {
  if (has_space(config, kXyzRole)) {
    *post = rgb_to_xyz(rec709()).inverse();
    return config->getProcessor(source.c_str(), kXyzRole)->getDefaultCPUProcessor();
  }
  if (has_space(config, OCIO::ROLE_SCENE_LINEAR)) {
    post->reset();
    return config->getProcessor(source.c_str(), OCIO::ROLE_SCENE_LINEAR)->getDefaultCPUProcessor();
  }
  throw UsageError("the OCIO config has neither a " + std::string(kXyzRole) +
                   " nor a scene_linear role: cgtmo cannot tell where linear Rec.709 is");
}

void eval(const OCIO::ConstCPUProcessorRcPtr& cpu, const std::optional<Mat3>& post, double in[3], double out[3]) {
  float v[3] = {float(in[0]), float(in[1]), float(in[2])};
  cpu->applyRGB(v);
  if (post) post->apply(v[0], v[1], v[2]);
  for (int i = 0; i < 3; ++i) out[i] = v[i];
}

// The matrix of a conversion, when test colours show it linear.
std::optional<Mat3> as_matrix(const OCIO::ConstCPUProcessorRcPtr& cpu, const std::optional<Mat3>& post) {
  Mat3 m;
  for (int c = 0; c < 3; ++c) {
    double in[3] = {0, 0, 0}, out[3];
    in[c] = 1.0;
    eval(cpu, post, in, out);
    for (int r = 0; r < 3; ++r) m.m[r][c] = out[r];
  }
  const double tests[][3] = {{0, 0, 0}, {0.18, 0.18, 0.18}, {4, 0.5, 0.01}, {100, 20, 3}, {0.001, 0.002, 0.0005}, {0.3, 7, 1.5}};
  for (const auto& t : tests) {
    double in[3] = {t[0], t[1], t[2]}, out[3];
    eval(cpu, post, in, out);
    double want[3] = {in[0], in[1], in[2]};
    m.apply(want[0], want[1], want[2]);
    const double scale = std::max({std::abs(want[0]), std::abs(want[1]), std::abs(want[2]), 1e-3});
    for (int i = 0; i < 3; ++i)
      if (!(std::abs(out[i] - want[i]) <= 1e-4 * scale)) return std::nullopt;
  }
  return m;
}

// A component of the converted pixel within 2^-23 of the terms it sums (|sum| <= 2^-23 * sum|term|)
// is float32 residue, not colour: it is set to 0. Float32 storage of the input leaves at most
// 2^-24 of each term (the attribute's chromaticities are read as the published set, so the matrix
// itself adds nothing); kept, such a residue counts as negative in the non-finite policy or shows
// through a per-channel curve with a steep toe (a pure red at 2^15 stored as ACEScg comes back
// with a green of ~1e-3: 3 of 255 through Reinhard). The floor is no larger: above it the file
// does carry the colour (a red 20 stops below its green is 8e-7 of the terms: 21 of 255 through
// Reinhard, and kept). An OCIO view in a host converts in float32 and keeps the residue: the
// channels within this floor are where cgtmo and such a view may differ.
constexpr double kRoundingFloor = 0x1p-23;

void convert_pixel(const Mat3& m, float* p) {
  double out[3];
  for (int r = 0; r < 3; ++r) {
    double v = 0, mag = 0;
    for (int k = 0; k < 3; ++k) {
      const double t = m.m[r][k] * double(p[k]);
      v += t;
      mag += std::abs(t);
    }
    out[r] = std::abs(v) <= kRoundingFloor * mag ? 0.0 : v;
  }
  for (int r = 0; r < 3; ++r) p[r] = float(out[r]);
}

bool near_identity(const Mat3& m) { return max_abs_difference(m, Mat3::identity()) <= kIdentityTolerance; }

}  // namespace

InputSpace::InputSpace() = default;

OCIO::ConstConfigRcPtr config_for_input(const std::string& path, const std::string& name, std::string* origin) {
  if (!name.empty()) return display::load_config(path, origin);
  try {
    return display::load_config(path, origin);
  } catch (const std::exception&) {
    return nullptr;
  }
}

void check_colorspace_name(const OCIO::ConstConfigRcPtr& config, const std::string& name, const std::string& origin) {
  if (has_space(config, name.c_str())) return;
  const int n = config->getNumColorSpaces();
  std::string some;
  for (int i = 0; i < n && i < 6; ++i) some += std::string(i ? ", " : "") + "'" + config->getColorSpaceNameByIndex(i) + "'";
  throw UsageError("unknown colour space '" + name + "' in the OCIO config (" + origin + "); it has " + some +
                   (n > 6 ? " and " + std::to_string(n - 6) + " more" : std::string()));
}

std::optional<Mat3> named_space_matrix(const OCIO::ConstConfigRcPtr& config, const std::string& name) {
  std::optional<Mat3> post;
  const auto cpu = processor_to_working(config, name, &post);
  return as_matrix(cpu, post);
}

InputSpace InputSpace::resolve(const OCIO::ConstConfigRcPtr& config, const std::string& name,
                               const std::optional<Chromaticities>& attribute, std::string* warning) {
  if (warning) warning->clear();
  InputSpace s;
  auto set_matrix = [&s](const Mat3& m) {
    s.matrix_ = m;
    s.identity_ = near_identity(m);
  };
  if (!name.empty()) {
    const OCIO::ConstColorSpaceRcPtr cs = config ? config->getColorSpace(name.c_str()) : nullptr;
    if (!cs) throw UsageError("unknown colour space '" + name + "'");
    s.description_ = "OCIO colour space '" + std::string(cs->getName()) + "'";
    std::optional<Mat3> post;
    const auto cpu = processor_to_working(config, name, &post);
    if (const auto m = as_matrix(cpu, post)) {
      set_matrix(*m);
    } else {
      s.identity_ = false;
      s.cpu_ = cpu;
      s.matrix_.reset();
      s.post_ = post;
    }
    if (attribute && warning) {
      const Mat3 a = to_rec709(*attribute);
      const std::string said = "the file's chromaticities attribute (" + describe(*attribute) + ")";
      if (!s.matrix_)
        *warning = "colour space '" + name + "' is not linear but " + said + " says linear RGB: using '" + name + "'";
      else if (max_abs_difference(a, *s.matrix_) > kAgreementTolerance)
        *warning = "colour space '" + name + "' disagrees with " + said + ": using '" + name + "'";
    }
    return s;
  }
  if (attribute) {
    s.description_ = "chromaticities attribute (" + describe(*attribute) + ")";
    set_matrix(to_rec709(*attribute));
    return s;
  }
  if (has_space(config, OCIO::ROLE_SCENE_LINEAR)) {
    const std::string linear = config->getColorSpace(OCIO::ROLE_SCENE_LINEAR)->getName();
    s.description_ = "scene_linear role ('" + linear + "')";
    if (has_space(config, kXyzRole)) {
      std::optional<Mat3> post;
      const auto cpu = processor_to_working(config, OCIO::ROLE_SCENE_LINEAR, &post);
      if (const auto m = as_matrix(cpu, post)) set_matrix(*m);
      else throw DataError("the OCIO config's scene_linear role ('" + linear + "') is not a linear space");
    }
    return s;
  }
  return s;  // Linear Rec.709
}

void InputSpace::apply(float* px, std::size_t count, int channels) const {
  if (identity_ || count == 0) return;
  const std::size_t c = std::size_t(channels);
  parallel_rows(int64_t(count), [&](int64_t b, int64_t e) {
    if (matrix_) {
      for (int64_t i = b; i < e; ++i) {
        float* p = px + std::size_t(i) * c;
        if (!(std::isfinite(p[0]) && std::isfinite(p[1]) && std::isfinite(p[2]))) continue;
        convert_pixel(*matrix_, p);
      }
      return;
    }
    // A non-linear named space: OCIO over a packed RGB copy of the chunk's finite pixels.
    std::vector<float> tmp(std::size_t(e - b) * 3);
    for (int64_t i = b; i < e; ++i)
      for (int k = 0; k < 3; ++k) tmp[std::size_t(i - b) * 3 + k] = px[std::size_t(i) * c + k];
    OCIO::PackedImageDesc desc(tmp.data(), long(e - b), 1, 3);
    cpu_->apply(desc);
    for (int64_t i = b; i < e; ++i) {
      float* p = px + std::size_t(i) * c;
      if (!(std::isfinite(p[0]) && std::isfinite(p[1]) && std::isfinite(p[2]))) continue;
      float* q = &tmp[std::size_t(i - b) * 3];
      if (post_) convert_pixel(*post_, q);
      for (int k = 0; k < 3; ++k) p[k] = q[k];
    }
  });
}

}  // namespace cgtmo::color
