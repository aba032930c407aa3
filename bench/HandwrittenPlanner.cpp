// The hand-written planner (see HandwrittenPlanner.h): rules/library/planner_intermediate.holon
// written out by hand, rule for rule, under the planner's synchronous-round scheduler.

#include "HandwrittenPlanner.h"

#include <algorithm>
#include <bit>

namespace holon::bench {

namespace {
constexpr std::size_t kAhead = 8;
}  // namespace

HandwrittenPlanner::HandwrittenPlanner(const planner::Problem& problem, std::uint64_t randomSeed)
    : board_(problem.board->lattice(), problem.board->lower(), problem.board->extent(), 2), degree_(problem.board->lattice().degree()), random_(randomSeed) {
    for (int d = 0; d < degree_; ++d)
        for (int e = 0; e < degree_; ++e)
            if (board_.step(d) == -board_.step(e)) opposite_.push_back(e);
    const auto n = static_cast<std::size_t>(board_.size());
    cells_.assign(n, 0), bits_.assign(n, {}), marks_.assign(n, {}), stamp_.assign(n, 0);
    for (planner::Vec v : problem.target.cells) cells_[board_.index(v)] |= 1 << 5;
    for (planner::Vec v : problem.start.cells) cells_[board_.index(v)] |= U;
    const std::int64_t seed = board_.index(problem.seed);
    cells_[seed] = static_cast<std::uint8_t>((cells_[seed] & ~3) | F);
    for (std::int64_t i = 0; i < board_.size(); ++i) {
        offGoal_ += !atGoal(cells_[i]);
        if (kind(cells_[i]) != Empty) recheck(i);
    }
}

bool HandwrittenPlanner::enabled(std::int64_t a, int rule, int d) const {
    const std::uint8_t x = cells_[a];
    if (rule == Delete) {
        // P => _ if no nbr U and no nbr P&parent=@0
        if (kind(x) != P) return false;
        for (int e = 0; e < degree_; ++e) {
            const std::uint8_t y = cells_[a + board_.step(e)];
            if (kind(y) == U || (kind(y) == P && parent(y) == opposite_[e])) return false;
        }
        return true;
    }
    const std::uint8_t y = cells_[a + board_.step(d)];
    switch (rule) {
    case Finalize: return kind(x) == F && kind(y) == U && inTarget(y);      // F U&target => F F
    case PathFinalize: return kind(x) == F && kind(y) == P && inTarget(y);  // F P&target => F F
    case PathCreate: return kind(x) == F && kind(y) == U && !inTarget(y);   // F U&!target => F P&parent=@0
    case PathPropagate: return kind(x) == P && kind(y) == U;                // P U => P P&parent=@0
    case Create: return kind(x) == F && kind(y) == Empty && inTarget(y);    // F _&target => F F
    default: return false;
    }
}

void HandwrittenPlanner::recheck(std::int64_t a) {
    std::uint64_t now = 0;
    if (kind(cells_[a]) != Empty) {
        for (int rule = 0; rule < Delete; ++rule)
            for (int d = 0; d < degree_; ++d) now |= std::uint64_t{enabled(a, rule, d)} << (rule * 8 + d);
        now |= std::uint64_t{enabled(a, Delete, 0)} << (Delete * 8);
        evaluations_ += Delete * degree_ + 1;
    }
    bits_[a].enabled = now;
    std::uint64_t fresh = now & ~bits_[a].listed;
    bits_[a].listed |= fresh;
    while (fresh) {
        list_.push_back(static_cast<std::uint64_t>(a) * 64 + static_cast<std::uint64_t>(std::countr_zero(fresh)));
        fresh &= fresh - 1;
    }
}

bool HandwrittenPlanner::take(std::int64_t a, int rule, int d) {
    const auto round = static_cast<std::uint32_t>(rounds_);
    const std::int64_t written = rule == Delete ? a : a + board_.step(d);
    // Reads: the anchor and its neighbours for the deletion, the two cells otherwise.
    auto readsConflict = [&](std::int64_t c) { return marks_[c].write == round; };
    if (rule == Delete) {
        if (readsConflict(a)) return false;
        for (int e = 0; e < degree_; ++e)
            if (readsConflict(a + board_.step(e))) return false;
    } else if (readsConflict(a) || readsConflict(written)) {
        return false;
    }
    if (marks_[written].read == round) return false;
    marks_[a].read = round;
    if (rule == Delete)
        for (int e = 0; e < degree_; ++e) marks_[a + board_.step(e)].read = round;
    marks_[written].read = round;
    marks_[written].write = round;
    return true;
}

void HandwrittenPlanner::fire(std::int64_t a, int rule, int d) {
    const std::int64_t b = rule == Delete ? a : a + board_.step(d);
    const std::uint8_t before = cells_[b], targetBit = before & (1 << 5);
    std::uint8_t after = before;
    switch (rule) {
    case Finalize:
    case PathFinalize:
    case Create: after = targetBit | F; break;
    case PathCreate:
    case PathPropagate: after = static_cast<std::uint8_t>(targetBit | P | (opposite_[d] << 2)); break;
    case Delete: after = targetBit; break;
    default: break;
    }
    cells_[b] = after;
    offGoal_ += int(atGoal(before)) - int(atGoal(after));
    changed_.push_back(b);
    ++steps_;
}

bool HandwrittenPlanner::run() {
    std::vector<std::uint64_t> chosen;
    while (offGoal_ > 0) {
        ++rounds_;
        // Drop stale entries, then choose a maximal non-interfering set in random order.
        std::size_t out = 0;
        for (std::size_t k = 0; k < list_.size(); ++k) {
            if (k + kAhead < list_.size()) __builtin_prefetch(&bits_[list_[k + kAhead] / 64]);
            const std::uint64_t key = list_[k];
            const auto a = static_cast<std::int64_t>(key / 64);
            const std::uint64_t bit = std::uint64_t{1} << (key % 64);
            if (bits_[a].enabled & bit) list_[out++] = key;
            else bits_[a].listed &= ~bit;
        }
        list_.resize(out);
        random_.shuffle(list_);
        chosen.clear();
        for (std::size_t k = 0; k < list_.size(); ++k) {
            if (k + kAhead < list_.size()) __builtin_prefetch(&marks_[list_[k + kAhead] / 64]);
            const std::uint64_t key = list_[k];
            const auto a = static_cast<std::int64_t>(key / 64);
            const int rule = static_cast<int>(key % 64) / 8, d = static_cast<int>(key % 8);
            if (take(a, rule, d)) chosen.push_back(key);
        }
        if (chosen.empty()) return false;
        changed_.clear();
        for (std::size_t k = 0; k < chosen.size(); ++k) {
            if (k + kAhead < chosen.size()) __builtin_prefetch(&cells_[chosen[k + kAhead] / 64]);
            const std::uint64_t key = chosen[k];
            fire(static_cast<std::int64_t>(key / 64), static_cast<int>(key % 64) / 8, static_cast<int>(key % 8));
        }
        // Every rule reads its anchor and the anchor's neighbours only.
        if (++clock_ == 0) std::fill(stamp_.begin(), stamp_.end(), 0), clock_ = 1;
        anchors_.clear();
        for (std::int64_t c : changed_) {
            if (stamp_[c] != clock_) stamp_[c] = clock_, anchors_.push_back(c);
            for (int e = 0; e < degree_; ++e)
                if (const std::int64_t a = c + board_.step(e); stamp_[a] != clock_) stamp_[a] = clock_, anchors_.push_back(a);
        }
        for (std::size_t k = 0; k < anchors_.size(); ++k) {
            if (k + kAhead < anchors_.size()) __builtin_prefetch(&bits_[anchors_[k + kAhead]]), __builtin_prefetch(&cells_[anchors_[k + kAhead]]);
            recheck(anchors_[k]);
        }
    }
    return true;
}

std::int64_t HandwrittenPlanner::occupied() const {
    return std::count_if(cells_.begin(), cells_.end(), [](std::uint8_t c) { return kind(c) != Empty; });
}

}  // namespace holon::bench
