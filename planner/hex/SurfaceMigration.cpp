// holon's surface migration (--migrate; not in seed 003, whose §VI leaves abandoned modules to
// future work): every module outside the target that is no shepherd moves one lattice point along
// the surface (rules/library/hex_migrate.holon, through the compiled engine; seed 003's motion model,
// §V-A) toward the nearest target point still empty, provided the mass stays connected without it
// (the rule's `constraint connected`, decided by MassTree). Deletion (§IV-E) leaves walls one module
// thick outside the target that neither holes nor column collapse can clear, and creation cannot
// fill the last row of target points along the target's edge; migration moves modules from the one
// to the other.
// Three things make it converge, each measured (docs/hex.md, "holon's improvements"):
//  - the field: moves along the surface (onto points that touch the mass) to an empty target point,
//    by breadth-first search once per timestep; a migrant descends it strictly below the value it
//    arrived with, since the field is computed with every migrant where it stands and may count on
//    a migrant's own body to reach the next point (without that memory modules step back and forth);
//  - retraction: where the field does not reach (behind a wall, inside its loops) or gives no
//    descent, a module moves next to a filled neighbour at least two hops nearer MassTree's root than
//    itself, so walls shrink toward the mass, tip first, until their modules meet the field;
//  - advance (hex_migrate's second rule): a void in the mass or in a channel one cell wide (empty
//    target points no empty point outside the target touches) is filled from a neighbour nearer the
//    open surface, hops counted over every point; the void so travels out to where a migrant fills
//    it. Without it the first module to settle plugs a channel's mouth.

#include "planner/hex/HoleSculptor.h"

#include <limits>

namespace holon::planner::hex {

void HoleSculptor::migrate() {
    const auto touchesMass = [&](std::int64_t i) {
        for (int d = 0; d < 6; ++d)
            if (filled(i + array_->step(d))) return true;
        return false;
    };
    const auto touchesOutside = [&](std::int64_t i) {
        for (int d = 0; d < 6; ++d)
            if (const std::int64_t n = i + array_->step(d); array_->inside(n) && !filled(n) && !(*target_)[n]) return true;
        return false;
    };
    if (arrival_.empty()) arrival_.assign(cells_.size(), Arrival{});
    std::vector<std::int64_t> emptyTarget, movers, enclosed, open;
    for (std::int64_t i : array_->points()) {
        if (!filled(i) && (*target_)[i]) emptyTarget.push_back(i);
        if (!filled(i) && !(*target_)[i] && touchesMass(i)) open.push_back(i);
        if (module(i) && !(*target_)[i]) movers.push_back(i);
    }
    towardEmpty_ = hopsFrom(*array_, emptyTarget, [&](std::int64_t n, std::int64_t from) { return array_->inside(n) && !filled(n) && touchesMass(from); });
    // Enclosed points (empty target points no empty point outside the target touches) and, when
    // there are any, every point's hops to the open surface (empty points outside the target that
    // touch the mass), the potential a void descends.
    for (std::int64_t r : emptyTarget)
        if (!touchesOutside(r)) enclosed.push_back(r);
    const std::vector<std::int32_t> toOpen =
        enclosed.empty() ? std::vector<std::int32_t>{} : hopsFrom(*array_, open, [&](std::int64_t n, std::int64_t) { return array_->inside(n); });

    random_.shuffle(movers);
    const BoxEngine& engine = rules_->migrateEngine();
    constexpr std::int32_t kNone = std::numeric_limits<std::int32_t>::max();
    for (std::int64_t m : movers) {
        const std::int32_t arrived = time_ - arrival_[m].time <= kArrivalMemory ? arrival_[m].value : kNone;
        // Ranks: (0, field value) descends the field; (1, potential) retracts. The bar to beat is a
        // retraction two hops nearer the root.
        std::pair<int, std::int32_t> best{1, tree_->distance(m) - 1};
        int bestShape = -1;
        std::int64_t bestCell = -1;
        for (int d = 0; d < 6; ++d) {
            const std::int64_t b = m + array_->step(d);
            if (filled(b) || !array_->inside(b)) continue;
            std::pair<int, std::int32_t> rank{0, towardEmpty_[b]};
            if (towardEmpty_[b] < 0 || towardEmpty_[b] >= arrived) {
                rank = {1, kNone};
                for (int e = 0; e < 6; ++e)
                    if (const std::int64_t n = b + array_->step(e); n != m && filled(n)) rank.second = std::min(rank.second, tree_->distance(n));
            }
            if (rank >= best || !engine.matches(cells_.data(), m, rules_->migrate(d))) continue;
            best = rank, bestShape = rules_->migrate(d), bestCell = b;
        }
        if (bestShape < 0 || !tree_->change({m}, {bestCell})) continue;
        apply(engine, m, bestShape);
        // A retraction keeps the value the module arrived with, so that no mix of the two cycles.
        arrival_[bestCell] = best.first == 0 ? Arrival{best.second, time_} : Arrival{arrived, arrival_[m].time};
        arrival_[m] = Arrival{};
        ++counts_.migrated;
    }
    for (std::int64_t r : enclosed)
        for (int d = 0; d < 6 && !filled(r); ++d) {
            const std::int64_t a = r + array_->step(d);  // it would move in direction d + 3
            if (!module(a) || !(*target_)[a] || toOpen[a] < 0 || toOpen[a] >= toOpen[r]) continue;
            const int shape = rules_->advance((d + 3) % 6);
            if (engine.matches(cells_.data(), a, shape) && tree_->change({a}, {r})) {
                apply(engine, a, shape);
                ++counts_.migrated;
            }
        }
}

}  // namespace holon::planner::hex
