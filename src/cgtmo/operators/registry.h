#pragma once
// Every operator, in one list: the per-pixel ones and the scene ones (Scope), pixel first. Adding
// an operator: one file defining `OperatorDef xxx_operator()` and one line in registry.cpp; the
// CLI, Python module, add-on, LUT baker, config writer and tests pick it up.
#include <cstddef>
#include <string>
#include <vector>

#include <nlohmann/json_fwd.hpp>

#include "cgtmo/operators/operator.h"

namespace cgtmo::operators {

const std::vector<OperatorDef>& registry();

// The operators of one scope, in registry order (a contiguous run of registry()).
class OperatorRange {
 public:
  OperatorRange(const OperatorDef* first, const OperatorDef* last) : first_(first), last_(last) {}
  const OperatorDef* begin() const { return first_; }
  const OperatorDef* end() const { return last_; }
  std::size_t size() const { return std::size_t(last_ - first_); }

 private:
  const OperatorDef* first_;
  const OperatorDef* last_;
};
OperatorRange operators_of(Scope scope);

// Throws UsageError naming the known operators when `name` is not one of them.
const OperatorDef& find_operator(const std::string& name);

// An operator as every face shows it (`cgtmo list --json`, the Python module's operators(), the
// add-on): name, scope, kind, summary, citation, params (name, type, default, help; min, max and
// default_from for numbers when set; choices). One serialisation, so the faces cannot drift.
nlohmann::json describe(const OperatorDef& op);
nlohmann::json describe_registry();  // every operator, in registry order

}  // namespace cgtmo::operators
