#pragma once
// A planning problem: a planner rule system, a start shape, a target shape and a seed, laid out on
// a Board with the initial cell states (seed F, all others U; resources where the system has them).

#include "planner/BoxEngine.h"
#include "planner/Shape.h"
#include "rules/Model.h"

#include <memory>
#include <optional>
#include <random>

namespace holon::planner {

/// How a planner system names its parts: seed 000 §IV-A's labels and the target input.
struct PlannerSchema {
    int label = -1, unknown = -1, path = -1, final = -1;  // field index, and its values U, P, F
    int target = -1;                                     // input index
    int resource = -1;                                   // the field that carries mass, or -1
    int full = -1, creator = -1;                         // resource values of mass 1 (D) and the most mass (C)
    rules::Rational extra;                               // mass(C) - 1: what a creator carries beyond a metamodule
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

/// Validates and lays out a problem; throws InputError (exit 2) for a target that is not
/// connected, a start that is not connected, no overlap, a mass the target cannot hold, a shape of
/// the wrong dimension for the lattice, a seed outside start and target, or a system whose goal is
/// not of the form all(P) (the planner stops when every cell satisfies P).
Problem makeProblem(const rules::Model& model, Shape start, Shape target, std::optional<Vec> seed, std::uint64_t randomSeed);

}  // namespace holon::planner
