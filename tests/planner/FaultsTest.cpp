// Faults injected into plan runs (planner/Faults.h): after a random loss at a random round, with
// late and dropped messages, a run either goes on and the monitor never sees the ensemble
// disconnected (the judge let it go on only where the lemmas' hypotheses hold), or stops as
// "fault" with what the loss broke; delays and drops alone never keep a plan from its goal.

#include "PlannerSupport.h"

#include "planner/Faults.h"
#include "planner/Monitor.h"

namespace holon::test {

namespace {

struct FaultRun {
    planner::RunStats stats;
    std::string broken;
    bool monitorViolated = false;
    std::int64_t lost = 0;
};

FaultRun runWithFaults(const planner::Problem& problem, planner::Scheduler scheduler, std::uint64_t seed, const planner::FaultOptions& faultOptions) {
    auto allocator = planner::makeAllocator("random", problem, seed);
    planner::Faults faults(problem, faultOptions);
    planner::RunOptions options;
    options.scheduler = scheduler, options.seed = seed, options.budget = Budget::maxRounds(50000);
    const planner::Execution* running = nullptr;
    options.admit = [&](std::int64_t anchor, int shape) { return faults.admit(*running, anchor, shape); };
    planner::Execution ex(problem, *allocator, options);
    running = &ex;
    planner::Monitor monitor(problem, ex);
    FaultRun o;
    planner::RunObserver observer;
    observer.fired = [&](std::int64_t a, int s, const planner::BoxEngine::Value* old) {
        monitor.fired(a, s, old);
        faults.fired(ex, a, s, old);
    };
    observer.roundEnd = [&](const planner::RunStats& stats) {
        if (!monitor.roundEnd(stats)) return false;
        faults.roundEnd(ex, [&](std::int64_t cell, planner::BoxEngine::Value old) { monitor.lost(cell, old), ++o.lost; });
        return true;
    };
    o.stats = ex.run(observer);
    o.broken = faults.broken();
    if (o.broken.empty()) monitor.finish(o.stats);
    o.monitorViolated = monitor.violated();
    return o;
}

}  // namespace

TEST_CASE("after a loss a run goes on only where the planner cannot disconnect, and then completes") {
    int survived = 0, broken = 0;
    for (const char* rules : {"planner_intermediate", "planner_general1"})
        for (int dimension : {2, 3})
            for (std::uint64_t seed = 1; seed <= 10; ++seed) {
                const PlannerSystem system(rules, dimension);
                planner::Random random(seed);
                const planner::Vec box = dimension == 3 ? planner::Vec{5, 5, 5} : planner::Vec{12, 12, 1};
                const planner::Shape a = randomBlob(random, dimension, box, {0, 0, 0}, dimension == 3 ? 50 : 60);
                const planner::Shape b = randomBlob(random, dimension, box, {0, 0, 0}, dimension == 3 ? 50 : 60);
                const planner::Problem problem = planner::makeProblem(*system.model, a, b, planner::Vec{0, 0, 0}, seed);
                planner::FaultOptions faults;
                faults.seed = seed;
                faults.losses = {{static_cast<std::int64_t>(1 + random.below(6)), std::nullopt}, {static_cast<std::int64_t>(1 + random.below(12)), std::nullopt}};
                faults.delay = static_cast<std::int64_t>(random.below(3));
                faults.drop = seed % 2 ? 0.3 : 0;
                for (planner::Scheduler scheduler : {planner::Scheduler::Sync, planner::Scheduler::Async}) {
                    CAPTURE(rules);
                    CAPTURE(dimension);
                    CAPTURE(seed);
                    const FaultRun o = runWithFaults(problem, scheduler, seed, faults);
                    CAPTURE(stopReasonName(o.stats.stopped));
                    CAPTURE(o.broken);
                    CHECK_FALSE(o.monitorViolated);
                    if (o.broken.empty()) {
                        // The lemmas' hypotheses held after every loss: Safety and Progress apply.
                        CHECK(o.stats.complete);
                        survived += o.lost > 0;
                    } else {
                        CHECK(o.stats.stopped == StopReason::Fault);
                        ++broken;
                    }
                }
            }
    // Both outcomes occur, so neither check above is vacuous.
    CHECK(survived >= 10);
    CHECK(broken >= 10);
}

TEST_CASE("late and dropped messages hold instances back but every plan completes") {
    for (const char* rules : {"planner_intermediate", "planner_general2"})
        for (std::uint64_t seed = 1; seed <= 6; ++seed) {
            const PlannerSystem system(rules, 2);
            planner::Random random(seed);
            const planner::Shape a = randomBlob(random, 2, {10, 10, 1}, {0, 0, 0}, 40);
            const planner::Shape b = randomBlob(random, 2, {10, 10, 1}, {0, 0, 0}, 40);
            const planner::Problem problem = planner::makeProblem(*system.model, a, b, planner::Vec{0, 0, 0}, seed);
            planner::FaultOptions faults;
            faults.seed = seed, faults.delay = 4, faults.drop = 0.5;
            for (planner::Scheduler scheduler : {planner::Scheduler::Sync, planner::Scheduler::Async, planner::Scheduler::Adversarial}) {
                CAPTURE(rules);
                CAPTURE(seed);
                const FaultRun o = runWithFaults(problem, scheduler, seed, faults);
                CHECK(o.stats.complete);
                CHECK_FALSE(o.monitorViolated);
            }
        }
}

}  // namespace holon::test

namespace holon::test {

TEST_CASE("delays and drops longer than the no-progress window still end at the goal, not as no-progress") {
    // --delay 20000 and --drop 0.99999 on box:6x6 -> box:4x9 were stopped as no-progress (exit 1):
    // the window (1000 + 20 D^2 rounds) counted the rounds the fault model held everything back.
    const PlannerSystem system("planner_intermediate", 2);
    const planner::Problem problem = planner::makeProblem(*system.model, planner::parseShape("box:6x6"), planner::parseShape("box:4x9"), std::nullopt, 1);
    for (const auto& [delay, drop] : {std::pair<std::int64_t, double>{20000, 0}, {0, 0.9999}}) {
        planner::FaultOptions faults;
        faults.seed = 1, faults.delay = delay, faults.drop = drop;
        auto allocator = planner::makeAllocator("random", problem, 1);
        planner::Faults model(problem, faults);
        planner::RunOptions options;
        const planner::Execution* running = nullptr;
        options.admit = [&](std::int64_t anchor, int shape) { return model.admit(*running, anchor, shape); };
        planner::Execution ex(problem, *allocator, options);
        running = &ex;
        planner::RunObserver observer;
        observer.fired = [&](std::int64_t a, int s, const planner::BoxEngine::Value* old) { model.fired(ex, a, s, old); };
        const planner::RunStats stats = ex.run(observer);
        CAPTURE(delay);
        CAPTURE(drop);
        CHECK(stats.complete);
        CHECK(stats.rounds > 7000);  // beyond the window of 1000 + 20 * 15^2 rounds
    }
}

}  // namespace holon::test
