// The demand allocator against the transport bound and the intermediate planner on seeded shape
// bench problems (issue 28), the small ones of bench.shape_short's generator: starts heavier than
// the target, where the gradient allocator paid 3.7 to 14 times the bound, and a lighter one. A
// bound on the ratio, not a count: the test holds for any draw as good as these, and it checks
// that the problems still tell the allocators apart (the gradient allocator breaks the bound on
// at least one), so a generator that drew only easy problems would fail it too. The eager
// allocator against demand on the block at K = 16: under 0.7 times demand's rounds (measured
// 0.55) and 1.5 times the bound (measured 1.33). And what no allocator can change: a start with no
// creator waits for the relabelling wave before anything else can happen, which on a spiral start
// is more rounds than issue 28's 3 times the intermediate planner's (docs/allocators.md).

#include "PlannerSupport.h"
#include "ShapeGenerator.h"

#include "planner/Allocator.h"
#include "rules/Error.h"

#include <algorithm>

namespace holon::test {

namespace {

struct BenchOutcome {
    bool complete = false;
    double transfers = 0, rounds = 0;  // over the transport bound, over the intermediate planner's rounds
};

/// Problem `index` of the shape bench with seed 1 and about 60 metamodules, redrawn as the bench
/// does when the mass check refuses it.
BenchOutcome run(int dimension, int index, const std::string& allocator) {
    PlannerSystem general("planner_general1", dimension), intermediate("planner_intermediate", dimension);
    for (int attempt = 0;; ++attempt) {
        const bench::ShapePair pair = bench::shapePair(dimension, 1, index, attempt, 60, 1.9);
        try {
            const planner::Problem p = planner::makeProblem(*general.model, pair.start, pair.target, rules::Vec{}, 1);
            const planner::Problem base = planner::makeProblem(*intermediate.model, pair.start, pair.target, rules::Vec{}, 1);
            auto runOn = [](const planner::Problem& problem, const std::string& name) {
                auto a = planner::makeAllocator(name, problem, 1);
                planner::RunOptions options;
                options.seed = 1, options.budget = Budget::maxRounds(100000);
                planner::Execution ex(problem, *a, options);
                return ex.run();
            };
            const planner::RunStats s = runOn(p, allocator), b = runOn(base, "random");
            REQUIRE(b.complete);
            const std::int64_t bound = planner::transferLowerBound(p);
            REQUIRE(bound > 0);
            return {s.complete, double(s.transfers) / double(bound), double(s.rounds) / double(b.rounds)};
        } catch (const InputError&) {
            REQUIRE(attempt < 50);
        }
    }
}

// The heavy starts: 2D 8 (spiral -> polyomino) and 9 (letter -> spiral), 3D 1 (thin -> spiral)
// and 2 (ring -> ring); and 2D 5 (polyomino -> letter), a start half the target's mass.
constexpr std::pair<int, int> kProblems[] = {{2, 8}, {2, 9}, {3, 1}, {3, 2}, {2, 5}};
constexpr double kTransfers = 3, kRounds = 8;

}  // namespace

TEST_CASE("demand allocator: within 3x the transport bound and 8x the intermediate planner's rounds on seeded bench problems") {
    for (auto [dimension, index] : kProblems) {
        CAPTURE(dimension);
        CAPTURE(index);
        const BenchOutcome o = run(dimension, index, "demand");
        CHECK(o.complete);
        CHECK(o.transfers <= kTransfers);
        CHECK(o.rounds <= kRounds);
    }
}

TEST_CASE("the allocator problems stay hard: the gradient allocator exceeds the demand allocator's transfer bound on one") {
    double worst = 0;
    for (auto [dimension, index] : kProblems) worst = std::max(worst, run(dimension, index, "gradient").transfers);
    CHECK(worst > kTransfers);
}

TEST_CASE("eager allocator: the C's no creation claims are drawn on, so the block at K = 16 takes far fewer rounds than demand") {
    // Measured: demand 2,319 rounds and 1.24 times the bound, eager 1,280 and 1.33. Under demand
    // the nearest creations' claim regions wall the C's behind them off, and they rest.
    PlannerSystem sys("planner_general1", 3);
    const planner::Problem p = planner::makeProblem(*sys.model, planner::parseShape("box:6x3x2", 16), planner::parseShape("box:3x3x4", 16), std::nullopt, 1);
    auto runWith = [&](const std::string& name) {
        auto a = planner::makeAllocator(name, p, 1);
        planner::RunOptions options;
        options.seed = 1, options.budget = Budget::maxRounds(20000);
        planner::Execution ex(p, *a, options);
        return ex.run();
    };
    const planner::RunStats demand = runWith("demand"), eager = runWith("eager");
    REQUIRE(demand.complete);
    REQUIRE(eager.complete);
    CHECK(double(eager.rounds) < 0.7 * double(demand.rounds));
    CHECK(double(eager.transfers) < 1.5 * double(planner::transferLowerBound(p)));
}

TEST_CASE("a start with no creator: the rounds before the first deletion are the relabelling wave's under every allocator, over 3x the intermediate planner's on a spiral") {
    // 2D problem 13 of the shape bench (seed 1, about 300 metamodules): a one-wide spiral of 253
    // metamodules -> a polyomino of 206. Measured: 251 rounds of relabelling, then the first
    // deletion; the intermediate planner takes 40 rounds in all.
    PlannerSystem general("planner_general1", 2), intermediate("planner_intermediate", 2);
    const bench::ShapePair pair = bench::shapePair(2, 1, 13, 0, 300, 1.9);
    REQUIRE(pair.family == "spiral->polyomino");
    const planner::Problem p = planner::makeProblem(*general.model, pair.start, pair.target, rules::Vec{}, 1);
    const planner::Problem base = planner::makeProblem(*intermediate.model, pair.start, pair.target, rules::Vec{}, 1);
    REQUIRE(p.creators == 0);
    auto firstChange = [](const planner::Problem& problem, const std::string& name) {
        auto a = planner::makeAllocator(name, problem, 1);
        planner::RunOptions options;
        options.seed = 1, options.budget = Budget::maxRounds(100000);
        planner::Execution ex(problem, *a, options);
        std::int64_t first = -1, transfersBefore = 0;
        planner::RunObserver observer;
        observer.roundEnd = [&](const planner::RunStats& now) {
            if (first < 0 && now.creations + now.deletions > 0) first = now.rounds;
            if (first < 0) transfersBefore = now.transfers;
            return true;
        };
        const planner::RunStats s = ex.run(observer);
        CHECK(s.complete);
        CHECK(transfersBefore == 0);  // no C to move: the allocator has nothing to decide
        return std::pair{first, s.rounds};
    };
    const std::int64_t baseRounds = firstChange(base, "random").second;
    const std::int64_t wave = firstChange(p, "random").first;
    for (const char* name : {"gradient", "demand", "eager", "optimal"}) {
        CAPTURE(name);
        CHECK(firstChange(p, name).first == wave);
    }
    CHECK(double(wave - 1) > 3.0 * double(baseRounds));
}

}  // namespace holon::test
