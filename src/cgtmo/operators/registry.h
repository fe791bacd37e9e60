#pragma once
// Every operator, in one list. Adding an operator: one file defining `OperatorDef xxx_operator()`
// and one line in registry.cpp; the CLI, LUT baker, config writer and tests pick it up.
#include <string>
#include <vector>

#include "cgtmo/operators/operator.h"

namespace cgtmo::operators {

const std::vector<OperatorDef>& registry();

// Throws UsageError naming the known operators when `name` is not one of them.
const OperatorDef& find_operator(const std::string& name);

}  // namespace cgtmo::operators
