#pragma once
// What a display encoding is, colorimetrically, and the ICC profile that says so.
//
// The rule: the encoding of a display/view is the OCIO colour space of that view
// (Config::getDisplayViewColorSpaceName), taken without the view's looks; cgtmo's configs put the
// operator in the looks and the display encoding in the colour space. From scene_linear (linear
// Rec.709, D65: cgtmo's working space) to that colour space, OCIO's processor is sampled and fitted
// with the model  encoded = TRC(M * rgb)  where TRC is one of the sRGB piecewise curve or a pure
// power law, the same on the three channels. When the model reproduces the processor on a set of
// colours (within 1e-3), the display's primaries and white follow from M, and the profile is built
// with Little CMS. When it does not (a LUT, a tone curve or a gamut mapping inside the colour space,
// a display-referred colour space, data), the encoding is unknown: no profile, and `why` says so.
#include <array>
#include <string>
#include <vector>

#include <OpenColorIO/OpenColorIO.h>

namespace cgtmo::display {

namespace OCIO = OCIO_NAMESPACE;

struct DisplayProfile {
  bool known = false;
  std::string why;          // when !known: one clause, e.g. "colour space 'X' is not a matrix and a curve"
  std::string colorspace;   // the OCIO colour space that was examined
  std::array<std::array<double, 2>, 3> primaries{};  // CIE xy of R, G, B
  std::array<double, 2> white{};                     // CIE xy
  bool srgb_curve = false;  // the IEC 61966-2-1 piecewise curve; else a pure power law
  double gamma = 0;         // the power law's exponent (decoding: linear = encoded^gamma)
  std::vector<unsigned char> icc;  // the ICC profile (v4), empty when !known

  std::string transfer_name() const;  // "sRGB" or "gamma 2.4"
};

// Examines display/view of `config` (both must exist). Never throws for an unknown encoding.
DisplayProfile describe_display(const OCIO::ConstConfigRcPtr& config, const std::string& display,
                                const std::string& view);

// The profile of cgtmo's linear output (--no-display): Rec.709 primaries, D65, linear TRC.
DisplayProfile linear_rec709_profile();

// An ICC v4 display profile (Little CMS) for the given primaries, white and transfer.
std::vector<unsigned char> make_icc_profile(const DisplayProfile& p, const std::string& description);

}  // namespace cgtmo::display
