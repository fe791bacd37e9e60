#include "cgtmo/color/working_space.h"

#include <algorithm>
#include <cmath>

#include "cgtmo/color/chromaticities.h"
#include "cgtmo/errors.h"

namespace cgtmo::color {

Mat3 aces2065_to_rec709() { return to_rec709(aces_ap0()); }

Mat3 xyz_d65_to_rec709() { return rgb_to_xyz(rec709()).inverse(); }

OCIO::MatrixTransformRcPtr matrix_transform(const Mat3& m) {
  auto t = OCIO::MatrixTransform::Create();
  const double v[16] = {m.m[0][0], m.m[0][1], m.m[0][2], 0, m.m[1][0], m.m[1][1], m.m[1][2], 0,
                        m.m[2][0], m.m[2][1], m.m[2][2], 0, 0,         0,         0,         1};
  t->setMatrix(v);
  return t;
}

namespace {

// The product of the processor's operations in double, when every one is a matrix without offset.
std::optional<Mat3> exact_matrix(const OCIO::ConstProcessorRcPtr& processor) {
  const OCIO::GroupTransformRcPtr ops = processor->createGroupTransform();
  Mat3 product;
  for (int i = 0; i < ops->getNumTransforms(); ++i) {
    const auto m = OCIO::DynamicPtrCast<const OCIO::MatrixTransform>(ops->getTransform(i));
    if (!m) return std::nullopt;
    double v[16], offset[4];
    m->getMatrix(v);
    m->getOffset(offset);
    if (offset[0] != 0 || offset[1] != 0 || offset[2] != 0 || v[3] != 0 || v[7] != 0 || v[11] != 0) return std::nullopt;
    Mat3 step;
    for (int r = 0; r < 3; ++r)
      for (int c = 0; c < 3; ++c) step.m[r][c] = v[4 * r + c];
    if (m->getDirection() == OCIO::TRANSFORM_DIR_INVERSE) step = step.inverse();
    product = step * product;
  }
  return product;
}

}  // namespace

std::optional<Mat3> processor_matrix(const OCIO::ConstProcessorRcPtr& processor, const std::optional<Mat3>& post) {
  const OCIO::ConstCPUProcessorRcPtr cpu = processor->getDefaultCPUProcessor();
  auto eval = [&](const double in[3], double out[3]) {
    float v[3] = {float(in[0]), float(in[1]), float(in[2])};
    cpu->applyRGB(v);
    double d[3] = {v[0], v[1], v[2]};
    if (post) post->apply(d[0], d[1], d[2]);
    for (int i = 0; i < 3; ++i) out[i] = d[i];
  };
  Mat3 m;
  for (int c = 0; c < 3; ++c) {
    double in[3] = {0, 0, 0}, out[3];
    in[c] = 1.0;
    eval(in, out);
    for (int r = 0; r < 3; ++r) m.m[r][c] = out[r];
  }
  const double probes[][3] = {{0, 0, 0},        {0.18, 0.18, 0.18}, {0.02, 0.5, 3},         {40, 0.01, 7},
                              {4, 0.5, 0.01},   {100, 20, 3},       {0.001, 0.002, 0.0005}, {0.3, 7, 1.5},
                              {200, 150, 90}};
  for (const auto& p : probes) {
    double out[3], want[3] = {p[0], p[1], p[2]};
    eval(p, out);
    m.apply(want[0], want[1], want[2]);
    const double scale = std::max({std::abs(want[0]), std::abs(want[1]), std::abs(want[2]), 1e-3});
    for (int i = 0; i < 3; ++i)
      if (!(std::abs(out[i] - want[i]) <= 1e-4 * scale)) return std::nullopt;
  }
  // The same conversion in double, when OCIO's operations say so (and agree with what was measured).
  if (auto exact = exact_matrix(processor)) {
    if (post) *exact = *post * *exact;
    if (max_abs_difference(*exact, m) <= 1e-5 * std::max(1.0, max_abs_difference(m, Mat3{{}}))) return exact;
  }
  return m;
}

std::optional<Mat3> conversion_matrix(const OCIO::ConstConfigRcPtr& config, const std::string& src,
                                      const std::string& dst) {
  OCIO::ConstProcessorRcPtr processor;
  try {
    processor = config->getProcessor(src.c_str(), dst.c_str());
  } catch (const OCIO::Exception&) {
    return std::nullopt;  // no conversion (display-referred without a view transform, a missing LUT, ...)
  }
  return processor_matrix(processor, std::nullopt);
}

WorkingSpace find_working_space(const OCIO::ConstConfigRcPtr& config) {
  const auto sl = config ? config->getColorSpace(OCIO::ROLE_SCENE_LINEAR) : nullptr;
  if (!sl) throw DataError("the config has no scene_linear role: cannot tell which colour space the operators read");
  WorkingSpace w;
  const std::pair<const char*, Mat3> interchanges[] = {{"aces_interchange", aces2065_to_rec709()},
                                                       {"cie_xyz_d65_interchange", xyz_d65_to_rec709()}};
  for (const auto& [role, to_rec709] : interchanges) {
    if (!config->hasRole(role) || !config->getColorSpace(role)) continue;
    if (const auto m = conversion_matrix(config, sl->getName(), config->getColorSpace(role)->getName())) {
      w.scene_linear_to_rec709 = to_rec709 * *m;
      w.basis = role;
      if (max_abs_difference(w.scene_linear_to_rec709, Mat3::identity()) <= kRec709Tolerance)
        w.scene_linear_to_rec709 = Mat3::identity();
      break;
    }
  }
  return w;
}

}  // namespace cgtmo::color
