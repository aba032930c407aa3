// The demand stencil (planner/DemandProbe.h): the gradient and demand allocators ask a cell again
// whether a creation or deletion waits for it only when a cell changed within the stencil of that
// change. Checked here against asking every cell every round, on runs of every general system.

#include "PlannerSupport.h"

#include "planner/DemandProbe.h"

namespace holon::test {

TEST_CASE("demand stencil: every cell whose demand changes in a step lies in the stencil of a change in that step") {
    for (const char* stem : {"planner_general1", "planner_general2", "planner_general3", "planner_general_lock2"})
        for (int dimension : {2, 3}) {
            const std::string system = stem;
            CAPTURE(system);
            CAPTURE(dimension);
            PlannerSystem sys(stem, dimension);
            const std::string from = dimension == 3 ? "box:6x3x2" : "box:10x5", to = dimension == 3 ? "box:3x3x4" : "box:5x10";
            const planner::Problem p = planner::makeProblem(*sys.model, planner::parseShape(from), planner::parseShape(to), std::nullopt, 1);
            const planner::DemandProbe probe(p);
            const planner::DemandStencil stencil(p, probe);
            auto allocator = planner::makeAllocator("demand", p, 1);
            // One instance at a time: in a sync round other changes would cover a missed cell.
            planner::RunOptions options;
            options.scheduler = planner::Scheduler::Async;
            planner::Execution ex(p, *allocator, options);
            auto demands = [&] {
                std::vector<int> d(ex.cells().size(), 0);
                for (std::size_t i = 0; i < d.size(); ++i)
                    if (ex.cells()[i] && p.engine->combo(static_cast<std::int64_t>(i)) != planner::BoxEngine::kOutside)
                        d[i] = (probe.needsHeavier(ex, static_cast<std::int64_t>(i)) ? 1 : 0) | (probe.needsLighter(ex, static_cast<std::int64_t>(i)) ? 2 : 0);
                return d;
            };
            std::vector<planner::BoxEngine::Value> before = ex.cells();
            std::vector<int> demandBefore = demands();
            std::int64_t changedDemands = 0, missed = 0;
            std::size_t narrowest = SIZE_MAX, widest = 0;
            planner::RunObserver observer;
            observer.roundEnd = [&](const planner::RunStats&) {
                const std::vector<int> now = demands();
                std::vector<char> covered(now.size(), 0);
                for (std::size_t x = 0; x < before.size(); ++x) {
                    if (before[x] == ex.cells()[x]) continue;
                    const auto& steps = stencil.steps(before[x], ex.cells()[x]);
                    narrowest = std::min(narrowest, steps.size()), widest = std::max(widest, steps.size());
                    for (std::int64_t d : steps)
                        if (const std::int64_t i = static_cast<std::int64_t>(x) + d; i >= 0 && i < static_cast<std::int64_t>(covered.size())) covered[i] = 1;
                }
                for (std::size_t i = 0; i < now.size(); ++i)
                    if (now[i] != demandBefore[i]) ++changedDemands, missed += !covered[i];
                before = ex.cells(), demandBefore = now;
                return true;
            };
            CHECK(ex.run(observer).complete);
            CHECK(missed == 0);
            CHECK(changedDemands > 50);
            // The stencil depends on the change: a resource moving reads fewer sites than a cell appearing.
            CHECK(narrowest < widest);
        }
}

}  // namespace holon::test
