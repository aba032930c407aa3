// The demand allocator: a distributed resource manager for general_n that also knows where
// surplus resources may rest. Seed 000 §IV-B asks to send "the D to regions of anticipated
// deletion and the C to regions of anticipated creation"; when the start is heavier than the
// target, most C's that deletions make are wanted by no creation at all, and the transport bound
// (Transport.cpp) rests them in target metamodules, at most one per metamodule. The gradient
// allocator has no such place to send them: they wandered away from destroyers, often deeper into
// the region to delete, and those runs paid up to 380 times the bound.
//
// Every metamodule knows whether it lies in the target (seed 000 §IV-A) and learns from its own
// cells whether it is a demand (DemandProbe). Three values diffuse between lattice neighbours:
//   needC  hop count to a creation that waits for a C, each creation claiming the kClaims C's
//          nearest to it that no nearer creation claimed (a greedy matching of supply to demand:
//          with every C drawn to every creation, most of them chased creations others served);
//   sink   hop count to a place a C may go: a creation, or a final metamodule holding a D (never
//          a P one: it may yet be deleted, and the C swapped back and forth with its neighbour);
//   route  each unclaimed C that must leave (it lies outside the target, or a deletion waits for
//          it to be a D) is matched to the nearest final D no nearer such C took; every cell on
//          the path between them learns the next cell towards that D (under `eager`, below, a
//          drawn C is not unclaimed: it already moves towards a creation).
// A claimed C moves down needC. Otherwise a C outside the target moves down `sink`, and one inside
// it rests unless it lies on a route: then it steps along the route within the target, and the D
// comes back towards the C that must leave, one C of the queue between them at a time. (Marking
// the C's on a path without matching moved one D at a time along each queue; with the match, each
// C that must leave brings its own D, and they travel together: 2D rounds p90 19.2 -> 16.2.)
// Messages are cheap beside motions, so the fields are exchanged until they settle each round
// (a breadth-first search computes that fixpoint); rounds count motions only.
// When nothing fires and the fields have settled, the paper's randomizer moves resources until
// the next creation or deletion, as in the gradient allocator.
//
// The `eager` allocator is the same with a fourth value. A creation that has its C's stops its
// claim search, and the cells it reached stop the others', so the C's behind the nearest
// creations' regions are claimed by nobody and rest: on the block at K = 16, at round 500, 1,990
// of 2,389 creations had claimed no C, and by round 1,000 11,000 C's rested in the target while
// 1,729 creations waited (docs/allocators.md). `draw` is the hop count to the nearest creation
// whose claims are not met, through every metamodule; an unclaimed C moves down it. Rounds at
// K = 8, 16, 31: 445, 2,319, 28,261 -> 434, 1,280, 5,612; transfers 1.27, 1.24, 1.23 -> 1.33,
// 1.33, 1.35 times the bound. On the shape bench's problems of about 300 metamodules it also
// draws C's no creation needs: 2D transfers median / p90 / worst 1.54 / 5.95 / 12.9 -> 1.69 /
// 6.95 / 18.3 times the bound, rounds 3.93 / 9.17 / 16.8 -> 3.75 / 7.36 / 14.1 times the
// intermediate planner's.

#include "planner/Allocator.h"
#include "planner/ChangedCells.h"
#include "planner/DeletionOrder.h"
#include "planner/DemandProbe.h"
#include "planner/Execution.h"
#include "planner/StallFallback.h"

#include <algorithm>
#include <array>

namespace holon::planner {

std::unique_ptr<Allocator> demandAllocator(const Problem& problem, std::uint64_t seed, bool eager);

namespace {

// How many C's a creation claims: fewer make fewer transfers and more rounds (shape bench,
// general1, 2D median/p90/worst transfers over the bound and rounds over the intermediate
// planner's: 4 claims 1.40/4.30/7.77 and 12.5/28.5/60.0; 8: 1.43/4.61/8.67 and 8.1/21.5/54.3; 16:
// 1.47/5.72/11.9 and 6.8/16.2/44.1; 32: 1.56/7.17/14.4 and 5.9/15.5/40.5; all: 1.68/9.71/14.4 and
// 5.5/14.8/37.0). 16 is the fewest at which every figure beats the gradient allocator's.
constexpr int kClaims = 16;

class DemandAllocator final : public Allocator {
public:
    DemandAllocator(const Problem& problem, std::uint64_t seed, bool eager) : problem_(&problem), eager_(eager), probe_(problem), order_(problem), stall_(seed) {
        const Board& board = *problem.board;
        inTarget_.assign(static_cast<std::size_t>(board.size()), 0);
        for (Vec v : problem.target.cells) inTarget_[board.index(v)] = 1;
        needC_.assign(problem.cells.size(), kUnreached), draw_.assign(eager ? problem.cells.size() : 0, kUnreached), sink_.assign(problem.cells.size(), kUnreached), claimed_.assign(problem.cells.size(), 0), route_.assign(problem.cells.size(), -1);
        seen_.assign(problem.cells.size(), 0), role_.assign(problem.cells.size(), 0), stale_.assign(problem.cells.size(), 0), onPath_.assign(problem.cells.size(), 0);
        owner_.assign(problem.cells.size(), -1), stamp_.assign(problem.cells.size(), 0), parent_.assign(problem.cells.size(), -1);
    }
    std::string name() const override { return eager_ ? "eager" : "demand"; }

    bool update(const Execution& ex) override {
        const auto& cells = ex.cells();
        // A cell's role reads only the cells of the motion instances around it: only those near a
        // change are asked again (asking every cell every round was a fifth of the run).
        const auto size = static_cast<std::int64_t>(cells.size());
        forEachChangedCell(cells, seen_, [&](std::int64_t x, BoxEngine::Value was) {
            for (std::int64_t d : stencil_.steps(was, cells[x]))
                if (const std::int64_t i = x + d; i >= 0 && i < size && !stale_[i]) stale_[i] = 1, staleList_.push_back(i);
        });
        // Each half of the list writes only its own cells' roles.
        const std::size_t stale = staleList_.size();
        ex.together([&](int t) {
            for (std::size_t k = t == 0 ? 0 : stale / 2, end = t == 0 ? stale / 2 : stale; k < end; ++k) role_[staleList_[k]] = roleOf(ex, staleList_[k]), stale_[staleList_[k]] = 0;
        });
        staleList_.clear();
        std::vector<std::int64_t>&creations = creations_, &sinks = sinks_, &leaving = leaving_;
        creations.clear(), sinks.clear(), leaving.clear();
        for (std::size_t x = 0; x < cells.size(); ++x) {
            const char role = role_[x];
            if (!role) continue;
            const auto i = static_cast<std::int64_t>(x);
            if (role & kCreation) creations.push_back(i);
            if (role & kSink) sinks.push_back(i);
            if (role & kLeaving) leaving.push_back(i);
        }
        // The sink field and the deletion order read nothing the other searches write: on a large
        // board they run on a second thread (Execution::together).
        bool moved[2] = {false, false};
        ex.together([&](int t) {
            if (t == 1) {
                moved[1] = spread(cells, sinks, sink_, search_[1]);
                moved[1] = order_.update(ex) || moved[1];
                return;
            }
            moved[0] = claim(cells, creations);
            if (eager_) {
                hungry_.clear();
                for (std::size_t s = 0; s < creations.size(); ++s)
                    if (budget_[s] > 0) hungry_.push_back(creations[s]);
                moved[0] = spread(cells, hungry_, draw_, search_[0]) || moved[0];
            }
            moved[0] = route(cells, leaving) || moved[0];
        });
        return stall_.update(ex, moved[0] || moved[1]);
    }

    bool releases(const Execution& ex, std::int64_t anchor, int shape) const override { return stall_.active() || order_.releases(ex, anchor, shape); }

    bool wants(const Execution& ex, std::int64_t anchor, int shape) const override {
        if (stall_.active()) return stall_.wants(ex, anchor, shape);
        const auto [from, to] = transferEnds(ex, anchor, shape);  // `from` holds the C
        if (from < 0) return false;
        // An unclaimed C that draw_ reaches is drawn: from and to are neighbours through which the
        // search passes, so draw_[from] is unreached only when draw_[to] is.
        const bool drawn = claimed_[from] ? needC_[to] < needC_[from] : eager_ && draw_[to] < draw_[from];
        if (!inTarget_[from]) return drawn || sink_[to] < sink_[from];
        if (drawn) return true;
        // A C on a route makes room in the target; back in the region to delete it would only have
        // to leave again (and swapped back and forth with the C it made room for).
        return route_[from] == to && inTarget_[to];
    }

private:
    // role_ bits: a creation waits for this cell to be heavier; a C may come to rest here; the C
    // here must leave (it lies outside the target, or a deletion waits for it to be a D).
    static constexpr char kCreation = 1, kSink = 2, kLeaving = 4;
    char roleOf(const Execution& ex, std::int64_t i) const {
        const BoxEngine::Value v = ex.cells()[i];
        if (!v) return 0;
        char role = 0;
        if (probe_.needsHeavier(ex, i)) role |= kCreation | kSink;
        else if (probe_.final(v) && probe_.light(v)) role |= kSink;
        if (probe_.heavy(v) && (!inTarget_[i] || probe_.needsLighter(ex, i))) role |= kLeaving;
        return role;
    }

    /// A breadth-first search's own buffers: the field being computed and the queue.
    struct Search {
        std::vector<std::uint32_t> next;
        std::vector<std::uint32_t> queue;  // cell indices: a board has at most 2^31 cells (Board.h)
    };

    /// Hop counts through occupied cells from `sources` into `field`; whether any changed.
    bool spread(const std::vector<BoxEngine::Value>& cells, const std::vector<std::int64_t>& sources, std::vector<std::uint32_t>& field, Search& search) {
        std::vector<std::uint32_t>& next = search.next;
        next.assign(cells.size(), kUnreached);
        search.queue.clear();
        for (std::int64_t i : sources) next[i] = 0, search.queue.push_back(static_cast<std::uint32_t>(i));
        forEachReached(cells, search.queue, [&](std::int64_t i, std::int64_t j) {
            if (next[j] != kUnreached) return false;
            next[j] = next[i] + 1;
            return true;
        });
        const bool changed = next != field;
        field.swap(next);
        return changed;
    }

    /// Hop counts from the creations into needC_, each creation claiming the kClaims C's nearest
    /// to it that no nearer creation claimed; a creation that has its C's stops the search.
    bool claim(const std::vector<BoxEngine::Value>& cells, const std::vector<std::int64_t>& creations) {
        std::vector<std::uint32_t>& next = search_[0].next;
        std::vector<std::uint32_t>& queue = search_[0].queue;
        next.assign(cells.size(), kUnreached);
        std::vector<char>& claimed = nextClaimed_;
        claimed.assign(cells.size(), 0);
        std::vector<int>& budget = budget_;
        budget.assign(creations.size(), kClaims);
        queue.clear();
        for (std::size_t s = 0; s < creations.size(); ++s) next[creations[s]] = 0, owner_[creations[s]] = static_cast<std::int32_t>(s), queue.push_back(static_cast<std::uint32_t>(creations[s]));
        forEachReached(cells, queue, [&](std::int64_t i, std::int64_t j) {
            const std::int32_t s = owner_[i];
            if (next[j] != kUnreached || budget[s] == 0) return false;
            next[j] = next[i] + 1, owner_[j] = s;
            if (probe_.heavy(cells[j])) claimed[j] = 1, --budget[s];
            return true;
        });
        bool changed = next != needC_ || claimed != claimed_;
        needC_.swap(next), claimed_.swap(claimed);
        return changed;
    }

    /// Matches each C that must leave to the nearest final D no nearer one took and marks, on
    /// every cell of the path between them, the next cell towards the D (route_).
    bool route(const std::vector<BoxEngine::Value>& cells, const std::vector<std::int64_t>& leaving) {
        // Few cells take part (the searches end at the nearest final D's), so the search marks the
        // cells it reached with a stamp and route_ is changed where the paths are: clearing and
        // comparing board-sized arrays was most of its time (block at K = 16: 0.51 -> 0.014 s).
        if (++epoch_ == 0) std::fill(stamp_.begin(), stamp_.end(), 0), epoch_ = 1;
        done_.assign(leaving.size(), 0);
        std::vector<std::uint32_t>& queue = search_[0].queue;
        paths_.clear(), queue.clear();
        for (std::size_t s = 0; s < leaving.size(); ++s)
            if (!claimed_[leaving[s]] && !(eager_ && draw_[leaving[s]] != kUnreached))
                parent_[leaving[s]] = -1, owner_[leaving[s]] = static_cast<std::int32_t>(s), stamp_[leaving[s]] = epoch_, queue.push_back(static_cast<std::uint32_t>(leaving[s]));
        forEachReached(cells, queue, [&](std::int64_t i, std::int64_t j) {
            const std::int32_t s = owner_[i];
            if (stamp_[j] == epoch_ || done_[s]) return false;
            parent_[j] = i, owner_[j] = s, stamp_[j] = epoch_;
            if (!probe_.final(cells[j]) || !probe_.light(cells[j])) return true;
            // The D is taken: no other C's path ends there, and this search goes no further.
            done_[s] = 1;
            for (std::int64_t k = j; parent_[k] >= 0; k = parent_[k]) paths_.push_back({parent_[k], k});
            return false;
        });
        // Every cell has one owner, so the paths of different C's share no cell.
        bool changed = false;
        for (const auto& [cell, next] : paths_) onPath_[cell] = 1;
        for (std::int64_t i : routeCells_)
            if (!onPath_[i]) route_[i] = -1, changed = true;
        routeCells_.clear();
        for (const auto& [cell, next] : paths_) changed |= route_[cell] != next, route_[cell] = next, onPath_[cell] = 0, routeCells_.push_back(cell);
        return changed;
    }

    /// Breadth-first from `queue`: offers every occupied neighbour j of a queued cell i to
    /// `enter(i, j)`, which queues j by returning true.
    template <class F>
    void forEachReached(const std::vector<BoxEngine::Value>& cells, std::vector<std::uint32_t>& queue, F&& enter) const {
        const Board& board = *problem_->board;
        const int degree = board.lattice().degree();
        std::array<std::int64_t, 12> steps{};
        for (int d = 0; d < degree; ++d) steps[d] = board.step(d);
        const BoxEngine::Value* const at = cells.data();
        for (std::size_t k = 0; k < queue.size(); ++k) {
            const std::int64_t i = queue[k];
            for (int d = 0; d < degree; ++d)
                if (const std::int64_t j = i + steps[d]; at[j] && enter(i, j)) queue.push_back(static_cast<std::uint32_t>(j));
        }
    }

    const Problem* problem_;
    const bool eager_;
    DemandProbe probe_;
    DeletionOrder order_;
    DemandStencil stencil_{*problem_, probe_};
    std::vector<std::int64_t> staleList_;
    std::vector<BoxEngine::Value> seen_;  // the cells as of the previous update
    std::vector<char> inTarget_, claimed_, role_, stale_;
    std::vector<std::int32_t> owner_;
    std::vector<std::int64_t> route_;
    // Buffers each round refills: allocated once, since a board-sized vector freed every round
    // comes back as fresh pages the kernel must fault in and zero.
    std::vector<std::int64_t> creations_, sinks_, leaving_, hungry_;
    std::vector<char> nextClaimed_, done_;
    // The route search's own state: a cell's parent and owner are valid where its stamp is the
    // search's epoch; the cells where route_ is set, and paths_ being laid.
    std::vector<std::uint32_t> stamp_;
    std::uint32_t epoch_ = 0;
    std::vector<std::int64_t> parent_, routeCells_;
    std::vector<char> onPath_;
    std::vector<std::pair<std::int64_t, std::int64_t>> paths_;
    std::vector<int> budget_;
    std::vector<std::uint32_t> needC_, draw_, sink_;
    Search search_[2];  // [0]: the claim, draw and route searches; [1]: the sink field's, beside them
    StallFallback stall_;
};

}  // namespace

std::unique_ptr<Allocator> demandAllocator(const Problem& problem, std::uint64_t seed, bool eager) { return std::make_unique<DemandAllocator>(problem, seed, eager); }

}  // namespace holon::planner
