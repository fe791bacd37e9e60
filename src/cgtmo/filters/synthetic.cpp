#include "cgtmo/filters/synthetic.h"

#include <cmath>
#include <cstdint>

#include "cgtmo/util/parallel.h"
#include "cgtmo/util/repro_math.h"

namespace cgtmo::filters {

GuidedInput SyntheticScene::view() const {
  GuidedInput in;
  in.width = width;
  in.height = height;
  in.log_lum = Channel{log_lum.data(), 1};
  for (int k = 0; k < 3; ++k) {
    in.position[k] = Channel{position[k].data(), 1};
    in.normal[k] = Channel{normal[k].data(), 1};
    in.albedo[k] = Channel{albedo[k].data(), 1};
  }
  in.mask = Channel{mask.data(), 1};
  in.footprint = Channel{footprint.data(), 1};
  return in;
}

namespace {

struct V3 {
  double x, y, z;
};
V3 operator+(V3 a, V3 b) { return {a.x + b.x, a.y + b.y, a.z + b.z}; }
V3 operator-(V3 a, V3 b) { return {a.x - b.x, a.y - b.y, a.z - b.z}; }
V3 operator*(V3 a, double s) { return {a.x * s, a.y * s, a.z * s}; }
double dot(V3 a, V3 b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
V3 normalize(V3 a) { return a * (1.0 / std::sqrt(dot(a, a))); }

struct Hit {
  double t = 1e30;
  V3 n{0, 0, 0}, albedo{0, 0, 0};
};

struct Sphere {
  V3 c;
  double r;
  V3 albedo;
};
const Sphere kSpheres[2] = {{{-0.7, 0.5, -1.0}, 0.5, {0.85, 0.85, 0.8}}, {{0.8, 0.35, -0.4}, 0.35, {0.08, 0.1, 0.3}}};

bool hit_sphere(const Sphere& s, V3 o, V3 d, double tmax, double& t) {
  const V3 oc = o - s.c;
  const double b = dot(oc, d), c = dot(oc, oc) - s.r * s.r, disc = b * b - c;
  if (disc < 0) return false;
  const double q = std::sqrt(disc);
  double tt = -b - q;
  if (tt < 1e-6) tt = -b + q;
  if (tt < 1e-6 || tt >= tmax) return false;
  t = tt;
  return true;
}

// The room: floor y=0, ceiling y=3, walls x=+-2, back wall z=-3 with a hole onto background.
Hit trace(V3 o, V3 d) {
  Hit h;
  auto plane = [&](double t, V3 n, V3 albedo) {
    if (t > 1e-6 && t < h.t && (o + d * t).z >= -3.0001) {  // the room ends at the back wall
      h.t = t;
      h.n = n;
      h.albedo = albedo;
    }
  };
  if (d.y < 0) {
    const double t = -o.y / d.y;
    const V3 p = o + d * t;
    const bool check = (int(std::floor(p.x)) + int(std::floor(p.z))) & 1;
    plane(t, {0, 1, 0}, check ? V3{0.75, 0.75, 0.7} : V3{0.15, 0.15, 0.15});
  }
  if (d.y > 0) plane((3.0 - o.y) / d.y, {0, -1, 0}, {0.8, 0.8, 0.8});
  if (d.x < 0) plane((-2.0 - o.x) / d.x, {1, 0, 0}, {0.6, 0.15, 0.1});
  if (d.x > 0) plane((2.0 - o.x) / d.x, {-1, 0, 0}, {0.1, 0.5, 0.15});
  if (d.z < 0) {
    const double t = (-3.0 - o.z) / d.z;
    const V3 p = o + d * t;
    const bool hole = std::fabs(p.x - 0.3) < 0.6 && p.y > 1.4 && p.y < 2.4;
    if (!hole) plane(t, {0, 0, 1}, {0.55, 0.55, 0.6});
  }
  for (const Sphere& s : kSpheres) {
    double t;
    if (hit_sphere(s, o, d, h.t, t)) {
      h.t = t;
      h.n = normalize((o + d * t) - s.c);
      h.albedo = s.albedo;
    }
  }
  return h;
}

double hash_normal(uint32_t x, uint32_t y, uint32_t seed) {
  auto mix = [](uint32_t v) {
    v ^= v >> 16;
    v *= 0x7feb352dU;
    v ^= v >> 15;
    v *= 0x846ca68bU;
    v ^= v >> 16;
    return v;
  };
  const uint32_t a = mix(x * 1973u + y * 9277u + seed * 26699u), b = mix(a ^ 0x9e3779b9u);
  const double u1 = (a + 0.5) / 4294967296.0, u2 = (b + 0.5) / 4294967296.0;
  return std::sqrt(-2.0 * repro::log(u1)) * repro::cos(2.0 * M_PI * u2);
}

}  // namespace

SyntheticScene make_synthetic_scene(int width, int height, float noise_log10, unsigned seed) {
  SyntheticScene s;
  s.width = width;
  s.height = height;
  const std::size_t n = std::size_t(width) * height;
  s.log_lum.assign(n, 0.0f);
  s.mask.assign(n, 0.0f);
  s.footprint.assign(n, 0.0f);
  for (int k = 0; k < 3; ++k) {
    s.position[k].assign(n, 0.0f);
    s.normal[k].assign(n, 0.0f);
    s.albedo[k].assign(n, 0.0f);
  }
  const V3 eye{0.0, 1.4, 3.5}, light{0.2, 2.7, -0.8};
  const double tan_half = repro::tan(0.5 * 70.0 * M_PI / 180.0);  // 70 degrees horizontal
  const double pixel_angle = 2.0 * tan_half / width;
  parallel_rows(height, [&](int64_t y0, int64_t y1) {
    for (int64_t y = y0; y < y1; ++y)
      for (int x = 0; x < width; ++x) {
        const std::size_t i = std::size_t(y) * width + x;
        const V3 d = normalize({(x + 0.5 - 0.5 * width) * pixel_angle, -(y + 0.5 - 0.5 * height) * pixel_angle, -1.0});
        const Hit hit = trace(eye, d);
        double lum;
        if (hit.t >= 1e29) {
          lum = 2000.0 + 500.0 * d.y;  // a bright sky seen through the hole
        } else {
          const V3 p = eye + d * hit.t;
          const V3 to_light = light - p;
          const double dist2 = dot(to_light, to_light);
          const V3 l = normalize(to_light);
          double shadow = 1.0, t;
          for (const Sphere& sp : kSpheres)
            if (hit_sphere(sp, p + hit.n * 1e-4, l, std::sqrt(dist2), t)) shadow = 0.0;
          const double cosine = std::max(0.0, dot(hit.n, l));
          const double albedo_y = 0.2126 * hit.albedo.x + 0.7152 * hit.albedo.y + 0.0722 * hit.albedo.z;
          lum = albedo_y / M_PI * (60.0 * cosine * shadow / dist2 + 0.6);
          s.mask[i] = 1.0f;
          s.position[0][i] = float(p.x);
          s.position[1][i] = float(p.y);
          s.position[2][i] = float(p.z);
          s.normal[0][i] = float(hit.n.x);
          s.normal[1][i] = float(hit.n.y);
          s.normal[2][i] = float(hit.n.z);
          s.albedo[0][i] = float(hit.albedo.x);
          s.albedo[1][i] = float(hit.albedo.y);
          s.albedo[2][i] = float(hit.albedo.z);
          // World size of a pixel: distance times the pixel's angle (perpendicular to the ray).
          s.footprint[i] = float(hit.t * pixel_angle);
        }
        double v = repro::log10(std::max(lum, 1e-6));
        if (noise_log10 > 0.0f) v += noise_log10 * hash_normal(uint32_t(x), uint32_t(y), seed);
        s.log_lum[i] = float(v);
      }
  });
  return s;
}

}  // namespace cgtmo::filters
