// Diagnosable runs (issue 28): a cell short of the goal names the rule it waits on and what blocks
// it (planner/Diagnosis.h), and snapshots carry a legend, every layer of a 3D board, and the
// checker's orientation (y down the page).

#include "PlannerSupport.h"

#include "planner/Diagnosis.h"

#include <string>

namespace holon::test {

TEST_CASE("a P cell with an undecided neighbour waits on delete, blocked by that neighbour") {
    const PlannerSystem sys("planner_intermediate", 2);
    const planner::Problem p = planner::makeProblem(*sys.model, planner::parseShape("box:8x3"), planner::parseShape("box:3x8"), std::nullopt, 1);
    auto allocator = planner::makeAllocator("random", p, 1);
    planner::RunOptions options;
    options.budget = Budget::maxRounds(3);
    planner::Execution ex(p, *allocator, options);
    ex.run();
    const planner::BoardConfiguration board(p, ex.cells());
    const int inTarget = p.tables->comboIndex(1u << p.schema.target);
    const rules::Alphabet& alphabet = p.model->alphabet();
    int checked = 0;
    p.board->forEachInside([&](std::int64_t i, planner::Vec at) {
        const planner::BoxEngine::Value v = ex.cells()[i];
        if (!v || alphabet.fields(v)[p.schema.label] != p.schema.path || p.engine->combo(i) == inTarget) return;
        std::vector<std::string> blockers;
        for (int d = 0; d < p.board->lattice().degree(); ++d) {
            const planner::BoxEngine::Value n = ex.cells()[i + p.board->step(d)];
            if (n && alphabet.fields(n)[p.schema.label] == p.schema.unknown) blockers.push_back(planner::showCell(at + p.board->lattice().direction(d), 2) + " U");
        }
        if (blockers.empty()) return;
        const std::string why = planner::waitingOn(p, board, i);
        CAPTURE(why);
        // The guard's neighbourhood is named by its cell: `no nbr U` of the rule file reads `no nbr@(x,y) U`.
        CHECK(why.rfind("waits on rule delete at " + planner::showCell(at, 2) + ": guard `no nbr@" + planner::showCell(at, 2) + " U` is false: blocked by ", 0) == 0);
        for (const std::string& b : blockers) CHECK(why.find(b) != std::string::npos);
        ++checked;
    });
    CHECK(checked > 0);
}

TEST_CASE("an empty target cell away from F waits on create, whose neighbour is not F yet") {
    const PlannerSystem sys("planner_intermediate", 2);
    const planner::Problem p = planner::makeProblem(*sys.model, planner::parseShape("box:6x1"), planner::parseShape("box:1x6"), planner::Vec{0, 0, 0}, 1);
    const planner::BoardConfiguration board(p, p.cells);
    const std::string why = planner::waitingOn(p, board, p.board->index({0, 3, 0}));
    CAPTURE(why);
    CHECK(why.find("waits on rule create at ") == 0);
    CHECK(why.find("is empty, the rule needs F") != std::string::npos);
}

TEST_CASE("snapshots: a legend, every layer, y down the page") {
    const PlannerSystem flat("planner_general1", 2);
    const planner::Problem p = planner::makeProblem(*flat.model, planner::parseShape("box:3x3"), planner::parseShape("box:3x3"), planner::Vec{0, 0, 0}, 1);
    const std::string svg = planner::drawBoard(p, p.cells, "start");
    for (const char* key : {"U (undecided)", "P (path: to be deleted)", "F (final)", "empty target cell", "dot: creator resource", "y down the page"})
        CHECK(svg.find(key) != std::string::npos);
    // The seed at y = 0 is the one F cell, drawn in the top row as in the checker's pictures.
    const std::size_t f = svg.find("fill=\"#3d6fb0\" stroke");
    REQUIRE(f != std::string::npos);
    const std::size_t rect = svg.rfind("<rect", f);
    CHECK(svg.substr(rect, f - rect).find(" y=\"25\"") != std::string::npos);

    const PlannerSystem deep("planner_intermediate", 3);
    const planner::Problem q = planner::makeProblem(*deep.model, planner::parseShape("box:2x2x14"), planner::parseShape("box:2x2x14"), std::nullopt, 1);
    const std::string layers = planner::drawBoard(q, q.cells, "start");
    for (int z = 0; z < 14; ++z) CHECK(layers.find(">z=" + std::to_string(z) + "<") != std::string::npos);
}

}  // namespace holon::test
