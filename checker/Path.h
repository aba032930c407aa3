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

/// How to search. Auto: bidirectional to a given configuration when every rule runs backwards
/// exactly, else forward; forward to the goal.
enum class PathSearch { Auto,
                        Forward,
                        Bidirectional,
                        AStar };
std::string pathSearchName(PathSearch s);

struct PathQuery {
    rules::Configuration from;
    std::optional<rules::Configuration> to;  // nothing: any configuration where the goal holds
    PathSearch search = PathSearch::Auto;    // Bidirectional and AStar need `to`
    Limits limits;
    std::function<void(const ExploreStats&)> onProgress;
};

enum class PathOutcome { Found,
                         Unreachable,
                         Undecided };

struct PathResult {
    PathOutcome outcome = PathOutcome::Undecided;
    Trace trace;                              // when Found: a shortest path, trace.steps.size() - 1 rule steps
    ExploreStats stats;                       // the searched space (both sides of a bidirectional search)
    PathSearch search = PathSearch::Forward;  // the search that ran
    std::string fallback;                     // why it is not the one asked for, or empty
    int bound = -1;                           // A*: the bound at `from` (a lower bound on the length)
    /// When Unreachable, the evidence: a side that ran dry, all of whose configurations were
    /// searched: every configuration reachable from `from` (fromStart), or every one from which
    /// `to` is reachable.
    std::uint64_t closed = 0;
    bool closedFromStart = true;
};

/// A shortest path from `query.from` (legal; the caller checks). Forward: breadth-first on the
/// explorer, stopping after the level that stores a target: the BFS tree's path to it is a
/// shortest one. Among several goal configurations at that distance the smallest (cell by cell)
/// is taken, so the answer does not depend on the threads' timing. Bidirectional and A*:
/// checker/PathSearch.h. `engine` carries the inputs of `query.from`.
PathResult shortestPath(const rules::Engine& engine, const PathQuery& query);

}  // namespace holon::checker
