#pragma once
// Comparing two designs on one region (`holon diff`): the reconfiguration graphs each explores from
// the same starts, matched configuration by configuration through the names of the cell states (so
// a variant with other value numbers, or extra states, still compares), and the transitions and
// configurations one has and the other lacks, each kind with its witness nearest a start.

#include "checker/Check.h"
#include "checker/Explorer.h"
#include "checker/Trace.h"

#include <nlohmann/json.hpp>

#include <optional>
#include <string>
#include <variant>
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

/// Compares two fully explored designs (the caller checks that neither stopped at a limit), or
/// says why it stopped: the budget's deadline or a signal, read as it goes.
std::variant<DesignDifference, StopReason> compareDesigns(const ExploredDesign& a, const ExploredDesign& b, const Budget& budget);

struct DiffOptions {
    /// For the whole comparison: one timeout, and memoryBytes shared by the two explorations.
    Limits limits;
    bool all = false;  // every legal configuration instead of the ones reachable from `initial`
    /// Per design (A, B), in its own cell states: the starts (when !all) and the inputs, as in
    /// CheckOptions.
    std::vector<rules::Configuration> initial[2];
    std::vector<std::uint32_t> inputs[2];
};

struct DiffReport {
    std::string systems[2], region;
    Exploration explored[2];
    /// Set when both explorations and the comparison finished.
    std::optional<DesignDifference> difference;
    /// Why the comparison stopped (the deadline, a signal) when both explorations finished; else unset.
    std::optional<StopReason> comparisonStopped;
    /// The first design (0 for A, 1 for B) whose exploration a limit stopped, or -1; with -1 the
    /// comparison after them may still have stopped (comparisonStopped, and no `difference`).
    int stopped() const;
    /// What a side's transition witness shows: "A fires 'rule' after 2 steps; B has no such step".
    std::string witnessText(int side) const;
    /// The counts, and each side's witness as its description and ITF trace (needs `difference`).
    nlohmann::json toJson() const;
};

/// Explores both designs on the region from the same starts, with check's set-up (checkEngine,
/// startExplorer), and compares them when neither stopped at a limit. Throws InputError as check.
DiffReport diff(const rules::Model& a, const rules::Model& b, const rules::Region& region, const DiffOptions& options);

}  // namespace holon::checker
