#pragma once
// Seeded planning problems for the shape bench (issue 28): start and target shapes drawn from
// families the shape-formation literature uses — random polyominoes and polycubes, rings,
// spirals, letters, voxelised solids, thin snakes — at mass ratios from far lighter to far heavier
// than the target, with small and large overlaps. The same seed gives the same problems.

#include "planner/Shape.h"

#include <cstdint>
#include <random>
#include <string>
#include <vector>

namespace holon::bench {

struct ShapePair {
    std::string family;            // "polyomino->spiral", for the table
    planner::Shape start, target;  // both contain the origin, the planner's seed
};

/// The i-th problem of a bench in `dimension` (2 or 3) drawn from `seed`, with about `cells`
/// metamodules in the start (from half to one and a half times). Start and target are
/// face-connected and overlap at least at the origin; the target's size is drawn log-uniformly
/// within `maxRatio` of the start's. `attempt` redraws a problem a planner system refused (shapes
/// hit their sizes only roughly, so a drawn ratio can exceed what the system's mass allows).
ShapePair shapePair(int dimension, std::uint64_t seed, int index, int attempt, int cells, double maxRatio);

/// The families each dimension draws from, in order.
const std::vector<std::string>& shapeFamilies(int dimension);

/// One shape of a family with about `cells` cells, containing the origin.
planner::Shape shapeOf(const std::string& family, int dimension, int cells, std::mt19937_64& random);

}  // namespace holon::bench
