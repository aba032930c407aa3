// The connectivity test behind holon's connectivity-keeping hex moves (--keep-connected). Seed 003
// §V reports modules "abandoned during deletion" (its Fig. 6) and leaves keeping the mass whole to
// future work; the remedy comes from seed 000 §IV-A, whose planner deletes only a metamodule that no
// child hangs on. A change empties some cells and fills others. The cells that lose every parent
// are gathered in increasing potential: a cell is lost when none of its neighbours one hop nearer
// the root is left, and a lost cell's children (one hop farther) are examined in turn. Processing
// by increasing potential means a cell is judged only after every cell nearer the root, so a cell
// found supported really is. The lost cells are then re-seated from the rest of the mass by a
// shortest-path search that starts from their neighbours outside the lost set; one that cannot be
// reached was cut off (every cell of a cut-off piece has all its parents among the emptied or the
// lost cells), and the change is refused. So the answer is exact whenever the lost set fits the
// limit. The potential is the true hop count after rebuild() and an upper bound on it as changes
// are made; holon hex does not refresh it during a run.

#include "planner/hex/MassTree.h"

#include <limits>
#include <queue>
#include <stdexcept>

namespace holon::planner::hex {

namespace {

constexpr std::uint8_t kEmptied = 1, kFilledNow = 2, kLost = 4, kQueued = 8;
constexpr std::int32_t kUnreached = std::numeric_limits<std::int32_t>::max();

using Entry = std::pair<std::int32_t, std::int64_t>;  // (potential, cell), smallest first
using MinQueue = std::priority_queue<Entry, std::vector<Entry>, std::greater<>>;

}  // namespace

MassTree::MassTree(const HexArray& array, std::function<bool(std::int64_t)> filled)
    : array_(&array), filled_(std::move(filled)), d_(array.size(), -1), mark_(array.size(), 0) {}

void MassTree::rebuild(std::int64_t root) {
    root_ = root;
    if (!filled_(root)) throw std::logic_error("MassTree: the root is not filled");
    d_ = hopsFrom(*array_, {root}, [&](std::int64_t n, std::int64_t) { return filled_(n); });
    for (std::int64_t i : array_->points())
        if (filled_(i) && d_[i] < 0) throw std::logic_error("MassTree: the mass is not connected");
}

bool MassTree::filledAfter(std::int64_t i) const {
    if (mark_[i] & kFilledNow) return true;
    return !(mark_[i] & kEmptied) && filled_(i);
}

bool MassTree::change(const std::int64_t* emptied, int emptiedCount, const std::int64_t* filledNow, int filledCount) {
    std::vector<std::pair<std::int64_t, std::int32_t>> saved;  // (cell, potential before), to undo a refusal
    auto setD = [&](std::int64_t i, std::int32_t v) { saved.emplace_back(i, d_[i]), d_[i] = v; };
    auto mark = [&](std::int64_t i, std::uint8_t m) {
        if (!mark_[i]) touched_.push_back(i);
        mark_[i] |= m;
    };
    auto finish = [&](bool accepted) {
        if (!accepted)
            for (auto it = saved.rbegin(); it != saved.rend(); ++it) d_[it->first] = it->second;
        for (std::int64_t i : touched_) mark_[i] = 0;
        touched_.clear();
        return accepted;
    };

    for (int e = 0; e < emptiedCount; ++e) {
        if (emptied[e] == root_) return finish(false);
        mark(emptied[e], kEmptied);
    }
    for (int f = 0; f < filledCount; ++f) mark(filledNow[f], kFilledNow);
    // Newly filled cells take one more than their nearest filled neighbour; they may chain.
    for (bool progress = true; progress;) {
        progress = false;
        for (int f = 0; f < filledCount; ++f) {
            const std::int64_t c = filledNow[f];
            if (d_[c] >= 0) continue;
            std::int32_t best = kUnreached;
            for (int k = 0; k < 6; ++k) {
                const std::int64_t n = c + array_->step(k);
                if (d_[n] >= 0 && filledAfter(n)) best = std::min(best, d_[n] + 1);
            }
            if (best != kUnreached) setD(c, best), progress = true;
        }
    }
    for (int f = 0; f < filledCount; ++f)
        if (d_[filledNow[f]] < 0) return finish(false);  // filled apart from the mass

    // Gather the lost cells in increasing potential.
    MinQueue queue;
    auto enqueue = [&](std::int64_t c) {
        if ((mark_[c] & (kQueued | kLost)) || !filledAfter(c)) return;
        mark(c, kQueued);
        queue.emplace(d_[c], c);
    };
    for (int e = 0; e < emptiedCount; ++e)
        for (int k = 0; k < 6; ++k) enqueue(emptied[e] + array_->step(k));
    for (int f = 0; f < filledCount; ++f) enqueue(filledNow[f]);
    std::vector<std::int64_t> lost;
    while (!queue.empty()) {
        const std::int64_t c = queue.top().second;
        queue.pop();
        if (c == root_) continue;
        bool supported = false;
        for (int k = 0; k < 6 && !supported; ++k) {
            const std::int64_t n = c + array_->step(k);
            supported = d_[n] == d_[c] - 1 && !(mark_[n] & kLost) && filledAfter(n);
        }
        if (supported) continue;
        if (static_cast<int>(lost.size()) >= kReseatLimit) return finish(false);
        mark(c, kLost);
        lost.push_back(c);
        for (int k = 0; k < 6; ++k) {
            const std::int64_t n = c + array_->step(k);
            if (d_[n] == d_[c] + 1) enqueue(n);
        }
    }

    // Re-seat the lost cells: shortest paths from their neighbours that kept their parents.
    for (std::int64_t c : lost) setD(c, kUnreached);
    for (std::int64_t c : lost)
        for (int k = 0; k < 6; ++k) {
            const std::int64_t n = c + array_->step(k);
            if (!(mark_[n] & kLost) && d_[n] >= 0 && d_[n] != kUnreached && filledAfter(n) && d_[n] + 1 < d_[c]) d_[c] = d_[n] + 1;
        }
    for (std::int64_t c : lost)
        if (d_[c] != kUnreached) queue.emplace(d_[c], c);
    while (!queue.empty()) {
        const auto [dist, c] = queue.top();
        queue.pop();
        if (dist != d_[c]) continue;
        for (int k = 0; k < 6; ++k) {
            const std::int64_t n = c + array_->step(k);
            if ((mark_[n] & kLost) && dist + 1 < d_[n]) d_[n] = dist + 1, queue.emplace(dist + 1, n);
        }
    }
    for (std::int64_t c : lost)
        if (d_[c] == kUnreached) return finish(false);  // cut off from the root
    for (int e = 0; e < emptiedCount; ++e) setD(emptied[e], -1);
    return finish(true);
}

}  // namespace holon::planner::hex
