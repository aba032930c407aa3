#pragma once
// One step of a recorded run replayed through the reference interpreter, the judge shared by the
// back-end conformance harness (tests/planner/Conformance.h) and `holon replay` (a plan file): the
// instance must be enabled (left side and guard), and where the system has constraints, a legal
// configuration must stay legal after it. Instances a synchronous round fires together are
// replayed one after another in the order they were applied (they read and write disjoint cells).

#include "rules/Interpreter.h"

namespace holon::planner {

enum class StepFault { None,
                       NotEnabled,
                       ConstraintBroken };

/// Replays `instance` on `before`; on StepFault::None, `after` holds the interpreter's rewrite.
StepFault replayStep(const rules::Interpreter& in, const rules::Configuration& before, const rules::Instance& instance, rules::Configuration& after);

/// Why a step is illegal, in words ("" for None).
const char* describe(StepFault fault);

}  // namespace holon::planner
