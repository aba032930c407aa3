#pragma once
// Grid-level kinematics of a Roombots metamodule (seed 001 §III, Figs. 3-4): two RB modules in
// series, four half-modules on a cubic grid, six joints. Poses are computed in continuous angles so
// that the same forward kinematics gives both the grid cells of a joint setting and the cells swept
// while the joints move (the collision clouds).

#include <array>
#include <cstdint>
#include <string>
#include <vector>

namespace holon::planner::roombots {

struct Cell {
    int x = 0, y = 0, z = 0;
    friend bool operator==(const Cell&, const Cell&) = default;
    friend auto operator<=>(const Cell&, const Cell&) = default;
    Cell operator+(const Cell& o) const { return {x + o.x, y + o.y, z + o.z}; }
    Cell operator-(const Cell& o) const { return {x - o.x, y - o.y, z - o.z}; }
};

/// How the two RB modules are locked together (Fig. 3a), named by the relative orientation of the
/// body-diagonal axes of the two connected hemispheres.
enum class Coupling : std::uint8_t { PAR,
                                     PER,
                                     SRS,
                                     SRZ };
const char* couplingName(Coupling c);
Coupling parseCoupling(const std::string& name);  // throws InputError
constexpr std::array<Coupling, 4> kCouplings{Coupling::PAR, Coupling::PER, Coupling::SRS, Coupling::SRZ};

/// The five shapes a four-cell chain can take (§IV-A b).
enum class Shape : std::uint8_t { I,
                                  L,
                                  S,
                                  U,
                                  S3D };
const char* shapeName(Shape s);

/// A joint setting, from the foot: outer joint 1 (0..2 x 120°), swivel 1 (0..3 x 90°), outer joint 2,
/// outer joint 3, swivel 2, outer joint 4 (footnote 3: 3^4 * 4^2 = 1296 settings).
struct Joints {
    std::array<std::uint8_t, 6> q{};
    int index() const;
    static Joints fromIndex(int index);
    friend bool operator==(const Joints&, const Joints&) = default;
};
constexpr int kJointSettings = 1296;

/// The same physical pose read from the other end: the head becomes the foot.
Joints reversed(const Joints& j);

/// The foot hemisphere's connector faces down; `yaw` (0..3 x 90° about the vertical) is the only
/// freedom it has on a floor connector.
struct Posture {
    std::array<Cell, 4> cells;  // foot cell first, relative to the foot
    Cell headFace;              // direction the head connector faces
    int headYaw = 0;            // when the head faces down: the yaw of the head as the next foot
    /// The head faces down onto the floor the foot stands on: the end of an inch-worm step.
    bool stance() const { return headFace == Cell{0, 0, -1} && cells[3].z == 0; }
};

class Metamodule {
public:
    explicit Metamodule(Coupling coupling);
    Coupling coupling() const { return coupling_; }
    /// The discrete pose of a joint setting for a foot at the origin with the given yaw.
    Posture posture(const Joints& j, int yaw) const;
    /// The cells swept moving every joint at once along its shortest arc from `from` to `to`
    /// (`samples` steps), each half-module a ball of radius `radius` cell edges. Empty when the motion
    /// self-collides or dips below the floor (z < 0).
    std::vector<Cell> sweep(const Joints& from, const Joints& to, int yaw, int samples, double radius) const;

private:
    struct Chain;
    Chain chain(const std::array<double, 6>& angles, int yaw) const;
    Coupling coupling_;
    int lock_;  // quarter turns about the contact axis that realise coupling_
};

/// The shape of a chain of four distinct face-adjacent cells.
Shape classify(const std::array<Cell, 4>& cells);

}  // namespace holon::planner::roombots
