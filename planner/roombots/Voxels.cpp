// Seeds from a bare voxel model (seed 001 §VI b: "a scalable planner to automatically come up with a
// seeding recipe based on a CAD presentation of a structure"): the voxels are split into metamodules,
// chains of four face-adjacent voxels that each stand on the floor by one end, by an exact-cover
// search that always extends the voxel with the fewest ways to be covered (Knuth's heuristic for
// Algorithm X). Which order to fill them in is AutoRecipe.cpp's job. The search is exponential in
// the worst case: a chain covers two voxels of each colour of the 3D checkerboard, so models with
// unequal colours are refused before it starts, and it stops at the job's deadline or signal and
// after a fixed number of steps (exit 3: undecided, not bad input).

#include "planner/roombots/Structures.h"

#include "rules/Error.h"
#include "rules/Parameter.h"

#include <algorithm>
#include <functional>
#include <map>
#include <set>

namespace holon::planner::roombots {
namespace {

constexpr std::array<Cell, 6> kFaces{Cell{1, 0, 0}, Cell{-1, 0, 0}, Cell{0, 1, 0}, Cell{0, -1, 0}, Cell{0, 0, 1}, Cell{0, 0, -1}};

/// Every chain of four free voxels through `v` with an end on the floor, that end first.
std::vector<std::array<Cell, 4>> chainsThrough(const Cell& v, const std::set<Cell>& free) {
    std::set<std::array<Cell, 4>> chains;
    std::array<Cell, 4> path;
    std::function<void(int)> extend = [&](int length) {
        if (length == 4) {
            if (std::find(path.begin(), path.end(), v) == path.end()) return;
            if (path[0].z == 0) chains.insert(path);
            if (path[3].z == 0) chains.insert({path[3], path[2], path[1], path[0]});
            return;
        }
        for (const Cell& f : kFaces) {
            const Cell next = path[length - 1] + f;
            if (!free.count(next) || std::find(path.begin(), path.begin() + length, next) != path.begin() + length) continue;
            path[length] = next;
            extend(length + 1);
        }
    };
    // A chain through v starts at most three steps from v.
    for (const Cell& start : free) {
        const Cell d = start - v;
        if (std::abs(d.x) + std::abs(d.y) + std::abs(d.z) > 3) continue;
        path[0] = start;
        extend(1);
    }
    return {chains.begin(), chains.end()};
}

}  // namespace

std::vector<Seed> seedsFromVoxels(const std::vector<Cell>& voxels, const std::string& where, const Budget& budget) {
    std::set<Cell> free(voxels.begin(), voxels.end());
    if (free.size() != voxels.size()) throw InputError(where + ": a voxel is listed twice");
    if (voxels.size() % 4 != 0)
        throw InputError(where + ": " + std::to_string(voxels.size()) + " voxels; a metamodule fills four, so the count must be a multiple of 4");
    if (voxels.size() > 400) throw InputError(where + ": more than 400 voxels; holon roombots takes at most 100 metamodules");
    for (const Cell& v : voxels)
        if (v.z < 0) throw InputError(where + ": a voxel lies below the floor (z < 0)");
    std::size_t even = 0;
    for (const Cell& v : voxels) even += ((v.x + v.y + v.z) & 1) == 0;
    if (2 * even != voxels.size())
        throw InputError(where + ": cannot split the " + std::to_string(voxels.size()) + " voxels into metamodules: a chain of four face-adjacent voxels covers two of each colour of a 3D checkerboard, and this model has " +
                         std::to_string(even) + " of one colour and " + std::to_string(voxels.size() - even) + " of the other");
    std::vector<Seed> seeds;
    constexpr long kSteps = 2'000'000;  // search steps before giving up
    long steps = 0;
    std::function<bool()> cover = [&]() {
        if (free.empty()) return true;
        if (++steps > kSteps)
            throw LimitError(where + ": no split of the " + std::to_string(voxels.size()) + " voxels into metamodules found in " + std::to_string(kSteps) +
                             " search steps, and none ruled out; give the structure as `seed` lines");
        // A step rescans every free voxel: reading the clock each time costs nothing beside it.
        if (budget.interrupted()) throw Interrupted(budget.signal());
        if (budget.expired())
            throw LimitError(where + ": " + rules::parameterName(rules::Parameter::Timeout) + " reached while splitting the voxels into metamodules; raise it, or give the structure as `seed` lines",
                             rules::Parameter::Timeout);
        std::vector<std::array<Cell, 4>> fewest;
        bool first = true;
        for (const Cell& v : free) {
            auto chains = chainsThrough(v, free);
            if (first || chains.size() < fewest.size()) fewest = std::move(chains), first = false;
            if (fewest.empty()) return false;
        }
        for (const auto& chain : fewest) {
            for (const Cell& c : chain) free.erase(c);
            seeds.push_back({chain, static_cast<int>(seeds.size())});
            if (cover()) return true;
            seeds.pop_back();
            for (const Cell& c : chain) free.insert(c);
        }
        return false;
    };
    if (!cover())
        throw InputError(where + ": cannot split the " + std::to_string(voxels.size()) +
                         " voxels into metamodules (chains of four face-adjacent voxels, each standing on the floor by one end)");
    return seeds;
}

}  // namespace holon::planner::roombots
