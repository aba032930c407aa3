// A synchronous round's independent work on two threads (planner/Execution.cpp: recheckAround's
// halves; planner/DemandAllocator.cpp: the sink field and the deletion order beside the claim,
// draw and route searches) gives the plan one thread gives: the same instances in the same order,
// round by round.

#include "PlannerSupport.h"

#include <vector>

namespace holon::test {

TEST_CASE("two threads make the plan one thread makes, firing by firing") {
    // The block at K = 12 lies on a board of over 2^17 cells, where the second thread starts.
    PlannerSystem sys("planner_general1", 3);
    const planner::Problem p = planner::makeProblem(*sys.model, planner::parseShape("box:6x3x2", 12), planner::parseShape("box:3x3x4", 12), std::nullopt, 1);
    for (const char* name : {"demand", "eager"}) {
        std::vector<std::uint64_t> fired[2];
        planner::RunStats stats[2];
        int threads[2] = {0, 0};
        for (int run = 0; run < 2; ++run) {
            auto allocator = planner::makeAllocator(name, p, 1);
            planner::RunOptions options;
            options.threads = run + 1;
            options.budget = Budget::maxRounds(150);
            planner::Execution ex(p, *allocator, options);
            planner::RunObserver observer;
            observer.fired = [&](std::int64_t anchor, int shape, const planner::BoxEngine::Value*) { fired[run].push_back(static_cast<std::uint64_t>(anchor) << 8 | static_cast<std::uint64_t>(shape)); };
            stats[run] = ex.run(observer);
            threads[run] = ex.threads();
        }
        INFO(name);
        CHECK(threads[0] == 1);
        CHECK(threads[1] == 2);
        CHECK(stats[0].rounds == 150);
        CHECK(stats[1].transfers > 10000);  // the allocator's searches, not only the relabelling wave
        CHECK(stats[0].evaluations == stats[1].evaluations);
        CHECK(fired[0] == fired[1]);
    }
}

}  // namespace holon::test
