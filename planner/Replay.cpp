// The replay of one step through the reference interpreter (Replay.h). Constraints are checked only
// from a legal configuration: a step out of an illegal one (a sampled mirror, a hand-made start)
// proves nothing about the rule.

#include "planner/Replay.h"

namespace holon::planner {

StepFault replayStep(const rules::Interpreter& in, const rules::Configuration& before, const rules::Instance& instance, rules::Configuration& after) {
    if (!in.matches(before, instance)) return StepFault::NotEnabled;
    after = in.apply(before, instance);
    if (!in.model().system().constraints.empty() && in.legal(before) && !in.legal(after)) return StepFault::ConstraintBroken;
    return StepFault::None;
}

const char* describe(StepFault fault) {
    switch (fault) {
    case StepFault::None: return "";
    case StepFault::NotEnabled: return "it is not enabled there (left side or guard false)";
    case StepFault::ConstraintBroken: return "it leads into a configuration the system's constraints forbid";
    }
    return "";
}

}  // namespace holon::planner
