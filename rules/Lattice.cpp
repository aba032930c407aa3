// The three lattices of holon: square2d (4-neighbour grid), cubic3d (6-neighbour grid) and hex2d
// (hexagonal packing in axial coordinates, the lattice of seed 000 Fig. 1a and of seed 003).
// Each rotation group is generated from one or two generators by closure, so it is complete by
// construction; the point group adds one reflection composed with every rotation (a proper
// subgroup of index 2 and its coset make the whole group). The conformance test checks group
// closure, orders, determinants, opposites and neighbour symmetry.

#include "rules/Lattice.h"

#include <algorithm>

namespace holon::rules {

Vec LinearMap::apply(Vec v) const {
    const int in[3] = {v.x, v.y, v.z};
    int out[3] = {0, 0, 0};
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) out[i] += m[i][j] * in[j];
    return {out[0], out[1], out[2]};
}

LinearMap LinearMap::then(const LinearMap& next) const {
    LinearMap r;
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j)
            for (int k = 0; k < 3; ++k) r.m[i][j] += next.m[i][k] * m[k][j];
    return r;
}

int LinearMap::determinant() const {
    return m[0][0] * (m[1][1] * m[2][2] - m[1][2] * m[2][1]) - m[0][1] * (m[1][0] * m[2][2] - m[1][2] * m[2][0]) +
           m[0][2] * (m[1][0] * m[2][1] - m[1][1] * m[2][0]);
}

const char* symmetryName(Symmetry s) {
    switch (s) {
    case Symmetry::None: return "none";
    case Symmetry::Rotations: return "rotations";
    case Symmetry::RotationsReflections: return "rotations+reflections";
    }
    return "";
}

namespace {

LinearMap identity() { return LinearMap{{{{1, 0, 0}, {0, 1, 0}, {0, 0, 1}}}}; }

std::vector<LinearMap> closeGroup(const std::vector<LinearMap>& generators) {
    std::vector<LinearMap> group{identity()};
    for (std::size_t i = 0; i < group.size(); ++i)
        for (const LinearMap& g : generators) {
            LinearMap r = group[i].then(g);
            if (std::find(group.begin(), group.end(), r) == group.end()) group.push_back(r);
        }
    return group;
}

}  // namespace

Lattice::Lattice(LatticeKind kind, std::string name, int dimension, std::vector<Vec> directions,
                 std::vector<std::string> directionNames, std::vector<LinearMap> generators, LinearMap reflection)
    : kind_(kind), name_(std::move(name)), dimension_(dimension), directions_(std::move(directions)),
      directionNames_(std::move(directionNames)), rotations_(closeGroup(generators)) {
    for (Vec d : directions_) opposite_.push_back(directionOf(Vec{} - d));
    // Reflection first, then the rotation: the identity's coset element is the reflection itself,
    // which fixes every cell of a positionless rule.
    pointGroup_ = rotations_;
    for (const LinearMap& r : rotations_) pointGroup_.push_back(reflection.then(r));
}

std::span<const LinearMap> Lattice::symmetries(Symmetry s) const {
    switch (s) {
    case Symmetry::None: return {pointGroup_.data(), 1};
    case Symmetry::Rotations: return {pointGroup_.data(), rotations_.size()};
    case Symmetry::RotationsReflections: return pointGroup_;
    }
    return pointGroup_;
}

const Lattice& Lattice::get(LatticeKind kind) {
    // Square: +y points down the page (row 0 is the first line of ASCII art). Every reflection
    // below keeps direction 0 (+x, E) and the first coordinate axis.
    static const Lattice square(LatticeKind::Square2D, "square2d", 2, {{1, 0, 0}, {0, 1, 0}, {-1, 0, 0}, {0, -1, 0}},
                                {"+x", "+y", "-x", "-y"}, {LinearMap{{{{0, -1, 0}, {1, 0, 0}, {0, 0, 1}}}}},
                                LinearMap{{{{1, 0, 0}, {0, -1, 0}, {0, 0, 1}}}});  // y -> -y
    static const Lattice cubic(LatticeKind::Cubic3D, "cubic3d", 3,
                               {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}, {-1, 0, 0}, {0, -1, 0}, {0, 0, -1}},
                               {"+x", "+y", "+z", "-x", "-y", "-z"},
                               {LinearMap{{{{0, -1, 0}, {1, 0, 0}, {0, 0, 1}}}},   // quarter turn about z
                                LinearMap{{{{1, 0, 0}, {0, 0, -1}, {0, 1, 0}}}}},  // quarter turn about x
                               LinearMap{{{{1, 0, 0}, {0, -1, 0}, {0, 0, 1}}}});   // y -> -y
    // Hex, axial (q, r) with pointy tops: a 60° turn maps (q, r) to (q + r, -q); the mirror in the
    // E-W axis maps (q, r) to (q + r, -r), swapping NE with SE and NW with SW.
    static const Lattice hex(LatticeKind::Hex2D, "hex2d", 2,
                             {{1, 0, 0}, {1, -1, 0}, {0, -1, 0}, {-1, 0, 0}, {-1, 1, 0}, {0, 1, 0}},
                             {"E", "NE", "NW", "W", "SW", "SE"}, {LinearMap{{{{1, 1, 0}, {-1, 0, 0}, {0, 0, 1}}}}},
                             LinearMap{{{{1, 1, 0}, {0, -1, 0}, {0, 0, 1}}}});
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
