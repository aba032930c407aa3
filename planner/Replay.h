#pragma once
// One step of a recorded run replayed through the reference interpreter, the judge shared by the
// back-end conformance harness (tests/planner/Conformance.h) and `holon replay` (a plan file): the
// instance must be enabled (left side and guard), and where the system has constraints, a legal
// configuration must stay legal after it. Instances a synchronous round fires together are
// replayed one after another in the order they were applied (they read and write disjoint cells).

#include "rules/Interpreter.h"

#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace holon::planner {

enum class StepFault { None,
                       NotEnabled,
                       ConstraintBroken };

/// The pattern cells' states before a step: what undoStep puts back.
using StepUndo = std::vector<std::pair<int, rules::CellValue>>;

/// Replays `instance` on `now`, in place: on StepFault::None `now` holds the interpreter's rewrite
/// (and `undo`, if given, the pattern cells' old states); on a fault `now` is unchanged. In place,
/// so that a plan of n steps on m cells costs n patterns, not n copies of m cells.
StepFault replayStep(const rules::Interpreter& in, rules::Configuration& now, const rules::Instance& instance, StepUndo* undo = nullptr);
/// Puts back the states a step overwrote.
void undoStep(rules::Configuration& now, const StepUndo& undo);

/// Why a step is illegal, in words ("" for None).
const char* describe(StepFault fault);

/// The first of the system's invariants (and, with `progressAssumption`, the assumptions of its
/// progress properties) that `now` breaks, in words: "invariant 'safety': `connected` is false".
/// The hypotheses of seed 000's lemmas, as the system states them.
std::optional<std::string> brokenHypothesis(const rules::Interpreter& in, const rules::Configuration& now, bool progressAssumption);

}  // namespace holon::planner
