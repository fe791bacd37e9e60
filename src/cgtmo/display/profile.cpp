#include "cgtmo/display/profile.h"

#include <lcms2.h>

#include <cmath>
#include <cstdint>
#include <sstream>

#include "cgtmo/color/working_space.h"
#include "cgtmo/errors.h"
#include "cgtmo/util/repro_math.h"

namespace cgtmo::display {

namespace {

using Mat3 = std::array<std::array<double, 3>, 3>;

// Linear Rec.709 (D65) to CIE XYZ, IEC 61966-2-1.
constexpr Mat3 kRec709ToXyz = {{{0.4123908, 0.3575843, 0.1804808},
                                {0.2126390, 0.7151687, 0.0721923},
                                {0.0193308, 0.1191948, 0.9505322}}};

Mat3 multiply(const Mat3& a, const Mat3& b) {
  Mat3 c{};
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j)
      for (int k = 0; k < 3; ++k) c[i][j] += a[i][k] * b[k][j];
  return c;
}

bool invert(const Mat3& m, Mat3* out) {
  const double det = m[0][0] * (m[1][1] * m[2][2] - m[1][2] * m[2][1]) - m[0][1] * (m[1][0] * m[2][2] - m[1][2] * m[2][0]) +
                     m[0][2] * (m[1][0] * m[2][1] - m[1][1] * m[2][0]);
  if (!(std::abs(det) > 1e-9)) return false;
  Mat3& r = *out;
  r[0][0] = (m[1][1] * m[2][2] - m[1][2] * m[2][1]) / det;
  r[0][1] = (m[0][2] * m[2][1] - m[0][1] * m[2][2]) / det;
  r[0][2] = (m[0][1] * m[1][2] - m[0][2] * m[1][1]) / det;
  r[1][0] = (m[1][2] * m[2][0] - m[1][0] * m[2][2]) / det;
  r[1][1] = (m[0][0] * m[2][2] - m[0][2] * m[2][0]) / det;
  r[1][2] = (m[0][2] * m[1][0] - m[0][0] * m[1][2]) / det;
  r[2][0] = (m[1][0] * m[2][1] - m[1][1] * m[2][0]) / det;
  r[2][1] = (m[0][1] * m[2][0] - m[0][0] * m[2][1]) / det;
  r[2][2] = (m[0][0] * m[1][1] - m[0][1] * m[1][0]) / det;
  return true;
}

double srgb_encode(double x) { return x <= 0.0031308 ? 12.92 * x : 1.055 * repro::pow(x, 1 / 2.4) - 0.055; }
double srgb_decode(double e) { return e <= 0.04045 ? e / 12.92 : repro::pow((e + 0.055) / 1.055, 2.4); }

struct Trc {
  bool srgb = false;
  double gamma = 1;
  double encode(double x) const { return srgb ? srgb_encode(x) : repro::pow(x, 1 / gamma); }
  double decode(double e) const { return srgb ? srgb_decode(e) : repro::pow(e, gamma); }
};

constexpr double kTolerance = 1e-3;  // encoded units: about a quarter of an 8-bit code value

std::array<float, 3> run(const OCIO::ConstCPUProcessorRcPtr& cpu, double r, double g, double b) {
  float px[3] = {float(r), float(g), float(b)};
  cpu->applyRGB(px);
  return {px[0], px[1], px[2]};
}

std::array<double, 2> xy_of(double X, double Y, double Z) {
  const double s = X + Y + Z;
  return {X / s, Y / s};
}

std::string fixed(double v, int digits) {
  std::ostringstream s;
  s.precision(digits);
  s << std::fixed << v;
  return s.str();
}

}  // namespace

std::string DisplayProfile::transfer_name() const {
  if (srgb_curve) return "sRGB";
  return gamma == 1.0 ? "linear" : "gamma " + fixed(gamma, 2);
}

DisplayProfile describe_display(const OCIO::ConstConfigRcPtr& config, const std::string& display, const std::string& view) {
  DisplayProfile p;
  p.colorspace = config->getDisplayViewColorSpaceName(display.c_str(), view.c_str());
  auto unknown = [&p](const std::string& why) {
    p.known = false;
    p.why = why;
    return p;
  };
  const auto cs = config->getColorSpace(p.colorspace.c_str());
  if (!cs) return unknown("view '" + view + "' names no colour space of the config");
  if (cs->isData()) return unknown("colour space '" + p.colorspace + "' is data (no display encoding)");
  if (cs->getReferenceSpaceType() == OCIO::REFERENCE_SPACE_DISPLAY)
    return unknown("colour space '" + p.colorspace + "' is display-referred");
  OCIO::ConstCPUProcessorRcPtr cpu;
  try {
    // From linear Rec.709, what the operators output (color/working_space.h).
    auto g = OCIO::GroupTransform::Create();
    const color::WorkingSpace w = color::find_working_space(config);
    if (!w.is_rec709()) g->appendTransform(color::matrix_transform(w.scene_linear_to_rec709.inverse()));
    auto to_display = OCIO::ColorSpaceTransform::Create();
    to_display->setSrc(OCIO::ROLE_SCENE_LINEAR);
    to_display->setDst(p.colorspace.c_str());
    g->appendTransform(to_display);
    cpu = config->getProcessor(g)->getDefaultCPUProcessor();
  } catch (const OCIO::Exception& e) {
    std::string msg = e.what();
    return unknown("OCIO cannot convert to '" + p.colorspace + "': " + msg.substr(0, msg.find('\n')));
  }
  const std::string not_model = "colour space '" + p.colorspace + "' is not a matrix and an sRGB or power-law curve";

  // 1. The curve, from a grey ramp (greys must stay grey: the white is the one of the primaries).
  std::vector<double> grey_in, grey_out;
  for (int i = 1; i <= 64; ++i) {
    const double g = i / 64.0;
    const auto e = run(cpu, g, g, g);
    if (std::abs(e[0] - e[1]) > kTolerance || std::abs(e[0] - e[2]) > kTolerance) return unknown(not_model);
    grey_in.push_back(g);
    grey_out.push_back(e[1]);
  }
  auto fits = [&](const Trc& t) {
    for (std::size_t i = 0; i < grey_in.size(); ++i)
      if (!(std::abs(t.encode(grey_in[i]) - grey_out[i]) <= kTolerance)) return false;
    return true;
  };
  Trc trc;
  trc.srgb = true;
  if (!fits(trc)) {
    // A power law: the exponent from the mid-grey, rounded to 0.01 as displays are specified.
    trc.srgb = false;
    const double e = grey_out[31];  // 0.5
    if (!(e > 0 && e < 1)) return unknown(not_model);
    trc.gamma = std::round(repro::log(0.5) / repro::log(e) * 100) / 100;
    if (!(trc.gamma > 0.2 && trc.gamma < 5) || !fits(trc)) return unknown(not_model);
  }

  // 2. The matrix, from each primary at a quarter (inside the range of any display).
  Mat3 m{};
  for (int c = 0; c < 3; ++c) {
    double in[3] = {0, 0, 0};
    in[c] = 0.25;
    const auto e = run(cpu, in[0], in[1], in[2]);
    for (int r = 0; r < 3; ++r) {
      if (!(e[r] >= 0 && e[r] <= 1)) return unknown(not_model);
      m[r][c] = trc.decode(e[r]) / 0.25;
    }
  }

  // 3. The model must reproduce the processor on colours it does not come from.
  std::uint32_t seed = 12345;
  auto next = [&seed] {
    seed = seed * 1664525u + 1013904223u;
    return (seed >> 8) / double(1u << 24);
  };
  int checked = 0;
  for (int i = 0; i < 400 && checked < 100; ++i) {
    const double c[3] = {next(), next(), next()};
    double lin[3];
    bool inside = true;
    for (int r = 0; r < 3; ++r) {
      lin[r] = m[r][0] * c[0] + m[r][1] * c[1] + m[r][2] * c[2];
      inside = inside && lin[r] >= 0 && lin[r] <= 1;
    }
    if (!inside) continue;
    const auto e = run(cpu, c[0], c[1], c[2]);
    for (int r = 0; r < 3; ++r)
      if (!(std::abs(trc.encode(lin[r]) - e[r]) <= kTolerance)) return unknown(not_model);
    ++checked;
  }
  if (checked < 20) return unknown(not_model);

  // 4. Display RGB -> XYZ is Rec.709 -> XYZ after the inverse of M.
  Mat3 inv;
  if (!invert(m, &inv)) return unknown(not_model);
  const Mat3 to_xyz = multiply(kRec709ToXyz, inv);
  for (int c = 0; c < 3; ++c) p.primaries[c] = xy_of(to_xyz[0][c], to_xyz[1][c], to_xyz[2][c]);
  p.white = xy_of(to_xyz[0][0] + to_xyz[0][1] + to_xyz[0][2], to_xyz[1][0] + to_xyz[1][1] + to_xyz[1][2],
                  to_xyz[2][0] + to_xyz[2][1] + to_xyz[2][2]);
  p.srgb_curve = trc.srgb;
  p.gamma = trc.srgb ? 2.4 : trc.gamma;
  p.known = true;
  p.icc = make_icc_profile(p, "cgtmo " + display + " (" + p.colorspace + ", " + p.transfer_name() + ")");
  return p;
}

DisplayProfile linear_rec709_profile() {
  DisplayProfile p;
  p.known = true;
  p.colorspace = "linear Rec.709";
  const Mat3& m = kRec709ToXyz;
  for (int c = 0; c < 3; ++c) p.primaries[c] = xy_of(m[0][c], m[1][c], m[2][c]);
  p.white = {0.3127, 0.3290};
  p.gamma = 1.0;
  p.icc = make_icc_profile(p, "cgtmo linear Rec.709 (D65, linear)");
  return p;
}

std::vector<unsigned char> make_icc_profile(const DisplayProfile& p, const std::string& description) {
  cmsContext ctx = cmsCreateContext(nullptr, nullptr);
  if (!ctx) throw DataError("Little CMS: cannot create a context");
  cmsToneCurve* curve = nullptr;
  if (p.srgb_curve) {
    const cmsFloat64Number params[5] = {2.4, 1 / 1.055, 0.055 / 1.055, 1 / 12.92, 0.04045};
    curve = cmsBuildParametricToneCurve(ctx, 4, params);
  } else {
    curve = cmsBuildGamma(ctx, p.gamma);
  }
  const cmsCIExyY white = {p.white[0], p.white[1], 1.0};
  const cmsCIExyYTRIPLE primaries = {{p.primaries[0][0], p.primaries[0][1], 1.0},
                                     {p.primaries[1][0], p.primaries[1][1], 1.0},
                                     {p.primaries[2][0], p.primaries[2][1], 1.0}};
  cmsToneCurve* curves[3] = {curve, curve, curve};
  cmsHPROFILE h = curve ? cmsCreateRGBProfileTHR(ctx, &white, &primaries, curves) : nullptr;
  std::vector<unsigned char> bytes;
  if (h) {
    cmsMLU* desc = cmsMLUalloc(ctx, 1);
    cmsMLU* copyright = cmsMLUalloc(ctx, 1);
    cmsMLUsetASCII(desc, "en", "US", description.c_str());
    cmsMLUsetASCII(copyright, "en", "US", "No copyright, use freely");
    cmsWriteTag(h, cmsSigProfileDescriptionTag, desc);
    cmsWriteTag(h, cmsSigCopyrightTag, copyright);
    cmsMLUfree(desc);
    cmsMLUfree(copyright);
    cmsUInt32Number size = 0;
    if (cmsSaveProfileToMem(h, nullptr, &size) && size > 0) {
      bytes.resize(size);
      if (!cmsSaveProfileToMem(h, bytes.data(), &size)) bytes.clear();
      bytes.resize(size);
    }
    cmsCloseProfile(h);
  }
  if (curve) cmsFreeToneCurve(curve);
  cmsDeleteContext(ctx);
  if (bytes.size() < 128) throw DataError("Little CMS: cannot build the ICC profile '" + description + "'");
  // Little CMS stamps the header with the time of saving (bytes 24-35, six big-endian uint16: year,
  // month, day, hour, minute, second); a fixed date makes two runs write the same bytes. The
  // profile ID (bytes 84-99) is left zero ("not computed"), so nothing else depends on the date.
  const std::uint16_t date[6] = {2000, 1, 1, 0, 0, 0};
  for (int i = 0; i < 6; ++i) {
    bytes[24 + 2 * i] = static_cast<unsigned char>(date[i] >> 8);
    bytes[25 + 2 * i] = static_cast<unsigned char>(date[i] & 0xff);
  }
  return bytes;
}

}  // namespace cgtmo::display
