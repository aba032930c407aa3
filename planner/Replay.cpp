// The replay of one step through the reference interpreter (Replay.h). Constraints are checked only
// from a legal configuration: a step out of an illegal one (a sampled mirror, a hand-made start)
// proves nothing about the rule.

#include "planner/Replay.h"

#include "rules/Printer.h"

#include <algorithm>

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

InvariantWatch::InvariantWatch(const rules::Interpreter& in, std::uint64_t visits) : in_(&in), budget_(visits) {
    const auto& properties = in.model().system().properties;
    watching_ = std::any_of(properties.begin(), properties.end(), [](const rules::Property& p) { return p.kind == rules::Property::Kind::Invariant; });
}

std::optional<std::string> InvariantWatch::start(const rules::Configuration& now) const { return watching_ ? brokenHypothesis(*in_, now, false) : std::nullopt; }

std::optional<std::string> InvariantWatch::afterStep(const rules::Configuration& now) {
    ++steps_;
    if (!watching_ || checked_ + 1 < steps_ || (visits_ += in_->region().size()) > budget_) return std::nullopt;
    ++checked_;
    return brokenHypothesis(*in_, now, false);
}

void InvariantWatch::afterLoss(const rules::Configuration& now, const std::string& where) {
    if (!watching_) return;
    if (const std::optional<std::string> broken = brokenHypothesis(*in_, now, false)) brokenByLoss_ = where + " broke " + *broken, watching_ = false;
}

std::optional<std::string> InvariantWatch::end(const rules::Configuration& now) const {
    if (!watching_ || checked_ == steps_) return std::nullopt;
    const std::optional<std::string> broken = brokenHypothesis(*in_, now, false);
    if (!broken) return std::nullopt;
    return *broken + " (they held after each of the first " + std::to_string(checked_) + " steps; the other " + std::to_string(steps_ - checked_) +
           " were not checked one by one: a check reads all " + std::to_string(in_->region().size()) + " cells)";
}

std::string InvariantWatch::summary() const {
    if (!brokenByLoss_.empty()) return "invariants held until " + brokenByLoss_ + "; not checked after it";
    if (!watching_) return "the system states no invariant";
    if (checked_ == steps_) return "invariants held at the start and after every step";
    return "invariants held at the start, after each of the first " + std::to_string(checked_) + " steps and at the end (the other " + std::to_string(steps_ - checked_) +
           " steps were not checked one by one: a check reads all " + std::to_string(in_->region().size()) + " cells)";
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
