// The optimal allocator: offline transport (seed 000 §IV-B leaves the allocator open; this is the
// min-cost-flow one). It solves the transport problem of Transport.cpp from the start and fires a
// transfer only along an arc where the optimal flow still has tokens to move, so a plan that
// follows the flow to its end pays exactly the lower bound. The flow ignores timing and which
// neighbour a deletion hands its tokens to, and it cannot say that a destroyer needs a D beside
// it; so the flow is solved again from the current configuration (optimal for what remains) every
// so many motions and whenever a round fires nothing, and when even the fresh flow moves nothing
// the gradient allocator (which falls back to the randomizer in turn) moves resources until the
// next motion. It is centralised: the comparison shows what the distributed gradient allocator
// leaves on the table (little on general1, a third or more for n >= 2).

#include "planner/Allocator.h"
#include "planner/Execution.h"
#include "planner/Transport.h"

namespace holon::planner {

std::unique_ptr<Allocator> optimalAllocator(const Problem& problem, std::uint64_t seed);
std::unique_ptr<Allocator> gradientAllocator(const Problem& problem, std::uint64_t seed);

namespace {

// The flow is solved again after every 1/kSolves of the plan's motions: creations and deletions
// hand tokens to whichever neighbour their rule picks, so the flow drifts. Solving after every
// motion gave no fewer transfers on the block experiments (1.31x vs 1.32x of the bound at 2304
// metamodules) at four times the time.
constexpr std::int64_t kSolves = 32;

class OptimalAllocator final : public Allocator {
public:
    OptimalAllocator(const Problem& problem, std::uint64_t seed)
        : problem_(&problem), degree_(problem.board->lattice().degree()), fallback_(gradientAllocator(problem, seed)),
          resolveEvery_(std::max<std::int64_t>(1, (problem.toCreate + problem.toDelete) / kSolves)) {
        if (std::optional<TransportPlan> plan = planTransport(problem, problem.cells)) flow_ = std::move(plan->flow);
    }
    std::string name() const override { return "optimal"; }

    bool update(const Execution& ex) override {
        const bool fieldsMoved = fallback_->update(ex);
        const RunStats& st = ex.stats();
        // No step since the previous update: true on the Execution's retry after an empty round and
        // again on the next round's update, so a stall both hands over to the gradient and solves
        // the flow once more (told only of the retry, optimal took 40x the rounds on general2).
        const bool stalled = st.steps == stepsAtUpdate_;
        const std::int64_t motions = st.creations + st.deletions;
        stepsAtUpdate_ = st.steps;
        if (motions != motionsAtSolve_) falling_ = false;
        if (!stalled && motions - motionsAtSolve_ < resolveEvery_) return fieldsMoved;
        motionsAtSolve_ = motions;
        std::optional<TransportPlan> plan = planTransport(*problem_, ex.cells());
        if (plan && plan->flow != flow_) {
            flow_ = std::move(plan->flow);
            return true;
        }
        if (stalled && !falling_) {
            falling_ = true;
            return true;
        }
        return fieldsMoved;
    }

    bool wants(const Execution& ex, std::int64_t anchor, int shape) const override {
        const std::int64_t key = arcKey(ex, anchor, shape);
        if (key >= 0 && flow_.count(key)) return true;
        return falling_ && fallback_->wants(ex, anchor, shape);
    }

    void firing(const Execution& ex, std::int64_t anchor, int shape) override {
        const auto it = flow_.find(arcKey(ex, anchor, shape));
        if (it != flow_.end() && --it->second == 0) flow_.erase(it);
    }

private:
    /// The flow key of the arc a token takes in this enabled transfer.
    std::int64_t arcKey(const Execution& ex, std::int64_t anchor, int shape) const {
        const auto [from, to] = transferEnds(ex, anchor, shape);
        if (from < 0) return -1;
        for (int d = 0; d < degree_; ++d)
            if (from + problem_->board->step(d) == to) return from * degree_ + d;
        return -1;
    }

    const Problem* problem_;
    int degree_;
    std::unordered_map<std::int64_t, std::int32_t> flow_;
    std::unique_ptr<Allocator> fallback_;
    /// The flow stalled: until the next motion the gradient allocator's transfers fire too (and,
    /// when it stalls in turn, any transfer).
    bool falling_ = false;
    std::int64_t stepsAtUpdate_ = -1, motionsAtSolve_ = 0;
    std::int64_t resolveEvery_;
};

}  // namespace

std::unique_ptr<Allocator> optimalAllocator(const Problem& problem, std::uint64_t seed) { return std::make_unique<OptimalAllocator>(problem, seed); }

}  // namespace holon::planner
