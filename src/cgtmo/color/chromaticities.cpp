#include "cgtmo/color/chromaticities.h"

#include <cmath>
#include <cstdio>

#include "cgtmo/errors.h"

namespace cgtmo::color {

Chromaticities rec709() { return {{0.640, 0.330}, {0.300, 0.600}, {0.150, 0.060}, {kD65[0], kD65[1]}}; }
Chromaticities aces_ap1() { return {{0.713, 0.293}, {0.165, 0.830}, {0.128, 0.044}, {kD60Aces[0], kD60Aces[1]}}; }
Chromaticities aces_ap0() { return {{0.7347, 0.2653}, {0.0, 1.0}, {0.0001, -0.0770}, {kD60Aces[0], kD60Aces[1]}}; }
Chromaticities rec2020() { return {{0.708, 0.292}, {0.170, 0.797}, {0.131, 0.046}, {kD65[0], kD65[1]}}; }
Chromaticities p3_d65() { return {{0.680, 0.320}, {0.265, 0.690}, {0.150, 0.060}, {kD65[0], kD65[1]}}; }
Chromaticities cie_xyz() { return {{1.0, 0.0}, {0.0, 1.0}, {0.0, 0.0}, {1.0 / 3.0, 1.0 / 3.0}}; }

namespace {

// xyY with Y = 1 -> XYZ. A primary with y = 0 (CIE XYZ's X and Z "primaries") has no finite
// XYZ at Y = 1: its column is taken at Y = 0 with unit sum instead (x, 0, 1 - x), which the
// normalisation below scales like any other column.
void xy_to_column(const double xy[2], double out[3]) {
  if (xy[1] == 0.0) {
    out[0] = xy[0];
    out[1] = 0.0;
    out[2] = 1.0 - xy[0];
    return;
  }
  out[0] = xy[0] / xy[1];
  out[1] = 1.0;
  out[2] = (1.0 - xy[0] - xy[1]) / xy[1];
}

double determinant(const Mat3& p) {
  const auto& a = p.m;
  return a[0][0] * (a[1][1] * a[2][2] - a[1][2] * a[2][1]) - a[0][1] * (a[1][0] * a[2][2] - a[1][2] * a[2][0]) +
         a[0][2] * (a[1][0] * a[2][1] - a[1][1] * a[2][0]);
}

bool finite_xy(const double xy[2]) { return std::isfinite(xy[0]) && std::isfinite(xy[1]); }

}  // namespace

Mat3 rgb_to_xyz(const Chromaticities& c) {
  const double* prim[3] = {c.red, c.green, c.blue};
  // A primary may lie outside the spectral locus (AP0's blue has y < 0): only finiteness is asked.
  for (const double* p : prim)
    if (!finite_xy(p)) throw DataError("chromaticities: a primary's xy is not finite");
  if (!finite_xy(c.white) || c.white[1] <= 0) throw DataError("chromaticities: the white point's y is not positive");
  Mat3 p;
  for (int col = 0; col < 3; ++col) {
    double v[3];
    xy_to_column(prim[col], v);
    for (int r = 0; r < 3; ++r) p.m[r][col] = v[r];
  }
  if (std::abs(determinant(p)) < 1e-9) throw DataError("chromaticities: the primaries are collinear");
  double w[3];
  xy_to_column(c.white, w);
  const Mat3 inv = p.inverse();
  double s[3];
  for (int i = 0; i < 3; ++i) s[i] = inv.m[i][0] * w[0] + inv.m[i][1] * w[1] + inv.m[i][2] * w[2];
  for (int r = 0; r < 3; ++r)
    for (int col = 0; col < 3; ++col) p.m[r][col] *= s[col];
  return p;
}

Mat3 bradford(const double from[2], const double to[2]) {
  if (from[0] == to[0] && from[1] == to[1]) return Mat3::identity();
  Mat3 b;
  b.m = {{{0.8951, 0.2664, -0.1614}, {-0.7502, 1.7135, 0.0367}, {0.0389, -0.0685, 1.0296}}};
  double ws[3], wd[3];
  xy_to_column(from, ws);
  xy_to_column(to, wd);
  Mat3 scale;
  for (int i = 0; i < 3; ++i) {
    const double cs = b.m[i][0] * ws[0] + b.m[i][1] * ws[1] + b.m[i][2] * ws[2];
    const double cd = b.m[i][0] * wd[0] + b.m[i][1] * wd[1] + b.m[i][2] * wd[2];
    scale.m[i][i] = cd / cs;
  }
  return b.inverse() * scale * b;
}

Mat3 to_rec709(const Chromaticities& c) {
  // OpenEXR labels XYZ data with white E only so that RGB (1,1,1) is XYZ (1,1,1): the values are
  // colorimetric, so they go to Rec.709 unadapted (as OCIO's cie_xyz_d65_interchange does).
  if (same_chromaticities(c, cie_xyz())) return rgb_to_xyz(rec709()).inverse();
  return rgb_to_xyz(rec709()).inverse() * bradford(c.white, kD65) * rgb_to_xyz(c);
}

bool same_chromaticities(const Chromaticities& a, const Chromaticities& b, double tol) {
  const double* pa[4] = {a.red, a.green, a.blue, a.white};
  const double* pb[4] = {b.red, b.green, b.blue, b.white};
  for (int i = 0; i < 4; ++i)
    for (int k = 0; k < 2; ++k)
      if (!(std::abs(pa[i][k] - pb[i][k]) <= tol)) return false;
  return true;
}

std::string describe(const Chromaticities& c) {
  struct Known {
    Chromaticities (*make)();
    const char* primaries;
  };
  static const Known known[] = {{rec709, "Rec.709/sRGB primaries"}, {aces_ap1, "ACEScg (AP1) primaries"},
                                {aces_ap0, "ACES2065-1 (AP0) primaries"}, {rec2020, "Rec.2020 primaries"},
                                {p3_d65, "P3 primaries"}, {cie_xyz, "CIE XYZ"}};
  const Chromaticities whites[] = {rec709(), aces_ap1(), cie_xyz()};
  const char* white_names[] = {"D65 white", "ACES white (D60)", "white E"};
  auto xy = [](const double v[2]) {
    char buf[64];
    std::snprintf(buf, sizeof buf, "(%.4g,%.4g)", v[0], v[1]);
    return std::string(buf);
  };
  std::string white = "white " + xy(c.white);
  for (int i = 0; i < 3; ++i) {
    Chromaticities probe = c;
    for (int k = 0; k < 2; ++k) probe.white[k] = whites[i].white[k];
    if (same_chromaticities(c, probe)) white = white_names[i];
  }
  for (const auto& k : known) {
    Chromaticities ref = k.make();
    for (int i = 0; i < 2; ++i) ref.white[i] = c.white[i];
    if (same_chromaticities(c, ref)) return std::string(k.primaries) + ", " + white;
  }
  return "primaries R " + xy(c.red) + " G " + xy(c.green) + " B " + xy(c.blue) + ", " + white;
}

Chromaticities published_from_float32(const Chromaticities& stored) {
  auto rounds_to = [](const double exact[2], const double v[2]) {
    return float(exact[0]) == float(v[0]) && float(exact[1]) == float(v[1]);
  };
  Chromaticities out = stored;
  for (auto make : {rec709, aces_ap1, aces_ap0, rec2020, p3_d65, cie_xyz}) {
    const Chromaticities k = make();
    if (rounds_to(k.red, stored.red) && rounds_to(k.green, stored.green) && rounds_to(k.blue, stored.blue)) {
      for (int i = 0; i < 2; ++i) out.red[i] = k.red[i], out.green[i] = k.green[i], out.blue[i] = k.blue[i];
      break;
    }
  }
  const double e[2] = {1.0 / 3.0, 1.0 / 3.0};
  for (const double* w : {kD65, kD60Aces, static_cast<const double*>(e)})
    if (rounds_to(w, stored.white)) {
      out.white[0] = w[0], out.white[1] = w[1];
      break;
    }
  return out;
}

double max_abs_difference(const Mat3& a, const Mat3& b) {
  double d = 0;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) d = std::max(d, std::abs(a.m[i][j] - b.m[i][j]));
  return d;
}

}  // namespace cgtmo::color
