// Hole-motion sculpting, seed 003 §IV-A..F, on the hex array. Hole moves run one hole at a time in
// a fresh random order each timestep: that is the serial order the paper's reservations produce
// (a hole reserves the cells of its move; a move that would touch another hole's shepherd group
// is refused and the hole picks a new random direction, §IV-D). Growth and deletion nodes are the
// surface modules inside active tri-regions (§IV-E); each runs its node test, then the column
// collapse of §IV-F. Modelling choices where the paper is silent are marked "choice:".

#include "planner/hex/HoleSculptor.h"

#include "rules/Components.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace holon::planner::hex {

namespace {

double cartesianX(Vec v) { return v.x + 0.5 * v.y; }
double cartesianY(Vec v) { return -HexArray::kRowHeight * v.y; }

/// The root of the connectivity tree: the point of source and target farthest from their edges
/// (of the source alone when they do not meet); it stays filled throughout.
std::int64_t deepestCell(const HexArray& array, const std::vector<std::uint8_t>& source, const std::vector<std::uint8_t>& target) {
    std::vector<std::uint8_t> mask(array.size(), 0);
    bool meet = false;
    for (std::int64_t i : array.points()) meet |= source[i] && target[i];
    for (std::int64_t i : array.points()) mask[i] = source[i] && (target[i] || !meet);
    std::vector<std::int64_t> edge;
    for (std::int64_t i : array.points()) {
        bool open = false;
        for (int d = 0; d < 6; ++d) open |= !mask[i + array.step(d)];
        if (mask[i] && open) edge.push_back(i);
    }
    std::int64_t deepest = edge.front();
    hopsFrom(
        array, edge, [&](std::int64_t n, std::int64_t) { return mask[n] != 0; }, &deepest);
    return deepest;
}

}  // namespace

HoleSculptor::HoleSculptor(const HexArray& array, const std::vector<std::uint8_t>& source, const std::vector<std::uint8_t>& target,
                           const TriPlan& plan, const SculptOptions& options)
    : array_(&array), target_(&target), plan_(&plan), options_(options), random_(options.seed),
      rules_(std::make_unique<HoleRules>(array, target)), cells_(array.size(), 0), class_(array.size(), 1), holeAt_(array.size(), -1),
      nearPerimeter_(array.size(), 0) {
    const rules::Lattice& hex = rules::Lattice::get(rules::LatticeKind::Hex2D);
    auto steps = [&](const std::vector<Vec>& offsets) {
        std::vector<std::int64_t> out;
        for (Vec v : offsets) out.push_back(array.offset(v));
        return out;
    };
    ring1_ = steps(hexRing(1)), disk1_ = steps(hexDisk(1)), ring2_ = steps(hexRing(2)), ring3_ = steps(hexRing(3)), disk2_ = steps(hexDisk(2)), disk3_ = steps(hexDisk(3));
    for (Vec v : hexDisk(3)) distance3_.push_back(hexDistance(v, {}));
    for (int d = 0; d < 6; ++d) {
        const Vec v = hex.direction(d);
        std::vector<Vec> shepherds = hexRing(2);
        const double ux = cartesianX(v), uy = cartesianY(v);
        std::stable_sort(shepherds.begin(), shepherds.end(), [&](Vec a, Vec b) {
            return cartesianX(a) * ux + cartesianY(a) * uy > cartesianX(b) * ux + cartesianY(b) * uy;
        });
        uppermost_[d] = steps(shepherds);
    }

    for (std::int64_t i : array.points()) {
        class_[i] = source[i] && target[i] ? 0 : !source[i] && !target[i] ? 1
                                             : target[i]                  ? 2
                                                                          : 3;
        ++classSize_[class_[i]];
        if (!target[i]) ++classCorrect_[class_[i]];  // everything starts empty
    }
    for (std::int64_t i : array.points())
        if (source[i]) place(i, rules_->module());
    placeInitialHoles();
    std::int64_t area = 0;
    for (std::int64_t i : array.points()) area += target[i] != 0;
    holeBudget_ = std::max<std::int64_t>(0, (area - modules_) / 7);
    if (options_.keepConnected || options_.migrate || options_.balance) {
        tree_ = std::make_unique<MassTree>(array, [this](std::int64_t i) { return filled(i); });
        tree_->rebuild(deepestCell(array, source, target));
    }

    for (std::int64_t i : array.points())
        if (plan.regionOf[i] >= 0) activePoints_.push_back(i);
    random_.shuffle(activePoints_);

    // d_near by breadth-first search from the target's perimeter; d_max over the source's perimeter.
    std::vector<std::int64_t> perimeter;
    for (std::int64_t i : array.points()) {
        bool edge = false;
        for (int d = 0; d < 6; ++d) edge |= target[i + array.step(d)] != target[i];
        if (edge && target[i]) perimeter.push_back(i);
    }
    const std::vector<std::int32_t> hops = hopsFrom(array, perimeter, [&](std::int64_t n, std::int64_t) { return array.inside(n); });
    for (std::int64_t i : array.points()) {
        nearPerimeter_[i] = std::max(hops[i], 1);
        bool edge = false;
        for (int d = 0; d < 6; ++d) edge |= source[i + array.step(d)] != source[i];
        if (edge && source[i]) maxDistance_ = std::max<double>(maxDistance_, hops[i]);
    }
}

void HoleSculptor::place(std::int64_t i, Value v) {
    const Value old = cells_[i];
    cells_[i] = v;
    changed(i, old);
}

void HoleSculptor::changed(std::int64_t i, Value old) {
    const bool target = (*target_)[i] != 0, wasFilled = old != 0, isFilled = filled(i);
    modules_ += static_cast<int>(module(i)) - static_cast<int>(old == rules_->module());
    classCorrect_[class_[i]] += static_cast<int>(isFilled == target) - static_cast<int>(wasFilled == target);
}

void HoleSculptor::apply(const BoxEngine& engine, std::int64_t anchor, int shape) {
    Value old[rules::RuleTables::kMaxCells];
    engine.apply(cells_.data(), anchor, shape, old);
    const auto steps = engine.cellSteps(shape);
    for (std::size_t k = 0; k < steps.size(); ++k)
        if (cells_[anchor + steps[k]] != old[k]) changed(anchor + steps[k], old[k]);
}

std::int32_t HoleSculptor::holeOf(std::int64_t i) const {
    if (cells_[i] == rules_->centre()) return holeAt_[i];
    if (cells_[i] != rules_->rim()) return -1;
    for (std::int64_t o : ring1_)
        if (cells_[i + o] == rules_->centre()) return holeAt_[i + o];
    return -1;
}

// Choice: initial holes are dropped at random source points whose radius-2 disk lies in the
// source, clear of other holes; they start moving at random timesteps below startWindow.
void HoleSculptor::placeInitialHoles() {
    std::vector<std::int64_t> candidates;
    for (std::int64_t i : array_->points())
        if (module(i)) candidates.push_back(i);
    const auto attempts = static_cast<std::int64_t>(options_.holeDensity * static_cast<double>(candidates.size()));
    for (std::int64_t a = 0; a < attempts; ++a) {
        const std::int64_t c = candidates[random_.below(candidates.size())];
        bool clear = true;
        for (std::int64_t o : disk2_) clear &= array_->inside(c + o) && module(c + o);
        if (!clear) continue;
        const int id = static_cast<int>(holesById_.size());
        for (std::int64_t o : ring1_) place(c + o, rules_->rim());
        place(c, rules_->centre());
        holeAt_[c] = id;
        holesById_.push_back({c, static_cast<int>(random_.below(6)), static_cast<int>(random_.below(options_.startWindow)), true});
        ++liveHoles_;
    }
}

// The move is hex_holes.holon's hole_move, run by the compiled engine: its left side asks for the
// complete new shepherd group, which also keeps the move off every other hole's shepherds.
bool HoleSculptor::canMove(int id, int d) const {
    return rules_->holeEngine().matches(cells_.data(), holesById_[id].centre, rules_->move(d));
}

bool HoleSculptor::shepherdsAnother(std::int64_t i, int id) const {
    for (int e = 0; e < 6; ++e) {  // a module next to a hole's cell is one of its shepherds
        const std::int32_t h = holeOf(i + array_->step(e));
        if (h >= 0 && h != id) return true;
    }
    return false;
}

void HoleSculptor::move(int id, int d) {
    Hole& h = holesById_[id];
    apply(rules_->holeEngine(), h.centre, rules_->move(d));
    holeAt_[h.centre] = -1;
    h.centre += array_->step(d);
    holeAt_[h.centre] = id;
    ++counts_.holeMoves;
}

bool HoleSculptor::onSurface(std::int64_t k) const {
    for (int d = 0; d < 6; ++d) {
        const std::int64_t n = k + array_->step(d);
        if (!filled(n)) return true;
    }
    return false;
}

void HoleSculptor::step() {
    deletionLicences_ = growthDemand_, growthDemand_ = 0;
    std::vector<int> order;
    for (int id = 0; id < static_cast<int>(holesById_.size()); ++id)
        if (holesById_[id].alive && holesById_[id].start <= time_) order.push_back(id);
    random_.shuffle(order);
    for (int id : order) {
        Hole& h = holesById_[id];
        if (canMove(id, h.direction)) move(id, h.direction);
        else h.direction = static_cast<int>(random_.below(6));
    }
    if (!activePoints_.empty()) {
        const std::size_t n = activePoints_.size(), first = random_.below(n);
        for (std::size_t j = 0; j < n; ++j) activate(activePoints_[(first + j) % n]);
        for (std::size_t j = 0; j < n; ++j) {
            const std::int64_t k = activePoints_[(first + j) % n];
            if (module(k) && onSurface(k)) smooth(k, plan_->regions[plan_->regionOf[k]].gravity);
        }
    }
    if (options_.balance && liveHoles_ > holeBudget_) deleteSurplus();
    if (options_.migrate) migrate();
    ++time_;
}

void HoleSculptor::activate(std::int64_t k) {
    if (!module(k) || !onSurface(k)) return;
    const TriRegion& region = plan_->regions[plan_->regionOf[k]];
    // holon's improvement (--delete-overflow): a module outside the target also deletes holes in a
    // growth region; otherwise the holes still alive at the end inflate the mass beyond the target.
    if (region.growth && !(options_.deleteOverflow && !(*target_)[k])) tryCreate(k);
    else tryDelete(k, region.gravity);
}

// §IV-E growth node: inside the target, no hole in the 2-hop radius, exactly 11 other modules in
// it; the 2-hop radius is rearranged into a shepherd group around a new hole at the node, by
// hex_growth.holon's hole_create run through the compiled engine. The count below only decides
// whether --flexible-growth has a module to spill or borrow first; the rule checks the rest.
void HoleSculptor::tryCreate(std::int64_t k) {
    if (!(*target_)[k]) return;
    int modules = 0;
    for (std::int64_t o : disk2_) {
        const std::int64_t i = k + o;
        if (!array_->inside(i) || holeCell(i)) return;
        // holon's improvement (--grow-inside): the new shepherd group must lie inside the target,
        // or creation at the target's edge pushes modules out of it.
        if (options_.growInside && !(*target_)[i]) return;
        modules += module(i);
    }
    // holon's improvement (--flexible-growth): one module more than a shepherd group needs moves out
    // onto an empty target point just outside the disk, one fewer is borrowed from a module just
    // outside it, so that growth also starts on the faces where no disk holds exactly 12.
    std::int64_t spill = -1, borrow = -1;
    if (modules != 12) {
        if (!options_.flexibleGrowth || (modules != 13 && modules != 11)) return;
        for (std::int64_t o : ring3_) {
            const std::int64_t c = k + o;
            if (!array_->inside(c) || holeCell(c)) continue;
            if (modules == 13 && !module(c) && (*target_)[c]) spill = c;
            if (modules == 11 && module(c) && !shepherdsAnother(c, -1) && !(*target_)[c]) borrow = c;
        }
        if (spill < 0 && borrow < 0) return;
    }
    // --balance: at the budget the node only asks for a hole, licensing a deletion (tryDelete).
    if (options_.balance && liveHoles_ >= holeBudget_) {
        ++growthDemand_;
        return;
    }
    // The rule rewrites the whole disk, so which disk module spills, or which empty disk point the
    // borrowed module enters, is immaterial to the cells; MassTree hears of it as one module's move
    // and then the disk's filling.
    const BoxEngine& engine = spill >= 0 || borrow >= 0 ? rules_->flexibleEngine() : rules_->growthEngine();
    const int shape = spill >= 0 ? rules_->spill(spill - k) : borrow >= 0 ? rules_->borrow(borrow - k)
                                                                          : rules_->create();
    std::int64_t from = borrow, to = spill;
    if (spill >= 0 || borrow >= 0) {
        for (std::int64_t o : disk2_) {
            const std::int64_t i = k + o;
            if (from < 0 && i != k && module(i)) from = i;
            if (to < 0 && !cells_[i]) to = i;
        }
        if (tree_ && !tree_->change({from}, {to})) return;
    }
    if (shape < 0 || !engine.matches(cells_.data(), k, shape)) throw std::logic_error("no hole creation rule matches a growth node with 12 modules");
    std::int64_t newlyFilled[19];
    int fills = 0;
    for (std::int64_t o : disk2_)
        if (const std::int64_t i = k + o; (!cells_[i] && i != to) || i == from) newlyFilled[fills++] = i;
    if (tree_ && !tree_->change(nullptr, 0, newlyFilled, fills)) throw std::logic_error("a hole's creation cut the mass apart");
    apply(engine, k, shape);
    holeAt_[k] = static_cast<std::int32_t>(holesById_.size());
    holesById_.push_back({k, static_cast<int>(random_.below(6)), time_ + 1, true});
    ++liveHoles_, ++counts_.created;
}

// §IV-E deletion node: outside the target; exactly one hole in the 2-hop radius, holding one of
// the node's neighbours, with its 12 shepherds; the temperature test; the hole cannot move
// against gravity. A hole that still can is steered against gravity instead.
void HoleSculptor::tryDelete(std::int64_t k, int gravity) {
    if ((*target_)[k]) return;
    // --balance: at or below the budget a deletion needs a growth node that asked for a hole in the
    // last timestep, so that creation restores the volume; once growth is done, deletion stops.
    const bool licensed = options_.balance && liveHoles_ <= holeBudget_;
    if (licensed && deletionLicences_ <= 0) return;
    int id = -1;
    for (std::int64_t o : disk2_) {
        const std::int32_t h = holeOf(k + o);
        if (h < 0) continue;
        if (id >= 0 && h != id) return;
        id = h;
    }
    if (id < 0) return;
    bool touches = false;
    for (int d = 0; d < 6; ++d) touches |= holeOf(k + array_->step(d)) == id;
    if (!touches) return;
    const std::int64_t c = holesById_[id].centre;
    int shepherds = 0;
    for (std::int64_t o : ring2_) shepherds += module(c + o);
    if (shepherds != 12) return;
    const int up = (gravity + 3) % 6;
    if (canMove(id, up)) {
        holesById_[id].direction = up;
        ++counts_.steered;
        return;
    }
    // Choice: t / c_decay, not c_decay · t as printed: with c_decay in [15, 50] the printed form
    // reaches its floor within dmax/c_decay (a handful of) timesteps, and the test would no
    // longer favour the extremities over a 10,000-step run as §IV-B says it does.
    const double p = 1.0 + std::log(nearPerimeter_[k] / std::max(maxDistance_ - time_ / options_.decay, 1.0));
    if (static_cast<double>(random_.next() >> 11) * 0x1p-53 >= p) return;
    const std::vector<std::int64_t> emptied = nearestTheSurface(id, towardSurface(c, k, up));
    if (emptied.empty()) return;
    const int shape = deletion(id, emptied);
    if (tree_ && !tree_->change(emptied, {})) {
        ++counts_.refusedSplits;
        return;
    }
    remove(id, shape);
    if (licensed) --deletionLicences_;
}

int HoleSculptor::deletion(int id, const std::vector<std::int64_t>& emptied) const {
    const std::int64_t c = holesById_[id].centre;
    std::vector<std::int64_t> steps;
    for (std::int64_t i : emptied) steps.push_back(i - c);
    const int shape = rules_->deletion(steps);
    if (shape < 0 || !rules_->deleteEngine().matches(cells_.data(), c, shape)) throw std::logic_error("no hex_delete rule matches a deletion");
    return shape;
}

void HoleSculptor::remove(int id, int shape) {
    const std::int64_t c = holesById_[id].centre;
    apply(rules_->deleteEngine(), c, shape);
    holeAt_[c] = -1;
    holesById_[id].alive = false;
    --liveHoles_, ++counts_.deleted;
}

// holon's improvement (--balance, not in seed 003): the ensemble's volume, modules plus seven
// points per hole, must equal the target's area for compliance to reach 100%, so the right number
// of live holes is a constant, (area - modules) / 7. Creation stops at it. Below it, a deletion node
// deletes only as often as growth nodes asked for holes the timestep before (tryCreate, tryDelete):
// the pairing of the paper's steady state, where each deletion lets one creation follow; without
// it, deletion outlives growth and the volume falls short by seven points a hole. Above it, a hole
// with a shepherd outside the target on the surface is deleted there as a deletion node would (the
// seven shepherds nearest the surface fill it) if the mass stays connected, and migration fills
// whatever target points that uncovers. (Deleting at surfaces inside the target as well churned:
// the emptied target points were refilled by creation elsewhere.) The count of live holes is a sum
// over the mass, which an ensemble gathers along the spanning tree MassTree keeps.
void HoleSculptor::deleteSurplus() {
    std::vector<int> order;
    for (int id = 0; id < static_cast<int>(holesById_.size()); ++id)
        if (holesById_[id].alive) order.push_back(id);
    random_.shuffle(order);
    for (int id : order) {
        if (liveHoles_ <= holeBudget_) return;
        const std::int64_t c = holesById_[id].centre;
        int toward = -1;
        for (std::size_t j = 0; j < ring2_.size() && toward < 0; ++j)
            if (!(*target_)[c + ring2_[j]] && !shepherdsAnother(c + ring2_[j], id) && onSurface(c + ring2_[j])) toward = towardSurface(c, c + ring2_[j], 0);
        if (toward < 0) continue;
        const std::vector<std::int64_t> emptied = nearestTheSurface(id, toward);
        if (emptied.empty()) continue;
        const int shape = deletion(id, emptied);
        if (!tree_->change(emptied, {})) continue;
        remove(id, shape);
        ++counts_.surplusDeleted;
    }
}

// Choice: "the portion of the hole's shepherd group closest to the perimeter" is the 7 shepherds
// fewest hops from an empty cell that is not a hole cell, ties broken toward the deletion node;
// shepherds shared with a neighbouring hole stay (found by the invariant test in HexSculptTest).
// (Taking the half of the ring facing the node instead empties cells that may be walled in by
// modules beyond the ring; those bubbles become new surface inside the mass and, measured, turn
// deletion regions into a sponge.)
std::vector<std::int64_t> HoleSculptor::nearestTheSurface(int id, int toward) const {
    std::vector<std::pair<int, int>> rank;  // (hops to the outside, position in uppermost_[toward])
    const std::int64_t centre = holesById_[id].centre;
    const auto& order = uppermost_[toward];
    for (int j = 0; j < static_cast<int>(order.size()); ++j) {
        if (shepherdsAnother(centre + order[j], id)) continue;  // shared with a neighbouring hole: stays
        int hops = 4;
        for (std::size_t e = 0; e < disk3_.size(); ++e) {
            const std::int64_t i = centre + order[j] + disk3_[e];
            if (!filled(i)) hops = std::min(hops, distance3_[e]);
        }
        rank.emplace_back(hops, j);
    }
    if (rank.size() < 7) return {};
    std::stable_sort(rank.begin(), rank.end());
    std::vector<std::int64_t> out;
    for (int j = 0; j < 7; ++j) out.push_back(centre + order[rank[j].second]);
    return out;
}

// The lattice direction from a hole centre toward the deletion node; a node between two
// directions takes the one nearer to "up".
int HoleSculptor::towardSurface(std::int64_t centre, std::int64_t node, int up) const {
    const double dx = array_->x(node) - array_->x(centre), dy = array_->y(node) - array_->y(centre);
    int best = up;
    double bestDot = -1e9;
    for (int d = 0; d < 6; ++d) {
        const double angle = d * M_PI / 3;
        const double dot = dx * std::cos(angle) + dy * std::sin(angle) + (d == up ? 1e-6 : 0.0);
        if (dot > bestDot + 1e-9) bestDot = dot, best = d;
    }
    return best;
}

// §IV-F column collapse, as hex_collapse.holon's rules run by the compiled engine: the
// column head k looks at its neighbours at +120° and -60° from gravity; when the neighbouring
// column's head is two or three hops down, k moves on top of it, provided k's neighbours after the
// move are one arc (the rules' guards; shepherds never collapse, that would break a hole). Which
// rules may fire is orchestration: the improvements' rules only with their options.
void HoleSculptor::smooth(std::int64_t k, int gravity) {
    const BoxEngine& engine = rules_->collapseEngine();
    // holon's improvement (--roll): outside the target a column head also steps onto a neighbouring
    // column only one hop lower, and rolls down the slope at 60° from gravity, so that the thin
    // filaments deletion leaves behind drain towards the target instead of standing.
    const bool roll = options_.roll && !(*target_)[k];
    // With --migrate, migration alone moves the modules outside the target, and no collapse moves a
    // module out of it: collapse along gravity and migration along the surface would undo each
    // other's moves (measured: collapses emptied 42,000 target points in 5,000 timesteps of one run
    // at N = 200 and refilled 30,000, migration carrying the rest back).
    if (options_.migrate && !(*target_)[k]) return;
    for (int side : {0, 2, 5, 1}) {
        if ((side == 1 && !roll) || (side == 0 && !options_.dropOverhangs)) continue;  // --drop-overhangs: fall into a gap
        for (int hops = 1; hops <= 3; ++hops) {
            const int shape = rules_->collapse(side, hops, gravity);
            if (shape < 0 || (hops == 1 && (side == 2 || side == 5) && !roll) || !engine.matches(cells_.data(), k, shape)) continue;
            const std::int64_t to = k + engine.cellSteps(shape)[hops];
            if (options_.migrate && !(*target_)[to]) break;  // migration would only carry it back
            if (tree_ && !tree_->change({k}, {to})) {
                ++counts_.refusedSplits;
                break;  // the next side
            }
            apply(engine, k, shape);
            ++counts_.collapsed;
            return;
        }
    }
}

std::vector<std::int64_t> HoleSculptor::holeCentres() const {
    std::vector<std::int64_t> out;
    for (const Hole& h : holesById_)
        if (h.alive) out.push_back(h.centre);
    return out;
}

double HoleSculptor::completeness() const {
    const std::int64_t n = classSize_[2] + classSize_[3];
    return n ? static_cast<double>(classCorrect_[2] + classCorrect_[3]) / n : 1.0;
}
double HoleSculptor::stability() const {
    const std::int64_t n = classSize_[0] + classSize_[1];
    return n ? static_cast<double>(classCorrect_[0] + classCorrect_[1]) / n : 1.0;
}
double HoleSculptor::compliance() const {
    const std::int64_t n = classSize_[0] + classSize_[1] + classSize_[2] + classSize_[3];
    return static_cast<double>(classCorrect_[0] + classCorrect_[1] + classCorrect_[2] + classCorrect_[3]) / n;
}

std::int64_t HoleSculptor::islands() const {
    std::vector<std::int64_t> mods;  // per island
    rules::Flood flood;
    rules::components(
        flood, cells_.size(),
        [&](auto&& f) {
            for (std::int64_t s : array_->points())
                if (filled(s)) f(s);
        },
        rules::offsetEdges(
            6, [&](int d) { return array_->step(d); }, [&](std::int64_t m) { return filled(m); }),
        [&](std::int64_t c, int k) {
            if (k == static_cast<int>(mods.size())) mods.push_back(0);
            mods[k] += module(c);
        });
    const std::int64_t largest = mods.empty() ? 0 : *std::max_element(mods.begin(), mods.end());
    return modules_ - largest;
}

SculptResidue HoleSculptor::residue() const {
    SculptResidue r;
    // Empty points reachable from an empty point outside the target without crossing the mass.
    std::vector<std::int64_t> outsideEmpty;
    for (std::int64_t i : array_->points())
        if (!filled(i) && !(*target_)[i]) outsideEmpty.push_back(i);
    const std::vector<std::int32_t> open =
        hopsFrom(*array_, outsideEmpty, [&](std::int64_t n, std::int64_t) { return array_->inside(n) && !filled(n); });
    for (std::int64_t i : array_->points()) {
        const bool inTarget = (*target_)[i] != 0;
        if (module(i) && !inTarget) ++r.outside;
        if (holeCell(i) && !inTarget) ++r.holeCellsOutside;
        if (!filled(i) && inTarget) ++r.emptyInside, r.walledIn += open[i] < 0;
    }
    return r;
}

}  // namespace holon::planner::hex
