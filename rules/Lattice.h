#pragma once
// Lattices holon knows: their neighbour directions, opposites and point groups (the rotations, and
// the rotations with the reflections).

#include <array>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace holon::rules {

/// A lattice point or offset. 2D lattices leave z at 0; hex2d uses axial (q, r) in (x, y).
struct Vec {
    int x = 0, y = 0, z = 0;
    friend Vec operator+(Vec a, Vec b) { return {a.x + b.x, a.y + b.y, a.z + b.z}; }
    friend Vec operator-(Vec a, Vec b) { return {a.x - b.x, a.y - b.y, a.z - b.z}; }
    friend bool operator==(Vec, Vec) = default;
    friend auto operator<=>(Vec, Vec) = default;
};

/// An integer linear map acting on lattice coordinates: a symmetry of a lattice is one that permutes
/// its neighbour directions, a rotation (determinant 1) or a reflection composed with one (-1).
struct LinearMap {
    std::array<std::array<int, 3>, 3> m{};
    Vec apply(Vec v) const;
    LinearMap then(const LinearMap& next) const;  // next ∘ this
    int determinant() const;
    friend bool operator==(const LinearMap&, const LinearMap&) = default;
};

enum class LatticeKind { Square2D,
                         Cubic3D,
                         Hex2D };

/// The symmetries a system's rules are closed under (`symmetry none | rotations |
/// rotations+reflections`): the identity, the proper rotations, or the lattice's full point group.
enum class Symmetry { None,
                      Rotations,
                      RotationsReflections };

/// "none", "rotations", "rotations+reflections": the spelling of the `symmetry` declaration.
const char* symmetryName(Symmetry s);

class Lattice {
public:
    static const Lattice& get(LatticeKind kind);
    /// "square2d", "cubic3d" or "hex2d"; nullptr for anything else.
    static const Lattice* byName(std::string_view name);
    static const std::vector<const Lattice*>& all();

    LatticeKind kind() const { return kind_; }
    const std::string& name() const { return name_; }
    int dimension() const { return dimension_; }
    int degree() const { return static_cast<int>(directions_.size()); }
    Vec direction(int d) const { return directions_[d]; }
    const std::vector<Vec>& directions() const { return directions_; }
    const std::string& directionName(int d) const { return directionNames_[d]; }
    std::optional<int> directionByName(std::string_view name) const;
    /// The index of a unit offset, or -1 when v is not a neighbour offset.
    int directionOf(Vec v) const;
    int opposite(int d) const { return opposite_[d]; }
    /// The proper rotations of the lattice, identity first: 4 on square2d, 24 on cubic3d, 6 on hex2d.
    const std::vector<LinearMap>& rotations() const { return rotations_; }
    /// The full point group, 8 / 48 / 12: the rotations in the order of rotations(), then each of
    /// them after the reflection that fixes direction 0 (a line of cells along it maps onto itself).
    const std::vector<LinearMap>& pointGroup() const { return pointGroup_; }
    /// The first 1, rotations().size() or pointGroup().size() elements of pointGroup().
    std::span<const LinearMap> symmetries(Symmetry s) const;
    bool adjacent(Vec a, Vec b) const { return directionOf(b - a) >= 0; }

private:
    Lattice(LatticeKind kind, std::string name, int dimension, std::vector<Vec> directions,
            std::vector<std::string> directionNames, std::vector<LinearMap> generators, LinearMap reflection);
    LatticeKind kind_;
    std::string name_;
    int dimension_;
    std::vector<Vec> directions_;
    std::vector<std::string> directionNames_;
    std::vector<int> opposite_;
    std::vector<LinearMap> rotations_;
    std::vector<LinearMap> pointGroup_;
};

}  // namespace holon::rules
