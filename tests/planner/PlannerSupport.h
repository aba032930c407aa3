#pragma once
// Helpers for the planner tests: random connected shapes and problems built from library systems.

#include "planner/Execution.h"
#include "rules/Library.h"

#include <doctest/doctest.h>
#include <memory>
#include <set>

namespace holon::test {

/// A random connected shape of `size` cells grown from `from` inside [0, box).
inline planner::Shape randomBlob(planner::Random& random, int dimension, planner::Vec box, planner::Vec from, int size) {
    const rules::Lattice& lattice = rules::Lattice::get(dimension == 3 ? rules::LatticeKind::Cubic3D : rules::LatticeKind::Square2D);
    std::set<planner::Vec> cells{from};
    std::vector<planner::Vec> list{from};
    for (int guard = 0; static_cast<int>(cells.size()) < size && guard < 100000; ++guard) {
        const planner::Vec v = list[random.below(list.size())] + lattice.direction(static_cast<int>(random.below(lattice.degree())));
        if (v.x < 0 || v.y < 0 || v.z < 0 || v.x >= box.x || v.y >= box.y || v.z >= box.z) continue;
        if (cells.insert(v).second) list.push_back(v);
    }
    planner::Shape s;
    s.dimension = dimension;
    s.cells.assign(cells.begin(), cells.end());
    s.name = "blob";
    return s;
}

/// A library system on a lattice, owning both.
struct PlannerSystem {
    rules::System system;
    std::unique_ptr<rules::Model> model;
    PlannerSystem(const std::string& stem, int dimension) : system(rules::librarySystem(stem)) {
        model = std::make_unique<rules::Model>(system, rules::Lattice::get(dimension == 3 ? rules::LatticeKind::Cubic3D : rules::LatticeKind::Square2D));
    }
};

}  // namespace holon::test
