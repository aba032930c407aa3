#pragma once
// A planning problem: a planner rule system, a start shape, a target shape and a seed, laid out on
// a Board with the initial cell states (seed F, all others U; resources where the system has them).

#include "planner/BoxEngine.h"
#include "planner/Shape.h"
#include "rules/Model.h"

#include <functional>
#include <memory>
#include <optional>
#include <random>

namespace holon::planner {

/// How a planner system names its parts: seed 000 §IV-A's labels and the target input.
struct PlannerSchema {
    int label = -1, unknown = -1, path = -1, final = -1;  // field index, and its values U, P, F
    int target = -1;                                      // input index
    int parent = -1;                                      // the dir field 'parent' pointing a P up its tree, or -1
    int resource = -1;                                    // the field that carries mass, or -1
    int full = -1, creator = -1;                          // resource values of mass 1 (D) and the most mass (C)
    rules::Rational extra;                                // mass(C) - 1: what a creator carries beyond a metamodule
    /// Reads the schema of a system; throws InputError naming what is missing.
    static PlannerSchema of(const rules::System& system);
};

struct Problem {
    const rules::Model* model = nullptr;
    PlannerSchema schema;
    Shape start, target;
    Vec seed;
    std::unique_ptr<rules::RuleTables> tables;
    /// The system's goal `all(P)`, compiled: a cell is as the goal wants it when P accepts it.
    rules::RuleTables::Mask goal;
    std::unique_ptr<Board> board;
    std::unique_ptr<BoxEngine> engine;
    std::vector<BoxEngine::Value> cells;  // the initial configuration on the board
    std::int64_t creators = 0;            // C resources placed in the start
    /// Counts of what the plan must do: |T \ S| creations and |S \ T| deletions.
    std::int64_t toCreate = 0, toDelete = 0;
};

/// The least and most mass (in the tables' mass units) a cell with input combination `combo` holds
/// in a state the goal accepts there, the empty state included; nothing when it accepts none.
struct GoalMass {
    std::int64_t least = 0, most = 0;
};
std::optional<GoalMass> goalMass(const Problem& problem, int combo);

/// Memory a plan keeps per cell of its board (the box around start and target, padded), for
/// --memory: the problem's layout (target combo, start cell, connectivity marks), the run's state
/// (planner/Execution.h: the cell, its enabled and listed bits, marks, stamp), one list entry per
/// enabled instance at most, the allocator's and monitor's few bytes and, for a system with
/// resources, the transport problem of the transfer bound (planner/Transport.h: a node and
/// degree + 2 arcs per cell, with the network simplex's arrays). An upper bound: 1.3 to 4 times
/// the peak measured on boards of 10^6 cells (docs/cli.md, "Exit codes and limits").
constexpr std::uint64_t planBytesPerCell(int shapes, int degree, bool resources) {
    const std::uint64_t words = (static_cast<std::uint64_t>(shapes) + 63) / 64;
    const std::uint64_t run = 6 + 1 + 16 * words + 8 + 4 + 8 * static_cast<std::uint64_t>(shapes) + 16;
    return run + (resources ? 100 * (static_cast<std::uint64_t>(degree) + 2) : 0);
}

/// Validates and lays out a problem; throws InputError (exit 2) for a target that is not
/// connected, a start that is not connected, no overlap, a mass the target cannot hold, a shape of
/// the wrong dimension for the lattice, a seed outside start and target, or a system whose goal is
/// not of the form all(P) (the planner stops when every cell satisfies P); throws LimitError (exit
/// 3) before the board is made when it needs more than `memoryBytes` (planBytesPerCell).
/// `checkpoint` is called between its phases (each a second or so at 10^7 cells), where the caller
/// may stop it by throwing (a deadline, a signal).
Problem makeProblem(
    const rules::Model& model, Shape start, Shape target, std::optional<Vec> seed, std::uint64_t randomSeed,
    std::uint64_t memoryBytes = UINT64_MAX, const std::function<void()>& checkpoint = [] {});

}  // namespace holon::planner
