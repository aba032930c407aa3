// general_n metamodules on hex disks (seed 000 Fig. 4a): every motion sequence of the design holds
// whatever the neighbouring slots hold, in every direction and both ways; planner runs expand into
// single-disk pivot moves that the independent replay accepts, every slot ending in its layout;
// and the replay's own checks bite.

#include "PlannerSupport.h"

#include "planner/Random.h"
#include "planner/hex/DiskMetamodules.h"
#include "planner/hex/PivotRules.h"
#include "rules/Error.h"

#include <set>

namespace holon::test {

namespace {

using planner::Vec;

/// Runs the planner and expands every fired instance into disk moves; returns whether all expanded.
bool expand(const planner::Problem& problem, planner::hex::DiskMetamodules& disks) {
    auto allocator = planner::makeAllocator("random", problem, 1);
    planner::RunOptions options;
    options.budget = Budget::maxRounds(200000);
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

std::set<std::pair<int, int>> keys(const std::vector<Vec>& cells) {
    std::set<std::pair<int, int>> out;
    for (Vec v : cells) out.insert({v.x, v.y});
    return out;
}

}  // namespace

TEST_CASE("every motion sequence of the hex disk design holds whatever the neighbouring slots hold, every way round") {
    planner::Random random(5);
    for (int units : {2, 3, 4}) {  // general1, general2, general3
        CAPTURE(units);
        const planner::hex::DiskDesign design(units);
        const int s = design.side();
        CHECK(design.disksPerUnit() == 4 * s - 6);  // the ring: the border without its two acute corners
        for (int level = 1; level <= units; ++level) CHECK(design.layout(level).size() == static_cast<std::size_t>(level * design.disksPerUnit()));
        // Every move of every base sequence rolls within the pair: both cells next to both its
        // ends lie in slots A or B, so no neighbouring slot's content can matter.
        const rules::Lattice& hex = rules::Lattice::get(rules::LatticeKind::Hex2D);
        for (int k = 0; k < units; ++k)
            for (const auto& m : design.base(k))
                for (int d = 0; d < 6; ++d)
                    if (m.from + hex.direction(d) == m.to)
                        for (Vec c : {m.from + hex.direction((d + 1) % 6), m.from + hex.direction((d + 5) % 6)})
                            CHECK((c.x >= 0 && c.y >= 0 && c.x < 2 * s && c.y < s));
        int checked = 0;
        for (const bool alongY : {false, true})
            for (int a0 = 0; a0 <= units; ++a0)
                for (int b0 = 0; b0 <= units; ++b0)
                    for (const int gives : {-1, 1}) {  // A gives one unit to B, or B to A
                        const int a1 = a0 - gives, b1 = b0 + gives;
                        if (a1 < 0 || b1 < 0 || a1 > units || b1 > units) continue;
                        // The pair in a 4 x 4 block of slots; the others empty (the pair alone), or
                        // holding random levels (every neighbour present).
                        const Vec a{1, 1, 0}, b = alongY ? Vec{1, 2, 0} : Vec{2, 1, 0};
                        for (int round = 0; round < 3; ++round) {
                            std::vector<Vec> start, end;
                            for (int y = 0; y < 4; ++y)
                                for (int x = 0; x < 4; ++x) {
                                    const Vec slot{x, y, 0};
                                    const int other = round == 0 ? 0 : 1 + static_cast<int>(random.below(units));
                                    const int before = slot == a ? a0 : slot == b ? b0
                                                                                  : other,
                                              after = slot == a ? a1 : slot == b ? b1
                                                                                 : other;
                                    for (Vec c : design.layout(before)) start.push_back(Vec{s * x, s * y, 0} + c);
                                    for (Vec c : design.layout(after)) end.push_back(Vec{s * x, s * y, 0} + c);
                                }
                            bool ok = false;
                            const auto moves = design.sequence(a0, b0, a1, b1, alongY, Vec{s * a.x, s * a.y, 0}, ok);
                            INFO("levels " << a0 << "," << b0 << " -> " << a1 << "," << b1 << (alongY ? " along y" : " along x") << ", round " << round);
                            // One unit moves: a ring, or payload of a ring's size.
                            const bool allowed = (gives > 0 ? a0 == units || b1 == units : b0 == units || a1 == units);
                            REQUIRE(ok == allowed);
                            if (!ok) continue;
                            std::vector<planner::hex::DiskMove> replay;
                            for (const auto& m : moves) replay.push_back({0, "t", m.from, m.to, m.pivot});
                            CHECK(planner::hex::replayDiskMoves(start, replay).empty());
                            std::set<std::pair<int, int>> cells = keys(start);
                            for (const auto& m : moves) cells.erase({m.from.x, m.from.y}), cells.insert({m.to.x, m.to.y});
                            CHECK(cells == keys(end));
                            ++checked;
                        }
                    }
        // One unit apart with C on the giving side before or the receiving side after: 2 units - 1
        // transitions each way, in two directions and three rounds.
        CHECK(checked == 2 * 3 * 2 * (2 * units - 1));
    }
}

TEST_CASE("a general_2 plan becomes pivot moves of hex disks that the replay accepts") {
    PlannerSystem sys("planner_general2", 2);
    for (const char* plan : {"box:3x2 box:2x3", "box:4x4 T:4"}) {
        CAPTURE(plan);
        const std::string p = plan;
        const planner::Problem problem = planner::makeProblem(*sys.model, planner::parseShape(p.substr(0, p.find(' '))), planner::parseShape(p.substr(p.find(' ') + 1)),
                                                              std::nullopt, 1);
        planner::hex::DiskMetamodules disks(problem);
        REQUIRE_MESSAGE(expand(problem, disks), disks.failure());
        CHECK(disks.moves().size() > 1000);
        CHECK(disks.disks().size() == disks.startDisks().size());
        CHECK(planner::hex::replayDiskMoves(disks.startDisks(), disks.moves()).empty());
    }
}

TEST_CASE("the disk replay refuses a move without a pivot, onto a disk, or one that disconnects") {
    using planner::hex::DiskMove;
    const std::vector<Vec> line{{0, 0, 0}, {1, 0, 0}, {2, 0, 0}};
    // Rolling the end disk about its neighbour, the cell on the other side empty: accepted.
    CHECK(planner::hex::replayDiskMoves(line, {DiskMove{0, "r", {2, 0, 0}, {2, -1, 0}, {1, 0, 0}}}).empty());
    auto fault = [&](DiskMove m) { return planner::hex::replayDiskMoves(line, {m}); };
    CHECK(fault({0, "r", {2, 0, 0}, {1, 0, 0}, {1, -1, 0}}).find("occupied") != std::string::npos);
    CHECK(fault({0, "r", {2, 0, 0}, {3, 0, 0}, {2, -1, 0}}).find("not a pivot") != std::string::npos);
    CHECK(fault({0, "r", {1, 0, 0}, {1, -1, 0}, {0, 0, 0}}).find("no longer connected") != std::string::npos);
    CHECK(planner::hex::replayDiskMoves({{0, 0, 0}, {2, 0, 0}}, {}).find("not connected") != std::string::npos);
}

TEST_CASE("hex_pivot compiled for the disks rolls a disk about an occupied neighbour, the other side empty, and nothing else") {
    const planner::hex::PivotRules pivots(Vec{0, 0, 0}, Vec{6, 6, 1});
    const planner::Board& board = pivots.board();
    std::vector<planner::BoxEngine::Value> cells(static_cast<std::size_t>(board.size()), 0);
    for (Vec v : {Vec{2, 2, 0}, Vec{3, 2, 0}}) cells[board.index(v)] = pivots.disk();
    // (3,2) rolls about (2,2) to (2,3) (direction SW, pivot W = clockwise), the swept cell (3,3) empty.
    const auto roll = pivots.find({3, 2, 0}, {2, 3, 0}, {2, 2, 0});
    REQUIRE(roll.shape >= 0);
    CHECK(pivots.engine().matches(cells.data(), roll.anchor, roll.shape));
    cells[board.index({3, 3, 0})] = pivots.disk();  // the swept cell full: no roll
    CHECK_FALSE(pivots.engine().matches(cells.data(), roll.anchor, roll.shape));
    cells[board.index({3, 3, 0})] = 0;
    planner::BoxEngine::Value old[rules::RuleTables::kMaxCells];
    pivots.engine().apply(cells.data(), roll.anchor, roll.shape, old);
    CHECK(cells[board.index({2, 3, 0})] == pivots.disk());
    CHECK(cells[board.index({3, 2, 0})] == 0);
    CHECK(cells[board.index({2, 2, 0})] == pivots.disk());
    // Not a pivot move: not neighbours, or the pivot not next to both ends.
    CHECK(pivots.find({3, 2, 0}, {5, 2, 0}, {4, 2, 0}).shape < 0);
    CHECK(pivots.find({3, 2, 0}, {4, 2, 0}, {2, 2, 0}).shape < 0);
}

TEST_CASE("hex disks refuse what they cannot realise") {
    PlannerSystem inter("planner_intermediate", 2), sys3("planner_general2", 3);
    const planner::Problem flat = planner::makeProblem(*inter.model, planner::parseShape("box:3x2"), planner::parseShape("box:2x3"), std::nullopt, 1);
    CHECK_THROWS_WITH_AS(planner::hex::DiskMetamodules{flat}, doctest::Contains("does not conserve mass"), InputError);
    const planner::Problem solid = planner::makeProblem(*sys3.model, planner::parseShape("box:3x2x2"), planner::parseShape("box:2x3x2"), std::nullopt, 1);
    CHECK_THROWS_WITH_AS(planner::hex::DiskMetamodules{solid}, doctest::Contains("disks lie in the plane"), InputError);
}

}  // namespace holon::test
