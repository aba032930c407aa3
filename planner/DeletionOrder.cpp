// The order in which the field allocators let P metamodules be deleted (see DeletionOrder.h).
//
// Why: the planner allows a deletion at every P leaf that has destroyers, and in general_1 every
// metamodule starts as one, so right behind the relabelling wave all leaves went at once, nearest
// the F region first (their creators drained there first). The region to delete eroded into a
// dendrite, and late in the run a large subtree hung on a single-lane trunk through which its
// whole mass had to leave, one unit per round: rounds grew with the area (box:100x100 ->
// box:50x200, 5,205 rounds where the intermediate planner needs 225).
//
// The policy: each P metamodule knows its depth in the planner's forest (1 below an F, its
// parent's plus one otherwise: a value passed down the tree one hop per round) and the deepest P
// metamodule behind it (its own depth, or the largest such value among its deeper neighbours:
// passed from the far rim inwards one hop per round). A deletion that would start at it waits
// while something deeper lies behind it. So every metamodule keeps the neighbours nearer the F
// region that the mass behind it passes through: the region shrinks from its far rim and its mass
// leaves through its full width. Each metamodule decides from its own state and values its
// neighbours pass on (seed 000 §IV-B). Comparing a metamodule's depth with its neighbours' alone
// (no value passed on) kept the boxes a little faster (block at K = 8: 713 against 905 rounds) but
// serialised 3D spiral starts of the shape bench (spiral->ring: 505 rounds against 138 without
// any order, 143 with this one).
//
// Nothing is held for ever: the deepest P metamodule is a leaf (a child would be deeper) and has
// nothing behind it, so it is never held once the values have settled; the allocators also lift
// every hold when their stall fallback (the paper's randomizer) has the turn. Holding an enabled
// instance back is a choice among enabled instances, so Safety and the ranking of Termination
// hold as proved for any scheduler.

#include "planner/DeletionOrder.h"
#include "planner/ChangedCells.h"
#include "planner/Execution.h"

#include <algorithm>

namespace holon::planner {

DeletionOrder::DeletionOrder(const Problem& problem) : problem_(&problem) {
    const rules::Alphabet& alphabet = problem.model->alphabet();
    const PlannerSchema& s = problem.schema;
    const BoxEngine& engine = *problem.engine;
    const Board& board = *problem.board;
    const auto size = static_cast<std::size_t>(alphabet.size());
    path_.assign(size, 0), full_.assign(size, 0), up_.assign(size, 0);
    for (int v = 1; v < alphabet.size() && s.parent >= 0 && s.resource >= 0; ++v) {
        const std::vector<int>& f = alphabet.fields(static_cast<rules::CellValue>(v));
        path_[v] = f[s.label] == s.path, full_[v] = f[s.resource] == s.full;
        if (f[s.parent] != rules::kAbsent) up_[v] = board.step(f[s.parent]);
    }
    const rules::RuleTables& tables = *problem.tables;
    starts_.assign(static_cast<std::size_t>(engine.shapeCount()), 0);
    for (int sh = 0; sh < engine.shapeCount(); ++sh) {
        if (engine.kind(sh) != ShapeKind::Motion) continue;
        const auto& t = tables.shape(sh);
        for (std::size_t k = 0; k < t.lhs.size(); ++k)
            for (std::size_t v = 1; v < size && !t.rhs[k].empty(); ++v)
                for (int c = 0; c < tables.comboCount() && path_[v] && full_[v]; ++c)
                    if (tables.test(t.lhs[k], c, static_cast<rules::CellValue>(v)) && tables.massUnitsOf(t.rhs[k][v]) < tables.massUnitsOf(static_cast<rules::CellValue>(v)))
                        starts_[sh] = 1;
    }
    for (int d = 0; d < board.lattice().degree(); ++d) around_.push_back(board.step(d));
    depth_.assign(problem.cells.size(), 0), behind_.assign(problem.cells.size(), 0), seen_.assign(problem.cells.size(), 0), mark_.assign(problem.cells.size(), 0);
}

DeletionOrder::Values DeletionOrder::derive(const std::vector<BoxEngine::Value>& cells, std::int64_t i) const {
    const BoxEngine::Value v = cells[i];
    if (!path_[v]) return {0, 0};
    const std::int64_t parent = i + up_[v];
    // Safety keeps the forest acyclic; the cap only bounds a broken rule file's cycle.
    const std::uint32_t depth = path_[cells[parent]] ? std::min<std::uint32_t>(depth_[parent], 1u << 30) + 1 : 1;
    // The deepest metamodule behind this one, through neighbours each deeper than the last: the
    // steps go strictly deeper, so a value that falls (a far metamodule deleted) spreads without
    // counting down.
    std::uint32_t behind = depth;
    for (std::int64_t s : around_)
        if (path_[cells[i + s]] && depth_[i + s] > depth) behind = std::max(behind, behind_[i + s]);
    return {depth, behind};
}

bool DeletionOrder::update(const Execution& ex) {
    const auto& cells = ex.cells();
    const BoxEngine& engine = *problem_->engine;
    auto dirty = [&](std::int64_t i) {
        if (engine.combo(i) == BoxEngine::kOutside || mark_[i]) return;
        mark_[i] = 1, dirty_.push_back(i);
    };
    // Only a metamodule whose own cell or a neighbour's values changed derives its values again.
    forEachChangedCell(cells, seen_, [&](std::int64_t x, BoxEngine::Value) { dirty(x); });
    updates_.clear();
    for (std::int64_t i : dirty_) {
        mark_[i] = 0;
        const Values now = derive(cells, i);
        if (now.depth != depth_[i] || now.behind != behind_[i]) updates_.push_back({i, now});
    }
    dirty_.clear();
    for (const auto& [i, now] : updates_) {
        depth_[i] = now.depth, behind_[i] = now.behind;
        for (std::int64_t s : around_) dirty(i + s);
    }
    return !updates_.empty();
}

bool DeletionOrder::releases(const Execution& ex, std::int64_t anchor, int shape) const {
    if (!starts_[shape]) return true;
    const BoxEngine& engine = ex.engine();
    const auto& t = engine.tables().shape(shape);
    const std::span<const std::int64_t> steps = engine.cellSteps(shape);
    const auto& cells = ex.cells();
    for (std::size_t k = 0; k < steps.size(); ++k) {
        const std::int64_t i = anchor + steps[k];
        const BoxEngine::Value v = cells[i];
        if (!path_[v] || !full_[v] || t.rhs[k].empty() || engine.tables().massUnitsOf(t.rhs[k][v]) >= engine.tables().massUnitsOf(v)) continue;
        if (behind_[i] > depth_[i]) return false;
    }
    return true;
}

}  // namespace holon::planner
