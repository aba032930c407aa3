// Bounded regions: boxes of the square and cubic lattices and hexagons of radius R on the hex lattice
// (3R(R+1)+1 cells, the shape seed 003 sculpts on). Cells are numbered row-major (x fastest) so that a
// configuration is a flat array; neighbours are precomputed once per region.

#include "rules/Region.h"

#include "rules/Error.h"
#include "rules/Limits.h"

#include <algorithm>
#include <charconv>
#include <cstdlib>
#include <limits>
#include <set>
#include <tuple>

namespace holon::rules {

namespace {

std::vector<int> parseDims(std::string_view text, std::string_view spec, std::size_t count) {
    std::vector<int> dims;
    while (true) {
        int value = 0;
        auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), value);
        if (ec == std::errc::result_out_of_range)
            throw InputError("bad region '" + std::string(spec) + "': a size is larger than 2147483647; choose a smaller region");
        if (ec != std::errc() || value <= 0)
            throw InputError("bad region '" + std::string(spec) + "': sizes must be positive integers");
        dims.push_back(value);
        text.remove_prefix(static_cast<std::size_t>(end - text.data()));
        if (text.empty()) break;
        if (text.front() != 'x')
            throw InputError("bad region '" + std::string(spec) + "': separate sizes with 'x', as in square:5x5");
        text.remove_prefix(1);
    }
    if (dims.size() != count)
        throw InputError("bad region '" + std::string(spec) + "': expected " + std::to_string(count) + " sizes");
    return dims;
}

}  // namespace

Region::Region(const Lattice& lattice, std::string spec, std::vector<Vec> cells)
    : lattice_(&lattice), spec_(std::move(spec)), cells_(std::move(cells)) {
    Vec lo = cells_.front(), hi = cells_.front();
    for (Vec c : cells_) {
        lo = {std::min(lo.x, c.x), std::min(lo.y, c.y), std::min(lo.z, c.z)};
        hi = {std::max(hi.x, c.x), std::max(hi.y, c.y), std::max(hi.z, c.z)};
    }
    lower_ = lo;
    extent_ = Vec{hi.x - lo.x + 1, hi.y - lo.y + 1, hi.z - lo.z + 1};
    boxIndex_.assign(static_cast<std::size_t>(extent_.x) * extent_.y * extent_.z, -1);
    for (int i = 0; i < size(); ++i) {
        Vec r = cells_[i] - lower_;
        boxIndex_[(static_cast<std::size_t>(r.z) * extent_.y + r.y) * extent_.x + r.x] = i;
    }
    const int degree = lattice.degree();
    neighbours_.resize(cells_.size() * degree);
    for (int i = 0; i < size(); ++i)
        for (int d = 0; d < degree; ++d)
            neighbours_[static_cast<std::size_t>(i) * degree + d] = indexOf(cells_[i] + lattice.direction(d));
}

int Region::indexOf(Vec v) const {
    // In 64 bits: a position near the edge of the int range minus a negative lower corner (hex
    // regions are centred on the origin) overflows an int (a configuration at x = 2^31 - 1, found by
    // fuzzing).
    const std::int64_t x = std::int64_t{v.x} - lower_.x, y = std::int64_t{v.y} - lower_.y, z = std::int64_t{v.z} - lower_.z;
    if (x < 0 || y < 0 || z < 0 || x >= extent_.x || y >= extent_.y || z >= extent_.z) return -1;
    return boxIndex_[static_cast<std::size_t>((z * extent_.y + y) * extent_.x + x)];
}

Region Region::box(const Lattice& lattice, Vec size) {
    std::vector<Vec> cells;
    cells.reserve(static_cast<std::size_t>(size.x) * size.y * size.z);
    for (int z = 0; z < size.z; ++z)
        for (int y = 0; y < size.y; ++y)
            for (int x = 0; x < size.x; ++x) cells.push_back({x, y, z});
    std::string spec = lattice.kind() == LatticeKind::Cubic3D
                           ? "cubic:" + std::to_string(size.x) + "x" + std::to_string(size.y) + "x" +
                                 std::to_string(size.z)
                           : "square:" + std::to_string(size.x) + "x" + std::to_string(size.y);
    return Region(lattice, spec, std::move(cells));
}

Region Region::of(const Lattice& lattice, std::string spec, std::vector<Vec> cells) {
    if (cells.empty()) throw InternalError("a region needs a cell");
    return Region(lattice, std::move(spec), std::move(cells));
}

Region Region::hexagon(int radius) {
    std::vector<Vec> cells;
    for (int r = -radius; r <= radius; ++r)
        for (int q = -radius; q <= radius; ++q)
            if (std::abs(q + r) <= radius) cells.push_back({q, r, 0});
    return Region(Lattice::get(LatticeKind::Hex2D), "hex:r" + std::to_string(radius), std::move(cells));
}

Region Region::grown(int margin) const { return *grown(margin, std::numeric_limits<std::size_t>::max()); }

std::optional<Region> Region::grown(int margin, std::size_t maxCells) const {
    // The grown region holds the ball of radius `margin` around any cell: at least 2 m^2 cells on
    // the planar lattices, 4/3 m^3 on the cubic one. Beyond the limit, known without growing.
    const double m = margin, ball = lattice_->dimension() == 3 ? 4.0 / 3.0 * m * m * m : 2.0 * m * m;
    if (ball > static_cast<double>(maxCells)) return std::nullopt;
    std::vector<Vec> cells = cells_;
    std::set<std::tuple<int, int, int>> seen;
    for (Vec c : cells_) seen.insert({c.x, c.y, c.z});
    std::size_t layerStart = 0;
    for (int step = 0; step < margin; ++step) {
        const std::size_t layerEnd = cells.size();
        for (std::size_t k = layerStart; k < layerEnd; ++k)
            for (Vec d : lattice_->directions()) {
                const Vec n = cells[k] + d;
                if (seen.insert({n.x, n.y, n.z}).second) cells.push_back(n);
                if (cells.size() > maxCells) return std::nullopt;
            }
        layerStart = layerEnd;
    }
    return Region(*lattice_, spec_ + "+" + std::to_string(margin), std::move(cells));
}

Region Region::parse(std::string_view spec, std::size_t maxCells, const std::function<void(std::uint64_t cells)>& admit) {
    const auto colon = spec.find(':');
    const std::string_view kind = spec.substr(0, colon);
    const std::string_view rest = colon == std::string_view::npos ? std::string_view{} : spec.substr(colon + 1);
    auto checkSize = [&](std::uint64_t cells) {
        if (cells > maxCells)
            throw InputError("region '" + std::string(spec) + "' has " + countText(cells) +
                             " cells, more than the limit of " + std::to_string(maxCells) + "; choose a smaller region");
        if (admit) admit(cells);
    };
    if (colon == std::string_view::npos || rest.empty())
        throw InputError("bad region '" + std::string(spec) + "': write square:WxH, cubic:WxHxD or hex:rR");
    if (kind == "square") {
        auto d = parseDims(rest, spec, 2);
        checkSize(checkedProduct({std::uint64_t(d[0]), std::uint64_t(d[1])}));
        return box(Lattice::get(LatticeKind::Square2D), {d[0], d[1], 1});
    }
    if (kind == "cubic") {
        auto d = parseDims(rest, spec, 3);
        checkSize(checkedProduct({std::uint64_t(d[0]), std::uint64_t(d[1]), std::uint64_t(d[2])}));
        return box(Lattice::get(LatticeKind::Cubic3D), {d[0], d[1], d[2]});
    }
    if (kind == "hex") {
        if (rest.front() != 'r')
            throw InputError("bad region '" + std::string(spec) + "': a hexagon is written hex:rR, as in hex:r2");
        auto d = parseDims(rest.substr(1), spec, 1);
        checkSize(3u * static_cast<std::uint64_t>(d[0]) * (static_cast<std::uint64_t>(d[0]) + 1) + 1);  // below 2^64 for any int R
        return hexagon(d[0]);
    }
    throw InputError("unknown lattice '" + std::string(kind) + "' in region '" + std::string(spec) +
                     "': use square:WxH, cubic:WxHxD or hex:rR");
}

}  // namespace holon::rules
