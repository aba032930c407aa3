// Goal reachability, built in for a system with a goal: the goal stays reachable from every
// reachable state (AG EF goal), so a scheduler that picks enabled instances at random reaches it
// with probability 1, even where the ranking admits cycles. A deadlock outside the goal violates
// it; so does a trap of cycles with no way out. Explicit state only (BGL breadth-first search on
// the reversed graph): it is about reachability, which a proof over every configuration of the
// region does not see.

#include "checker/ProofRunner.h"
#include "checker/properties/Kinds.h"

namespace holon::checker::properties {

namespace {

constexpr PhaseCost kGoalCost{32, 12};

class GoalReachable : public PropertyType {
public:
    GoalReachable() : PropertyType("goal_reachable", "goal_reachable") {}

    std::optional<PhaseCost> cost(bool complete) const override { return complete ? std::optional(kGoalCost) : std::nullopt; }

    PropertyResult check(const ExploredGraph& g) const override {
        PropertyResult r = named();
        if (!g.complete) {
            r.summary = "needs the whole graph; the search stopped at a limit";
            return r;
        }
        const Explorer* ex = &g.explorer;
        std::vector<StateId> goals;
        const std::vector<StateId> ids = ex->ids();
        for (StateId s : ids)
            if (g.engine.holds(*g.model.system().goal, ex->cells(s).data())) goals.push_back(s);
        const std::vector<char> reach = canReach(*ex, goals);
        if (!violatedAtNearest(
                r, *ex, ids, [&](StateId s) { return !reach[s]; }, "from which no run reaches the goal",
                "no run from here reaches the goal", "trapped")) {
            r.verdict = Verdict::Holds;
            r.summary = "from every state some run reaches the goal (" + std::to_string(goals.size()) + " goal states)";
        }
        return r;
    }

    Obligation prove(const ProofContext&) const override {
        return notEncoded(name(), kind(), "goal reachability is checked by holon check (it needs reachability)");
    }
};

}  // namespace

std::unique_ptr<PropertyType> goalReachable() { return std::make_unique<GoalReachable>(); }

}  // namespace holon::checker::properties
