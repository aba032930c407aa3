// The gradient allocator: a distributed resource manager for general_n (seed 000 §IV-B asks for
// one that sends "the D to regions of anticipated deletion and the C to regions of anticipated
// creation"; §V blames the random one's slow diffusion for general_1's long deletion phase).
//
// Every metamodule learns, from its own cells only, whether it is a demand (DemandProbe: a creation
// or deletion instance it takes part in would fire if its resource were heavier or lighter).
// Demands seed two hop-count fields, relaxed by one message exchange between lattice neighbours
// per round, through the metamodules that can pass a resource on (distance-vector routing, as in
// the hormone/gradient fields of the modular robotics literature). A transfer fires only when it
// moves the heavy resource down the "needs C" field or the light one down the "needs D" field,
// i.e. when it lowers their sum.
// Which resource is heavy or light, and which rules create or delete, is read off the compiled
// rule tables: nothing here names a rule of a particular system.

#include "planner/Allocator.h"
#include "planner/ChangedCells.h"
#include "planner/DeletionOrder.h"
#include "planner/DemandProbe.h"
#include "planner/Execution.h"
#include "planner/StallFallback.h"

#include <algorithm>

namespace holon::planner {

std::unique_ptr<Allocator> gradientAllocator(const Problem& problem, std::uint64_t seed);

namespace {

class GradientAllocator final : public Allocator {
public:
    GradientAllocator(const Problem& problem, std::uint64_t seed) : problem_(&problem), probe_(problem), order_(problem), stencil_(problem, probe_), stall_(seed) {
        needC_.assign(problem.cells.size(), kUnreached), needD_.assign(problem.cells.size(), kUnreached);
        // The first round sees every cell change from empty.
        seen_.assign(problem.cells.size(), 0), mark_.assign(problem.cells.size(), 0), demand_.assign(problem.cells.size(), 0);
    }
    std::string name() const override { return "gradient"; }

    bool update(const Execution& ex) override {
        const auto& cells = ex.cells();
        const Board& board = *problem_->board;
        const int degree = board.lattice().degree();
        // Only the metamodules whose inputs changed recompute: a cell whose own neighbourhood and
        // whose neighbours' values are as they were would compute the value it holds. So a round
        // costs what changed in it, not the board (a full pass per round made 10^6 metamodules
        // take hours), and the fields evolve as if every metamodule recomputed (up to the cap
        // below, which a cell sees anew only when it recomputes).
        forEachChangedCell(cells, seen_, [&](std::int64_t x, BoxEngine::Value was) {
            // What a change at a cell can affect at once: the demand of every cell in a motion
            // instance that reads it, and the field values of its neighbours.
            occupied_ += (cells[x] != 0) - (was != 0);
            for (std::int64_t d : stencil_.steps(was, cells[x])) dirty(x + d, kDemand);
            for (int d = 0; d < degree; ++d) dirty(x + board.step(d), kValue);
        });
        // No path is longer than the ensemble: capping there stops a field cut off from every
        // demand from counting up to kUnreached one round at a time (distance-vector count-to-infinity).
        const std::uint32_t far = static_cast<std::uint32_t>(std::min<std::int64_t>(kUnreached, 2 * occupied_ + 2));
        updates_.clear();
        for (std::int64_t i : dirty_) {
            const BoxEngine::Value v = cells[i];
            if (mark_[i] & kDemand)
                demand_[i] = static_cast<char>((v && probe_.needsHeavier(ex, i) ? kNeedsC : 0) | (v && probe_.needsLighter(ex, i) ? kNeedsD : 0));
            mark_[i] = 0;
            std::uint32_t c = kUnreached, dd = kUnreached;
            // A field passes only through cells that can hand a resource on: a partial metamodule
            // (B1, B2) takes part in no transfer, so a C beside it is no nearer a creator on its
            // far side than the way around. Counted through the partial, that C sat in a false
            // minimum; under the lock rules only the locked creator can finish the partial, and
            // when the C was the last one the run waited for the randomizer to walk it there
            // (general-lock3, 2,304 metamodules: 26,000 of 30,410 rounds).
            if (v && probe_.carrier(ex, i)) {
                std::uint32_t bestC = kUnreached, bestD = kUnreached;
                for (int d = 0; d < degree; ++d) {
                    const std::int64_t j = i + board.step(d);
                    if (!cells[j]) continue;
                    bestC = std::min(bestC, needC_[j]), bestD = std::min(bestD, needD_[j]);
                }
                c = bestC + 1 >= far ? kUnreached : bestC + 1;
                dd = bestD + 1 >= far ? kUnreached : bestD + 1;
            }
            if (demand_[i] & kNeedsC) c = 0;
            if (demand_[i] & kNeedsD) dd = 0;
            if (c != needC_[i] || dd != needD_[i]) updates_.push_back({i, c, dd});
        }
        dirty_.clear();
        for (const Update& u : updates_) {
            needC_[u.cell] = u.c, needD_[u.cell] = u.d;
            for (int d = 0; d < degree; ++d) dirty(u.cell + board.step(d), kValue);
        }
        const bool deeper = order_.update(ex);
        return stall_.update(ex, !updates_.empty() || deeper);
    }

    bool releases(const Execution& ex, std::int64_t anchor, int shape) const override { return stall_.active() || order_.releases(ex, anchor, shape); }

    bool wants(const Execution& ex, std::int64_t anchor, int shape) const override {
        if (stall_.active()) return stall_.wants(ex, anchor, shape);
        // The cell that loses mass gives its heavy resource to the one that gains it.
        const auto [from, to] = transferEnds(ex, anchor, shape);
        if (from < 0) return false;
        // The heavy resource goes down the creators' field. The light one goes down the
        // destroyers' field only where no creation is in reach: a transfer that brings a D also
        // takes a C away, and sending C's off from where creations wait cost a quarter more
        // transfers on the block experiments (1.62x against 1.32x of the bound at 2304).
        if (needC_[to] != needC_[from]) return needC_[to] < needC_[from];
        if (needC_[to] != kUnreached) return false;
        return needD_[from] < needD_[to];
    }

private:
    const Problem* problem_;
    DemandProbe probe_;
    DeletionOrder order_;
    // mark_ bits: the cell is in dirty_ (its value is recomputed), its demand is recomputed too.
    static constexpr char kValue = 1, kDemand = 3;
    // demand_ bits: a creation or deletion waits for this cell to be heavier / lighter.
    static constexpr char kNeedsC = 1, kNeedsD = 2;
    void dirty(std::int64_t i, char how) {
        // The stencil reaches up to twice the board's padding from a cell at its edge.
        if (i < 0 || i >= static_cast<std::int64_t>(mark_.size()) || problem_->engine->combo(i) == BoxEngine::kOutside) return;
        if (!mark_[i]) dirty_.push_back(i);
        mark_[i] |= how;
    }
    struct Update {
        std::int64_t cell;
        std::uint32_t c, d;
    };
    std::vector<std::uint32_t> needC_, needD_;
    std::vector<BoxEngine::Value> seen_;  // the cells as of the previous update
    std::vector<char> mark_, demand_;
    DemandStencil stencil_;
    std::vector<std::int64_t> dirty_;
    std::vector<Update> updates_;
    std::int64_t occupied_ = 0;
    StallFallback stall_;
};

}  // namespace

std::unique_ptr<Allocator> gradientAllocator(const Problem& problem, std::uint64_t seed) { return std::make_unique<GradientAllocator>(problem, seed); }

}  // namespace holon::planner
