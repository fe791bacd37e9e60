#pragma once
// How an operator is baked for OpenColorIO: a log2 shaper, then a 1D LUT (per-channel curve, with
// the operator's matrices kept as matrices) or a 3D LUT (operators that mix channels), then a clamp
// to [0, 1]. The LUT values are sampled from the registry's evaluator, never from a second copy of
// a curve. 3D LUTs hold unclamped values, stored as log2(y + 2^k) so that interpolation error is
// relative (as the eye and the display encoding see it), and the clamp comes after the LUT.
#include <OpenColorIO/OpenColorIO.h>

#include <optional>
#include <string>
#include <vector>

#include "cgtmo/color/matrix.h"
#include "cgtmo/operators/operator.h"

namespace cgtmo::bake {

namespace OCIO = OCIO_NAMESPACE;

// A RangeTransform that clamps every channel to [lo, hi].
OCIO::TransformRcPtr range_clamp(double lo, double hi);

// s = (log2(x + 2^lo) - lo) / (hi - lo): 0 at x = 0, 1 at x = 2^hi - 2^lo; linear in x well below
// 2^lo and logarithmic above, so black and every stop up to 2^hi get nodes.
struct Log2Shaper {
  int lo = -18;
  int hi = 16;
  double forward(double x) const;
  double inverse(double s) const;
  OCIO::TransformRcPtr transform(OCIO::TransformDirection dir = OCIO::TRANSFORM_DIR_FORWARD) const;
  std::string describe() const;  // "log2(x + 2^-8) over [-8, 16]"
};

// The config's "Log2 Shaper" colour space, the process space of every look and the input of the
// .cube exports: wide enough for every operator's window, 2^-18 to 65504.
inline constexpr Log2Shaper kShaperSpace{-18, 16};

// A LUT design: what --max-error chooses between.
struct Representation {
  int dims = 1;          // 1: per-channel curve (or luminance curve, below); 3: RGB -> RGB
  // 1D only: the operator scales RGB by curve(Y) / Y (Y: the library's luminance), which keeps
  // chromaticity. Baked as RGB -> (R, Y, B) matrix -> XYZ_TO_xyY -> 1D LUT that is the identity on
  // the two chromaticity channels and the curve on Y (behind a log2 shaper on Y only) -> back.
  bool luminance = false;
  // 1D only: the operator keeps hue in the steps of operators::HueKeepingSteps. Baked with
  // RGB_TO_HSV, then four 1D LUTs (toe of the minimum, shoulder and desaturation of the peak, in
  // log2 with matrices between them) and back to RGB; the whole chain is one .ctf file.
  bool hue_steps = false;
  // 3D only: a per-channel pre-curve (1D LUT of warp_size entries behind the shaper, one column
  // per channel, values in [0, 1]) moves each axis's nodes to where the operator curves: node
  // density along an axis follows sqrt(|second derivative| x code-value sensitivity) of the
  // stored values, probed on lines through the cube (node_warp), smoothed. Generic: found by
  // probing the evaluator, no property of the operator assumed. Chain: clamp to [0, 65504] ->
  // shaper -> pre-curve -> 3D LUT -> decode -> clamp; the whole chain is one .ctf file.
  bool warped = false;
  int warp_size = 1024;
  int size = 4096;       // entries (1D) or nodes per axis (3D)
  Log2Shaper shaper;     // the LUT's own input shaper (its window of the input range)
  int out_log2 = 0;      // 3D only: values stored as log2(y + 2^out_log2)
  std::string describe() const;   // for reports: "1D 1024, log2 [-12, 16]", "1D 1024 on Y (xyY), log2 [-12, 16]"
  std::string extension() const;  // ".spi1d", ".spi3d" or ".ctf" (hue_steps, warped)
};

// A sampled LUT with the matrices that surround it.
struct BakedLut {
  Representation rep;
  // 1D: size (luminance: size RGB triples; hue_steps: four tables of size, see lut.cpp);
  // 3D: size^3 RGB triples, red slowest, blue fastest.
  std::vector<float> values;
  std::optional<color::Mat3> input_matrix, output_matrix;
  // warped 3D only: the pre-curve, warp_size RGB triples (s per channel at the shaper's entries).
  std::vector<float> warp;
};

// Samples `ev` (built with clamp_output = false for 3D) into the representation.
// 1D requires a per-channel evaluator, or (luminance) one for which scales_by_luminance() holds,
// or (hue_steps) one with hue_keeping_steps(); hue_steps_apply() says whether it can be baked.
BakedLut sample_lut(const operators::Evaluator& ev, const Representation& rep);

// True when `ev` (unclamped) maps every RGB to RGB * curve(Y) / Y, Y = the library's Rec.709
// luminance: checked on a grid of colours from black-adjacent to 65504 (relative 1e-3), so any
// operator with that property (luminance mode, saturation 1) is recognised without naming it.
bool scales_by_luminance(const operators::Evaluator& ev);

// True when `ev` has hue_keeping_steps() whose peak map can be undone in the baked chain (the
// chain needs log2 R(p) + 3 log2 p increasing, R = shoulder(p) desaturation(p) / p).
bool hue_steps_apply(const operators::Evaluator& ev);

// The warped design's pre-curve for `ev` (unclamped): per channel, s(u) at warp_size evenly
// spaced shaper values u, increasing from 0 to 1, as warp_size RGB triples. Along each input axis
// the stored values of every output channel are probed on lines through the cube (the other two
// channels at 0 and at 11 shaper levels); a linear interpolation error is h^2 |f''| / 8, so nodes
// are spaced as 1 / sqrt(|f''| x code values per stored unit), the largest over the lines.
std::vector<float> node_warp(const operators::Evaluator& ev, const Representation& rep);

// A 3D LUT's nodes along channel c, as scene-linear inputs: shaper value j / (size - 1), or
// (warped) where the pre-curve `warp` (linear between its entries, as OCIO interpolates it)
// reaches j / (size - 1).
std::vector<double> node_axis(const Representation& rep, const std::vector<float>& warp, int c);
// The pre-curve of channel c at shaper value u (linear between entries; u itself when not warped).
double warp_at(const Representation& rep, const std::vector<float>& warp, int c, double u);

// The RGB -> (R, Y, B) matrix of the luminance design: its middle row is the library's luminance
// weights (color/luminance.h), so Y is exactly the Y the operator scales by.
color::Mat3 rgb_to_ryb();

// The transform from scene-linear to display-linear [0, 1] that the LUT stands for. With an
// empty `lut_file` the LUT is inline (Lut1D/Lut3DTransform: for the search and the exports);
// otherwise a FileTransform of that file name (resolved through the config's search_path); a
// hue_steps or warped .ctf file holds the whole chain.
OCIO::GroupTransformRcPtr view_transform(const BakedLut& lut, const std::string& lut_file = "");

// The same as a look in kShaperSpace: shaper-encoded in, shaper-encoded out.
OCIO::GroupTransformRcPtr look_transform(const BakedLut& lut, const std::string& lut_file);

}  // namespace cgtmo::bake
