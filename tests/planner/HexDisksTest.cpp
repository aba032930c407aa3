// general_2 metamodules on hex disks (seed 000 Fig. 4a): a planner run expanded into single-disk
// pivot moves, re-checked by the independent replay, and the replay's own checks shown to bite.

#include "PlannerSupport.h"

#include "planner/hex/DiskMetamodules.h"
#include "rules/Error.h"

namespace holon::test {

namespace {

/// Runs the planner and expands every fired instance into disk moves; returns whether all expanded.
bool expand(const planner::Problem& problem, planner::hex::DiskMetamodules& disks) {
    auto allocator = planner::makeAllocator("random", problem, 1);
    planner::RunOptions options;
    options.maxRounds = 200000;
    planner::Execution ex(problem, *allocator, options);
    bool ok = true;
    planner::RunObserver observer;
    observer.fired = [&](std::int64_t anchor, int shape, const planner::BoxEngine::Value* old) {
        if (ok) ok = disks.fired(anchor, shape, old, ex.cells());
    };
    CHECK(ex.run(observer).complete);
    std::string why;
    CHECK_MESSAGE(disks.slotsMatch(ex.cells(), why), why);
    return ok;
}

}  // namespace

TEST_CASE("a general_2 plan becomes pivot moves of hex disks that the replay accepts") {
    PlannerSystem sys("planner_general2", 2);
    const planner::Problem p = planner::makeProblem(*sys.model, planner::parseShape("box:3x2"), planner::parseShape("box:2x3"), std::nullopt, 1);
    planner::hex::DiskMetamodules disks(p);
    CHECK(disks.side() == 13);
    CHECK(disks.disksPerUnit() == 2 * disks.side() - 1);  // one unit of mass is the skeleton
    REQUIRE_MESSAGE(expand(p, disks), disks.failure());
    CHECK(disks.moves().size() > 1000);
    CHECK(disks.disks().size() == disks.startDisks().size());
    CHECK(planner::hex::replayDiskMoves(disks.startDisks(), disks.moves()).empty());
}

TEST_CASE("the disk replay refuses a move without a pivot, onto a disk, or one that disconnects") {
    using planner::Vec;
    using planner::hex::DiskMove;
    const std::vector<Vec> line{{0, 0, 0}, {1, 0, 0}, {2, 0, 0}};
    // Rolling the end disk about its neighbour, the cell on the other side empty: accepted.
    CHECK(planner::hex::replayDiskMoves(line, {DiskMove{0, "r", {2, 0, 0}, {2, -1, 0}, {1, 0, 0}}}).empty());
    auto fault = [&](DiskMove m) { return planner::hex::replayDiskMoves(line, {m}); };
    CHECK(fault({0, "r", {2, 0, 0}, {1, 0, 0}, {1, -1, 0}}).find("occupied") != std::string::npos);
    CHECK(fault({0, "r", {2, 0, 0}, {3, 0, 0}, {2, -1, 0}}).find("not a pivot") != std::string::npos);
    CHECK(fault({0, "r", {1, 0, 0}, {1, -1, 0}, {0, 0, 0}}).find("no longer connected") != std::string::npos);
}

TEST_CASE("hex disks refuse what they cannot realise") {
    PlannerSystem inter("planner_intermediate", 2), sys3("planner_general2", 3);
    const planner::Problem flat = planner::makeProblem(*inter.model, planner::parseShape("box:3x2"), planner::parseShape("box:2x3"), std::nullopt, 1);
    CHECK_THROWS_WITH_AS(planner::hex::DiskMetamodules{flat}, doctest::Contains("does not conserve mass"), InputError);
    const planner::Problem solid = planner::makeProblem(*sys3.model, planner::parseShape("box:3x2x2"), planner::parseShape("box:2x3x2"), std::nullopt, 1);
    CHECK_THROWS_WITH_AS(planner::hex::DiskMetamodules{solid}, doctest::Contains("disks lie in the plane"), InputError);
}

}  // namespace holon::test
