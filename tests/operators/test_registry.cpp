// The registry as data (names, parameters, citations, kinds) and properties every operator must
// have, checked by iterating the registry: curve() agrees with apply(), monotonic greys, output
// range, hue kept by the luminance and max-RGB modes and shifted by the per-channel mode.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <set>
#include <sstream>

#include <nlohmann/json.hpp>

#include "cgtmo/errors.h"
#include "cgtmo/operators/registry.h"
#include "op_test_util.h"

namespace cgtmo::operators::test {
namespace {

// Statistics for building evaluators outside an image: a plausible HDR frame.
ImageStats some_stats() {
  ImageStats s;
  s.max_channel = 40;
  s.max_luminance = 30;
  s.log_average_luminance = 0.2;
  return s;
}

bool has_param(const OperatorDef& op, const std::string& name) {
  for (const auto& p : op.params)
    if (p.name == name) return true;
  return false;
}

// Every value of `mode` the operator accepts ({""} when it has none: the default only).
std::vector<std::string> modes_of(const OperatorDef& op) {
  for (const auto& p : op.params)
    if (p.name == "mode") return p.choices;
  return {""};
}

Params with_mode(const std::string& mode) { return mode.empty() ? Params{} : Params{{"mode", mode}}; }

TEST(Registry, HasExactlyTheIssuesOperators) {
  std::vector<std::string> names;
  for (const auto& op : registry()) names.push_back(op.name);
  const std::vector<std::string> expected = {"linear", "reinhard", "reinhard-ext", "reinhard-lum", "reinhard-jodie",
                                             "hable", "hable-piecewise", "aces-hill", "aces-narkowicz", "uchimura",
                                             "lottes", "unreal", "pbr-neutral", "agx", "drago", "camera",
                                             "cgtmo", "wls"};
  EXPECT_EQ(names, expected);
  EXPECT_EQ(std::set<std::string>(names.begin(), names.end()).size(), names.size());
}

TEST(Registry, ScopesSplitTheOneList) {
  // Pixel operators first, each with a per-pixel evaluation; then the scene operators, without.
  const auto pixel = operators_of(Scope::Pixel);
  const auto scene = operators_of(Scope::Scene);
  EXPECT_EQ(pixel.size() + scene.size(), registry().size());
  EXPECT_EQ(pixel.begin(), registry().data());
  EXPECT_EQ(pixel.end(), scene.begin());
  for (const auto& op : pixel) {
    EXPECT_EQ(op.scope, Scope::Pixel) << op.name;
    EXPECT_NE(op.make, nullptr) << op.name;
  }
  std::vector<std::string> scene_names;
  for (const auto& op : scene) {
    EXPECT_EQ(op.scope, Scope::Scene) << op.name;
    EXPECT_EQ(op.make, nullptr) << op.name;
    scene_names.push_back(op.name);
    // No per-pixel form: refused with a usage error naming it.
    try {
      make_evaluator(op, {}, nullptr);
      ADD_FAILURE() << op.name;
    } catch (const UsageError& e) {
      EXPECT_NE(std::string(e.what()).find("'" + op.name + "' is a scene operator"), std::string::npos) << e.what();
    }
  }
  EXPECT_EQ(scene_names, (std::vector<std::string>{"cgtmo", "wls"}));
}

TEST(Registry, DescriptionSpellsScopeKindAndImageDefaults) {
  const auto all = describe_registry();
  ASSERT_EQ(all.size(), registry().size());
  for (std::size_t i = 0; i < all.size(); ++i) {
    const auto& op = registry()[i];
    EXPECT_EQ(all[i]["name"], op.name);
    EXPECT_EQ(all[i]["scope"], op.scope == Scope::Pixel ? "pixel" : "scene");
    EXPECT_EQ(all[i]["kind"], op.default_kind == Kind::PerChannel ? "per-channel" : "mixing");
    ASSERT_EQ(all[i]["params"].size(), op.params.size());
  }
  const auto drago = describe(find_operator("drago"));
  for (const auto& p : drago["params"]) {
    if (p["name"] == "lw_max") EXPECT_EQ(p["default_from"], "max_luminance");
    if (p["name"] == "lw_a") EXPECT_EQ(p["default_from"], "log_average_luminance");
    if (p["name"] == "b") EXPECT_FALSE(p.contains("default_from"));
  }
}

TEST(Registry, FindOperator) {
  for (const auto& op : registry()) EXPECT_EQ(&find_operator(op.name), &op);
  try {
    find_operator("reinhardt");
    FAIL();
  } catch (const UsageError& e) {
    EXPECT_NE(std::string(e.what()).find("reinhardt"), std::string::npos);
    EXPECT_NE(std::string(e.what()).find("hable-piecewise"), std::string::npos);  // lists the known ones
  }
}

TEST(Registry, EveryOperatorIsWellDescribed) {
  for (const auto& op : operators_of(Scope::Pixel)) {
    SCOPED_TRACE(op.name);
    EXPECT_FALSE(op.summary.empty());
    EXPECT_GT(op.citation.size(), 10u);
    EXPECT_NE(op.make, nullptr);
    std::set<std::string> seen;
    for (const auto& p : op.params) {
      SCOPED_TRACE(p.name);
      EXPECT_FALSE(p.name.empty());
      EXPECT_TRUE(seen.insert(p.name).second) << "duplicate parameter";
      EXPECT_FALSE(p.help.empty());
      switch (p.type) {
        case ParamType::Number:
          EXPECT_TRUE(std::isfinite(p.min_value) && std::isfinite(p.max_value) && std::isfinite(p.default_value));
          EXPECT_LT(p.min_value, p.max_value);
          EXPECT_GE(p.default_value, p.min_value);
          EXPECT_LE(p.default_value, p.max_value);
          break;
        case ParamType::Choice:
          EXPECT_FALSE(p.choices.empty());
          EXPECT_NE(std::find(p.choices.begin(), p.choices.end(), p.default_text), p.choices.end());
          break;
        case ParamType::Text:
          break;
      }
    }
    // A saturation control only makes sense next to a mode.
    EXPECT_EQ(has_param(op, "saturation"), has_param(op, "mode") || op.name == "reinhard-lum");
  }
}

TEST(Registry, KindOfTheBuiltEvaluatorIsTheDeclaredOne) {
  const ImageStats s = some_stats();
  for (const auto& op : operators_of(Scope::Pixel)) {
    SCOPED_TRACE(op.name);
    EXPECT_EQ(make_evaluator(op, {}, &s)->kind(), op.default_kind);
    if (has_param(op, "mode")) {
      EXPECT_EQ(make_evaluator(op, {{"mode", "per-channel"}}, &s)->kind(), Kind::PerChannel);
      EXPECT_EQ(make_evaluator(op, {{"mode", "luminance"}}, &s)->kind(), Kind::Mixing);
      EXPECT_EQ(make_evaluator(op, {{"mode", "max-rgb"}}, &s)->kind(), Kind::Mixing);
    }
  }
}

// What the 1D LUT baker relies on: a per-channel evaluator is output_matrix * curve(input_matrix * c),
// clamped. Every scalar curve an evaluator exposes (curve evaluators expose theirs in every mode;
// the others throw) must be finite everywhere on [0, 65504], 0 included.
TEST(Registry, PerChannelCurveAgreesWithApplyAndCurvesAreFinite) {
  const ImageStats s = some_stats();
  const std::vector<RGB> colours = {{0.f, 0.f, 0.f}, {0.18f, 0.18f, 0.18f}, {1.f, 0.2f, 0.05f},
                                    {0.02f, 0.5f, 3.f}, {20.f, 10.f, 5.f}, {1e-7f, 0.f, 0.f}};
  std::vector<double> xs = {0.0, 1e-45, 1e-300};
  for (double x : log_sweep(1e-30, 65504, 400)) xs.push_back(x);
  for (const auto& op : operators_of(Scope::Pixel))
    for (const auto& mode : modes_of(op)) {
      SCOPED_TRACE(op.name + " " + mode);
      auto ev = make_evaluator(op, with_mode(mode), &s);
      bool has_curve = true;
      try {
        ev->curve(0.5);
      } catch (const UsageError&) {
        has_curve = false;
      }
      EXPECT_TRUE(has_curve || ev->kind() == Kind::Mixing) << "a per-channel operator must have a curve";
      if (has_curve)
        for (double x : xs) ASSERT_TRUE(std::isfinite(ev->curve(x))) << "curve(" << x << ")";
      if (ev->kind() != Kind::PerChannel) continue;
      const color::Mat3 in = ev->input_matrix.value_or(color::Mat3::identity());
      const color::Mat3 out = ev->output_matrix.value_or(color::Mat3::identity());
      for (RGB c : colours) {
        double v[3] = {c[0], c[1], c[2]};
        in.apply(v[0], v[1], v[2]);
        for (double& x : v) x = ev->curve(x);
        out.apply(v[0], v[1], v[2]);
        ev->apply(c.data(), 1, 3);
        for (int k = 0; k < 3; ++k) EXPECT_NEAR(c[k], std::clamp(v[k], 0.0, 1.0), 2e-5) << k;
      }
    }
}

// Every numeric parameter at the ends of its range (the others at their defaults), in every mode:
// the scalar curve stays finite on [0, 65504] (no inf * 0 or inf / inf inside a curve) and pixels
// come out finite in [0, 1]. Image-derived parameters are given explicitly here too.
TEST(Registry, EveryAdvertisedExtremeIsAcceptedAndFinite) {
  const ImageStats s = some_stats();
  std::vector<double> xs = {0.0, 1e-45, 1e-300};
  for (double x : log_sweep(1e-30, 65504, 300)) xs.push_back(x);
  const std::vector<RGB> colours = {{0.f, 0.f, 0.f}, {65504.f, 65504.f, 65504.f}, {65504.f, 0.f, 0.f},
                                    {1e-40f, 0.f, 0.f}, {0.18f, 0.18f, 0.18f}, {3.f, 0.5f, 0.01f}};
  for (const auto& op : operators_of(Scope::Pixel))
    for (const auto& p : op.params) {
      if (p.type != ParamType::Number) continue;
      for (double v : {p.min_value, p.max_value})
        for (const auto& mode : modes_of(op)) {
          std::ostringstream text;
          text.precision(17);
          text << v;
          Params given = with_mode(mode);
          given[p.name] = text.str();
          SCOPED_TRACE(op.name + " " + p.name + "=" + text.str() + " " + mode);
          // Each end of the range `cgtmo list` advertises works with the other parameters at
          // their defaults (uchimura refused its own minimum max_brightness once).
          std::unique_ptr<Evaluator> ev;
          try {
            ev = make_evaluator(op, given, &s);
          } catch (const UsageError& e) {
            ADD_FAILURE() << "the advertised value is refused: " << e.what();
            continue;
          }
          try {
            for (double x : xs) ASSERT_TRUE(std::isfinite(ev->curve(x))) << "curve(" << x << ") = " << ev->curve(x);
          } catch (const UsageError&) {
            EXPECT_EQ(ev->kind(), Kind::Mixing);  // no scalar curve
          }
          std::vector<RGB> px = colours;
          ev->apply(px[0].data(), px.size(), 3);
          for (const RGB& c : px)
            for (float x : c) ASSERT_TRUE(x >= 0.f && x <= 1.f) << x;
        }
    }
}

TEST(Properties, MonotonicGreysOverTheWholeRange) {
  std::vector<RGB> sweep;
  for (double x : log_sweep(1e-6, 65504, 3000)) sweep.push_back({float(x), float(x), float(x)});
  for (const auto& op : operators_of(Scope::Pixel))
    for (const auto& mode : modes_of(op)) {
      SCOPED_TRACE(op.name + " " + mode);
      const auto out = run(op.name, sweep, with_mode(mode));
      for (std::size_t i = 1; i < out.size(); ++i)
        for (int k = 0; k < 3; ++k)
          ASSERT_GE(out[i][k], out[i - 1][k] - 4e-7f) << "at " << sweep[i][0] << " channel " << k;
      EXPECT_GT(out.back()[0], out.front()[0]);  // and not flat
    }
}

TEST(Properties, OutputInUnitRange) {
  std::vector<RGB> px;
  for (double x : log_sweep(1e-6, 65504, 200)) {
    const float v = float(x);
    for (RGB c : {RGB{v, v, v}, RGB{v, 0, 0}, RGB{0, v, 0}, RGB{0, 0, v}, RGB{v, v * 0.1f, v * 0.01f}, RGB{0, v, v}})
      px.push_back(c);
  }
  const RGB brightest_grey = px[px.size() - 6];
  // The image-derived parameters come from the whole sweep, as tonemap() computes them.
  const ImageStats stats = compute_image_stats(px[0].data(), px.size(), 3);
  for (const auto& op : operators_of(Scope::Pixel))
    for (const auto& mode : modes_of(op)) {
      SCOPED_TRACE(op.name + " " + mode);
      const auto out = run(op.name, px, with_mode(mode));
      for (const RGB& c : out)
        for (float v : c) ASSERT_TRUE(v >= 0.f && v <= 1.f) << v;
      // In range because it is the operator's output, not because of the clamp alone: a
      // per-channel operator gives clamp01(output_matrix * curve(input_matrix * c)) exactly; a
      // mixing one gives what its evaluator gives each pixel on its own.
      const auto ev = make_evaluator(op, with_mode(mode), &stats);
      const color::Mat3 in = ev->input_matrix.value_or(color::Mat3::identity());
      const color::Mat3 om = ev->output_matrix.value_or(color::Mat3::identity());
      for (std::size_t i = 0; i < px.size(); ++i) {
        RGB want = px[i];
        if (ev->kind() == Kind::PerChannel) {
          double v[3] = {want[0], want[1], want[2]};
          in.apply(v[0], v[1], v[2]);
          for (double& x : v) x = ev->curve(x);
          om.apply(v[0], v[1], v[2]);
          for (int k = 0; k < 3; ++k) want[k] = float(std::clamp(v[k], 0.0, 1.0));
        } else {
          ev->apply(want.data(), 1, 3);
        }
        for (int k = 0; k < 3; ++k) ASSERT_NEAR(out[i][k], want[k], 2e-5) << "pixel " << i << " channel " << k;
      }
      // And not a degenerate image: the brightest grey comes out (close to) white.
      const RGB top = out[px.size() - 6];
      ASSERT_EQ(brightest_grey[0], brightest_grey[2]);
      for (int k = 0; k < 3; ++k) EXPECT_GT(top[k], 0.9f) << "channel " << k;
    }
}

// A saturated orange (R:G:B = 16:4:1) next to a bright grey, so that image-derived white points sit
// well above it.
std::vector<RGB> hue_image(float scale) {
  return {{0.2f * scale, 0.05f * scale, 0.0125f * scale}, {16.f, 16.f, 16.f}};
}

TEST(Properties, LuminanceAndMaxRgbModesKeepRgbRatios) {
  for (const auto& op : operators_of(Scope::Pixel))
    for (const auto& mode : modes_of(op)) {
      if (mode != "luminance" && mode != "max-rgb") continue;
      SCOPED_TRACE(op.name + " " + mode);
      // The ratio is only meaningful where no channel clips: take the first scale that does not
      // (steep curves such as the camera's push the orange's red past 1 at scale 1).
      bool checked = false;
      for (float scale : {1.f, 0.1f, 0.01f}) {
        const RGB out = run(op.name, hue_image(scale), with_mode(mode))[0];
        if (!(out[0] < 0.999f)) continue;
        ASSERT_GT(out[2], 0.f);
        EXPECT_NEAR(out[0] / out[1], 4.0, 4e-5);
        EXPECT_NEAR(out[1] / out[2], 4.0, 4e-5);
        checked = true;
        break;
      }
      EXPECT_TRUE(checked) << "clipped at every scale";
    }
}

TEST(Properties, PerChannelModeShiftsSaturatedColours) {
  int checked = 0;
  for (const auto& op : operators_of(Scope::Pixel))
    for (const auto& mode : modes_of(op)) {
      if (mode != "per-channel") continue;
      SCOPED_TRACE(op.name);
      const RGB out = run(op.name, hue_image(1.f), with_mode(mode))[0];
      const double r_over_g = out[0] / out[1];
      EXPECT_GT(std::abs(r_over_g - 4.0), 0.04) << "ratio " << r_over_g;
      ++checked;
    }
  EXPECT_GE(checked, 9);
}

}  // namespace
}  // namespace cgtmo::operators::test
