#pragma once
// Parallel steps for `holon path --parallel`: the steps of a sequential path grouped into rounds
// of instances that fire together, and the check of such a schedule by the reference interpreter.

#include "checker/PathSearch.h"
#include "checker/Trace.h"

#include <string>
#include <vector>

namespace holon::checker {

/// Rounds of a path's steps (indices into Trace::steps, from 1), each round's steps in path order.
struct Schedule {
    std::vector<std::vector<int>> rounds;
    std::size_t makespan() const { return rounds.size(); }
};

/// A greedy compaction of `path` (not a shortest parallel path): each step in turn goes into the
/// earliest round after the last one holding an earlier step it interferes with (Footprints) where
/// the schedule stays valid (validFrom, on the engine), else into a new last round.
Schedule compactSteps(const Trace& path, const rules::Engine& engine, const Footprints& footprints);

/// The schedule replayed through the reference interpreter: every step of the path in exactly one
/// round; in each round, every instance has a successor from the round's start (enabled, the
/// result legal) and the round's instances, fired one after another in path order and in reverse
/// order, are each enabled at their turn and end in the same legal configuration (they commute);
/// the last round ends at the path's last configuration.
bool replaySchedule(const Schedule& schedule, const Trace& path, const rules::Engine& engine, const rules::Interpreter& in, std::string* why = nullptr);

}  // namespace holon::checker
