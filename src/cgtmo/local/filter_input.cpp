#include "cgtmo/local/filter_input.h"

#include <algorithm>
#include <cmath>
#include <sstream>

#include "cgtmo/color/luminance.h"
#include "cgtmo/local/explain_number.h"
#include "cgtmo/local/stats.h"

namespace cgtmo::local {

double log_floor_of(double lw_a) { return std::max(kLogFloorRelative * lw_a, 1e-12); }

std::vector<float> beauty_luminance(const scene::Frame& s) { return color::luminance_plane(s.beauty, s.channels); }

void FilterInput::release() {
  for (std::vector<float>* plane : {&log_lum, &mask, &footprint, &normal}) std::vector<float>().swap(*plane);
  input = filters::GuidedInput{};
}

FilterInput build_filter_input(const scene::Frame& s, std::vector<float> log_lum) {
  const std::size_t n = s.pixel_count();
  FilterInput fi;
  fi.log_lum = std::move(log_lum);
  filters::GuidedInput& in = fi.input;
  in.width = s.width;
  in.height = s.height;
  in.log_lum = filters::Channel{fi.log_lum.data(), 1};

  // Background: the reader's mask (depth at 1e10 in Blender, or non-finite).
  std::vector<float>& mask = fi.mask;
  if (!s.depth.empty() || !s.background.empty()) {
    mask.resize(n);
    for (std::size_t i = 0; i < n; ++i) {
      const bool background = is_background(s, i);
      mask[i] = background ? 0.f : 1.f;
      fi.background += background;
    }
  } else {
    fi.lines.push_back("background: no depth pass, every pixel is treated as geometry");
  }
  fi.background_fraction = n ? double(fi.background) / double(n) : 0.0;

  // Normals: the filters compare them as stored, so they must be unit length. The reader has
  // renormalised them already (Blender averages them over samples); a scene built by hand with
  // unnormalised ones gets a renormalised copy. A normal without a direction makes its pixel
  // background for the filter (mask 0): that pixel is neither a source nor filtered, and gets the
  // global curve. No copy when none needs it: three float planes less at the peak.
  const float* normal_data = s.normal.empty() ? nullptr : s.normal.data();
  if (normal_data) {
    if (s.normal_valid.empty()) {
      bool unit = true;
      for (std::size_t i = 0; i < n && unit; ++i) {
        const float* v = &s.normal[3 * i];
        const float len2 = v[0] * v[0] + v[1] * v[1] + v[2] * v[2];
        unit = !(std::abs(len2 - 1.0f) > 1e-5f) || !has_normal(s, i);
      }
      if (!unit) {
        fi.normal = s.normal;
        for (std::size_t i = 0; i < n; ++i) {
          if (!has_normal(s, i)) continue;
          float* v = &fi.normal[3 * i];
          const float len = std::sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
          v[0] /= len, v[1] /= len, v[2] /= len;
        }
        normal_data = fi.normal.data();
      }
    }
    for (std::size_t i = 0; i < n; ++i) {
      if (has_normal(s, i)) continue;
      if (mask.empty()) mask.assign(n, 1.f);
      if (mask[i] > 0.5f) {
        mask[i] = 0.f;
        ++fi.invalid_normals;
      }
    }
  }
  if (!mask.empty()) in.mask = filters::Channel{mask.data(), 1};

  if (!s.position.empty()) {
    for (int k = 0; k < 3; ++k) in.position[k] = filters::Channel{s.position.data() + k, 3};
    fi.available |= filters::kGuidePosition;
    if (s.footprint_at_1m > 0 && !s.depth.empty()) {
      fi.footprint.resize(n);
      for (std::size_t i = 0; i < n; ++i) fi.footprint[i] = float(double(s.depth[i]) * s.footprint_at_1m);
      fi.lines.push_back("footprint: depth x " + explain_number(s.footprint_at_1m) + " (sidecar camera)");
    } else {
      fi.footprint = filters::footprint_from_positions(in);
      fi.lines.push_back("footprint: from neighbouring positions (no sidecar camera or depth)");
    }
    in.footprint = filters::Channel{fi.footprint.data(), 1};
  }
  if (normal_data) {
    for (int k = 0; k < 3; ++k) in.normal[k] = filters::Channel{normal_data + k, 3};
    fi.available |= filters::kGuideNormal;
  }
  if (!s.albedo.empty()) {
    for (int k = 0; k < 3; ++k) in.albedo[k] = filters::Channel{s.albedo.data() + k, 3};
    fi.available |= filters::kGuideAlbedo;
  }
  if (fi.invalid_normals)
    fi.lines.push_back("normals: " + std::to_string(fi.invalid_normals) +
                       " zero-length (no direction): those pixels take the global curve");
  return fi;
}

FilterInput luminance_filter_input(const scene::Frame& s, const LocalOptions& opt, double* lw_a_used) {
  std::vector<float> lum = beauty_luminance(s);
  double lw_a = opt.lw_a;
  if (!(lw_a > 0)) lw_a = compute_scene_stats(s, lum, opt.adaptation_options()).lw_a;
  if (lw_a_used) *lw_a_used = lw_a;
  const double floor = log_floor_of(lw_a);
  for (float& v : lum) v = floored_log10(v, floor);
  return build_filter_input(s, std::move(lum));
}

}  // namespace cgtmo::local
