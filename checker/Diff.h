#pragma once
// Comparing two designs on one region (`holon diff`): the reconfiguration graphs each explores from
// the same starts, matched configuration by configuration through the names of the cell states (so
// a variant with other value numbers, or extra states, still compares), and the transitions and
// configurations one has and the other lacks, each kind with its witness nearest a start.

#include "checker/Explorer.h"
#include "checker/Trace.h"

#include <optional>
#include <string>
#include <vector>

namespace holon::checker {

/// One design explored: its engine and graph (edges recorded).
struct ExploredDesign {
    const rules::Engine* engine;
    const Explorer* explorer;
};

struct DesignDifference {
    std::uint64_t transitions[2] = {0, 0};  // distinct (configuration, successor) pairs of A and of B
    std::uint64_t states[2] = {0, 0};
    /// Transitions (and reachable configurations) of A that B lacks, and of B that A lacks.
    std::uint64_t onlyTransitions[2] = {0, 0}, onlyStates[2] = {0, 0};
    /// Per side: a shortest trace to the nearest source of a transition the other side lacks, then
    /// that step (its last step names the instance); nothing when there is none.
    std::optional<Trace> transitionWitness[2];
    bool same() const { return !onlyTransitions[0] && !onlyTransitions[1] && !onlyStates[0] && !onlyStates[1]; }
};

/// Compares two fully explored designs (the caller checks that neither stopped at a limit).
DesignDifference compareDesigns(const ExploredDesign& a, const ExploredDesign& b);

}  // namespace holon::checker
