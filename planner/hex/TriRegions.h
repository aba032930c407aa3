#pragma once
// The planner of seed 003 §IV-B/C: the plane tiled with equilateral triangles; each triangle in
// which source and target differ becomes a growth or a deletion tri-region with a gravity
// direction.

#include "planner/hex/HexArray.h"
#include "rules/Budget.h"

#include <cstdint>
#include <vector>

namespace holon::planner::hex {

struct TriRegion {
    bool growth = false;
    int gravity = 0;          // lattice direction 0..5 that is "down"
    std::int64_t points = 0;  // lattice points inside
    std::int64_t toFill = 0, toEmpty = 0;
};

struct TriPlan {
    double side = 0;                     // triangle edge, in module diameters
    std::vector<TriRegion> regions;      // active tri-regions
    std::vector<std::int32_t> regionOf;  // per board cell: index into regions, or -1
    int gravityFallbacks = 0;            // regions never touched by the perimeter (gravity toward the mass centre)
};

/// Tiles the array with triangles of edge `side` module diameters and assigns gravity by the
/// worklist algorithm of §IV-C. Once `budget` is reached the plan is left unfinished: the caller
/// must not use it (on a 4000 x 4000 array the plan takes seconds).
TriPlan planTriRegions(const HexArray& array, const std::vector<std::uint8_t>& source, const std::vector<std::uint8_t>& target, double side,
                       const Budget& budget = Budget());

}  // namespace holon::planner::hex
