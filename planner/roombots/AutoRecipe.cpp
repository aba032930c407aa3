// Automatic seeding recipes (seed 001 §VI b asks for them): an order of the seeds derived from the
// structure and the metamodule's kinematics, using the reservation strategy's walk planner.

#include "planner/roombots/Assembly.h"

#include "planner/roombots/Reservation.h"

namespace holon::planner::roombots {

using detail::CellSet;

// choice: the structures here stand on the floor, so "attached to something already built" always
// holds; what decides a good order is that no seed walls in a later one. Greedily, the next seed is
// one a metamodule can walk to and fill now and after which the hardest later seed keeps the most
// postures it can be filled from (seatings); ties go to the seed farthest from the starts. If no
// seed leaves every later one fillable, the given order is kept.
Recipe automaticRecipe(const CloudTable& table, Coupling coupling, const Setting& setting, const Budget& budget) {
    detail::Reservation probe(table, coupling, setting);
    const auto& seeds = setting.recipe.seeds;
    double cx = 0, cy = 0;
    for (const Cell& s : setting.starts) cx += s.x, cy += s.y;
    cx /= setting.starts.size(), cy /= setting.starts.size();
    std::vector<bool> done(seeds.size());
    CellSet built;
    Recipe recipe{"auto", {}};
    for (std::size_t round = 0; round < seeds.size(); ++round) {
        int pick = -1;
        std::pair<int, double> best{0, 0};  // (seatings of the hardest later seed, distance from the starts)
        for (std::size_t s = 0; s < seeds.size(); ++s) {
            if (done[s]) continue;
            if (budget.reached()) throw AssemblyStopped{};
            CellSet after = built;
            after.insert(seeds[s].cells.begin(), seeds[s].cells.end());
            int hardest = std::numeric_limits<int>::max();
            for (std::size_t r = 0; r < seeds.size() && hardest > 0; ++r)
                if (!done[r] && r != s) hardest = std::min(hardest, probe.seatings(static_cast<int>(r), after));
            const std::pair<int, double> score{hardest, std::hypot(seeds[s].cells[0].x - cx, seeds[s].cells[0].y - cy)};
            if (hardest == 0 || (pick >= 0 && score <= best)) continue;
            bool reachable = false;
            for (const Cell& start : setting.starts)
                if (probe.walk(static_cast<int>(s), start, built) >= 0) {
                    reachable = true;
                    break;
                }
            if (reachable) pick = static_cast<int>(s), best = score;
        }
        if (pick < 0) return setting.recipe;
        done[pick] = true;
        built.insert(seeds[pick].cells.begin(), seeds[pick].cells.end());
        Seed seed = seeds[pick];
        seed.group = static_cast<int>(round);
        recipe.seeds.push_back(seed);
    }
    return recipe;
}

std::vector<int> unfillableSeeds(const CloudTable& table, Coupling coupling, const Setting& setting) {
    const detail::Reservation probe(table, coupling, setting);
    std::vector<int> unfillable;
    for (int s = 0; s < static_cast<int>(setting.recipe.seeds.size()); ++s)
        if (probe.seatings(s, {}) == 0) unfillable.push_back(s);
    return unfillable;
}

}  // namespace holon::planner::roombots
