// The gradient allocator's fields (planner/GradientAllocator.cpp) and the demands that seed them
// (planner/DemandProbe.cpp).
//
// The fields count hops only through metamodules that can pass a resource on. A partial metamodule
// takes part in no transfer; counted through it, a C beside a partial looked one hop from the creator locked on its far side, a false
// minimum the C never left, and the run waited for the randomizer to walk it round (general-lock3
// at 2,304 metamodules: 30,410 rounds, 26,000 of them for the last C).

#include "PlannerSupport.h"

#include "planner/Allocator.h"
#include "rules/ConfigIo.h"

#include <nlohmann/json.hpp>

#include <algorithm>

namespace holon::test {

namespace {
/// The state with exactly these fields.
planner::BoxEngine::Value state(const rules::Model& model, const nlohmann::json& fields) {
    for (int v = 1; v < model.alphabet().size(); ++v)
        if (rules::stateFields(model, static_cast<rules::CellValue>(v)) == fields) return static_cast<planner::BoxEngine::Value>(v);
    FAIL("no state " << fields.dump());
    return 0;
}
}  // namespace

TEST_CASE("gradient: the last C beside a partial goes round it to the creator locked on its far side") {
    for (const char* stem : {"planner_general_lock2", "planner_general_lock3"}) {
        INFO(std::string(stem));
        // Every target cell final and full but one partial in the top row, (1, top), locked to
        // its creator (2, top) that waits for a C; the one C left is at (0, top), beside the
        // partial on the other side. Mass: a D per target cell.
        const PlannerSystem sys(stem, 2);
        const int width = 24, height = 24, top = height - 1;
        const planner::Shape box = planner::parseShape("box:" + std::to_string(width) + "x" + std::to_string(height));
        planner::Problem p = planner::makeProblem(*sys.model, box, box, std::nullopt, 1);
        const bool three = std::string(stem) == "planner_general_lock3";
        const auto cell = [&](int x, int y) { return p.board->index({x, y, 0}); };
        for (const planner::Vec v : box.cells) p.cells[cell(v.x, v.y)] = state(*sys.model, {{"label", "F"}, {"lock", "none"}, {"res", "D"}});
        p.cells[cell(0, top)] = state(*sys.model, {{"label", "F"}, {"lock", "none"}, {"res", "C"}});
        p.cells[cell(1, top)] = state(*sys.model, {{"label", "F"}, {"lock", "+x"}, {"res", three ? "B2" : "B1"}});
        p.cells[cell(2, top)] = state(*sys.model, {{"label", "F"}, {"lock", "-x"}, {"res", "D"}});
        auto allocator = planner::makeAllocator("gradient", p, 1);
        const planner::RunStats stats = planner::Execution(p, *allocator, {}).run();
        CHECK(stats.complete);
        // The shortest way round the partial: (0, top-1), (1, top-1), (2, top-1), (2, top).
        CHECK(stats.transfers == 4);
        // The fields settle within the board's diameter; the randomizer never gets the turn.
        CHECK(stats.rounds <= width + height);
    }
}

// The end of a heavy start (the shape bench's general3 spiral -> polyomino, 2D problem 8: 54,357
// rounds, 40,000 of them for its last two deletions): the target is full and holds C's but for a
// few D's far off, and the last P arm outside it is a leaf and its parent, both holding C's. The
// leaf's deletion (D&P D => ...) waits for two D's, its own and its partner's; asked one change at
// a time, neither cell is a demand, no field reaches them, and the randomizer had to walk the D's
// there across the target.
TEST_CASE("gradient: a P leaf and its partner both holding C's draw the D's their deletion waits for") {
    for (const char* stem : {"planner_general1", "planner_general3"}) {
        INFO(std::string(stem));
        const PlannerSystem sys(stem, 2);
        const int width = 16, height = 16;
        const planner::Shape box = planner::parseShape("box:" + std::to_string(width) + "x" + std::to_string(height));
        planner::Shape start = box;
        start.cells.push_back({-2, 0, 0}), start.cells.push_back({-1, 0, 0});
        std::sort(start.cells.begin(), start.cells.end());
        planner::Problem p = planner::makeProblem(*sys.model, start, box, planner::Vec{0, 0, 0}, 1);
        const auto cell = [&](int x, int y) { return p.board->index({x, y, 0}); };
        for (const planner::Vec v : box.cells) p.cells[cell(v.x, v.y)] = state(*sys.model, {{"label", "F"}, {"res", "C"}});
        // The D's the two deletions need (each stage takes one from the cell deleted or its
        // partner), in the corner farthest from the arm.
        const int needed = std::string(stem) == "planner_general1" ? 4 : 8;
        for (int k = 0; k < needed; ++k) p.cells[cell(width - 1 - k % 4, height - 1 - k / 4)] = state(*sys.model, {{"label", "F"}, {"res", "D"}});
        p.cells[cell(-1, 0)] = state(*sys.model, {{"label", "P"}, {"parent", "+x"}, {"res", "C"}});
        p.cells[cell(-2, 0)] = state(*sys.model, {{"label", "P"}, {"parent", "+x"}, {"res", "C"}});
        auto allocator = planner::makeAllocator("gradient", p, 1);
        const planner::RunStats stats = planner::Execution(p, *allocator, {}).run();
        CHECK(stats.complete);
        // The D's come down the field: a few times the board's diameter (before: 3,666 rounds for
        // general1, 15,504 for general3, the randomizer walking them).
        CHECK(stats.rounds <= 6 * (width + height));
    }
}

}  // namespace holon::test
