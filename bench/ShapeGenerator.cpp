// Seeded start/target shapes for the shape bench (issue 28). Random polyominoes and polycubes grow
// by the Eden model (a uniformly chosen free face neighbour at a time), which gives the blobby
// shapes of the self-assembly literature; "thin" trees grow only where the new cell touches one
// cell, so every branch is one cell wide (the shapes that look disconnected at a glance). Rings,
// spirals, letters and voxelised solids are the test shapes of the shape-formation papers.

#include "ShapeGenerator.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <set>
#include <stdexcept>

namespace holon::bench {

using rules::Vec;

namespace {

/// The lattice neighbours of v on the planner's lattice of that dimension (square2d, cubic3d).
std::vector<Vec> faceNeighbours(Vec v, int dimension) {
    const rules::Lattice& lattice = rules::Lattice::get(dimension == 3 ? rules::LatticeKind::Cubic3D : rules::LatticeKind::Square2D);
    std::vector<Vec> out;
    for (int d = 0; d < lattice.degree(); ++d) out.push_back(v + lattice.direction(d));
    return out;
}

/// Eden growth from the origin; `thin` accepts a cell only when it touches exactly one shape cell.
std::vector<Vec> grow(int cells, int dimension, bool thin, std::mt19937_64& random) {
    std::set<Vec> shape = {Vec{}};
    std::vector<Vec> frontier = faceNeighbours(Vec{}, dimension);
    auto touching = [&](Vec v) {
        int n = 0;
        for (Vec w : faceNeighbours(v, dimension)) n += shape.count(w) ? 1 : 0;
        return n;
    };
    while (static_cast<int>(shape.size()) < cells && !frontier.empty()) {
        const std::size_t pick = std::uniform_int_distribution<std::size_t>(0, frontier.size() - 1)(random);
        const Vec v = frontier[pick];
        frontier[pick] = frontier.back(), frontier.pop_back();
        if (shape.count(v) || (thin && touching(v) != 1)) continue;
        shape.insert(v);
        for (Vec w : faceNeighbours(v, dimension))
            if (!shape.count(w)) frontier.push_back(w);
    }
    return {shape.begin(), shape.end()};
}

/// A square (2D) or cubic (3D) spiral corridor of width 1 with walls of gaps between its turns.
std::vector<Vec> spiral(int cells, int dimension) {
    std::vector<Vec> out;
    Vec at{};
    const std::array<Vec, 4> step = {Vec{1, 0, 0}, Vec{0, 1, 0}, Vec{-1, 0, 0}, Vec{0, -1, 0}};
    const int layers = dimension == 3 ? 2 : 1;
    for (int arm = 0; static_cast<int>(out.size()) * layers < cells; ++arm) {
        const int length = 2 * (arm / 2 + 1);  // 2, 2, 4, 4, 6, 6, ...: one cell of gap between turns
        for (int k = 0; k < length && static_cast<int>(out.size()) * layers < cells; ++k) out.push_back(at), at = at + step[arm % 4];
    }
    std::vector<Vec> solid;
    for (Vec v : out)
        for (int z = 0; z < layers; ++z) solid.push_back({v.x, v.y, z});
    return solid;
}

/// An annulus (2D) or a thick ring (3D) of about `cells` cells; the width is random, at least two
/// cells, since a digital annulus thinner than sqrt(2) falls apart into diagonal pieces.
std::vector<Vec> ring(int cells, int dimension, std::mt19937_64& random) {
    int width = std::uniform_int_distribution<int>(2, 4)(random);
    const int depth = dimension == 3 ? 2 : 1;
    // area of an annulus of outer radius R and width w: pi (R^2 - (R-w)^2) = pi w (2R - w); the
    // smallest ring of width w (R = w + 1) must not overshoot the size asked for
    const double perLayer = double(cells) / depth;
    while (width > 2 && M_PI * width * (width + 2) > perLayer) --width;
    const int outer = std::max(width + 1, static_cast<int>(std::ceil((perLayer / (M_PI * width) + width) / 2)));
    std::vector<Vec> out;
    for (int x = -outer; x <= outer; ++x)
        for (int y = -outer; y <= outer; ++y) {
            const double r = std::sqrt(double(x) * x + double(y) * y);
            if (r <= outer && r > outer - width)
                for (int z = 0; z < depth; ++z) out.push_back({x, y, z});
        }
    return out;
}

/// Block letters on a 5x5 grid, each face-connected; strokes are k cells wide.
std::vector<Vec> letter(int cells, int dimension, std::mt19937_64& random) {
    static const std::vector<std::array<const char*, 5>> font = {
        {"#####", "#....", "####.", "#....", "#####"},  // E
        {"#...#", "#...#", "#####", "#...#", "#...#"},  // H
        {"#....", "#....", "#....", "#....", "#####"},  // L
        {"#####", "..#..", "..#..", "..#..", "..#.."},  // T
        {"#...#", "#...#", "#...#", "#...#", "#####"},  // U
        {"#####", "#....", "#####", "....#", "#####"},  // S
        {"#####", "#....", "#....", "#....", "#####"},  // C
    };
    const auto& glyph = font[std::uniform_int_distribution<std::size_t>(0, font.size() - 1)(random)];
    int ink = 0;
    for (const char* row : glyph) ink += static_cast<int>(std::count(row, row + 5, '#'));
    // 2D: ink k^2 cells; 3D: the letter extruded 2k deep, 2 ink k^3 cells
    const int depth = dimension == 3 ? 2 : 1;
    const double perStroke = double(cells) / (ink * depth);
    const int k = std::max(1, static_cast<int>(std::lround(dimension == 3 ? std::cbrt(perStroke) : std::sqrt(perStroke))));
    std::vector<Vec> out;
    for (int r = 0; r < 5; ++r)
        for (int c = 0; c < 5; ++c)
            if (glyph[r][c] == '#')
                for (int dx = 0; dx < k; ++dx)
                    for (int dy = 0; dy < k; ++dy)
                        for (int z = 0; z < depth * (dimension == 3 ? k : 1); ++z) out.push_back({c * k + dx, (4 - r) * k + dy, z});
    return out;
}

/// Voxelised solids: a ball, a hollow box (walls two cells thick) or a chair (seat, back, legs).
std::vector<Vec> solid(int cells, std::mt19937_64& random) {
    const int kind = std::uniform_int_distribution<int>(0, 2)(random);
    std::vector<Vec> out;
    if (kind == 0) {
        const int r = std::max(1, static_cast<int>(std::lround(std::cbrt(3.0 * cells / (4 * M_PI)))));
        for (int x = -r; x <= r; ++x)
            for (int y = -r; y <= r; ++y)
                for (int z = -r; z <= r; ++z)
                    if (x * x + y * y + z * z <= r * r) out.push_back({x, y, z});
    } else if (kind == 1) {
        // n^3 - (n-4)^3 ~ 12 n^2 for walls two thick
        const int n = std::max(5, static_cast<int>(std::lround(std::sqrt(cells / 12.0))));
        for (int x = 0; x < n; ++x)
            for (int y = 0; y < n; ++y)
                for (int z = 0; z < n; ++z)
                    if (x < 2 || y < 2 || z < 2 || x >= n - 2 || y >= n - 2 || z >= n - 2) out.push_back({x, y, z});
    } else {
        // seat n x n x t, back n x t x n above it, four legs t x t x n below: about 2 t n^2 + 4 t^2 n
        const int t = std::uniform_int_distribution<int>(1, 2)(random);
        const int n = std::max(3, static_cast<int>(std::lround(std::sqrt(cells / (2.0 * t)))));
        for (int x = 0; x < n; ++x)
            for (int y = 0; y < n; ++y)
                for (int z = 0; z < t; ++z) out.push_back({x, y, n + z});
        for (int x = 0; x < n; ++x)
            for (int y = 0; y < t; ++y)
                for (int z = n + t; z < 2 * n + t; ++z) out.push_back({x, y, z});
        for (int lx : {0, n - t})
            for (int ly : {0, n - t})
                for (int x = lx; x < lx + t; ++x)
                    for (int y = ly; y < ly + t; ++y)
                        for (int z = 0; z < n; ++z) out.push_back({x, y, z});
    }
    return out;
}

/// Moves the shape so that a random cell of it (or its cell nearest the centre, for a large
/// overlap) sits at the origin, the planner's seed.
planner::Shape anchored(std::vector<Vec> cells, int dimension, bool central, std::mt19937_64& random, std::string name) {
    std::sort(cells.begin(), cells.end());
    cells.erase(std::unique(cells.begin(), cells.end()), cells.end());
    Vec anchor = cells[std::uniform_int_distribution<std::size_t>(0, cells.size() - 1)(random)];
    if (central) {
        double cx = 0, cy = 0, cz = 0;
        for (Vec v : cells) cx += v.x, cy += v.y, cz += v.z;
        cx /= cells.size(), cy /= cells.size(), cz /= cells.size();
        auto d = [&](Vec v) { return (v.x - cx) * (v.x - cx) + (v.y - cy) * (v.y - cy) + (v.z - cz) * (v.z - cz); };
        anchor = *std::min_element(cells.begin(), cells.end(), [&](Vec a, Vec b) { return d(a) < d(b); });
    }
    planner::Shape s;
    s.dimension = dimension, s.name = std::move(name);
    for (Vec v : cells) s.cells.push_back(v - anchor);
    std::sort(s.cells.begin(), s.cells.end());
    return s;
}

}  // namespace

const std::vector<std::string>& shapeFamilies(int dimension) {
    static const std::vector<std::string> two = {"polyomino", "thin", "ring", "spiral", "letter"};
    static const std::vector<std::string> three = {"polycube", "thin", "ring", "spiral", "letter", "solid"};
    return dimension == 3 ? three : two;
}

planner::Shape shapeOf(const std::string& family, int dimension, int cells, std::mt19937_64& random) {
    std::vector<Vec> c;
    if (family == "polyomino" || family == "polycube") c = grow(cells, dimension, false, random);
    else if (family == "thin") c = grow(cells, dimension, true, random);
    else if (family == "ring") c = ring(cells, dimension, random);
    else if (family == "spiral") c = spiral(cells, dimension);
    else if (family == "letter") c = letter(cells, dimension, random);
    else if (family == "solid") c = solid(cells, random);
    else throw std::invalid_argument("unknown shape family " + family);
    const bool central = std::uniform_int_distribution<int>(0, 1)(random) == 1;
    return anchored(std::move(c), dimension, central, random, family);
}

ShapePair shapePair(int dimension, std::uint64_t seed, int index, int attempt, int cells, double maxRatio) {
    std::seed_seq mix{seed, static_cast<std::uint64_t>(dimension), static_cast<std::uint64_t>(index), static_cast<std::uint64_t>(attempt)};
    std::mt19937_64 random(mix);
    const auto& families = shapeFamilies(dimension);
    const std::string from = families[static_cast<std::size_t>(index) % families.size()];
    const std::string to = families[std::uniform_int_distribution<std::size_t>(0, families.size() - 1)(random)];
    // The target's size relative to the start, log-uniform: from far lighter to far heavier.
    const double ratio = std::exp(std::uniform_real_distribution<double>(-std::log(maxRatio), std::log(maxRatio))(random));
    const int size = std::uniform_int_distribution<int>(cells / 2, cells * 3 / 2)(random);
    ShapePair p;
    p.family = from + "->" + to;
    p.start = shapeOf(from, dimension, size, random);
    p.target = shapeOf(to, dimension, std::max(2, static_cast<int>(size * ratio)), random);
    return p;
}

}  // namespace holon::bench
