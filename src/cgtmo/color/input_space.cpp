#include "cgtmo/color/input_space.h"

#include <algorithm>
#include <cmath>

#include "cgtmo/color/working_space.h"
#include "cgtmo/display/display.h"
#include "cgtmo/errors.h"
#include "cgtmo/util/parallel.h"
#include "cgtmo/util/text.h"

namespace cgtmo::color {

namespace {

// A matrix this close to the identity (element-wise) converts nothing worth the pass.
constexpr double kIdentityTolerance = 1e-5;
// A named space and the file's attribute agree when their matrices to Rec.709 differ by less
// than this, element-wise (independent derivations of the same primaries differ by ~1e-4).
constexpr double kAgreementTolerance = 2e-3;

bool has_space(const OCIO::ConstConfigRcPtr& config, const char* name) {
  return config && config->getColorSpace(name) != nullptr;
}

// The conversion from `source` to linear Rec.709 as OCIO evaluates it: the processor into the
// config's scene_linear, then `post`, scene_linear -> Rec.709 as measured through the config's
// interchange roles (color/working_space.h; none when scene_linear is taken as linear Rec.709).
OCIO::ConstProcessorRcPtr processor_to_working(const OCIO::ConstConfigRcPtr& config, const std::string& source,
                                               std::optional<Mat3>* post) {
  if (!has_space(config, OCIO::ROLE_SCENE_LINEAR))
    throw UsageError("the OCIO config has no scene_linear role: cgtmo cannot tell where linear Rec.709 is");
  const WorkingSpace w = find_working_space(config);
  if (w.is_rec709()) post->reset();
  else *post = w.scene_linear_to_rec709;
  return config->getProcessor(source.c_str(), OCIO::ROLE_SCENE_LINEAR);
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
  std::vector<std::string> known;
  for (int i = 0; i < n; ++i) {
    known.emplace_back(config->getColorSpaceNameByIndex(i));
    if (i < 6) some += std::string(i ? ", " : "") + "'" + known.back() + "'";
  }
  throw UsageError("unknown colour space '" + name + "' in the OCIO config (" + origin + ")" + did_you_mean(name, known) + "; it has " + some +
                   (n > 6 ? " and " + std::to_string(n - 6) + " more" : std::string()));
}

std::optional<Mat3> named_space_matrix(const OCIO::ConstConfigRcPtr& config, const std::string& name) {
  std::optional<Mat3> post;
  return processor_matrix(processor_to_working(config, name, &post), post);
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
    const auto processor = processor_to_working(config, name, &post);
    if (const auto m = processor_matrix(processor, post)) {
      set_matrix(*m);
    } else {
      s.identity_ = false;
      s.cpu_ = processor->getDefaultCPUProcessor();
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
    const WorkingSpace w = find_working_space(config);
    if (!w.is_rec709()) set_matrix(w.scene_linear_to_rec709);
    return s;
  }
  return s;  // Linear Rec.709
}

InputSpace InputSpace::resolve(const OCIO::ConstConfigRcPtr& config, const std::string& name, const FileColour& file,
                               std::string* warning) {
  if (!name.empty() || file.chromaticities || file.display_referred.empty())
    return resolve(config, name, file.chromaticities, warning);
  // Display-referred values tone-mapped as light would be mapped twice: decode the sRGB curve
  // (OCIO's exponent-with-linear-segment: 2.4, offset 0.055), primaries Rec.709.
  InputSpace s;
  auto curve = OCIO::ExponentWithLinearTransform::Create();
  const double gamma[4] = {2.4, 2.4, 2.4, 1.0}, offset[4] = {0.055, 0.055, 0.055, 0.0};
  curve->setGamma(gamma);
  curve->setOffset(offset);
  s.identity_ = false;
  s.cpu_ = OCIO::Config::CreateRaw()->getProcessor(curve)->getDefaultCPUProcessor();
  s.description_ = "sRGB-encoded Rec.709 (" + file.display_referred + ")";
  if (warning)
    *warning = "the input is " + file.display_referred + ", display-referred: its sRGB values are decoded to linear light before the "
               "operator (--colorspace NAME names its colour space instead)";
  return s;
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
