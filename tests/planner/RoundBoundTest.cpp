// The cut bound on rounds (planner/RoundBound.cpp): its value where it can be worked out by hand,
// and no synchronous run of any allocator beating it on random problems of the mass-conserving
// systems.

#include "PlannerSupport.h"

#include "ShapeGenerator.h"
#include "planner/RoundBound.h"

namespace holon::test {

namespace {

planner::Shape line(int from, int to) {
    planner::Shape s;
    s.dimension = 2, s.name = "line";
    for (int x = from; x <= to; ++x) s.cells.push_back({x, 0, 0});
    return s;
}

std::int64_t massAt(const planner::Problem& p, planner::Vec v) { return p.tables->massUnitsOf(p.cells[p.board->index(v)]); }

}  // namespace

TEST_CASE("the cut bound: a tail to delete leaves through its one cell next to the target") {
    PlannerSystem sys("planner_general1", 2);
    const planner::Problem p = planner::makeProblem(*sys.model, line(0, 9), line(0, 5), planner::Vec{0, 0, 0}, 1);
    const std::optional<planner::RoundBound> b = planner::roundLowerBound(p);
    REQUIRE(b);
    std::int64_t tail = 0;
    for (int x = 6; x <= 9; ++x) tail += massAt(p, {x, 0, 0});
    CHECK_FALSE(b->creation);
    CHECK(b->gate == 1);
    CHECK(b->perCell == 1);
    CHECK(b->cells == 4);
    CHECK(b->rounds == tail);
}

TEST_CASE("the cut bound: a thin arm to build is fed through its base, one unit a round") {
    PlannerSystem sys("planner_general1", 2);
    const planner::Problem p = planner::makeProblem(*sys.model, planner::parseShape("box:3x3"), line(0, 8), planner::Vec{0, 0, 0}, 1);
    const std::optional<planner::RoundBound> b = planner::roundLowerBound(p);
    REQUIRE(b);
    // Cells (3,0)..(8,0) are built, each of mass 1, and only (2,0) borders them: (3,1) is neither
    // in the start nor in the target, so it never holds mass.
    CHECK(b->creation);
    CHECK(b->gate == 1);
    CHECK(b->cells == 6);
    CHECK(b->rounds == 6);
}

TEST_CASE("the cut bound: no system without declared mass conservation gets one") {
    PlannerSystem sys("planner_intermediate", 2);
    const planner::Problem p = planner::makeProblem(*sys.model, line(0, 9), line(0, 5), planner::Vec{0, 0, 0}, 1);
    CHECK_FALSE(planner::roundLowerBound(p));
}

TEST_CASE("the cut bound holds: no synchronous run of any allocator takes fewer rounds") {
    // The shape bench's families (spirals and thin arms, heavier and lighter starts) for general1,
    // random blobs for general2, which moves mass in halves through partials. A bound that counted
    // a cell's giving twice in a round, or let mass through a cell that can never hold any, is
    // beaten here.
    planner::Random random(7);
    int bounded = 0;
    double closest = 1e9;
    for (const char* system : {"planner_general1", "planner_general2"})
        for (int dimension : {2, 3})
            for (int k = 0; k < 8; ++k) {
                PlannerSystem sys(system, dimension);
                std::optional<planner::Problem> p;
                for (int attempt = 0; attempt < 20 && !p; ++attempt) {
                    planner::Shape start, target;
                    if (std::string(system) == "planner_general1") {
                        bench::ShapePair pair = bench::shapePair(dimension, 5, k, attempt, 40, 1.9);
                        start = pair.start, target = pair.target;
                    } else {
                        const planner::Vec box = dimension == 3 ? planner::Vec{5, 5, 4} : planner::Vec{9, 9, 1};
                        start = randomBlob(random, dimension, box, {0, 0, 0}, 8 + static_cast<int>(random.below(14)));
                        target = randomBlob(random, dimension, box, {0, 0, 0}, 8 + static_cast<int>(random.below(14)));
                    }
                    try {
                        p.emplace(planner::makeProblem(*sys.model, start, target, planner::Vec{0, 0, 0}, 1));
                    } catch (const InputError&) {
                        // more or less mass than the target can hold: draw again
                    }
                }
                REQUIRE(p);
                const std::optional<planner::RoundBound> b = planner::roundLowerBound(*p);
                REQUIRE(b);
                ++bounded;
                for (const char* name : {"random", "gradient", "demand", "eager", "optimal"}) {
                    auto allocator = planner::makeAllocator(name, *p, 3);
                    planner::RunOptions options;
                    options.seed = 3;
                    planner::Execution ex(*p, *allocator, options);
                    const planner::RunStats stats = ex.run();
                    INFO(std::string(system) << ", " << dimension << "D problem " << k << ", " << std::string(name) << ": " << stats.rounds << " rounds, bound " << b->rounds);
                    if (!stats.complete) continue;
                    CHECK(stats.rounds >= b->rounds);
                    closest = std::min(closest, double(stats.rounds) / double(b->rounds));
                }
            }
    MESSAGE(bounded << " problems; the closest run took " << closest << " times the bound");
}

}  // namespace holon::test
