// The planner end to end: bad problems are refused with their fix, plans reach the target with
// the action counts the problem implies, runs are deterministic per seed, and the monitor holds.

#include "PlannerSupport.h"

#include "planner/Monitor.h"

#include <filesystem>
#include <fstream>
#include <map>

namespace holon::test {

namespace {
planner::RunStats plan(const planner::Problem& problem, planner::Scheduler scheduler, std::uint64_t seed, bool check = true,
                       const std::string& allocatorName = "random") {
    auto allocator = planner::makeAllocator(allocatorName, problem, seed);
    planner::RunOptions options;
    options.scheduler = scheduler, options.seed = seed, options.budget = Budget::maxRounds(200000);  // a regression fails, it does not hang
    planner::Execution ex(problem, *allocator, options);
    planner::Monitor monitor(problem, ex);
    planner::RunObserver observer;
    observer.fired = [&](std::int64_t a, int s, const planner::BoxEngine::Value* old) { monitor.fired(a, s, old); };
    if (check) observer.roundEnd = [&](const planner::RunStats& stats) { return monitor.roundEnd(stats); };
    planner::RunStats stats = ex.run(observer);
    CHECK_FALSE(monitor.violated());
    return stats;
}
}  // namespace

TEST_CASE("bad problems are refused with a message naming the fix") {
    PlannerSystem sys("planner_intermediate", 2), g1("planner_general1", 2);
    auto make = [&](const PlannerSystem& s, const std::string& a, const std::string& b) { return planner::makeProblem(*s.model, planner::parseShape(a), planner::parseShape(b), std::nullopt, 1); };
    const auto dir = std::filesystem::temp_directory_path() / "holon_planner_test";
    std::filesystem::create_directories(dir);
    std::ofstream(dir / "split.txt") << "#.#\n###\n#.#\n..#\n#..\n";
    CHECK_THROWS_WITH_AS(make(sys, "box:3x3", (dir / "split.txt").string()), doctest::Contains("is not connected"), InputError);
    std::ofstream(dir / "far.json") << "[[10,10],[11,10]]";
    CHECK_THROWS_WITH_AS(make(sys, "box:3x3", (dir / "far.json").string()), doctest::Contains("do not overlap"), InputError);
    CHECK_THROWS_WITH_AS(make(sys, "box:3x3x3", "box:3x3x3"), doctest::Contains("3D but the lattice square2d is 2D"), InputError);
    // The capacity quoted is the start's mass with every metamodule a creator (2 x 4), not its cell count.
    CHECK_THROWS_WITH_AS(make(g1, "box:2x2", "box:9x1"), doctest::Contains("not enough mass: start 'box:2x2' holds at most 8 metamodules' worth"), InputError);
    CHECK_THROWS_WITH_AS(make(g1, "box:10x10", "box:3x3"), doctest::Contains("too much mass"), InputError);
    CHECK_THROWS_WITH_AS(planner::makeProblem(*sys.model, planner::parseShape("box:3x3"), planner::parseShape("box:3x3"), planner::Vec{7, 7, 0}, 1),
                         doctest::Contains("not in both start and target"), InputError);
    PlannerSystem goalless("planner_intermediate", 2);
    goalless.system.goal.reset();
    CHECK_THROWS_WITH_AS(make(goalless, "box:3x3", "box:3x3"), doctest::Contains("needs a goal of the form all(P)"), InputError);
    PlannerSystem plain("intermediate", 2);
    CHECK_THROWS_WITH_AS(make(plain, "box:3x3", "box:3x3"), doctest::Contains("needs a field 'label"), InputError);
}

TEST_CASE("the block experiment of seed 000: the creations and deletions the shapes imply") {
    for (int dimension : {2, 3}) {
        PlannerSystem sys("planner_intermediate", dimension);
        const std::string from = dimension == 3 ? "box:6x3x2" : "box:12x6", to = dimension == 3 ? "box:3x3x4" : "box:6x12";
        const planner::Problem p = planner::makeProblem(*sys.model, planner::parseShape(from, 2), planner::parseShape(to, 2), std::nullopt, 3);
        for (planner::Scheduler s : {planner::Scheduler::Sync, planner::Scheduler::Async, planner::Scheduler::Adversarial}) {
            const planner::RunStats stats = plan(p, s, 5);
            CHECK(stats.complete);
            // The paper's planner may delete a P leaf inside the target and create it again later
            // (path propagation recruits target cells too): never fewer actions than the shapes
            // imply, and as many extra creations as extra deletions.
            CHECK(stats.creations >= p.toCreate);
            CHECK(stats.creations - p.toCreate == stats.deletions - p.toDelete);
            CHECK(stats.metamodules == static_cast<std::int64_t>(p.target.cells.size()));
            // Every start metamodule but the seed is relabelled exactly once (U -> F or U -> P -> F
            // or U -> P); created ones are born F.
            CHECK(stats.relabels >= static_cast<std::int64_t>(p.start.cells.size()) - 1);
        }
    }
}

TEST_CASE("a transfer exchanges resources and the stages of a general_n creation or deletion are motions") {
    // The allocator decides only transfers: when the second creator completing a partial
    // (C B1 => D D) counted as one, the gradient allocator never asked for it and the last partials
    // of a general_2 run waited thousands of rounds for a randomly walking creator.
    for (const char* stem : {"planner_general2", "planner_general3", "planner_general_lock2"}) {
        PlannerSystem sys(stem, 2);
        const planner::Problem p = planner::makeProblem(*sys.model, planner::parseShape("box:4x2"), planner::parseShape("box:2x4"), std::nullopt, 1);
        std::map<std::string, std::set<planner::ShapeKind>> kinds;
        for (int sh = 0; sh < p.engine->shapeCount(); ++sh) kinds[sys.model->rules()[p.engine->ruleOf(sh)].name].insert(p.engine->kind(sh));
        INFO(stem);
        CHECK(kinds["transfer"] == std::set{planner::ShapeKind::Transfer});
        for (const char* stage : {"create1", "create2", "delete1", "delete2"}) CHECK(kinds[stage] == std::set{planner::ShapeKind::Motion});
        CHECK(kinds["finalize"] == std::set{planner::ShapeKind::Relabel});
    }
}

TEST_CASE("every allocator completes every general system, never below the transport bound, optimal beats random") {
    for (const char* stem : {"planner_general1", "planner_general2", "planner_general3", "planner_general_lock2", "planner_general_lock3"})
        for (int dimension : {2, 3}) {
            PlannerSystem sys(stem, dimension);
            const std::string from = dimension == 3 ? "box:6x3x2" : "box:8x4", to = dimension == 3 ? "box:3x3x4" : "box:4x8";
            const planner::Problem p = planner::makeProblem(*sys.model, planner::parseShape(from), planner::parseShape(to), std::nullopt, 2);
            const std::int64_t bound = planner::transferLowerBound(p);
            CHECK(bound > 0);
            std::map<std::string, std::int64_t> transfers;
            for (const char* allocator : {"random", "gradient", "demand", "eager", "optimal"}) {
                const planner::RunStats stats = plan(p, planner::Scheduler::Sync, 3, true, allocator);
                INFO(stem << " " << dimension << "D " << allocator);
                CHECK(stats.complete);
                CHECK(stats.transfers >= bound);
                transfers[allocator] = stats.transfers;
            }
            CHECK(transfers["optimal"] < transfers["random"]);
        }
}

TEST_CASE("tight mass: every allocator completes where every target cell must end a creator") {
    // These hung: approving every transfer in a synchronous round moved every resource every
    // round (random), and the gradient fields saw no way forward and counted to infinity.
    PlannerSystem sys("planner_general1", 2);
    for (auto [from, to] : {std::pair{"box:8x1", "box:4x1"}, std::pair{"box:6x2", "box:3x2"}, std::pair{"box:4x4", "box:4x2"}})
        for (const char* allocator : {"random", "gradient", "demand", "eager", "optimal"})
            for (std::uint64_t seed : {1, 2, 3}) {
                const planner::Problem p = planner::makeProblem(*sys.model, planner::parseShape(from), planner::parseShape(to), std::nullopt, seed);
                INFO(from << " -> " << to << " " << allocator << " seed " << seed);
                CHECK(plan(p, planner::Scheduler::Sync, seed, true, allocator).complete);
            }
}

TEST_CASE("a run where only transfers fire for too long stops as no-progress, it does not hang") {
    PlannerSystem sys("planner_general1", 2);
    const planner::Problem p = planner::makeProblem(*sys.model, planner::parseShape("box:8x4"), planner::parseShape("box:4x8"), std::nullopt, 1);
    auto allocator = planner::makeAllocator("random", p, 1);
    planner::RunOptions options;
    options.maxIdleRounds = 1;  // two transfer-only rounds in a row end it
    planner::Execution ex(p, *allocator, options);
    const planner::RunStats stats = ex.run();
    CHECK(stats.stopped == StopReason::NoProgress);
    CHECK_FALSE(stats.complete);
}

TEST_CASE("demand and eager: a livelock of transfers under the lock rules gets the randomizer's turn, and the run completes") {
    // disc:6 -> ring:3,7 (audit 12): the fields swapped six transfers back and forth for 20,000
    // rounds while a locked pair waited for a D, and 14 of these 40 runs stopped as no-progress;
    // random, gradient and optimal completed every one.
    for (const char* rules : {"planner_general_lock2", "planner_general_lock3"}) {
        PlannerSystem sys(rules, 2);
        for (const char* allocator : {"demand", "eager"})
            for (std::uint64_t seed = 1; seed <= 10; ++seed) {
                const planner::Problem p = planner::makeProblem(*sys.model, planner::parseShape("disc:6"), planner::parseShape("ring:3,7"), std::nullopt, seed);
                const planner::RunStats stats = plan(p, planner::Scheduler::Sync, seed, false, allocator);
                INFO(rules << " " << allocator << " seed " << seed << ": " << stopReasonName(stats.stopped) << " after " << stats.rounds << " rounds");
                CHECK(stats.complete);
                CHECK(stats.rounds < 2000);
            }
    }
}

TEST_CASE("goal mass: a target cell holds a D or a C at the goal, a cell outside it nothing") {
    // Faults judges a loss by the least, RoundBound its cuts by both; the empty state counts.
    PlannerSystem sys("planner_general3", 2);
    const planner::Problem p = planner::makeProblem(*sys.model, planner::parseShape("box:4x2"), planner::parseShape("box:2x4"), std::nullopt, 1);
    const rules::RuleTables& tables = *p.tables;
    const std::optional<planner::GoalMass> in = planner::goalMass(p, tables.comboIndex(1u << p.schema.target)), out = planner::goalMass(p, tables.comboIndex(0));
    REQUIRE(in);
    REQUIRE(out);
    CHECK(in->least == tables.massDenominator());         // D = 1
    CHECK(in->most == tables.massDenominator() * 4 / 3);  // C = 4/3
    CHECK(out->least == 0);
    CHECK(out->most == 0);
}

TEST_CASE("the no-progress window grows with the message delay") {
    // Under --delay every hop of a resource may wait that many rounds, so a run that is slow, not
    // stuck, gets as many times the window. Here the hook refuses half the transfers each round,
    // as late messages do.
    PlannerSystem sys("planner_general1", 2);
    const planner::Problem p = planner::makeProblem(*sys.model, planner::parseShape("box:8x4"), planner::parseShape("box:4x8"), std::nullopt, 1);
    planner::RunOptions options;
    options.maxIdleRounds = 1;
    options.budget = Budget::maxRounds(100000);
    const planner::Execution* running = nullptr;
    options.admit = [&](std::int64_t anchor, int shape) { return running->engine().kind(shape) != planner::ShapeKind::Transfer || (anchor + running->stats().rounds) % 2 == 0; };
    auto runWith = [&](std::int64_t delay) {
        options.messageDelay = delay;
        auto allocator = planner::makeAllocator("random", p, 1);
        planner::Execution ex(p, *allocator, options);
        running = &ex;
        return ex.run();
    };
    const planner::RunStats prompt = runWith(0), late = runWith(50);
    CHECK(prompt.stopped == StopReason::NoProgress);
    CHECK(late.rounds > prompt.rounds);
}

TEST_CASE("runs are deterministic for a seed and differ across seeds") {
    PlannerSystem sys("planner_general1", 2);
    const planner::Problem p = planner::makeProblem(*sys.model, planner::parseShape("box:8x4"), planner::parseShape("box:4x8"), std::nullopt, 1);
    const planner::RunStats a = plan(p, planner::Scheduler::Async, 11), b = plan(p, planner::Scheduler::Async, 11), c = plan(p, planner::Scheduler::Async, 12);
    CHECK(a.steps == b.steps);
    CHECK(a.transfers == b.transfers);
    CHECK(a.complete);
    CHECK(c.complete);
    CHECK((a.steps != c.steps || a.transfers != c.transfers));
}

TEST_CASE("synchronous rounds grow with the diameter, not the size") {
    PlannerSystem sys("planner_intermediate", 2);
    auto rounds = [&](int k) {
        const planner::Problem p = planner::makeProblem(*sys.model, planner::parseShape("box:2x1", k), planner::parseShape("box:1x2", k), std::nullopt, 1);
        return plan(p, planner::Scheduler::Sync, 1, false).rounds;
    };
    const std::int64_t r10 = rounds(10), r40 = rounds(40);
    // 16x the metamodules, 4x the diameter.
    CHECK(r40 < 6 * r10);
    CHECK(r40 > 2 * r10);
}

}  // namespace holon::test
