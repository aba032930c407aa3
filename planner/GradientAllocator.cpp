// The gradient allocator: a distributed resource manager for general_n (seed 000 §IV-B asks for
// one that sends "the D to regions of anticipated deletion and the C to regions of anticipated
// creation"; §V blames the random one's slow diffusion for general_1's long deletion phase).
//
// Every metamodule learns, from its own cells only, whether it is a demand (DemandProbe: a creation
// or deletion instance it takes part in would fire if its resource were heavier or lighter). Demands seed two hop-count fields, relaxed by one message exchange between lattice
// neighbours per round (distance-vector routing, as in the hormone/gradient fields of the modular
// robotics literature). A transfer fires only when it moves the heavy resource down the "needs C"
// field or the light one down the "needs D" field, i.e. when it lowers their sum.

#include "planner/Allocator.h"
#include "planner/DemandProbe.h"
#include "planner/Execution.h"
#include "planner/StallFallback.h"

#include <algorithm>

namespace holon::planner {

std::unique_ptr<Allocator> gradientAllocator(const Problem& problem, std::uint64_t seed);

namespace {

constexpr std::uint32_t kFar = 1u << 30;

class GradientAllocator final : public Allocator {
public:
    GradientAllocator(const Problem& problem, std::uint64_t seed) : problem_(&problem), probe_(problem), stall_(seed) {
        needC_.assign(problem.cells.size(), kFar), needD_.assign(problem.cells.size(), kFar);
        occupied_ = static_cast<std::int64_t>(problem.start.cells.size());
    }
    std::string name() const override { return "gradient"; }

    bool update(const Execution& ex) override {
        const auto& cells = ex.cells();
        const Board& board = *problem_->board;
        const int degree = board.lattice().degree();
        // No path is longer than the ensemble: capping there stops a field cut off from every
        // demand from counting up to kFar one round at a time (distance-vector count-to-infinity).
        const std::uint32_t far = static_cast<std::uint32_t>(std::min<std::int64_t>(kFar, 2 * occupied_ + 2));
        std::vector<std::uint32_t> nextC(cells.size(), kFar), nextD(cells.size(), kFar);
        bool moved = false;
        occupied_ = 0;
        for (std::size_t x = 0; x < cells.size(); ++x) {
            if (!cells[x]) continue;
            ++occupied_;
            const auto i = static_cast<std::int64_t>(x);
            std::uint32_t bestC = kFar, bestD = kFar;
            for (int d = 0; d < degree; ++d) {
                const std::int64_t j = i + board.step(d);
                if (!cells[j]) continue;
                bestC = std::min(bestC, needC_[j]), bestD = std::min(bestD, needD_[j]);
            }
            nextC[x] = probe_.needsHeavier(ex, i) ? 0 : bestC + 1 >= far ? kFar : bestC + 1;
            nextD[x] = probe_.needsLighter(ex, i) ? 0 : bestD + 1 >= far ? kFar : bestD + 1;
            moved = moved || nextC[x] != needC_[x] || nextD[x] != needD_[x];
        }
        needC_.swap(nextC), needD_.swap(nextD);
        return stall_.update(ex, moved);
    }

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
        if (needC_[to] != kFar) return false;
        return needD_[from] < needD_[to];
    }

private:
    const Problem* problem_;
    DemandProbe probe_;
    std::vector<std::uint32_t> needC_, needD_;
    std::int64_t occupied_ = 0;
    StallFallback stall_;
};

}  // namespace

std::unique_ptr<Allocator> gradientAllocator(const Problem& problem, std::uint64_t seed) { return std::make_unique<GradientAllocator>(problem, seed); }

}  // namespace holon::planner
