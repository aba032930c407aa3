// Design comparison (checker/Diff.h). Each configuration is keyed by the names of its cells'
// states (a shared name table for both designs), so the graphs compare as sets of named
// configurations and named transitions; a move that ignores a blocking cell is a transition the
// reference lacks. The witness of a kind is its transition whose source is nearest a start (the
// explorers' BFS trees give the distances).

#include "checker/Diff.h"

#include "rules/Budget.h"

#include <algorithm>
#include <map>
#include <span>
#include <unordered_map>

namespace holon::checker {

namespace {

/// Names of cell states, numbered in the order met, shared by both designs: per design, the
/// number of each of its values (a lookup per cell, not a string per cell and state).
class NameTable {
public:
    std::vector<std::uint32_t> numbers(const rules::Engine& engine) {
        const rules::Alphabet& alphabet = engine.model().alphabet();
        std::vector<std::uint32_t> out(static_cast<std::size_t>(alphabet.size()));
        for (int v = 0; v < alphabet.size(); ++v)
            out[static_cast<std::size_t>(v)] = ids_.emplace(alphabet.name(static_cast<CellValue>(v)), static_cast<std::uint32_t>(ids_.size())).first->second;
        return out;
    }

private:
    std::map<std::string, std::uint32_t> ids_;
};

/// One side: every state's key (its cells' state numbers) in one flat array, and the states by
/// the key's hash.
struct Keyed {
    std::size_t cells = 0;
    std::vector<std::uint32_t> keys;  // state s's key at keys[s * cells, (s + 1) * cells); holes are zeros
    std::unordered_multimap<std::uint64_t, StateId> byHash;
    std::span<const std::uint32_t> key(StateId s) const { return {keys.data() + static_cast<std::size_t>(s) * cells, cells}; }
    static std::uint64_t hash(std::span<const std::uint32_t> k) {
        std::uint64_t h = 1469598103934665603ull;
        for (std::uint32_t v : k) h = (h ^ v) * 1099511628211ull;
        return h;
    }
    StateId find(std::span<const std::uint32_t> k) const {
        const auto [from, to] = byHash.equal_range(hash(k));
        for (auto it = from; it != to; ++it)
            if (std::equal(k.begin(), k.end(), key(it->second).begin())) return it->second;
        return kNoState;
    }
};

/// Reads the budget every 4,096 states: a comparison of millions of states takes seconds.
struct Pacer {
    const Budget* budget;
    std::uint32_t ticks = 0;
    std::optional<StopReason> stop;
    bool stopped() {
        if (stop) return true;
        if (++ticks < 4096) return false;
        ticks = 0;
        stop = budget->reached();
        return stop.has_value();
    }
};

std::optional<Keyed> keyAll(const ExploredDesign& d, NameTable& names, Pacer& pacer) {
    Keyed k;
    const std::vector<std::uint32_t> number = names.numbers(*d.engine);
    k.cells = static_cast<std::size_t>(d.engine->region().size());
    k.keys.assign(d.explorer->store().capacityUsed() * k.cells, 0);
    k.byHash.reserve(d.explorer->stats().states);
    for (StateId s : d.explorer->ids()) {
        if (pacer.stopped()) return std::nullopt;
        const std::vector<CellValue> cells = d.explorer->cells(s);
        std::uint32_t* key = k.keys.data() + static_cast<std::size_t>(s) * k.cells;
        for (std::size_t i = 0; i < k.cells; ++i) key[i] = number[cells[i]];
        k.byHash.emplace(Keyed::hash(k.key(s)), s);
    }
    return k;
}

/// Whether `other` has the step from its state f to its state t (kNoState: it lacks the configuration).
bool hasStep(const ExploredDesign& other, StateId f, StateId t) {
    if (f == kNoState || t == kNoState) return false;
    const auto& row = other.explorer->rowStart();
    const auto& succ = other.explorer->successors();
    for (std::uint64_t e = row[f]; e < row[f + 1]; ++e)
        if (succ[e] == t) return true;
    return false;
}

/// Steps from a start to state s along the explorer's tree.
std::size_t depthOf(const Explorer& ex, StateId s) {
    std::size_t depth = 0;
    for (StateId p = ex.parent(s); p != kNoState; p = ex.parent(p)) ++depth;
    return depth;
}

}  // namespace

std::variant<DesignDifference, StopReason> compareDesigns(const ExploredDesign& a, const ExploredDesign& b, const Budget& budget) {
    NameTable names;
    Pacer pacer{&budget, 0, std::nullopt};
    const ExploredDesign sides[2] = {a, b};
    std::optional<Keyed> keyed[2];
    for (int side = 0; side < 2; ++side)
        if (!(keyed[side] = keyAll(sides[side], names, pacer))) return *pacer.stop;
    DesignDifference diff;
    std::vector<StateId> seen;  // a state's distinct successors: several instances may lead to one
    std::vector<StateId> twin;  // per state of this side: the other side's state of the same configuration
    for (int side = 0; side < 2; ++side) {
        const ExploredDesign& other = sides[1 - side];
        const Keyed& k = *keyed[side];
        const Explorer& ex = *sides[side].explorer;
        const auto& row = ex.rowStart();
        const auto& succ = ex.successors();
        twin.assign(ex.store().capacityUsed(), kNoState);
        for (StateId s : ex.ids()) {
            if (pacer.stopped()) return *pacer.stop;
            ++diff.states[side];
            if ((twin[s] = keyed[1 - side]->find(k.key(s))) == kNoState) ++diff.onlyStates[side];
        }
        StateId nearest = kNoState;
        std::uint64_t nearestEdge = 0;
        std::size_t nearestDepth = 0;
        for (StateId s : ex.ids()) {
            if (pacer.stopped()) return *pacer.stop;
            seen.clear();
            for (std::uint64_t e = row[s]; e < row[s + 1]; ++e) {
                if (std::find(seen.begin(), seen.end(), succ[e]) != seen.end()) continue;
                seen.push_back(succ[e]);
                ++diff.transitions[side];
                if (hasStep(other, twin[s], twin[succ[e]])) continue;
                ++diff.onlyTransitions[side];
                const std::size_t depth = depthOf(ex, s);
                if (nearest == kNoState || depth < nearestDepth) nearest = s, nearestEdge = e, nearestDepth = depth;
            }
        }
        if (nearest != kNoState) diff.transitionWitness[side] = traceWithStep(ex, nearest, nearestEdge);
    }
    return diff;
}

int DiffReport::stopped() const {
    for (int side = 0; side < 2; ++side)
        if (!explored[side].explorer || explored[side].explorer->stats().stopped != StopReason::Finished) return side;
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
    for (int side = 0; side < 2; ++side) report.systems[side] = models[side]->system().name;
    for (int side = 0; side < 2; ++side) {
        // A stopped first exploration decides the report: building B's engine after the deadline or
        // a signal would throw, and A's report would be lost.
        if (side == 1 && report.stopped() == 0) break;
        CheckOptions co;
        co.limits = options.limits;
        co.limits.memoryBytes /= 2;
        co.all = options.all, co.initial = options.initial[side], co.inputs = options.inputs[side];
        Exploration& x = report.explored[side];
        x.engine = checkEngine(*models[side], region, co, co.limits);
        Explorer::Options xo;
        xo.limits = co.limits;
        xo.budget = budget;
        x.explorer = startExplorer(*x.engine, co, xo);
        x.explorer->explore();
    }
    if (report.stopped() >= 0) return report;
    auto compared = compareDesigns({report.explored[0].engine.get(), report.explored[0].explorer.get()}, {report.explored[1].engine.get(), report.explored[1].explorer.get()}, budget);
    if (auto* d = std::get_if<DesignDifference>(&compared)) report.difference = std::move(*d);
    else report.comparisonStopped = std::get<StopReason>(compared);
    return report;
}

}  // namespace holon::checker
