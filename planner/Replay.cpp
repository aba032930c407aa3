// The replay of one step through the reference interpreter (Replay.h). Constraints are checked only
// from a legal configuration: a step out of an illegal one (a sampled mirror, a hand-made start)
// proves nothing about the rule.

#include "planner/Replay.h"

#include "rules/Printer.h"

namespace holon::planner {

StepFault replayStep(const rules::Interpreter& in, rules::Configuration& now, const rules::Instance& instance, StepUndo* undo) {
    if (!in.matches(now, instance)) return StepFault::NotEnabled;
    StepUndo saved;
    const rules::Region& region = in.region();
    for (rules::Vec o : in.model().shapes()[instance.shape].offsets) {
        const int cell = region.indexOf(instance.anchor + o);
        saved.push_back({cell, now.cells[cell]});
    }
    const bool keepLegal = !in.model().system().constraints.empty() && in.legal(now);
    in.applyInPlace(now, instance);
    if (keepLegal && !in.legal(now)) {
        undoStep(now, saved);
        return StepFault::ConstraintBroken;
    }
    if (undo) *undo = std::move(saved);
    return StepFault::None;
}

void undoStep(rules::Configuration& now, const StepUndo& undo) {
    for (const auto& [cell, value] : undo) now.cells[cell] = value;
}

std::optional<std::string> brokenHypothesis(const rules::Interpreter& in, const rules::Configuration& now, bool progressAssumption) {
    const rules::System& system = in.model().system();
    for (const rules::Property& p : system.properties) {
        const bool invariant = p.kind == rules::Property::Kind::Invariant;
        if ((!invariant && !(progressAssumption && p.kind == rules::Property::Kind::Progress)) || p.exprs.empty()) continue;
        const int failing = in.firstFalseConjunct(p.exprs[0], now);
        if (failing < 0) continue;
        const std::string conjunct = rules::printExpr(system, *rules::conjuncts(p.exprs[0])[static_cast<std::size_t>(failing)]);
        return (invariant ? "invariant '" + p.name + "'" : "the assumption of progress property '" + p.name + "'") + ": `" + conjunct + "` is false";
    }
    return std::nullopt;
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
