// Design comparison (checker/Diff.h). Each configuration is keyed by the names of its cells'
// states (a shared name table for both designs), so the graphs compare as sets of named
// configurations and named transitions; a move that ignores a blocking cell is a transition the
// reference lacks. The witness of a kind is its transition whose source is nearest a start (the
// explorers' BFS trees give the distances).

#include "checker/Diff.h"

#include "rules/Budget.h"

#include <map>
#include <unordered_map>
#include <unordered_set>

namespace holon::checker {

namespace {

using Key = std::vector<std::uint32_t>;

struct KeyHash {
    std::size_t operator()(const Key& k) const {
        std::size_t h = 1469598103934665603ull;
        for (std::uint32_t v : k) h = (h ^ v) * 1099511628211ull;
        return h;
    }
};

/// Names of cell states, numbered in the order met, shared by both designs.
class NameTable {
public:
    Key key(const rules::Engine& engine, const std::vector<CellValue>& cells) {
        Key k(cells.size());
        for (std::size_t i = 0; i < cells.size(); ++i) {
            const std::string name = engine.model().alphabet().name(cells[i]);
            k[i] = ids_.emplace(name, static_cast<std::uint32_t>(ids_.size())).first->second;
        }
        return k;
    }

private:
    std::map<std::string, std::uint32_t> ids_;
};

/// One side: every state's key, and the index from keys to states.
struct Keyed {
    std::vector<Key> keyOf;  // by state id (empty for holes)
    std::unordered_map<Key, StateId, KeyHash> stateOf;
};

Keyed keyAll(const ExploredDesign& d, NameTable& names) {
    Keyed k;
    k.keyOf.resize(d.explorer->store().capacityUsed());
    for (StateId s : d.explorer->ids()) {
        k.keyOf[s] = names.key(*d.engine, d.explorer->cells(s));
        k.stateOf.emplace(k.keyOf[s], s);
    }
    return k;
}

/// Whether `other` has the step from the configuration keyed `from` to the one keyed `to`.
bool hasStep(const ExploredDesign& other, const Keyed& keyed, const Key& from, const Key& to) {
    const auto f = keyed.stateOf.find(from), t = keyed.stateOf.find(to);
    if (f == keyed.stateOf.end() || t == keyed.stateOf.end()) return false;
    const auto& row = other.explorer->rowStart();
    const auto& succ = other.explorer->successors();
    for (std::uint64_t e = row[f->second]; e < row[f->second + 1]; ++e)
        if (succ[e] == t->second) return true;
    return false;
}

}  // namespace

DesignDifference compareDesigns(const ExploredDesign& a, const ExploredDesign& b) {
    NameTable names;
    const ExploredDesign sides[2] = {a, b};
    const Keyed keyed[2] = {keyAll(a, names), keyAll(b, names)};
    DesignDifference diff;
    for (int side = 0; side < 2; ++side) {
        const ExploredDesign& mine = sides[side];
        const ExploredDesign& other = sides[1 - side];
        const Keyed& k = keyed[side];
        const Explorer& ex = *mine.explorer;
        const auto& row = ex.rowStart();
        const auto& succ = ex.successors();
        StateId nearest = kNoState;
        std::uint64_t nearestEdge = 0;
        std::size_t nearestDepth = 0;
        for (StateId s : ex.ids()) {
            ++diff.states[side];
            if (!keyed[1 - side].stateOf.count(k.keyOf[s])) ++diff.onlyStates[side];
            std::unordered_set<StateId> seen;  // several instances may lead to one successor
            for (std::uint64_t e = row[s]; e < row[s + 1]; ++e) {
                if (!seen.insert(succ[e]).second) continue;
                ++diff.transitions[side];
                if (hasStep(other, keyed[1 - side], k.keyOf[s], k.keyOf[succ[e]])) continue;
                ++diff.onlyTransitions[side];
                const std::size_t depth = ex.pathTo(s).size();
                if (nearest == kNoState || depth < nearestDepth) nearest = s, nearestEdge = e, nearestDepth = depth;
            }
        }
        if (nearest != kNoState) diff.transitionWitness[side] = traceWithStep(ex, nearest, nearestEdge);
    }
    return diff;
}

int DiffReport::stopped() const {
    for (int side = 0; side < 2; ++side)
        if (explored[side].explorer->stats().stopped != StopReason::Finished) return side;
    return -1;
}

std::string DiffReport::witnessText(int side) const {
    const Trace& t = *difference->transitionWitness[side];
    const rules::Engine& engine = *explored[side].engine;
    const std::string& rule = engine.model().rules()[engine.instances()[t.steps.back().placed].rule].name;
    return systems[side] + " fires '" + rule + "' after " + stepCount(t.steps.size() - 2) + "; " + systems[1 - side] + " has no such step";
}

nlohmann::json DiffReport::toJson() const {
    const DesignDifference& d = *difference;
    nlohmann::json j = {{"a", systems[0]}, {"b", systems[1]}, {"region", region}, {"same", d.same()}};
    for (int side = 0; side < 2; ++side) {
        nlohmann::json s = {{"system", systems[side]},
                            {"states", d.states[side]},
                            {"transitions", d.transitions[side]},
                            {"only_states", d.onlyStates[side]},
                            {"only_transitions", d.onlyTransitions[side]}};
        if (d.transitionWitness[side]) {
            const rules::Engine& engine = *explored[side].engine;
            s["witness"] = {{"description", witnessText(side)}, {"trace", traceJson(*d.transitionWitness[side], engine, rules::Interpreter(engine.model(), engine.region()))}};
        }
        j[side == 0 ? "in_a" : "in_b"] = s;
    }
    return j;
}

DiffReport diff(const rules::Model& a, const rules::Model& b, const rules::Region& region, const DiffOptions& options) {
    DiffReport report;
    report.region = region.spec();
    const Budget budget = options.limits.budget();  // one timeout for both
    const rules::Model* models[2] = {&a, &b};
    for (int side = 0; side < 2; ++side) {
        CheckOptions co;
        co.limits = options.limits;
        co.limits.memoryBytes /= 2;
        co.all = options.all, co.initial = options.initial[side], co.inputs = options.inputs[side];
        Explorer::Options xo;
        xo.limits = co.limits;
        xo.budget = budget;
        Exploration& x = report.explored[side];
        x.engine = checkEngine(*models[side], region, co);
        x.explorer = startExplorer(*x.engine, co, xo);
        x.explorer->explore();
        report.systems[side] = models[side]->system().name;
    }
    if (report.stopped() < 0)
        report.difference = compareDesigns({report.explored[0].engine.get(), report.explored[0].explorer.get()}, {report.explored[1].engine.get(), report.explored[1].explorer.get()});
    return report;
}

}  // namespace holon::checker
