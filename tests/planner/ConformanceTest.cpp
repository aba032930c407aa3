// Every back-end runs only rules of the systems it claims, as the reference interpreter runs them:
// the conformance harness (Conformance.h) over the U/P/F planner on square and cubic lattices, hex
// sculpting (the paper's algorithm and holon's improvements), hex disks and Roombots coordination.
// A back-end joins by one line in kBackends. The harness itself must catch a hand-written write.

#include "Conformance.h"
#include "PlannerSupport.h"

#include "planner/hex/DiskMetamodules.h"
#include "planner/hex/SculptRun.h"
#include "planner/roombots/Assembly.h"

#include <functional>

namespace holon::test {

namespace {

/// Runs a back-end, calling `checkpoint` at the end of each of its steps.
using Run = std::function<void(const std::function<void()>& checkpoint)>;

struct Backend {
    const char* name;
    std::vector<std::string> claims;  // the systems whose rules it may apply
    std::int64_t period, window;      // sampling (Conformance.h)
    Run run;
};

/// The U/P/F planner on a start and target of `stem`, expanding every fired template with `alsoFired`.
void plan(const std::string& stem, int dimension, const char* from, const char* to, const std::function<void()>& checkpoint,
          const std::function<void(const planner::Problem&, const planner::Execution&, std::int64_t, int, const planner::BoxEngine::Value*)>& alsoFired = {}) {
    PlannerSystem sys(stem, dimension);
    const planner::Problem problem = planner::makeProblem(*sys.model, planner::parseShape(from), planner::parseShape(to), std::nullopt, 1);
    auto allocator = planner::makeAllocator("random", problem, 1);
    planner::Execution ex(problem, *allocator, planner::RunOptions{});
    planner::RunObserver observer;
    if (alsoFired) observer.fired = [&](std::int64_t anchor, int shape, const planner::BoxEngine::Value* old) { alsoFired(problem, ex, anchor, shape, old); };
    observer.roundEnd = [&](const planner::RunStats&) {
        checkpoint();
        return true;
    };
    REQUIRE(ex.run(observer).complete);
}

void sculpt(bool improvements, const std::function<void()>& checkpoint) {
    planner::hex::SculptSetup setup;
    setup.size = 60, setup.steps = 600;
    setup.options.decay = 5;
    planner::hex::SculptOptions& o = setup.options;
    o.dropOverhangs = o.flexibleGrowth = o.roll = o.deleteOverflow = o.growInside = o.keepConnected = o.migrate = o.balance = improvements;
    planner::hex::runSculpt(setup, [&](const planner::hex::HoleSculptor&) { checkpoint(); });
}

const std::vector<Backend> kBackends = {
    {"U/P/F planner, square", {"planner_general2"}, 1, 1, [](auto& c) { plan("planner_general2", 2, "box:4x4", "T:4", c); }},
    {"U/P/F planner, cubic", {"planner_intermediate"}, 1, 1, [](auto& c) { plan("planner_intermediate", 3, "box:3x3x2", "box:2x3x3", c); }},
    {"hex sculpting, seed 003", {"hex_holes", "hex_delete", "hex_collapse", "hex_growth"}, 400, 100, [](auto& c) { sculpt(false, c); }},
    {"hex sculpting, holon's improvements", {"hex_holes", "hex_delete", "hex_collapse", "hex_growth", "hex_growth_flexible", "hex_migrate"}, 400, 100, [](auto& c) { sculpt(true, c); }},
    {"hex disks", {"planner_general2", "hex_pivot"}, 50, 50, [](auto& c) {
         std::unique_ptr<planner::hex::DiskMetamodules> disks;
         plan("planner_general2", 2, "box:3x2", "box:2x3", c, [&](const planner::Problem& p, const planner::Execution& ex, std::int64_t anchor, int shape, const auto* old) {
             if (!disks) disks = std::make_unique<planner::hex::DiskMetamodules>(p);
             REQUIRE_MESSAGE(disks->fired(anchor, shape, old, ex.cells()), disks->failure());
         });
     }},
    {"Roombots coordination", {"roombots_reserve"}, 1, 1, [](auto&) {
         const auto table = planner::roombots::CloudTable::load(planner::roombots::CloudTable::defaultPath());
         for (const auto& setting : planner::roombots::loadScenario("chair", 1, 1))
             REQUIRE(planner::roombots::assemble(table, planner::roombots::Coupling::PAR, planner::roombots::Strategy::Reserve, setting).completed);
     }},
};

}  // namespace

TEST_CASE("every back-end applies only enabled instances of the rules it claims, and writes nothing else") {
    for (const Backend& b : kBackends) {
        const std::string name = b.name;
        CAPTURE(name);
        Conformance conformance(b.claims, b.period, b.window);
        b.run([&] { conformance.checkpoint(); });
        CHECK_MESSAGE(conformance.verdict() == "", conformance.verdict());
        CHECK(conformance.replayed() > 0);
    }
}

TEST_CASE("the harness catches a hand-written write, a rule that is not enabled, and a system not claimed") {
    PlannerSystem sys("planner_intermediate", 2);
    const planner::Problem problem = planner::makeProblem(*sys.model, planner::parseShape("box:3x3"), planner::parseShape("box:4x2"), std::nullopt, 1);
    const planner::BoxEngine& engine = *problem.engine;
    std::vector<planner::BoxEngine::Value> cells = problem.cells;
    std::int64_t anchor = -1;
    int shape = -1;
    problem.board->forEachInside([&](std::int64_t i, planner::Vec) {
        engine.forEachMatchAt(cells.data(), i, [&](int s) {
            if (shape < 0) anchor = i, shape = s;
        });
    });
    REQUIRE(shape >= 0);
    planner::BoxEngine::Value old[rules::RuleTables::kMaxCells];
    {  // the rule instance alone conforms
        Conformance c({"planner_intermediate"}, 1, 1);
        std::vector<planner::BoxEngine::Value> copy = cells;
        engine.apply(copy.data(), anchor, shape, old);
        c.checkpoint();
        CHECK(c.verdict() == "");
    }
    {  // a cell emptied by hand after it
        Conformance c({"planner_intermediate"}, 1, 1);
        std::vector<planner::BoxEngine::Value> copy = cells;
        engine.apply(copy.data(), anchor, shape, old);
        std::int64_t filled = -1;
        problem.board->forEachInside([&](std::int64_t i, planner::Vec) {
            if (copy[i] != 0) filled = i;
        });
        copy[filled] = 0;
        c.checkpoint();
        CHECK(c.verdict().find("a write no rule instance explains") != std::string::npos);
    }
    {  // an instance applied where it does not match
        std::int64_t elsewhere = -1;
        problem.board->forEachInside([&](std::int64_t i, planner::Vec) {
            if (!engine.matches(cells.data(), i, shape)) elsewhere = i;
        });
        REQUIRE(elsewhere >= 0);
        Conformance c({"planner_intermediate"}, 1, 1);
        std::vector<planner::BoxEngine::Value> copy = cells;
        engine.apply(copy.data(), elsewhere, shape, old);
        CHECK(c.verdict().find("not enabled") != std::string::npos);
    }
    {  // a back-end that claims another system
        Conformance c({"planner_general2"}, 1, 1);
        std::vector<planner::BoxEngine::Value> copy = cells;
        engine.apply(copy.data(), anchor, shape, old);
        CHECK(c.verdict().find("does not claim") != std::string::npos);
    }
}

}  // namespace holon::test
