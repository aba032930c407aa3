#pragma once
// Shortest reconfiguration paths (`holon path`): from one configuration to another, or to any
// configuration where the system's goal holds. The Modular Robotics Web Tool's Pathfinder answers
// the same question with BFS over move patterns; holon runs it on the explorer, so a path search
// has the explorer's packed states, threads and limits, and a path is replayable like a trace.

#include "checker/Explorer.h"
#include "checker/Trace.h"
#include "rules/Interpreter.h"

#include <functional>
#include <optional>

namespace holon::checker {

struct PathQuery {
    rules::Configuration from;
    std::optional<rules::Configuration> to;  // nothing: any configuration where the goal holds
    Limits limits;
    std::function<void(const ExploreStats&)> onProgress;
};

enum class PathOutcome { Found,
                         Unreachable,
                         Undecided };

struct PathResult {
    PathOutcome outcome = PathOutcome::Undecided;
    Trace trace;         // when Found: a shortest path, trace.steps.size() - 1 rule steps
    ExploreStats stats;  // the searched space: when Unreachable, every configuration reachable from `from`
};

/// Breadth-first from `query.from` (legal; the caller checks), stopping after the level that
/// stores a target: the BFS tree's path to it is a shortest one. Among several goal
/// configurations at that distance the smallest (cell by cell) is taken, so the answer does not
/// depend on the threads' timing. `engine` carries the inputs of `query.from`.
PathResult shortestPath(const rules::Engine& engine, const PathQuery& query);

}  // namespace holon::checker
