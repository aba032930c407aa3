// The three lattices of holon: square2d (4-neighbour grid), cubic3d (6-neighbour grid) and hex2d
// (hexagonal packing in axial coordinates, the lattice of seed 000 Fig. 1a and of seed 003).
// Each rotation group is generated from one or two generators by closure, so it is complete by
// construction; the conformance test checks group closure, opposites and neighbour symmetry.

#include "rules/Lattice.h"

#include <algorithm>

namespace holon::rules {

Vec Rotation::apply(Vec v) const {
    const int in[3] = {v.x, v.y, v.z};
    int out[3] = {0, 0, 0};
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) out[i] += m[i][j] * in[j];
    return {out[0], out[1], out[2]};
}

Rotation Rotation::then(const Rotation& next) const {
    Rotation r;
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j)
            for (int k = 0; k < 3; ++k) r.m[i][j] += next.m[i][k] * m[k][j];
    return r;
}

namespace {

Rotation identity() { return Rotation{{{{1, 0, 0}, {0, 1, 0}, {0, 0, 1}}}}; }

std::vector<Rotation> closeGroup(const std::vector<Rotation>& generators) {
    std::vector<Rotation> group{identity()};
    for (std::size_t i = 0; i < group.size(); ++i)
        for (const Rotation& g : generators) {
            Rotation r = group[i].then(g);
            if (std::find(group.begin(), group.end(), r) == group.end()) group.push_back(r);
        }
    return group;
}

}  // namespace

Lattice::Lattice(LatticeKind kind, std::string name, int dimension, std::vector<Vec> directions,
                 std::vector<std::string> directionNames, std::vector<Rotation> generators)
    : kind_(kind), name_(std::move(name)), dimension_(dimension), directions_(std::move(directions)),
      directionNames_(std::move(directionNames)), rotations_(closeGroup(generators)) {
    for (Vec d : directions_) opposite_.push_back(directionOf(Vec{} - d));
}

const Lattice& Lattice::get(LatticeKind kind) {
    // Square: +y points down the page (row 0 is the first line of ASCII art).
    static const Lattice square(LatticeKind::Square2D, "square2d", 2, {{1, 0, 0}, {0, 1, 0}, {-1, 0, 0}, {0, -1, 0}},
                                {"+x", "+y", "-x", "-y"}, {Rotation{{{{0, -1, 0}, {1, 0, 0}, {0, 0, 1}}}}});
    static const Lattice cubic(LatticeKind::Cubic3D, "cubic3d", 3,
                               {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}, {-1, 0, 0}, {0, -1, 0}, {0, 0, -1}},
                               {"+x", "+y", "+z", "-x", "-y", "-z"},
                               {Rotation{{{{0, -1, 0}, {1, 0, 0}, {0, 0, 1}}}},   // quarter turn about z
                                Rotation{{{{1, 0, 0}, {0, 0, -1}, {0, 1, 0}}}}}); // quarter turn about x
    // Hex, axial (q, r) with pointy tops: a 60° turn maps (q, r) to (q + r, -q).
    static const Lattice hex(LatticeKind::Hex2D, "hex2d", 2,
                             {{1, 0, 0}, {1, -1, 0}, {0, -1, 0}, {-1, 0, 0}, {-1, 1, 0}, {0, 1, 0}},
                             {"E", "NE", "NW", "W", "SW", "SE"}, {Rotation{{{{1, 1, 0}, {-1, 0, 0}, {0, 0, 1}}}}});
    switch (kind) {
    case LatticeKind::Square2D: return square;
    case LatticeKind::Cubic3D: return cubic;
    case LatticeKind::Hex2D: return hex;
    }
    return square;
}

const std::vector<const Lattice*>& Lattice::all() {
    static const std::vector<const Lattice*> lattices{&get(LatticeKind::Square2D), &get(LatticeKind::Cubic3D),
                                                      &get(LatticeKind::Hex2D)};
    return lattices;
}

const Lattice* Lattice::byName(std::string_view name) {
    for (const Lattice* l : all())
        if (l->name() == name) return l;
    return nullptr;
}

std::optional<int> Lattice::directionByName(std::string_view name) const {
    for (int d = 0; d < degree(); ++d)
        if (directionNames_[d] == name) return d;
    return std::nullopt;
}

int Lattice::directionOf(Vec v) const {
    for (int d = 0; d < degree(); ++d)
        if (directions_[d] == v) return d;
    return -1;
}

}  // namespace holon::rules
