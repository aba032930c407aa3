// The field allocators' deletion order (planner/DeletionOrder.cpp): deletions start at the deepest
// P metamodules first, so the region to delete keeps its exits wide and rounds follow the diameter
// rather than the area (issue 28, docs/scale.md).

#include "PlannerSupport.h"

#include "planner/DeletionOrder.h"
#include "planner/Monitor.h"

namespace holon::test {

namespace {

/// The extents of the box around start and target, summed: the diameter the rounds are held to.
std::int64_t diameter(const planner::Problem& p) {
    const planner::Vec e = p.board->extent();
    return std::int64_t{e.x} + e.y + e.z;
}

}  // namespace

TEST_CASE("general1 with the gradient allocator: rounds within a fixed multiple of the diameter") {
    // Before the deletion order the region to delete eroded into a dendrite and its mass left
    // through single-lane trunks: box:60x60 -> box:30x120 took 2,039-2,284 rounds (11.3-12.6 per
    // unit of diameter as computed here, seeds 1-3) and the block 6x3x2 -> 3x3x4 at scale 4 428-584
    // (8.2-11.2); with it, 1,350-1,595 (7.5-8.8) and 264-341 (5.1-6.6).
    struct Case {
        const char *from, *to;
        int dimension;
        std::int64_t perDiameter;
    };
    for (const Case& c : {Case{"box:60x60", "box:30x120", 2, 10}, Case{"box:24x12x8", "box:12x12x16", 3, 8}}) {
        PlannerSystem sys("planner_general1", c.dimension);
        const planner::Problem p = planner::makeProblem(*sys.model, planner::parseShape(c.from), planner::parseShape(c.to), std::nullopt, 1);
        for (std::uint64_t seed = 1; seed <= 2; ++seed) {
            auto allocator = planner::makeAllocator("gradient", p, seed);
            planner::RunOptions options;
            options.seed = seed;
            planner::Execution ex(p, *allocator, options);
            const planner::RunStats stats = ex.run();
            INFO(std::string(c.from) << " -> " << std::string(c.to) << ", seed " << seed << ": " << stats.rounds << " rounds, diameter " << diameter(p));
            CHECK(stats.complete);
            CHECK(stats.rounds <= c.perDiameter * diameter(p));
        }
    }
}

TEST_CASE("a deletion starts only at the far rim, and every scheduler completes") {
    // Nothing is held for ever: the adversarial scheduler fires only what the allocator releases,
    // and completes.
    // A DeletionOrder kept in step with the allocator's own (both update at the start of a round,
    // after the previous round's end) sees each deletion as it fires: no deleted metamodule knew of
    // a deeper one behind it. Without the order, 177 of the 288 deletions of this run did.
    PlannerSystem sys("planner_general1", 2);
    const planner::Problem p = planner::makeProblem(*sys.model, planner::parseShape("box:24x24"), planner::parseShape("box:12x48"), std::nullopt, 1);
    for (planner::Scheduler scheduler : {planner::Scheduler::Sync, planner::Scheduler::Async, planner::Scheduler::Adversarial}) {
        auto allocator = planner::makeAllocator("gradient", p, 1);
        planner::RunOptions options;
        options.scheduler = scheduler;
        planner::Execution ex(p, *allocator, options);
        planner::Monitor monitor(p, ex);
        planner::DeletionOrder order(p);
        order.update(ex);
        std::int64_t deletions = 0, behind = 0;
        planner::RunObserver observer;
        observer.fired = [&](std::int64_t anchor, int shape, const planner::BoxEngine::Value* old) {
            monitor.fired(anchor, shape, old);
            const auto steps = ex.engine().cellSteps(shape);
            for (std::size_t k = 0; k < steps.size(); ++k) {
                const std::int64_t i = anchor + steps[k];
                if (!old[k] || ex.cells()[i]) continue;
                ++deletions;
                behind += order.behind(i) > order.depth(i);
            }
        };
        observer.roundEnd = [&](const planner::RunStats& stats) {
            order.update(ex);
            return monitor.roundEnd(stats);
        };
        const planner::RunStats stats = ex.run(observer);
        INFO("scheduler " << static_cast<int>(scheduler));
        CHECK(stats.complete);
        CHECK_FALSE(monitor.violated());
        CHECK(deletions == stats.deletions);  // the observer saw every deletion
        // Async and adversarial runs update the allocator once per round of steps, not per step.
        if (scheduler == planner::Scheduler::Sync) CHECK(behind == 0);
    }
}

}  // namespace holon::test
