// The metamodule design of DiskDesign.h and the search that finds its motion sequences. The pair
// of slots A (west) and B (east) is the whole world of the search: a move is allowed only if
// hex_pivot.holon enables it with every cell it reads inside the pair (the rule compiled on the
// pair alone, PivotRules, so it never reads a neighbouring slot), the pair's disks are one connected
// set after it, and it leaves the rings alone outside the door.
// A sequence has three phases. The door's three disks on each side roll into their own pocket
// (not right beside the door, where a parked disk would rest on the next door disk). The unit
// moves: each disk by a shortest pivot path (breadth-first search with the disk lifted), leaving A
// nearest the door first and filling B in the reverse of an order in which B's new disks could
// leave through the open door one by one, so that every target is reachable when its turn comes.
// The doors close, B's first, from B's own parked disks or, when B was empty, from A through A's
// door; top down, since once its other cells are filled only the lowest door cell can still be
// entered from A. The payload is placed in whole orbits of the slot's symmetries (half turn,
// mirror q <-> r), so the layouts are the same seen from every side and one search serves all four
// directions. The smallest odd side (and, for it, the smallest free zone around the doors) for
// which every sequence is found is the design.

#include "planner/hex/DiskDesign.h"

#include "planner/hex/HexArray.h"
#include "planner/hex/PivotRules.h"
#include "rules/Components.h"
#include "rules/Error.h"

#include <algorithm>
#include <deque>
#include <functional>
#include <map>

namespace holon::planner::hex {

namespace {

/// The pair of slots as a small grid of disk cells, 2s wide and s high, A at q < s, on which
/// hex_pivot is compiled (shared by copies: a copy is a what-if of the disks only).
class Pair {
public:
    explicit Pair(const PivotRules& rules) : rules_(&rules), cells_(static_cast<std::size_t>(rules.board().size()), 0) {}
    bool inside(Vec v) const {
        const Vec e = rules_->board().extent();
        return v.x >= 0 && v.y >= 0 && v.x < e.x && v.y < e.y;
    }
    bool filled(Vec v) const { return inside(v) && cells_[index(v)]; }
    void set(Vec v, bool f) { cells_[index(v)] = f ? rules_->disk() : 0; }
    /// The pivot of a roll of a disk at `a` (there or not: the path search lifts it) to its
    /// neighbour in direction d, if hex_pivot enables one there.
    bool step(Vec a, int d, Vec& pivot) const {
        for (int side = 0; side < 2; ++side) {
            const PivotRules::Instance roll = rules_->roll(index(a), d, side);
            if (rules_->engine().matches(cells_.data(), roll.anchor, roll.shape, index(a), rules_->disk())) {
                pivot = a + hex().direction((d + (side ? 5 : 1)) % 6);
                return true;
            }
        }
        return false;
    }
    bool connected() const {
        const planner::Board& board = rules_->board();
        const auto disk = [&](std::int64_t i) { return filled(board.point(i)); };
        rules::Flood flood;
        return rules::connected(
            flood, cells_.size(),
            [&](auto&& f) {
                board.forEachInside([&](std::int64_t i, Vec) {
                    if (cells_[i]) f(i);
                });
            },
            rules::offsetEdges(
                6, [&](int d) { return board.step(d); }, disk));
    }
    /// A shortest pivot path for the disk at `from` (lifted) to the reachable cell with the least
    /// rank (ranks below 0 are not goals); empty if none.
    std::vector<PivotMove> path(Vec from, const std::function<int(Vec)>& rank) {
        set(from, false);
        std::map<std::pair<int, int>, std::pair<Vec, Vec>> parent;  // cell -> (previous, pivot)
        std::deque<Vec> queue{from};
        parent[{from.x, from.y}] = {from, from};
        Vec best{};
        int bestRank = -1;
        while (!queue.empty()) {
            const Vec c = queue.front();
            queue.pop_front();
            if (const int r = rank(c); r >= 0 && (bestRank < 0 || r < bestRank)) bestRank = r, best = c;
            for (int d = 0; d < 6; ++d) {
                Vec pivot;
                const Vec n = c + hex().direction(d);
                if (!step(c, d, pivot) || parent.count({n.x, n.y})) continue;
                parent[{n.x, n.y}] = {c, pivot};
                queue.push_back(n);
            }
        }
        set(from, true);
        std::vector<PivotMove> moves;
        if (bestRank < 0) return moves;
        for (Vec c = best; !(c == from);) {
            const auto& [previous, pivot] = parent.at({c.x, c.y});
            moves.push_back({previous, c, pivot});
            c = previous;
        }
        std::reverse(moves.begin(), moves.end());
        return moves;
    }
    void apply(const std::vector<PivotMove>& moves) {
        if (moves.empty()) return;
        set(moves.front().from, false), set(moves.back().to, true);
    }

private:
    static const rules::Lattice& hex() { return rules::Lattice::get(rules::LatticeKind::Hex2D); }
    std::size_t index(Vec v) const { return static_cast<std::size_t>(rules_->board().index(v)); }
    const PivotRules* rules_;
    std::vector<PivotRules::Value> cells_;
};

bool contains(const std::vector<Vec>& cells, Vec v) { return std::find(cells.begin(), cells.end(), v) != cells.end(); }

}  // namespace

DiskDesign::DiskDesign(int units) : units_(units) {
    if (units < 2) throw InputError("hex disks: a metamodule system needs at least two levels of mass (D and C)");
    for (int side = 9; side <= 41; side += 2)
        for (int doorZone = 3; doorZone <= 5; ++doorZone)
            if (build(side, doorZone)) return;
    throw InputError("hex disks: no motion sequences found for " + std::to_string(units) + " levels of mass with slots up to 41 disks wide");
}

bool DiskDesign::build(int s, int doorZone) {
    side_ = s, ringSize_ = 4 * s - 6;
    const int m = (s - 1) / 2;
    const std::vector<Vec> doorCentres{{s - 2, m, 0}, {1, m, 0}, {m, s - 2, 0}, {m, 1, 0}};  // inside each side's middle
    // Payload cells in whole symmetry orbits: layer by layer from the ring inward, each layer far
    // from the doors first; cells near a door stay free for the door's disks and the passage.
    std::vector<std::pair<std::pair<int, int>, Vec>> ranked;
    for (int j = 1; j < s - 1; ++j)
        for (int i = 1; i < s - 1; ++i) {
            const Vec c{i, j, 0};
            int door = 1 << 20;
            for (Vec d : doorCentres) door = std::min(door, hexDistance(c, d));
            if (door < doorZone) continue;
            const int layer = std::min({i, j, s - 1 - i, s - 1 - j});
            ranked.push_back({{layer, -door}, c});
        }
    std::stable_sort(ranked.begin(), ranked.end(), [](const auto& a, const auto& b) { return a.first < b.first; });
    const auto orbit = [&](Vec c) {
        std::vector<Vec> o;
        for (Vec v : {c, Vec{s - 1 - c.x, s - 1 - c.y, 0}, Vec{c.y, c.x, 0}, Vec{s - 1 - c.y, s - 1 - c.x, 0}})
            if (!contains(o, v)) o.push_back(v);
        return o;
    };
    std::vector<Vec> payload;
    const std::size_t needed = static_cast<std::size_t>(ringSize_) * (units_ - 1);
    for (std::size_t target = ringSize_; target <= needed; target += ringSize_)
        for (const auto& [rank, c] : ranked) {
            if (payload.size() == target) break;
            if (contains(payload, c)) continue;
            const std::vector<Vec> o = orbit(c);
            if (payload.size() + o.size() <= target) payload.insert(payload.end(), o.begin(), o.end());
        }
    if (payload.size() != needed) return false;
    // The ring: the border without its two acute corners, which touch no cell inside the slot
    // but two ring cells, so no move could fill them once those were placed; the ring stays a
    // cycle (the cells beside an acute corner are neighbours) and touches every neighbouring slot.
    const auto acute = [&](Vec c) { return (c.x == 0 && c.y == 0) || (c.x == s - 1 && c.y == s - 1); };
    std::vector<Vec> ring;
    for (int j = 0; j < s; ++j)
        for (int i = 0; i < s; ++i)
            if ((i == 0 || j == 0 || i == s - 1 || j == s - 1) && !acute(Vec{i, j, 0})) ring.push_back({i, j, 0});
    layouts_.assign(units_ + 1, {});
    for (int level = 1; level <= units_; ++level) {
        layouts_[level] = ring;
        layouts_[level].insert(layouts_[level].end(), payload.begin(), payload.begin() + (level - 1) * ringSize_);
    }

    base_.assign(units_, {});
    const PivotRules rules(Vec{0, 0, 0}, Vec{2 * s, s, 1});
    const Vec east{s, 0, 0};
    std::vector<Vec> doorA, doorB;
    for (int j = m - 1; j <= m + 1; ++j) doorA.push_back({s - 1, j, 0}), doorB.push_back({s, j, 0});
    for (int k = 0; k < units_; ++k) {
        Pair pair(rules);
        std::vector<Vec> goal, fixed;
        for (Vec c : layouts_[units_]) pair.set(c, true);
        for (Vec c : layouts_[k]) pair.set(c + east, true);
        for (Vec c : layouts_[units_ - 1]) goal.push_back(c);
        for (Vec c : layouts_[k + 1]) goal.push_back(c + east);
        for (Vec c : ring)
            if (!contains(doorA, c)) fixed.push_back(c);
        if (k >= 1)
            for (Vec c : ring)
                if (!contains(doorB, c + east)) fixed.push_back(c + east);
        std::vector<PivotMove>& out = base_[k];
        const auto commit = [&](const std::vector<PivotMove>& moves) {
            pair.apply(moves);
            out.insert(out.end(), moves.begin(), moves.end());
        };
        const auto inA = [&](Vec v) { return v.x < s; };
        const auto onRing = [&](Vec v) {
            const int i = v.x % s;
            return i == 0 || i == s - 1 || v.y == 0 || v.y == s - 1;
        };
        const Vec doorway{s, m, 0};
        const auto nearDoor = [&](Vec c) {
            for (const auto* cells : {&doorA, &doorB})
                for (Vec e : *cells)
                    if (hexDistance(c, e) < 2) return true;
            return false;
        };
        // Phase 1: the door's disks roll into their own pocket, onto free cells no goal needs.
        std::vector<Vec> parked;
        for (const auto* door : {&doorA, &doorB})
            for (Vec d : *door) {
                if (!pair.filled(d)) continue;
                const bool a = inA(d);
                pair.set(d, false);
                const bool cuts = !pair.connected();
                pair.set(d, true);
                if (cuts) return false;
                const auto moves = pair.path(d, [&](Vec c) { return inA(c) != a || onRing(c) || nearDoor(c) || contains(goal, c) ? -1 : hexDistance(c, d); });
                if (moves.empty()) return false;
                commit(moves);
                parked.push_back(moves.back().to);
            }
        // Phase 2: the unit of payload (or B's ring) moves across, door cells excepted.
        std::vector<Vec> sources, targets;
        for (Vec c : layouts_[units_])
            if (!contains(layouts_[units_ - 1], c)) sources.push_back(c);
        for (Vec c : layouts_[k + 1])
            if (!contains(layouts_[k], c) && !contains(doorB, c + east)) targets.push_back(c + east);
        std::stable_sort(sources.begin(), sources.end(), [&](Vec a, Vec b) { return hexDistance(a, doorway) < hexDistance(b, doorway); });
        const auto moveOne = [&](std::vector<Vec>& from, const std::function<int(Vec)>& rank) {
            for (std::size_t i = 0; i < from.size(); ++i) {
                pair.set(from[i], false);
                const bool cuts = !pair.connected();
                pair.set(from[i], true);
                if (cuts || contains(fixed, from[i])) continue;
                const auto moves = pair.path(from[i], rank);
                if (moves.empty()) continue;
                commit(moves);
                from.erase(from.begin() + static_cast<std::ptrdiff_t>(i));
                return moves.back().to;
            }
            return Vec{-1, -1, 0};
        };
        // B fills in the reverse of an order in which its new disks could leave through the open
        // door one by one, the rest staying connected: each target is then reachable when filled.
        std::vector<Vec> fill;
        {
            Pair peeled = pair;
            for (Vec t : targets) peeled.set(t, true);
            std::vector<Vec> left = targets;
            std::stable_sort(left.begin(), left.end(), [&](Vec a, Vec b) { return hexDistance(a, doorway) < hexDistance(b, doorway); });
            while (!left.empty()) {
                bool peeledOne = false;
                for (std::size_t i = 0; i < left.size() && !peeledOne; ++i) {
                    peeled.set(left[i], false);
                    const bool cuts = !peeled.connected();
                    peeled.set(left[i], true);
                    if (cuts || peeled.path(left[i], [&](Vec c) { return contains(doorA, c) ? 0 : -1; }).empty()) continue;
                    peeled.set(left[i], false);
                    fill.push_back(left[i]);
                    left.erase(left.begin() + static_cast<std::ptrdiff_t>(i));
                    peeledOne = true;
                }
                if (!peeledOne) return false;
            }
            std::reverse(fill.begin(), fill.end());
        }
        for (Vec t : fill)
            if (moveOne(sources, [&](Vec c) { return c == t ? 0 : -1; }).x < 0) return false;
        // Phase 3: the parked disks and what is left of the unit close the doors, B's first: from
        // B's own side when it parked disks, else from A through A's door, still open. Top down:
        // once the others are filled only the lowest door cell can still be entered from A.
        std::vector<Vec> rest = parked;
        rest.insert(rest.end(), sources.begin(), sources.end());
        std::stable_partition(rest.begin(), rest.end(), [&](Vec c) { return !inA(c); });
        for (const auto* door : {&doorB, &doorA})
            for (;;) {
                std::vector<Vec> gaps;
                for (Vec d : *door)
                    if (contains(goal, d) && !pair.filled(d)) gaps.push_back(d);
                if (gaps.empty()) break;
                if (moveOne(rest, [&](Vec c) { return contains(gaps, c) ? s - c.y : -1; }).x < 0) return false;
            }
        for (Vec c : goal)
            if (!pair.filled(c)) return false;
    }
    return true;
}

std::vector<PivotMove> DiskDesign::sequence(int a0, int b0, int a1, int b1, bool alongY, Vec origin, bool& ok) const {
    ok = true;
    const int s = side_;
    // The base sequences give from A (level units -> units - 1) to B (k -> k + 1). The half turn
    // about the pair's centre swaps the roles; reversal runs a sequence backwards.
    const std::vector<PivotMove>* base = nullptr;
    bool turn = false, backwards = false;
    if (a1 == a0 - 1 && b1 == b0 + 1) {  // A gives
        if (a0 == units_) base = &base_[b0];
        else if (b1 == units_) base = &base_[a1], turn = true, backwards = true;  // B gave, run back
    } else if (a1 == a0 + 1 && b1 == b0 - 1) {                                    // B gives
        if (b0 == units_) base = &base_[a0], turn = true;
        else if (a1 == units_) base = &base_[b1], backwards = true;
    }
    if (!base) {
        ok = false;
        return {};
    }
    const auto place = [&](Vec v) {
        if (turn) v = Vec{2 * s - 1 - v.x, s - 1 - v.y, 0};
        if (alongY) v = Vec{v.y, v.x, 0};
        return v + origin;
    };
    std::vector<PivotMove> out;
    out.reserve(base->size());
    for (const PivotMove& m : *base) out.push_back({place(m.from), place(m.to), place(m.pivot)});
    if (backwards) {
        std::reverse(out.begin(), out.end());
        for (PivotMove& m : out) std::swap(m.from, m.to);
    }
    return out;
}

}  // namespace holon::planner::hex
