#pragma once
// Goal structures and seeding recipes (seed 001 §IV-A b, §V): where each metamodule of the structure
// stands (its foot on the floor and its four cells), in which order the seeds become active, and where
// the metamodules start.

#include "planner/roombots/Kinematics.h"
#include "rules/Budget.h"

#include <string>
#include <vector>

namespace holon::planner::roombots {

struct Seed {
    std::array<Cell, 4> cells;  // foot first; the foot stands on the floor (z = 0)
    int group = 0;              // seeds of the lowest unfilled group are the active ones
};

struct Recipe {
    std::string name;
    std::vector<Seed> seeds;  // in recipe order
};

/// One run's setting: a recipe and the starting feet (one per seed, metamodules standing as an upright I).
struct Setting {
    Recipe recipe;
    std::vector<Cell> starts;
};

/// The runs of an experiment per metamodule type and strategy: for "cube" (experiment I) the four L
/// legs of a non-dense 3 x 3 x 3 cube from three starts shifted by one or two fields; for "chair"
/// (experiment II) the same legs as the seat frame plus two upright I back posts, under the recipes
/// circular, cross-wise, equal priority and cross-wise with starts shifted by up to two fields; or a
/// recipe file. `runs` > 0 asks for that many runs instead (cube: more shifted starts; chair: the
/// recipes in turn; a file: its starts, then starts shifted by up to two fields).
/// A recipe file's voxel model is split under `budget` (seedsFromVoxels).
std::vector<Setting> loadScenario(const std::string& name, std::uint64_t seed, int runs = 0, const Budget& budget = Budget());

/// A bare voxel model split into seeds: chains of four face-adjacent voxels, each standing on the
/// floor by one end, in a canonical order. Throws InputError naming `where` when none exists,
/// LimitError when the search gives up or `budget`'s deadline passes, Interrupted on its signal.
std::vector<Seed> seedsFromVoxels(const std::vector<Cell>& voxels, const std::string& where, const Budget& budget = Budget());

/// A seeding order from a recipe file (its `start` lines are ignored) for a structure with the same
/// seeds.
Recipe loadRecipe(const std::string& path, const Recipe& structure, const Budget& budget = Budget());

}  // namespace holon::planner::roombots
