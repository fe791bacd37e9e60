#pragma once
// Small synthetic scenes for the pipeline's tests: a plane seen head-on (position = pixel grid
// times `spacing`, depth 1, footprint = spacing), with optional second object, background,
// light groups and probe. Everything is explicit so each test states what it varies.
#include <cmath>
#include <functional>
#include <string>
#include <vector>

#include "cgtmo/filters/filter_table.h"
#include "cgtmo/scene/frame.h"

namespace cgtmo::local::test {

inline scene::Frame plane_scene(int w, int h, const std::function<float(int, int)>& lum, double spacing = 0.01) {
  scene::Frame s;
  s.width = w;
  s.height = h;
  const std::size_t n = std::size_t(w) * h;
  s.beauty.resize(n * 3);
  s.position.resize(n * 3);
  s.normal.resize(n * 3);
  s.albedo.assign(n * 3, 0.5f);
  s.depth.assign(n, 1.0f);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      const std::size_t i = std::size_t(y) * w + x;
      const float l = lum(x, y);
      s.beauty[3 * i] = s.beauty[3 * i + 1] = s.beauty[3 * i + 2] = l;  // grey: luminance = l
      s.position[3 * i] = float(x * spacing);
      s.position[3 * i + 1] = float(y * spacing);
      s.position[3 * i + 2] = 0.f;
      s.normal[3 * i + 2] = 1.f;
    }
  s.footprint_at_1m = spacing;
  return s;
}

// A light group as the loader leaves it: its luminance per pixel (the RGB is not kept).
inline scene::LightGroupPlane light_group(const std::string& name, std::vector<float> luminance) {
  scene::LightGroupPlane g;
  g.name = name;
  g.luminance = std::move(luminance);
  return g;
}

// A probe of `w` x `h` pixels whose luminance is row_lum(row).
inline scene::Probe probe(int w, int h, const std::function<float(int)>& row_lum) {
  scene::Probe p;
  p.width = w;
  p.height = h;
  p.luminance.resize(std::size_t(w) * h);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) p.luminance[std::size_t(y) * w + x] = row_lum(y);
  return p;
}

// Drago 2003 written out from the paper (not through operators/drago_curve.h):
// Ld = (ld_max/100) / log10(1 + Lmax') * ln(1 + L') / ln(2 + 8 (L'/Lmax')^(ln b / ln 0.5)).
inline double drago_by_hand(double l, double lw_max, double lw_a, double b = 0.85, double ld_max = 100) {
  const double lp = l / lw_a, mp = lw_max / lw_a;
  return (ld_max / 100) / std::log10(1 + mp) * std::log(1 + lp) / std::log(2 + 8 * std::pow(lp / mp, std::log(b) / std::log(0.5)));
}

// Every filter an operator runs (filters/filter_table.h: cgtmo's choices and wls).
inline std::vector<std::string> operator_filters() {
  std::vector<std::string> v;
  for (const auto& f : cgtmo::filters::filter_table())
    if (*f.used_by) v.emplace_back(f.name);
  return v;
}

}  // namespace cgtmo::local::test
