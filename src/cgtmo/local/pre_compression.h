#pragma once
// output=scene-linear: the local pre-compression of the base layer (docs/cgtmo.md, section 11).
// With u = log2(base / Lw_a), a pixel's luminance is multiplied by 2^(u' - u), so its detail
// (luminance / base) is kept and Lw_a stays where it is:
//   highlights  above the knee K_h, v = u - K_h:  v' = v / (1 + k_h v)   (the base's maximum U lands
//               at the target T_h, slope 1 at the knee; k_h = 0 when U <= T_h: nothing to compress)
//   shadows     below -K_s, w = -(u + K_s):       w' = w / (1 + k_s w)   (everything below -K_s lands
//               in (-S, -K_s]: the deepest shadows approach S stops under Lw_a, slope 1 at the knee)
// The highlight target is set where scene-referred views put white: `white_stops` above the
// scene-linear mid grey 0.18 (Filmic and AgX clip 6.5 stops above it), so a scene exposed darker
// than that grey is compressed less.
namespace cgtmo::local {

// Scene-linear mid grey: where scene-referred view transforms (Filmic, AgX, ACES) anchor their range.
inline constexpr double kSceneLinearGrey = 0.18;

struct PreCompression {
  double target = 0;          // T_h: where the base's maximum lands, stops above Lw_a
  double knee_high = 0;       // K_h, stops above Lw_a
  double k_high = 0;          // 0: the highlights are left alone
  double knee_low = 0;        // K_s, stops under Lw_a
  double k_low = 0;           // 0: the shadows are left alone
  // log2 of the factor for a pixel whose base is 2^u Lw_a.
  double log2_gain(double u) const {
    if (k_high > 0 && u > knee_high) {
      const double v = u - knee_high;
      return v / (1 + k_high * v) - v;
    }
    if (k_low > 0 && u < -knee_low) {
      const double w = -(u + knee_low);
      return w - w / (1 + k_low * w);
    }
    return 0;
  }
};

// `headroom`: U, the base's maximum in stops above Lw_a. `white_stops`: where the maximum should
// land, in stops above kSceneLinearGrey (at least one stop above Lw_a). `shadow_stops`: S (0: no
// lift of the shadows).
PreCompression plan_pre_compression(double headroom, double lw_a, double white_stops, double shadow_stops);

}  // namespace cgtmo::local
