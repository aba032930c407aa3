#pragma once
// One step of a recorded run replayed through the reference interpreter, the judge shared by the
// back-end conformance harness (tests/planner/Conformance.h) and `holon replay` (a plan file): the
// instance must be enabled (left side and guard), and where the system has constraints, a legal
// configuration must stay legal after it. Instances a synchronous round fires together are
// replayed one after another in the order they were applied (they read and write disjoint cells).

#include "rules/Interpreter.h"

#include <cstdint>
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

/// The system's invariants held over a replayed plan: on the start, after each step while the
/// checks' cell visits stay within a budget (each check reads the whole region), then at the end.
/// A loss may break them (plan then stops as a fault): none is checked after a loss that did.
class InvariantWatch {
public:
    /// About a second: a check of general1's invariant visits a cell in some 75 ns (a plan of
    /// 877,511 steps on 30,000 cells took 3.8 s to replay, and 24 s with a budget of 2^28).
    static constexpr std::uint64_t kVisits = std::uint64_t{1} << 24;
    explicit InvariantWatch(const rules::Interpreter& in, std::uint64_t visits = kVisits);
    /// What the start breaks, or nothing.
    std::optional<std::string> start(const rules::Configuration& now) const;
    /// What the configuration after a step breaks, or nothing (and nothing once the budget is spent).
    std::optional<std::string> afterStep(const rules::Configuration& now);
    /// After the loss `where` names ("the loss at line 14").
    void afterLoss(const rules::Configuration& now, const std::string& where);
    /// What the end breaks, where the steps were not all checked one by one; else nothing.
    std::optional<std::string> end(const rules::Configuration& now) const;
    /// What was checked: "invariants held at the start and after every step", and so on.
    std::string summary() const;

private:
    const rules::Interpreter* in_;
    std::uint64_t budget_, visits_ = 0;
    std::int64_t steps_ = 0, checked_ = 0;  // steps seen, and those after which the invariants were checked
    bool watching_;                         // the system has invariants, and no loss broke one
    std::string brokenByLoss_;
};

}  // namespace holon::planner
