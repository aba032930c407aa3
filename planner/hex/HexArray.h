#pragma once
// The hex-lattice array of seed 003 §V-A: N rows of N lattice points each (alternate rows shifted
// by half a module), stored on the planner's padded Board in axial coordinates so that every
// neighbour is a fixed index step away. Holes, shepherd groups and the disks the algorithm reads
// (§IV-A: a module, its neighbours and their neighbours) are offset lists precomputed here.

#include "planner/Board.h"

#include <array>
#include <cmath>
#include <cstdint>
#include <vector>

namespace holon::planner::hex {

/// Hex distance between two axial offsets.
inline int hexDistance(Vec a, Vec b) {
    const int dq = a.x - b.x, dr = a.y - b.y;
    return (std::abs(dq) + std::abs(dr) + std::abs(dq + dr)) / 2;
}

class HexArray {
public:
    static constexpr int kPad = 5;  // the farthest pattern read (a flexible creation's third-ring cell and its neighbours) is 4 cells away
    explicit HexArray(int n);
    /// The board cells an array of side n takes, without making it (for a memory estimate).
    static std::int64_t boardSize(int n);

    int n() const { return n_; }
    const Board& board() const { return board_; }
    std::int64_t size() const { return board_.size(); }
    /// Whether the board cell is one of the array's N x N lattice points.
    bool inside(std::int64_t i) const { return inside_[i] != 0; }
    /// The lattice points, row by row.
    const std::vector<std::int64_t>& points() const { return points_; }
    /// Cartesian position in module diameters: x to the right, y up (row 0 is the top), the array's
    /// lower left point at the origin.
    double x(std::int64_t i) const {
        const Vec p = board_.point(i);
        return p.x + 0.5 * p.y;
    }
    double y(std::int64_t i) const { return kRowHeight * (n_ - 1 - board_.point(i).y); }
    double width() const { return n_ - 0.5; }
    double height() const { return kRowHeight * (n_ - 1); }
    /// The picture frame in which geometries are defined and drawn: the lattice turned by 90° so
    /// that lattice lines run vertically (x right, y up, lower left at the origin).
    double frameX(std::int64_t i) const { return y(i); }
    double frameY(std::int64_t i) const { return width() - x(i); }
    double frameWidth() const { return height(); }
    double frameHeight() const { return width(); }
    /// The lattice point drawn at picture row `row` (0 at the top) and column `col` (0 at the left).
    std::int64_t pictureIndex(int row, int col) const { return points_[static_cast<std::size_t>(n_ - 1 - col) * n_ + row]; }
    /// Index step of lattice direction d (0..5 counterclockwise from east, as rules::Lattice hex2d).
    std::int64_t step(int d) const { return board_.step(((d % 6) + 6) % 6); }
    std::int64_t offset(Vec v) const { return board_.offset(v); }

    static constexpr double kRowHeight = 0.8660254037844386;  // sqrt(3)/2

private:
    int n_;
    Board board_;
    std::vector<std::uint8_t> inside_;
    std::vector<std::int64_t> points_;
};

/// Hops from `sources` (0) to every cell reachable through cells where `passable(next, from)`
/// holds, by breadth-first search in layers, the sources in the order given; -1 where not reached.
/// `last`, when given, receives the last cell reached (in that order).
template <class Passable>
std::vector<std::int32_t> hopsFrom(const HexArray& array, std::vector<std::int64_t> sources, Passable passable, std::int64_t* last = nullptr) {
    std::vector<std::int32_t> hops(static_cast<std::size_t>(array.size()), -1);
    for (std::int64_t c : sources) hops[c] = 0;
    std::vector<std::int64_t> next;
    for (std::int32_t level = 1; !sources.empty(); ++level, sources.swap(next)) {
        if (last) *last = sources.back();
        next.clear();
        for (std::int64_t c : sources)
            for (int d = 0; d < 6; ++d)
                if (const std::int64_t n = c + array.step(d); hops[n] < 0 && passable(n, c)) hops[n] = level, next.push_back(n);
    }
    return hops;
}

/// Axial offsets of the cells at exactly / at most distance r from the origin.
std::vector<Vec> hexRing(int r);
std::vector<Vec> hexDisk(int r);

}  // namespace holon::planner::hex
