#pragma once
// Lattices holon knows: their neighbour directions, opposites and rotation groups.

#include <array>
#include <optional>
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

/// An integer linear map acting on lattice coordinates; the rotations of a lattice are such maps.
struct Rotation {
    std::array<std::array<int, 3>, 3> m{};
    Vec apply(Vec v) const;
    Rotation then(const Rotation& next) const;  // next ∘ this
    friend bool operator==(const Rotation&, const Rotation&) = default;
};

enum class LatticeKind { Square2D, Cubic3D, Hex2D };

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
    /// The proper rotations of the lattice (identity first); rules are closed under these.
    const std::vector<Rotation>& rotations() const { return rotations_; }
    bool adjacent(Vec a, Vec b) const { return directionOf(b - a) >= 0; }

private:
    Lattice(LatticeKind kind, std::string name, int dimension, std::vector<Vec> directions,
            std::vector<std::string> directionNames, std::vector<Rotation> generators);
    LatticeKind kind_;
    std::string name_;
    int dimension_;
    std::vector<Vec> directions_;
    std::vector<std::string> directionNames_;
    std::vector<int> opposite_;
    std::vector<Rotation> rotations_;
};

}  // namespace holon::rules
