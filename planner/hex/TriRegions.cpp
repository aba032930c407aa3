// Tri-regions and their gravity, seed 003 §IV-B and §IV-C. A point belongs to the triangle found
// by skewing the plane onto the triangle lattice (u = x - y/sqrt3, v = 2y/sqrt3, in edges); the
// triangle is "up" or "down" by whether frac(u) + frac(v) < 1. Gravity follows the paper's
// worklist: a region is visited once some of its points are on the perimeter of the running
// representation R; gravity is the direction of filled neighbours most common over those points,
// after a 3-way moving average of the six totals; then R is filled (growth) or emptied (deletion)
// inside the region. Where the paper is silent: a perimeter point is a point of R with an empty
// neighbour or an empty point with a filled one, and a pass over the worklist that places no
// region ends the loop, the rest pointing toward the centre of the source mass.

#include "planner/hex/TriRegions.h"

#include "rules/Error.h"
#include "rules/Parameter.h"

#include <array>
#include <cmath>
#include <deque>
#include <unordered_map>

namespace holon::planner::hex {

namespace {

std::int64_t triangleKey(double x, double y, double side) {
    const double u = (x - y / std::sqrt(3.0)) / side, v = 2.0 * y / std::sqrt(3.0) / side;
    const double fu = std::floor(u), fv = std::floor(v);
    const int up = (u - fu) + (v - fv) < 1.0 ? 0 : 1;
    return ((static_cast<std::int64_t>(fu) + (1 << 20)) << 22 | (static_cast<std::int64_t>(fv) + (1 << 20))) << 1 | up;
}

/// The lattice direction closest to the Cartesian vector (dx, dy).
int nearestDirection(double dx, double dy) {
    const double angle = std::atan2(dy, dx);
    int d = static_cast<int>(std::lround(angle / (M_PI / 3)));
    return ((d % 6) + 6) % 6;
}

}  // namespace

TriPlan planTriRegions(const HexArray& array, const std::vector<std::uint8_t>& source, const std::vector<std::uint8_t>& target, double side,
                       const Budget& budget) {
    std::uint32_t polls = 0;
    const auto stopped = [&] { return ++polls % (1u << 16) == 0 && budget.reached(); };
    if (!(side >= 2.0))
        throw InputError(rules::parameterName(rules::Parameter::Tri) + ": tri-regions must be at least 2 module diameters wide", rules::Parameter::Tri);
    TriPlan plan;
    plan.side = side;
    plan.regionOf.assign(array.size(), -1);
    std::unordered_map<std::int64_t, std::int32_t> indexOf;
    std::vector<std::vector<std::int64_t>> members;
    for (std::int64_t i : array.points()) {
        if (stopped()) return plan;
        const std::int64_t key = triangleKey(array.x(i), array.y(i), side);
        auto [it, fresh] = indexOf.try_emplace(key, static_cast<std::int32_t>(members.size()));
        if (fresh) members.emplace_back(), plan.regions.emplace_back();
        members[it->second].push_back(i);
        TriRegion& t = plan.regions[it->second];
        ++t.points;
        t.toFill += target[i] && !source[i];
        t.toEmpty += source[i] && !target[i];
    }
    // Keep the triangles in which something changes; renumber densely.
    std::vector<TriRegion> active;
    std::vector<std::vector<std::int64_t>> activeMembers;
    for (std::size_t k = 0; k < plan.regions.size(); ++k) {
        TriRegion t = plan.regions[k];
        if (t.toFill + t.toEmpty == 0) continue;
        t.growth = t.toFill > t.toEmpty;
        for (std::int64_t i : members[k]) plan.regionOf[i] = static_cast<std::int32_t>(active.size());
        active.push_back(t);
        activeMembers.push_back(std::move(members[k]));
    }
    plan.regions = std::move(active);
    // Choice: a module belongs to a tri-region also when one of its neighbours does. Otherwise a
    // surface lying on a triangle edge belongs to no region: the unchanged triangle below it is
    // removed, the one above holds no module, and that stretch of surface never activates.
    std::vector<std::int32_t> dilated = plan.regionOf;
    for (std::int64_t i : array.points())
        for (int d = 0; d < 6 && dilated[i] < 0; ++d) dilated[i] = plan.regionOf[i + array.step(d)];
    plan.regionOf = std::move(dilated);

    std::vector<std::uint8_t> r = source;  // padding and cells outside the array stay empty
    double mx = 0, my = 0, mass = 0;
    for (std::int64_t i : array.points())
        if (source[i]) mx += array.x(i), my += array.y(i), mass += 1;
    mx /= mass, my /= mass;
    std::deque<int> worklist;
    for (int k = 0; k < static_cast<int>(plan.regions.size()); ++k) worklist.push_back(k);
    std::size_t sinceProgress = 0;
    while (!worklist.empty()) {
        if (stopped()) return plan;
        const int k = worklist.front();
        worklist.pop_front();
        std::array<std::int64_t, 6> totals{};
        bool onPerimeter = false;
        for (std::int64_t i : activeMembers[k]) {
            bool filledNbr = false, emptyNbr = false;
            for (int d = 0; d < 6; ++d) (r[i + array.step(d)] ? filledNbr : emptyNbr) = true;
            if (!(r[i] ? emptyNbr : filledNbr)) continue;
            onPerimeter = true;
            for (int d = 0; d < 6; ++d) totals[d] += r[i + array.step(d)];
        }
        if (!onPerimeter) {
            worklist.push_back(k);
            if (++sinceProgress > worklist.size()) break;
            continue;
        }
        sinceProgress = 0;
        int best = 0;
        std::int64_t bestScore = -1;
        for (int d = 0; d < 6; ++d) {
            const std::int64_t score = totals[(d + 5) % 6] + totals[d] + totals[(d + 1) % 6];
            if (score > bestScore) bestScore = score, best = d;
        }
        plan.regions[k].gravity = best;
        for (std::int64_t i : activeMembers[k]) r[i] = plan.regions[k].growth ? 1 : 0;
    }
    for (int k : worklist) {
        double cx = 0, cy = 0;
        for (std::int64_t i : activeMembers[k]) cx += array.x(i), cy += array.y(i);
        cx /= activeMembers[k].size(), cy /= activeMembers[k].size();
        plan.regions[k].gravity = nearestDirection(mx - cx, my - cy);
        ++plan.gravityFallbacks;
    }
    return plan;
}

}  // namespace holon::planner::hex
