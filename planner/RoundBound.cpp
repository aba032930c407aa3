// The cut bound on rounds for mass-conserving planner systems (issue 28). The shape bench compares
// rounds with the intermediate planner's (seed 000 §V), which creates and deletes for free. A
// system that conserves mass (general_n, seed 000 §IV-B) must carry every unit of a created
// metamodule in through the cells around it, and every unit of a deleted one out, and a narrow
// place lets only so much through a round.
//
// Under synchronous rounds (Execution.cpp) a cell loses mass in at most one rule instance a round:
// the round's instances write disjoint cells, and a pipelined transfer takes only from a cell that
// has not acted. An instance moves mass among its own cells only (the system conserves mass: what
// some of its cells gain, the others lose), so in one round mass enters a set S only from cells
// outside S within the rules' span of S (the gate), at most `perCell` units each: the most one
// cell of an instance can lose. A cell that is empty at the start and that no rule can fill never
// holds mass, so it is no gate. Hence, for every S that must gain G units in all,
//     rounds >= G / (|gate(S)| * perCell),
// and the same for a set that must lose mass, with its gate the cells of S within the span of the
// cells outside it that can hold mass. The sets tried: the cells to fill at least r steps from the
// start's mass, and the cells to empty at least r steps from any cell that may keep mass, for
// every r, each connected component apart. On a spiral arm one metamodule wide that must go, the
// gate is the arm's one cell next to the rest, and every unit of the arm leaves through it.

#include "planner/RoundBound.h"

#include "planner/BoxEngine.h"

#include <algorithm>
#include <limits>
#include <unordered_map>

namespace holon::planner {

namespace {

constexpr int kMaxSpan = 8;                                                     // patterns wider than this give no bound (none of the library's)
constexpr std::size_t kMaxCuts = 64;                                            // distances tried per side: a bound from fewer sets is still one
constexpr std::int64_t kNoGoalMass = std::numeric_limits<std::int64_t>::max();  // no goal state: nothing asked
constexpr std::int32_t kNoHops = std::numeric_limits<std::int32_t>::max();      // not reached

struct Rules {
    std::int64_t perCell = 0;  // the most mass units one cell of one instance can lose
    int span = 0;              // the largest lattice distance between two cells of an instance that moves mass
};

/// Lattice distance between two board offsets, or -1 beyond kMaxSpan.
int distance(const Board& board, std::int64_t from, std::int64_t to) {
    std::unordered_map<std::int64_t, int> seen{{from, 0}};
    std::vector<std::int64_t> layer{from};
    for (int d = 0; d <= kMaxSpan; ++d) {
        if (std::find(layer.begin(), layer.end(), to) != layer.end()) return d;
        std::vector<std::int64_t> next;
        for (std::int64_t x : layer)
            for (int k = 0; k < board.lattice().degree(); ++k)
                if (seen.emplace(x + board.step(k), d + 1).second) next.push_back(x + board.step(k));
        layer.swap(next);
    }
    return -1;
}

std::optional<Rules> massMoves(const Problem& problem) {
    const rules::RuleTables& tables = *problem.tables;
    const BoxEngine& engine = *problem.engine;
    const int values = tables.alphabet();
    auto admits = [&](const rules::RuleTables::Mask& m, int v) {
        for (int c = 0; c < tables.comboCount(); ++c)
            if (tables.test(m, c, static_cast<rules::CellValue>(v))) return true;
        return false;
    };
    Rules r;
    for (int s = 0; s < engine.shapeCount(); ++s) {
        const auto& t = tables.shape(s);
        bool moves = false;
        for (std::size_t k = 0; k < t.lhs.size(); ++k)
            for (int v = 0; v < values; ++v) {
                if (!admits(t.lhs[k], v)) continue;
                const std::int64_t was = tables.massUnitsOf(static_cast<rules::CellValue>(v));
                if (const int j = t.copyFrom[k]; j >= 0) {
                    for (int w = 0; w < values; ++w)
                        if (admits(t.lhs[static_cast<std::size_t>(j)], w)) {
                            const std::int64_t now = tables.massUnitsOf(static_cast<rules::CellValue>(w));
                            moves = moves || now != was, r.perCell = std::max(r.perCell, was - now);
                        }
                } else if (!t.rhs[k].empty()) {
                    const std::int64_t now = tables.massUnitsOf(t.rhs[k][static_cast<std::size_t>(v)]);
                    moves = moves || now != was, r.perCell = std::max(r.perCell, was - now);
                }
            }
        if (!moves) continue;
        const std::span<const std::int64_t> cells = engine.cellSteps(s);
        for (std::size_t a = 0; a < cells.size(); ++a)
            for (std::size_t b = a + 1; b < cells.size(); ++b) {
                const int d = distance(*problem.board, cells[a], cells[b]);
                if (d < 0) return std::nullopt;
                r.span = std::max(r.span, d);
            }
    }
    if (r.perCell == 0 || r.span == 0) return std::nullopt;
    return r;
}

class Cuts {
public:
    Cuts(const Problem& problem, const Rules& rules) : problem_(&problem), rules_(rules) {
        const Board& board = *problem.board;
        const BoxEngine& engine = *problem.engine;
        const rules::RuleTables& tables = *problem.tables;
        // Per input combination: whether a rule can fill an empty cell, and the least and most mass
        // a cell may hold at the goal.
        const int combos = tables.comboCount();
        std::vector<char> fillable(static_cast<std::size_t>(combos), 0);
        std::vector<std::int64_t> least(static_cast<std::size_t>(combos), kNoGoalMass), most(static_cast<std::size_t>(combos), 0);
        for (int c = 0; c < combos; ++c) {
            for (int s = 0; s < engine.shapeCount(); ++s) {
                const auto& t = tables.shape(s);
                for (std::size_t k = 0; k < t.lhs.size(); ++k)
                    if (tables.test(t.lhs[k], c, 0) && (t.copyFrom[k] >= 0 ? t.copyFrom[k] != static_cast<int>(k) : !t.rhs[k].empty() && t.rhs[k][0] != 0))
                        fillable[static_cast<std::size_t>(c)] = 1;
            }
            if (const std::optional<GoalMass> g = goalMass(problem, c)) least[static_cast<std::size_t>(c)] = g->least, most[static_cast<std::size_t>(c)] = g->most;
        }
        const auto size = static_cast<std::size_t>(board.size());
        mayHold_.assign(size, 0), keeps_.assign(size, 0), gain_.assign(size, 0), loss_.assign(size, 0);
        for (std::size_t i = 0; i < size; ++i) {
            const std::uint8_t c = engine.combo(static_cast<std::int64_t>(i));
            if (c == BoxEngine::kOutside) continue;
            const std::int64_t m = tables.massUnitsOf(problem.cells[i]);
            mayHold_[i] = problem.cells[i] != 0 || fillable[c];  // a metamodule of no mass may still take some
            keeps_[i] = mayHold_[i] && most[c] > 0;
            if (!mayHold_[i] || least[c] == kNoGoalMass) continue;  // no goal state here: nothing is asked
            gain_[i] = std::max<std::int64_t>(0, least[c] - m), loss_[i] = std::max<std::int64_t>(0, m - most[c]);
        }
        for (int d = 0; d < board.lattice().degree(); ++d) steps_.push_back(board.step(d));
        mark_.assign(size, 0), member_.assign(size, 0);
    }

    /// The best bound over the cuts of one side: cells that must gain mass (`creation`) or lose it.
    std::optional<RoundBound> best(bool creation) {
        const std::vector<std::int64_t>& need = creation ? gain_ : loss_;
        // Hop counts over the cells that may hold mass, from where the mass is (creation) or may stay.
        std::vector<std::int64_t> from;
        for (std::size_t i = 0; i < need.size(); ++i)
            if (mayHold_[i] && (creation ? problem_->tables->massUnitsOf(problem_->cells[i]) > 0 : loss_[i] == 0 && keeps_[i])) from.push_back(static_cast<std::int64_t>(i));
        const std::vector<std::int32_t> hops = spread(from);
        std::vector<std::int32_t> levels;
        for (std::size_t i = 0; i < need.size(); ++i)
            if (need[i] > 0) levels.push_back(hops[i]);
        if (levels.empty()) return std::nullopt;
        std::sort(levels.begin(), levels.end());
        levels.erase(std::unique(levels.begin(), levels.end()), levels.end());
        std::optional<RoundBound> best;
        for (std::size_t k = 0; k < std::min(levels.size(), kMaxCuts); ++k) {
            const std::int32_t r = levels[k * levels.size() / std::min(levels.size(), kMaxCuts)];
            for (std::size_t i = 0; i < need.size(); ++i) member_[i] = need[i] > 0 && hops[i] >= r;
            for (std::size_t i = 0; i < need.size(); ++i) {
                if (member_[i] != 1) continue;
                const RoundBound b = component(static_cast<std::int64_t>(i), need, creation);
                if (b.gate > 0 && (!best || b.rounds > best->rounds)) best = b;
            }
        }
        return best;
    }

private:
    bool inside(std::int64_t j) const { return j >= 0 && j < static_cast<std::int64_t>(mayHold_.size()); }

    std::vector<std::int32_t> spread(const std::vector<std::int64_t>& sources) const {
        std::vector<std::int32_t> hops(mayHold_.size(), kNoHops);
        std::vector<std::int64_t> queue = sources;
        for (std::int64_t i : sources) hops[static_cast<std::size_t>(i)] = 0;
        for (std::size_t k = 0; k < queue.size(); ++k)
            for (std::int64_t s : steps_)
                if (const std::int64_t j = queue[k] + s; inside(j) && mayHold_[j] && hops[j] == kNoHops) hops[j] = hops[queue[k]] + 1, queue.push_back(j);
        return hops;
    }

    /// The component of members through `seed` (marked 2 once taken) and its bound.
    RoundBound component(std::int64_t seed, const std::vector<std::int64_t>& need, bool creation) {
        std::vector<std::int64_t> cells{seed};
        member_[seed] = 2;
        RoundBound b;
        b.creation = creation, b.perCell = rules_.perCell;
        for (std::size_t k = 0; k < cells.size(); ++k) {
            b.mass += need[cells[k]];
            for (std::int64_t s : steps_)
                if (const std::int64_t j = cells[k] + s; inside(j) && member_[j] == 1) member_[j] = 2, cells.push_back(j);
        }
        b.cells = static_cast<std::int64_t>(cells.size());
        // The cells within the span of the component that are not in it and may hold mass: the
        // gate on the creation side; on the deletion side, the component's cells within the span
        // of them.
        std::vector<std::int64_t> near;
        forEachWithinSpan(cells, [&](std::int64_t j) {
            if (mayHold_[j]) near.push_back(j);
        });
        if (creation) b.gate = static_cast<std::int64_t>(near.size());
        else forEachWithinSpan(near, [&](std::int64_t j) { b.gate += member_[j] == 2; });
        if (b.gate > 0) b.rounds = (b.mass + b.gate * b.perCell - 1) / (b.gate * b.perCell);
        return b;
    }

    /// Calls f once for each cell not in `from` within the rules' span of it.
    template <class F>
    void forEachWithinSpan(const std::vector<std::int64_t>& from, F&& f) {
        if (++epoch_ == 0) std::fill(mark_.begin(), mark_.end(), 0), epoch_ = 1;
        for (std::int64_t i : from) mark_[i] = epoch_;
        std::vector<std::int64_t> layer = from;
        for (int d = 0; d < rules_.span; ++d) {
            std::vector<std::int64_t> next;
            for (std::int64_t i : layer)
                for (std::int64_t s : steps_)
                    if (const std::int64_t j = i + s; inside(j) && mark_[j] != epoch_) mark_[j] = epoch_, next.push_back(j), f(j);
            layer.swap(next);
        }
    }

    const Problem* problem_;
    Rules rules_;
    std::vector<char> mayHold_;              // per board cell: holds mass at the start, or a rule can fill it
    std::vector<char> keeps_;                // per board cell: a goal state here holds mass
    std::vector<std::int64_t> gain_, loss_;  // per board cell: mass it must gain, or lose, by the goal
    std::vector<std::int64_t> steps_;
    std::vector<std::uint32_t> mark_;
    std::uint32_t epoch_ = 0;
    std::vector<char> member_;  // 1: in the current set, 2: taken into a component
};

}  // namespace

std::optional<RoundBound> roundLowerBound(const Problem& problem) {
    if (!problem.model->system().conservesMass()) return std::nullopt;
    const std::optional<Rules> rules = massMoves(problem);
    if (!rules) return std::nullopt;
    Cuts cuts(problem, *rules);
    std::optional<RoundBound> best;
    for (bool creation : {true, false})
        if (const std::optional<RoundBound> b = cuts.best(creation); b && (!best || b->rounds > best->rounds)) best = b;
    return best;
}

}  // namespace holon::planner
