#pragma once
// RGB colour spaces given by their CIE 1931 xy chromaticities (the OpenEXR `chromaticities`
// attribute's data): the RGB -> XYZ matrix, Bradford chromatic adaptation between white points,
// and the matrix into cgtmo's working space, linear Rec.709 with a D65 white.
// Data only; input_space.h decides which conversion a file gets.
#include <optional>
#include <string>

#include "cgtmo/color/matrix.h"

namespace cgtmo::color {

// xy of the red, green and blue primaries and of the white point.
struct Chromaticities {
  double red[2], green[2], blue[2], white[2];
};

// Named sets, as published (ITU-R BT.709, SMPTE ST 2065-1 / S-2014-004, ITU-R BT.2020, SMPTE EG 432-1).
Chromaticities rec709();
Chromaticities aces_ap1();  // ACEScg
Chromaticities aces_ap0();  // ACES2065-1
Chromaticities rec2020();
Chromaticities p3_d65();
Chromaticities cie_xyz();  // primaries (1,0), (0,1), (0,0) and the equal-energy white E

// White points (xy).
inline constexpr double kD65[2] = {0.3127, 0.3290};
inline constexpr double kD60Aces[2] = {0.32168, 0.33767};

// The normalised primary matrix: RGB -> XYZ, with RGB (1,1,1) mapping to the white at Y = 1.
// Throws DataError when the chromaticities are degenerate (collinear primaries, y <= 0, non-finite).
Mat3 rgb_to_xyz(const Chromaticities& c);

// XYZ under white `from` -> XYZ under white `to` (Bradford cone response; identity when equal).
Mat3 bradford(const double from[2], const double to[2]);

// RGB in `c` -> linear Rec.709 (D65): RGB -> XYZ -> Bradford to D65 -> Rec.709. CIE XYZ with
// white E (OpenEXR's label for XYZ data) is colorimetric: XYZ -> Rec.709 with no adaptation.
Mat3 to_rec709(const Chromaticities& c);

// "ACEScg (AP1) primaries, ACES white (D60)" for a known set (within 5e-4 in xy), else the
// numbers: "primaries R (0.7,0.3) G (...) B (...), white (x,y)".
std::string describe(const Chromaticities& c);

// True when every coordinate of `a` and `b` agrees within `tolerance`.
bool same_chromaticities(const Chromaticities& a, const Chromaticities& b, double tolerance = 5e-4);

// The published set that a float32 attribute (OpenEXR stores chromaticities as float) was rounded
// from: primaries and white are each replaced by the named set whose every coordinate rounds to
// the stored float; anything else is returned as stored. The matrix of a rounded set differs from
// the published one by ~1e-7 per element, enough to leave colour in a pure primary at 2^13.
Chromaticities published_from_float32(const Chromaticities& stored);

// Largest absolute difference between the elements of two matrices.
double max_abs_difference(const Mat3& a, const Mat3& b);

}  // namespace cgtmo::color
