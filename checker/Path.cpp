// Shortest paths by breadth-first search on the explorer (checker/Path.h). The explorer asks
// `decided` after each level, so the first level that stores a target is its distance; the search
// keeps no edges (only the BFS tree), which is what makes 10^7-state spaces cheap to cross.

#include "checker/Path.h"

#include "rules/Error.h"

#include <algorithm>
#include <mutex>

namespace holon::checker {

PathResult shortestPath(const rules::Engine& engine, const PathQuery& query) {
    const std::size_t n = query.from.cells.size();
    const auto& goal = engine.model().system().goal;
    if (!query.to && !goal) throw InputError("system '" + engine.model().system().name + "' declares no goal; give --to CONFIG, or declare one with 'goal EXPR'");
    if (query.to && query.to->cells.size() != n) throw InputError("--to: the configuration does not fit the region of --from");
    const auto isTarget = [&](const CellValue* cells) {
        return query.to ? std::equal(cells, cells + n, query.to->cells.begin()) : engine.holds(*goal, cells);
    };

    std::mutex mutex;
    StateId best = kNoState;
    std::vector<CellValue> bestCells;
    Explorer::Options options;
    options.limits = query.limits;
    options.recordEdges = false;
    options.onProgress = query.onProgress;
    options.onState = [&](StateId id, const CellValue* cells) {
        if (!isTarget(cells)) return;
        std::lock_guard<std::mutex> lock(mutex);
        if (best == kNoState || std::lexicographical_compare(cells, cells + n, bestCells.begin(), bestCells.end()))
            best = id, bestCells.assign(cells, cells + n);
    };
    options.decided = [&] {
        std::lock_guard<std::mutex> lock(mutex);
        return best != kNoState;
    };
    Explorer explorer(engine, options);
    explorer.addInitial(query.from.cells.data());
    PathResult result;
    result.stats = explorer.explore();
    if (best != kNoState) {
        result.outcome = PathOutcome::Found;
        result.trace = traceTo(explorer, best);
        result.trace.description = query.to ? "a shortest path to the given configuration" : "a shortest path to the goal";
        return result;
    }
    switch (result.stats.stopped) {
    case StopReason::Finished: result.outcome = PathOutcome::Unreachable; break;
    case StopReason::MaxStates:
    case StopReason::Timeout:
    case StopReason::Memory:
    case StopReason::Interrupted:
    case StopReason::Decided: result.outcome = PathOutcome::Undecided; break;
    case StopReason::Goal:  // the planner's reasons: an exploration does not stop by them
    case StopReason::Stuck:
    case StopReason::NoProgress:
    case StopReason::Monitor:
    case StopReason::Fault:
    case StopReason::MaxSteps:
    case StopReason::MaxRounds: throw InternalError("findPath: the exploration stopped by " + stopReasonName(result.stats.stopped));
    }
    return result;
}

}  // namespace holon::checker
