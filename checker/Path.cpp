// Shortest paths (checker/Path.h): the choice of search, and the forward one, breadth-first on
// the explorer. The explorer asks `decided` after each level, so the first level that stores a
// target is its distance; the search keeps no edges (only the BFS tree), which is what makes
// 10^7-state spaces cheap to cross. The searches towards one given configuration, which need
// fewer states, are in PathBidirectional.cpp and PathAStar.cpp.

#include "checker/Path.h"

#include "checker/PathSearch.h"

#include "rules/Error.h"
#include "rules/Parameter.h"

#include <algorithm>
#include <mutex>

namespace holon::checker {

std::string pathSearchName(PathSearch s) {
    switch (s) {
    case PathSearch::Auto: return "auto";
    case PathSearch::Forward: return "forward";
    case PathSearch::Bidirectional: return "bidirectional";
    case PathSearch::AStar: return "astar";
    }
    return "?";
}

namespace {

PathResult forwardPath(const rules::Engine& engine, const PathQuery& query) {
    const std::size_t n = query.from.cells.size();
    const auto& goal = engine.model().system().goal;
    const auto isTarget = [&](const CellValue* cells) {
        return query.to ? std::equal(cells, cells + n, query.to->cells.begin()) : engine.holds(*goal, cells);
    };

    std::mutex mutex;
    StateId best = kNoState;
    std::vector<CellValue> bestCells;
    // The smallest target of the nearest level: the level stored while the one before is expanded,
    // but the start is at distance 0, and a smaller target one step away won over it (an audit).
    bool atStart = true, startIsTarget = false;
    Explorer::Options options;
    options.limits = query.limits;
    options.recordEdges = false;
    options.onProgress = query.onProgress;
    options.onState = [&](StateId id, const CellValue* cells) {
        if (!isTarget(cells)) return;
        std::lock_guard<std::mutex> lock(mutex);
        if (startIsTarget) return;
        startIsTarget = atStart;
        if (best == kNoState || startIsTarget || std::lexicographical_compare(cells, cells + n, bestCells.begin(), bestCells.end()))
            best = id, bestCells.assign(cells, cells + n);
    };
    options.decided = [&] {
        std::lock_guard<std::mutex> lock(mutex);
        return best != kNoState;
    };
    Explorer explorer(engine, options);
    explorer.addInitial(query.from.cells.data());
    atStart = false;
    PathResult result;
    result.search = PathSearch::Forward;
    result.stats = explorer.explore();
    if (best != kNoState) {
        result.outcome = PathOutcome::Found;
        result.trace = traceTo(explorer, best);
        result.trace.description = query.to ? "a shortest path to the given configuration" : "a shortest path to the goal";
        return result;
    }
    switch (result.stats.stopped) {
    case StopReason::Finished: result.outcome = PathOutcome::Unreachable, result.closed = result.stats.states; break;
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
    case StopReason::MaxRounds: throw InternalError("forwardPath: the exploration stopped by " + stopReasonName(result.stats.stopped));
    }
    return result;
}

}  // namespace

PathResult shortestPath(const rules::Engine& engine, const PathQuery& query) {
    using rules::Parameter, rules::parameterName;
    const std::string to = parameterName(Parameter::To), search = parameterName(Parameter::Search);
    if (!query.to && !engine.model().system().goal)
        throw InputError("system '" + engine.model().system().name + "' declares no goal; give " + to + " CONFIG, or declare one with 'goal EXPR'", Parameter::To);
    if (query.to && query.to->cells.size() != query.from.cells.size())
        throw InputError(to + ": the configuration does not fit the region of " + parameterName(Parameter::From), Parameter::To);
    if (!query.to && (query.search == PathSearch::Bidirectional || query.search == PathSearch::AStar))
        throw InputError(search + " " + pathSearchName(query.search) + " needs a target configuration: give " + to + " CONFIG instead of " + parameterName(Parameter::Goal) +
                             ", or " + search + " forward",
                         Parameter::Search);
    switch (query.search) {
    case PathSearch::Forward: return forwardPath(engine, query);
    case PathSearch::AStar: return aStarPath(engine, Footprints(engine), query);
    case PathSearch::Auto:
    case PathSearch::Bidirectional: break;
    }
    if (!query.to) return forwardPath(engine, query);
    const Predecessors predecessors(engine);
    if (predecessors.irreversible().empty()) return bidirectionalPath(engine, predecessors, query);
    PathResult result = forwardPath(engine, query);
    result.fallback = predecessors.irreversible();
    return result;
}

}  // namespace holon::checker
