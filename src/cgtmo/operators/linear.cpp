// linear: exposure only (applied by the pipeline before every operator), then clamp to [0, 1].
#include "cgtmo/operators/curve_evaluator.h"

namespace cgtmo::operators {
namespace {

struct IdentityCurve {
  template <class T>
  T operator()(T x) const {
    return x;
  }
};

}  // namespace

OperatorDef linear_operator() {
  OperatorDef d;
  d.name = "linear";
  d.summary = "exposure only, then clip to [0, 1]";
  d.citation = "the identity tone curve (clip), as in the seed tone-mapping guide";
  d.default_kind = Kind::PerChannel;
  d.make = [](const ParamValues&) { return make_curve_evaluator(IdentityCurve{}); };
  return d;
}

}  // namespace cgtmo::operators
