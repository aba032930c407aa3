// Forward kinematics of a Roombots metamodule (seed 001 §III and Figs. 3-4; the half-module is a
// Molecube, [19]). Each half-module fills one grid cell and is split by the plane normal to its body
// diagonal into two hemispheres; the outer joint turns one hemisphere against the other about that
// diagonal (120° steps permute the cell's faces), the swivel turns the two half-modules of an RB module
// against each other about the line joining their centres (90° steps).
//
// choice: hemisphere frames. In its own frame a hemisphere's diagonal is (1,1,1); an inner hemisphere
// carries the swivel face +x, an outer one the connector face -x, so all joints at 0 is the straight
// I. The chain from the foot is
//   O1 = O0 D(q1), O2 = O1 F X(q2), O3 = O2 D(q3), O4 = O3 F X(lock), O5 = O4 D(q4), O6 = O5 F X(q5),
//   O7 = O6 D(q6)
// with D a turn about the diagonal, X about x and F the half turn about z that makes two frames face
// each other. The four locks are told apart by the angle between the connected hemispheres' diagonals
// (Fig. 3a): antiparallel is PAR, 70.5° is PER, and the two 109.5° locks are mirror images, SRS and SRZ
// by the handedness of (contact normal, diagonal 1, diagonal 2) — derived below, not tabulated.

#include "planner/roombots/Kinematics.h"

#include "rules/Error.h"
#include "rules/Parameter.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>

namespace holon::planner::roombots {
namespace {

using Vec3 = std::array<double, 3>;
using Mat3 = std::array<double, 9>;  // row-major

Mat3 mul(const Mat3& a, const Mat3& b) {
    Mat3 c{};
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j)
            for (int k = 0; k < 3; ++k) c[3 * i + j] += a[3 * i + k] * b[3 * k + j];
    return c;
}
Vec3 times(const Mat3& a, const Vec3& v) {
    return {a[0] * v[0] + a[1] * v[1] + a[2] * v[2], a[3] * v[0] + a[4] * v[1] + a[5] * v[2],
            a[6] * v[0] + a[7] * v[1] + a[8] * v[2]};
}
Vec3 add(const Vec3& a, const Vec3& b) { return {a[0] + b[0], a[1] + b[1], a[2] + b[2]}; }
double dot(const Vec3& a, const Vec3& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }

/// Rotation by `angle` about the unit vector `u` (Rodrigues).
Mat3 turn(Vec3 u, double angle) {
    const double n = std::sqrt(dot(u, u));
    for (double& c : u) c /= n;
    const double c = std::cos(angle), s = std::sin(angle), t = 1 - c;
    const double x = u[0], y = u[1], z = u[2];
    return {t * x * x + c, t * x * y - s * z, t * x * z + s * y, t * x * y + s * z, t * y * y + c,
            t * y * z - s * x, t * x * z - s * y, t * y * z + s * x, t * z * z + c};
}

constexpr double kThird = 2 * std::numbers::pi / 3, kQuarter = std::numbers::pi / 2;
const Vec3 kX{1, 0, 0}, kMinusX{-1, 0, 0}, kDiagonal{1, 1, 1};
const Mat3 kFace = turn({0, 0, 1}, std::numbers::pi);
// The foot hemisphere at yaw 0: connector face (-x) down, so x up; y east, z north.
const Mat3 kFoot{0, 1, 0, 0, 0, 1, 1, 0, 0};

Mat3 foot(int yaw) { return mul(turn({0, 0, 1}, yaw * kQuarter), kFoot); }

Cell roundCell(const Vec3& v) {
    return {static_cast<int>(std::lround(v[0])), static_cast<int>(std::lround(v[1])), static_cast<int>(std::lround(v[2]))};
}

std::array<double, 6> angles(const Joints& j) {
    return {j.q[0] * kThird, j.q[1] * kQuarter, j.q[2] * kThird, j.q[3] * kThird, j.q[4] * kQuarter, j.q[5] * kThird};
}

/// Shortest signed arc from setting a to b of a joint with `positions` stops.
double arc(int a, int b, int positions) {
    int d = ((b - a) % positions + positions) % positions;
    if (2 * d > positions) d -= positions;
    return d * 2 * std::numbers::pi / positions;
}

}  // namespace

struct Metamodule::Chain {
    std::array<Vec3, 4> centres;  // half-module centres relative to the foot cell's centre
    std::array<Mat3, 8> frames;   // hemisphere frames, foot first
};

const char* couplingName(Coupling c) {
    static constexpr const char* kNames[] = {"PAR", "PER", "SRS", "SRZ"};
    return kNames[static_cast<int>(c)];
}

Coupling parseCoupling(const std::string& name) {
    for (Coupling c : kCouplings)
        if (name == couplingName(c)) return c;
    throw InputError(rules::parameterName(rules::Parameter::Metamodule) + ": unknown metamodule configuration '" + name + "'; use PAR, PER, SRS or SRZ",
                     rules::Parameter::Metamodule);
}

const char* shapeName(Shape s) {
    static constexpr const char* kNames[] = {"I", "L", "S", "U", "3D-S"};
    return kNames[static_cast<int>(s)];
}

int Joints::index() const {
    return ((((q[0] * 4 + q[1]) * 3 + q[2]) * 3 + q[3]) * 4 + q[4]) * 3 + q[5];
}

Joints Joints::fromIndex(int index) {
    Joints j;
    j.q[5] = index % 3, index /= 3;
    j.q[4] = index % 4, index /= 4;
    j.q[3] = index % 3, index /= 3;
    j.q[2] = index % 3, index /= 3;
    j.q[1] = index % 4, index /= 4;
    j.q[0] = static_cast<std::uint8_t>(index);
    return j;
}

Joints reversed(const Joints& j) {
    auto neg3 = [](int k) { return static_cast<std::uint8_t>((3 - k) % 3); };
    return Joints{{neg3(j.q[5]), j.q[4], neg3(j.q[3]), neg3(j.q[2]), j.q[1], neg3(j.q[0])}};
}

Metamodule::Metamodule(Coupling coupling) : coupling_(coupling), lock_(-1) {
    for (int lock = 0; lock < 4; ++lock) {
        lock_ = lock;
        const Chain c = chain({}, 0);
        const Vec3 a = times(c.frames[3], kDiagonal), b = times(c.frames[4], kDiagonal), n = times(c.frames[3], kMinusX);
        const double d = dot(a, b);
        const Vec3 axb{a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
        const Coupling found = d < -2.5 ? Coupling::PAR : d > 0         ? Coupling::PER
                                                      : dot(n, axb) > 0 ? Coupling::SRS
                                                                        : Coupling::SRZ;
        if (found == coupling) return;
    }
    throw std::logic_error("no lock realises coupling " + std::string(couplingName(coupling)));
}

Metamodule::Chain Metamodule::chain(const std::array<double, 6>& q, int yaw) const {
    const Vec3 diagonal = kDiagonal;
    Chain c;
    auto& o = c.frames;
    o[0] = foot(yaw);
    o[1] = mul(o[0], turn(diagonal, q[0]));
    o[2] = mul(mul(o[1], kFace), turn(kX, q[1]));
    o[3] = mul(o[2], turn(diagonal, q[2]));
    o[4] = mul(mul(o[3], kFace), turn(kX, lock_ * kQuarter));
    o[5] = mul(o[4], turn(diagonal, q[3]));
    o[6] = mul(mul(o[5], kFace), turn(kX, q[4]));
    o[7] = mul(o[6], turn(diagonal, q[5]));
    c.centres[0] = {0, 0, 0};
    c.centres[1] = add(c.centres[0], times(o[1], kX));
    c.centres[2] = add(c.centres[1], times(o[3], kMinusX));
    c.centres[3] = add(c.centres[2], times(o[5], kX));
    return c;
}

Posture Metamodule::posture(const Joints& j, int yaw) const {
    const Chain c = chain(angles(j), yaw);
    Posture p;
    for (int i = 0; i < 4; ++i) p.cells[i] = roundCell(c.centres[i]);
    p.headFace = roundCell(times(c.frames[7], kMinusX));
    for (int y = 0; y < 4; ++y) {
        const Mat3 f = foot(y);
        double error = 0;
        for (int k = 0; k < 9; ++k) error += std::abs(f[k] - c.frames[7][k]);
        if (error < 1e-6) p.headYaw = y;
    }
    return p;
}

std::vector<Cell> Metamodule::sweep(const Joints& from, const Joints& to, int yaw, int samples, double radius) const {
    const std::array<double, 6> a = angles(from);
    std::array<double, 6> d;
    for (int k = 0; k < 6; ++k) d[k] = arc(from.q[k], to.q[k], k == 1 || k == 4 ? 4 : 3);
    std::vector<Cell> cells;
    const double clearance = 2 * radius - 1e-9, floor = radius - 0.5 - 1e-9;
    for (int s = 0; s <= samples; ++s) {
        std::array<double, 6> q;
        const double t = static_cast<double>(s) / samples;
        for (int k = 0; k < 6; ++k) q[k] = a[k] + t * d[k];
        const Chain c = chain(q, yaw);
        for (int i = 0; i < 4; ++i) {
            if (c.centres[i][2] < floor) return {};
            for (int k = i + 2; k < 4; ++k) {
                Vec3 v{c.centres[i][0] - c.centres[k][0], c.centres[i][1] - c.centres[k][1], c.centres[i][2] - c.centres[k][2]};
                if (dot(v, v) < clearance * clearance) return {};
            }
            const Cell mid = roundCell(c.centres[i]);
            for (int dx = -1; dx <= 1; ++dx)
                for (int dy = -1; dy <= 1; ++dy)
                    for (int dz = -1; dz <= 1; ++dz) {
                        const Cell n = mid + Cell{dx, dy, dz};
                        const Vec3 cell{double(n.x), double(n.y), double(n.z)};
                        double gap = 0;
                        for (int axis = 0; axis < 3; ++axis) {
                            const double g = std::max(0.0, std::abs(c.centres[i][axis] - cell[axis]) - 0.5);
                            gap += g * g;
                        }
                        if (gap < radius * radius - 1e-12) cells.push_back(n);
                    }
        }
    }
    std::sort(cells.begin(), cells.end());
    cells.erase(std::unique(cells.begin(), cells.end()), cells.end());
    return cells;
}

Shape classify(const std::array<Cell, 4>& c) {
    const Cell u1 = c[1] - c[0], u2 = c[2] - c[1], u3 = c[3] - c[2];
    if (u1 == u2 && u2 == u3) return Shape::I;
    if (u1 == u2 || u2 == u3) return Shape::L;
    if (u1 == u3) return Shape::S;
    if (u1 == Cell{} - u3) return Shape::U;
    return Shape::S3D;
}

}  // namespace holon::planner::roombots
