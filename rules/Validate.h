#pragma once
// Semantic checks of a parsed system that need its cell alphabet and rule shapes.

#include "rules/Diagnostics.h"
#include "rules/Ir.h"

namespace holon::rules {

/// Reports errors (a right side that leaves a state incomplete, too many states) and named
/// warnings (unused states and inputs, unmassed values, duplicate rules, no rules).
void validate(const System& system, Diagnostics& diagnostics);

}  // namespace holon::rules
