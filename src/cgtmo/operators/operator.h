#pragma once
// An operator is data (name, scope, kind, typed parameters, citation) plus an evaluation. The
// registry (registry.h) lists them all; the CLI, the baker, the bindings and the tests iterate it.
#include <cstddef>
#include <functional>
#include <map>
#include <memory>
#include <optional>
#include <set>
#include <string>
#include <vector>

#include "cgtmo/color/matrix.h"

namespace cgtmo::operators {

// Per-channel operators map each channel through one curve (optionally between two matrices) and
// bake to 1D LUTs; mixing operators couple the channels and need 3D LUTs.
enum class Kind { PerChannel, Mixing };
const char* kind_name(Kind k);

// What an operator reads. Pixel operators map each pixel alone (a per-pixel Evaluator: they bake to
// LUTs, run in OCIO and over any image); scene operators are local and read the render's passes,
// light groups, probe and sidecar (CG-TMO, the WLS baseline: cgtmo/apply_scene.h runs them).
enum class Scope { Pixel, Scene };
const char* scope_name(Scope s);  // "pixel", "scene"

// How a scalar curve is applied to RGB, where the operator's definition leaves it open.
enum class Mode { PerChannel, Luminance, MaxRGB };
const char* mode_name(Mode m);

enum class ParamType { Number, Choice, Text };

// Which image statistic a parameter takes when the user gives none.
enum class ImageDefault { None, MaxChannel, MaxLuminance, LogAverageLuminance };
// "max_channel", "max_luminance", "log_average_luminance" ("" for None): the one spelling every face shows.
const char* image_default_name(ImageDefault d);

struct ParamSpec {
  std::string name;
  ParamType type = ParamType::Number;
  double default_value = 0.0;  // Number
  double min_value = 0.0;      // Number, inclusive
  double max_value = 0.0;      // Number, inclusive
  std::vector<std::string> choices;  // Choice
  std::string default_text;          // Choice and Text
  ImageDefault image_default = ImageDefault::None;
  std::string help;
};

// Statistics of the (exposed, sanitised) image that parameters may default to.
struct ImageStats {
  double max_channel = 0.0;
  double max_luminance = 0.0;
  double log_average_luminance = 0.0;  // exp(mean(ln(kLogAverageEpsilon + L)))
};
// The statistic an ImageDefault names (0 for ImageDefault::None).
double image_statistic(ImageDefault d, const ImageStats& s);

inline constexpr double kLogAverageEpsilon = 1e-4;  // as pfstmo_drago03, so results compare

// Parameter values after validation and defaulting: every parameter of the operator is present.
class ParamValues {
 public:
  double number(const std::string& name) const;
  const std::string& text(const std::string& name) const;
  void set_number(const std::string& name, double v) { numbers_[name] = v; }
  void set_text(const std::string& name, std::string v) { texts_[name] = std::move(v); }
  // Whether the user gave the value (false: the spec's default or an image statistic), for
  // operators whose defaults depend on each other.
  bool given(const std::string& name) const { return given_.count(name) > 0; }
  void mark_given(const std::string& name) { given_.insert(name); }
  const std::map<std::string, double>& numbers() const { return numbers_; }
  const std::map<std::string, std::string>& texts() const { return texts_; }

 private:
  std::map<std::string, double> numbers_;
  std::map<std::string, std::string> texts_;
  std::set<std::string> given_;
};

// Operators that keep hue by moving all three channels with one offset and one scale, in two
// steps: the smallest channel m becomes toe(m) (every channel shifted by toe(m) - m); then the
// largest channel p becomes shoulder(p) while the HSV saturation (p - min) / p is multiplied by
// desaturation(p). The LUT baker represents such an operator with OpenColorIO's HSV transform
// and 1D LUTs, without a 3D LUT (bake/lut.h).
struct HueKeepingSteps {
  std::function<double(double)> toe, shoulder, desaturation;
};

// An operator with its parameters bound: what runs over pixels. Output is display-linear RGB
// clamped to [0, 1]. apply() is called per row span, so the virtual call is not per pixel.
class Evaluator {
 public:
  virtual ~Evaluator() = default;
  Kind kind() const { return kind_; }

  // In place over `count` pixels whose RGB starts every `stride` floats (alpha is left alone).
  virtual void apply(float* pixels, std::size_t count, std::size_t stride) const = 0;

  // Per-channel operators: out = clamp01(output_matrix * curve(input_matrix * in)), per channel.
  // curve() is the scalar curve the 1D LUT bakes; input/output matrices are identity when absent.
  virtual double curve(double x) const;
  // Mixing operators with the structure of HueKeepingSteps return it; others null.
  virtual const HueKeepingSteps* hue_keeping_steps() const { return nullptr; }
  std::optional<color::Mat3> input_matrix;
  std::optional<color::Mat3> output_matrix;

  // False: apply() skips the final clamp to [0, 1]. The LUT baker samples unclamped values so
  // that the clamp it places after the LUT cuts exactly, instead of being blurred by interpolation.
  bool clamp_output = true;

 protected:
  explicit Evaluator(Kind k) : kind_(k) {}

 private:
  Kind kind_;
};

struct OperatorDef {
  std::string name;
  std::string summary;   // one line: what it does
  std::string citation;  // one line: where it comes from
  Scope scope = Scope::Pixel;
  Kind default_kind = Kind::PerChannel;
  std::vector<ParamSpec> params;
  // Pixel scope: the evaluator for resolved parameters. Scene scope: null (no per-pixel form).
  std::unique_ptr<Evaluator> (*make)(const ParamValues&) = nullptr;
};

// A Number parameter spec in one line, for the operator files.
ParamSpec number_param(std::string name, double def, double lo, double hi, std::string help,
                       ImageDefault image_default = ImageDefault::None);

// Validates user-given `key=value` strings against the operator's specs and fills defaults.
// Throws UsageError for unknown keys, empty values, unparsable numbers, values out of range, bad choices.
// Image-derived defaults need `stats`; pass nullptr only when needs_image_stats() is false.
ParamValues resolve_params(const OperatorDef& op, const std::map<std::string, std::string>& given,
                           const ImageStats* stats);

// True when some parameter is unset and defaults from the image.
bool needs_image_stats(const OperatorDef& op, const std::map<std::string, std::string>& given);

}  // namespace cgtmo::operators
