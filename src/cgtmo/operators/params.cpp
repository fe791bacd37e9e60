#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <sstream>

#include "cgtmo/errors.h"
#include "cgtmo/operators/curve_evaluator.h"
#include "cgtmo/operators/operator.h"
#include "cgtmo/util/text.h"

namespace cgtmo::operators {

const char* kind_name(Kind k) { return k == Kind::PerChannel ? "per-channel" : "mixing"; }

const char* scope_name(Scope s) { return s == Scope::Pixel ? "pixel" : "scene"; }

const char* image_default_name(ImageDefault d) {
  switch (d) {
    case ImageDefault::MaxChannel: return "max_channel";
    case ImageDefault::MaxLuminance: return "max_luminance";
    case ImageDefault::LogAverageLuminance: return "log_average_luminance";
    case ImageDefault::None: break;
  }
  return "";
}

const char* mode_name(Mode m) {
  switch (m) {
    case Mode::PerChannel: return "per-channel";
    case Mode::Luminance: return "luminance";
    case Mode::MaxRGB: return "max-rgb";
  }
  return "?";
}

double ParamValues::number(const std::string& name) const {
  auto it = numbers_.find(name);
  if (it == numbers_.end()) throw UsageError("internal: parameter '" + name + "' has no value");
  return it->second;
}

const std::string& ParamValues::text(const std::string& name) const {
  auto it = texts_.find(name);
  if (it == texts_.end()) throw UsageError("internal: parameter '" + name + "' has no value");
  return it->second;
}

static std::string fmt(double v) {
  std::ostringstream s;
  s << v;
  return s.str();
}

double image_statistic(ImageDefault d, const ImageStats& s) {
  switch (d) {
    case ImageDefault::MaxChannel: return s.max_channel;
    case ImageDefault::MaxLuminance: return s.max_luminance;
    case ImageDefault::LogAverageLuminance: return s.log_average_luminance;
    case ImageDefault::None: break;
  }
  return 0.0;
}

bool needs_image_stats(const OperatorDef& op, const std::map<std::string, std::string>& given) {
  for (const auto& p : op.params)
    if (p.image_default != ImageDefault::None && !given.count(p.name)) return true;
  return false;
}

ParamValues resolve_params(const OperatorDef& op, const std::map<std::string, std::string>& given,
                           const ImageStats* stats) {
  for (const auto& [key, value] : given) {
    bool known = false;
    for (const auto& p : op.params) known = known || p.name == key;
    if (!known) {
      std::string names;
      std::vector<std::string> known_names;
      for (const auto& p : op.params) {
        names += (names.empty() ? "" : ", ") + p.name;
        known_names.push_back(p.name);
      }
      throw UsageError("operator '" + op.name + "' has no parameter '" + key + "'" + did_you_mean(key, known_names) +
                       " (it has: " + (names.empty() ? std::string("none") : names) + ")");
    }
  }
  ParamValues out;
  for (const auto& p : op.params) {
    auto it = given.find(p.name);
    if (it != given.end()) out.mark_given(p.name);
    // `-p mode=` must not quietly mean the default. A text whose default is itself "" (camera's
    // curve: the table's first) takes "" as that value: resolved parameters, recorded and passed
    // back (manifest.json, provenance), must resolve again to the same.
    if (it != given.end() && it->second.empty() && !(p.type == ParamType::Text && p.default_text.empty()))
      throw UsageError(op.name + ": parameter '" + p.name + "' is given an empty value (leave it out for its default)");
    switch (p.type) {
      case ParamType::Number: {
        double v = p.default_value;
        if (it != given.end()) {
          const char* s = it->second.c_str();
          char* end = nullptr;
          errno = 0;
          v = std::strtod(s, &end);
          if (end == s || *end != '\0' || errno == ERANGE || !std::isfinite(v))
            throw UsageError(op.name + ": parameter '" + p.name + "' needs a number, got '" + it->second + "'");
        } else if (p.image_default != ImageDefault::None) {
          if (!stats) throw UsageError("internal: " + op.name + "." + p.name + " needs image statistics");
          v = image_statistic(p.image_default, *stats);
          // An image default is clamped into the valid range (a black image has max 0).
          v = std::min(std::max(v, p.min_value), p.max_value);
        }
        if (v < p.min_value || v > p.max_value)
          throw UsageError(op.name + ": parameter '" + p.name + "' = " + fmt(v) + " is out of range [" +
                           fmt(p.min_value) + ", " + fmt(p.max_value) + "]");
        out.set_number(p.name, v);
        break;
      }
      case ParamType::Choice: {
        std::string v = it != given.end() ? it->second : p.default_text;
        bool ok = false;
        for (const auto& c : p.choices) ok = ok || c == v;
        if (!ok) {
          std::string names;
          for (const auto& c : p.choices) names += (names.empty() ? "" : ", ") + c;
          throw UsageError(op.name + ": parameter '" + p.name + "' = '" + v + "'" + did_you_mean(v, p.choices) +
                           " is not one of: " + names);
        }
        out.set_text(p.name, v);
        break;
      }
      case ParamType::Text:
        out.set_text(p.name, it != given.end() ? it->second : p.default_text);
        break;
    }
  }
  return out;
}

double Evaluator::curve(double) const {
  throw UsageError("internal: curve() asked of a mixing operator");
}

ParamSpec number_param(std::string name, double def, double lo, double hi, std::string help,
                       ImageDefault image_default) {
  ParamSpec p;
  p.name = std::move(name);
  p.default_value = def;
  p.min_value = lo;
  p.max_value = hi;
  p.help = std::move(help);
  p.image_default = image_default;
  return p;
}

ParamSpec mode_param(Mode default_mode) {
  ParamSpec p;
  p.name = "mode";
  p.type = ParamType::Choice;
  p.choices = {"per-channel", "luminance", "max-rgb"};
  p.default_text = mode_name(default_mode);
  p.help = "apply the curve to each channel, to luminance (colour scaled by Lout/Lin), or to max(R,G,B)";
  return p;
}

ParamSpec saturation_param() {
  ParamSpec p;
  p.name = "saturation";
  p.default_value = 1.0;
  p.min_value = 0.0;
  p.max_value = 2.0;
  p.help = "luminance and max-rgb modes: out = Lout * (C/Lin)^saturation; 1 keeps the input's chromaticity";
  return p;
}

CurveOptions curve_options_from(const ParamValues& v) {
  CurveOptions o;
  const std::string& m = v.text("mode");
  o.mode = m == "luminance" ? Mode::Luminance : m == "max-rgb" ? Mode::MaxRGB : Mode::PerChannel;
  o.saturation = v.number("saturation");
  return o;
}

}  // namespace cgtmo::operators
