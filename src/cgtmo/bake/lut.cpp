#include "cgtmo/bake/lut.h"

#include <cmath>
#include <sstream>

#include "cgtmo/util/parallel.h"

namespace cgtmo::bake {

double Log2Shaper::forward(double x) const {
  const double l = std::log2(std::max(x, 0.0) + std::ldexp(1.0, lo));
  return (l - lo) / double(hi - lo);
}

double Log2Shaper::inverse(double s) const {
  return std::exp2(lo + s * double(hi - lo)) - std::ldexp(1.0, lo);
}

OCIO::TransformRcPtr Log2Shaper::transform(OCIO::TransformDirection dir) const {
  auto t = OCIO::LogAffineTransform::Create();
  t->setBase(2.0);
  const double lin_slope[3] = {1, 1, 1};
  const double lin_offset[3] = {std::ldexp(1.0, lo), std::ldexp(1.0, lo), std::ldexp(1.0, lo)};
  const double k = 1.0 / double(hi - lo);
  const double log_slope[3] = {k, k, k};
  const double log_offset[3] = {-lo * k, -lo * k, -lo * k};
  t->setLinSideSlopeValue(lin_slope);
  t->setLinSideOffsetValue(lin_offset);
  t->setLogSideSlopeValue(log_slope);
  t->setLogSideOffsetValue(log_offset);
  t->setDirection(dir);
  return t;
}

std::string Log2Shaper::describe() const {
  std::ostringstream s;
  s << "log2 [" << lo << ", " << hi << "]";
  return s.str();
}

std::string Representation::describe() const {
  std::ostringstream s;
  s << dims << "D " << size;
  if (dims == 3) s << "^3";
  s << ", " << shaper.describe();
  if (dims == 3) s << ", out log2(y+2^" << out_log2 << ")";
  return s.str();
}

std::string Representation::extension() const { return dims == 1 ? ".spi1d" : ".spi3d"; }

namespace {

// Decodes values stored as log2(y + 2^k).
OCIO::TransformRcPtr output_decode(int k) {
  auto t = OCIO::LogAffineTransform::Create();
  t->setBase(2.0);
  const double off[3] = {std::ldexp(1.0, k), std::ldexp(1.0, k), std::ldexp(1.0, k)};
  t->setLinSideOffsetValue(off);
  t->setDirection(OCIO::TRANSFORM_DIR_INVERSE);
  return t;
}

OCIO::TransformRcPtr matrix(const color::Mat3& m) {
  auto t = OCIO::MatrixTransform::Create();
  double v[16] = {m.m[0][0], m.m[0][1], m.m[0][2], 0, m.m[1][0], m.m[1][1], m.m[1][2], 0,
                  m.m[2][0], m.m[2][1], m.m[2][2], 0, 0,         0,         0,         1};
  t->setMatrix(v);
  return t;
}

OCIO::TransformRcPtr clamp01() {
  auto t = OCIO::RangeTransform::Create();
  t->setStyle(OCIO::RANGE_CLAMP);
  t->setMinInValue(0.0);
  t->setMinOutValue(0.0);
  t->setMaxInValue(1.0);
  t->setMaxOutValue(1.0);
  return t;
}

OCIO::TransformRcPtr lut_transform(const BakedLut& lut, const std::string& file) {
  const Representation& r = lut.rep;
  if (!file.empty()) {
    auto f = OCIO::FileTransform::Create();
    f->setSrc(file.c_str());
    f->setInterpolation(r.dims == 1 ? OCIO::INTERP_LINEAR : OCIO::INTERP_TETRAHEDRAL);
    return f;
  }
  if (r.dims == 1) {
    auto t = OCIO::Lut1DTransform::Create();
    t->setLength(unsigned(r.size));
    for (int i = 0; i < r.size; ++i) t->setValue(unsigned(i), lut.values[i], lut.values[i], lut.values[i]);
    t->setInterpolation(OCIO::INTERP_LINEAR);
    return t;
  }
  auto t = OCIO::Lut3DTransform::Create();
  t->setGridSize(unsigned(r.size));
  const unsigned n = unsigned(r.size);
  for (unsigned i = 0; i < n; ++i)
    for (unsigned j = 0; j < n; ++j)
      for (unsigned k = 0; k < n; ++k) {
        const float* v = &lut.values[((std::size_t(i) * n + j) * n + k) * 3];
        t->setValue(i, j, k, v[0], v[1], v[2]);
      }
  t->setInterpolation(OCIO::INTERP_TETRAHEDRAL);
  return t;
}

// After the LUT: decode, output matrix, clamp.
void append_tail(OCIO::GroupTransformRcPtr& g, const BakedLut& lut) {
  if (lut.rep.dims == 3) g->appendTransform(output_decode(lut.rep.out_log2));
  if (lut.output_matrix) g->appendTransform(matrix(*lut.output_matrix));
  g->appendTransform(clamp01());
}

}  // namespace

BakedLut sample_lut(const operators::Evaluator& ev, const Representation& rep) {
  BakedLut out;
  out.rep = rep;
  out.input_matrix = ev.input_matrix;
  out.output_matrix = ev.output_matrix;
  const int n = rep.size;
  if (rep.dims == 1) {
    out.values.resize(std::size_t(n));
    for (int i = 0; i < n; ++i) out.values[i] = float(ev.curve(rep.shaper.inverse(double(i) / (n - 1))));
    return out;
  }
  // 3D: the whole operator (matrices included) on every node, unclamped.
  std::vector<double> axis(static_cast<std::size_t>(n));
  for (int i = 0; i < n; ++i) axis[i] = rep.shaper.inverse(double(i) / (n - 1));
  const std::size_t nodes = std::size_t(n) * n * n;
  out.values.resize(nodes * 3);
  out.input_matrix.reset();
  out.output_matrix.reset();
  parallel_rows(n, [&](int64_t i0, int64_t i1) {
    for (int64_t i = i0; i < i1; ++i) {
      float* row = &out.values[std::size_t(i) * n * n * 3];
      for (int j = 0; j < n; ++j)
        for (int k = 0; k < n; ++k) {
          float* p = row + (std::size_t(j) * n + k) * 3;
          p[0] = float(axis[i]);
          p[1] = float(axis[j]);
          p[2] = float(axis[k]);
        }
      ev.apply(row, std::size_t(n) * n, 3);
      const double off = std::ldexp(1.0, rep.out_log2);
      for (std::size_t q = 0; q < std::size_t(n) * n * 3; ++q) row[q] = float(std::log2(std::max(double(row[q]), 0.0) + off));
    }
  });
  return out;
}

OCIO::GroupTransformRcPtr view_transform(const BakedLut& lut, const std::string& lut_file) {
  auto g = OCIO::GroupTransform::Create();
  if (lut.input_matrix) g->appendTransform(matrix(*lut.input_matrix));
  g->appendTransform(lut.rep.shaper.transform());
  g->appendTransform(lut_transform(lut, lut_file));
  append_tail(g, lut);
  return g;
}

OCIO::GroupTransformRcPtr look_transform(const BakedLut& lut, const std::string& lut_file) {
  auto g = OCIO::GroupTransform::Create();
  g->appendTransform(kShaperSpace.transform(OCIO::TRANSFORM_DIR_INVERSE));
  auto v = view_transform(lut, lut_file);
  for (int i = 0; i < v->getNumTransforms(); ++i) g->appendTransform(v->getTransform(i));
  g->appendTransform(kShaperSpace.transform());
  return g;
}

}  // namespace cgtmo::bake
