// Checks src/cgtmo/bake/audit.cpp: the reference encoding against IEC 61966-2-1 hand values, and
// that the audit finds a known error (so it can fail) and passes an exact transform.
#include <gtest/gtest.h>

#include <cmath>

#include "cgtmo/bake/audit.h"
#include "cgtmo/bake/choose.h"
#include "cgtmo/operators/apply.h"
#include "cgtmo/operators/registry.h"

using namespace cgtmo;
using namespace cgtmo::bake;

TEST(SrgbEncode, HandValues) {
  EXPECT_DOUBLE_EQ(srgb_encode(0.0), 0.0);
  EXPECT_NEAR(srgb_encode(0.0031308), 0.0404500, 1e-6);
  EXPECT_NEAR(srgb_encode(0.18), 0.4613561, 1e-6);
  EXPECT_NEAR(srgb_encode(1.0), 1.0, 1e-12);
  EXPECT_DOUBLE_EQ(srgb_encode(3.0), 1.0);  // clamped
}

TEST(AuditSamples, CoverTheHalfDomain) {
  const auto& s = audit_samples();
  float lo = 1e30f, hi = 0;
  for (float v : s) {
    lo = std::min(lo, v);
    hi = std::max(hi, v);
  }
  EXPECT_EQ(lo, 0.f);
  EXPECT_EQ(hi, 65504.f);
  EXPECT_GT(s.size() / 3, 31744u * 4);  // every non-negative finite half, four ways
}

namespace {
OCIO::ConstCPUProcessorRcPtr clamp_then_srgb(double gain) {
  auto g = OCIO::GroupTransform::Create();
  auto m = OCIO::MatrixTransform::Create();
  const double v[16] = {gain, 0, 0, 0, 0, gain, 0, 0, 0, 0, gain, 0, 0, 0, 0, 1};
  m->setMatrix(v);
  g->appendTransform(m);
  auto r = OCIO::RangeTransform::Create();
  r->setMinInValue(0);
  r->setMinOutValue(0);
  r->setMaxInValue(1);
  r->setMaxOutValue(1);
  g->appendTransform(r);
  g->appendTransform(srgb_display_encoding()->createEditableCopy());
  return OCIO::Config::CreateRaw()->getProcessor(g)->getDefaultCPUProcessor();
}
}  // namespace

TEST(Audit, ExactTransformOfLinearOperatorIsWithinFloatNoise) {
  const auto ev = operators::make_evaluator(operators::find_operator("linear"), {}, nullptr);
  const AuditResult a = audit(clamp_then_srgb(1.0), *ev);
  EXPECT_LT(a.max_cv, 0.05);
}

TEST(Audit, FindsAOnePercentGainError) {
  // 1% more light: at display value 0.9, sRGB moves by about 0.0044, i.e. 4.5 code values.
  const auto ev = operators::make_evaluator(operators::find_operator("linear"), {}, nullptr);
  const AuditResult a = audit(clamp_then_srgb(1.01), *ev);
  EXPECT_GT(a.max_cv, 3.0);
  EXPECT_LT(a.max_cv, 6.0);
}

TEST(Choose, PerChannelOperatorMeetsTightBudgetWith1D) {
  BakeSubject s = make_subject(operators::find_operator("reinhard"), {}, reference_scene_stats());
  const Choice c = choose_representation(s, 0.1);
  EXPECT_TRUE(c.met);
  EXPECT_EQ(c.lut.rep.dims, 1);
  EXPECT_LE(c.audit.max_cv, 0.1);
  // Cheapest: the next smaller size with the same shaper misses the budget.
  if (c.lut.rep.size > 256) {
    Representation smaller = c.lut.rep;
    smaller.size /= 2;
    const AuditResult a = audit(encoded_processor(sample_lut(*s.exact, smaller)), *s.exact);
    EXPECT_GT(a.max_cv, 0.1);
  }
}
