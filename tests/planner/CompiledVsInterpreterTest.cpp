// The compiled planner engine against the reference interpreter, side by side: on random start and
// target shapes, every instance the planner fires must be enabled in the interpreter and lead to
// the same configuration, and after every step or round the two must agree on the whole set of
// enabled instances. Sync rounds are replayed one instance at a time, which also checks that a
// round is an interleaving.

#include "PlannerSupport.h"

#include "rules/Interpreter.h"

namespace holon::test {

namespace {

struct SideBySide {
    const planner::Problem& problem;
    rules::Region region;
    rules::Interpreter in;
    rules::Configuration config;
    std::vector<std::int64_t> boardOf;  // region cell -> board index
    int checks = 0;

    explicit SideBySide(const planner::Problem& p)
        : problem(p), region(rules::Region::box(p.board->lattice(), p.board->extent())), in(*p.model, region) {
        config = in.empty();
        for (int i = 0; i < region.size(); ++i) {
            const std::int64_t b = p.board->index(region.cell(i) + p.board->lower());
            boardOf.push_back(b);
            config.cells[i] = p.cells[b];
            config.inputs[i] = p.engine->combo(b) == p.tables->comboIndex(1u << p.schema.target) ? 1u << p.schema.target : 0u;
        }
    }

    rules::Instance instance(std::int64_t anchor, int shape) const {
        return {shape, problem.board->point(anchor) - problem.board->lower() - problem.model->shapes()[shape].offsets[0]};
    }

    void fired(std::int64_t anchor, int shape) {
        const rules::Instance inst = instance(anchor, shape);
        REQUIRE(in.matches(config, inst));
        config = in.apply(config, inst);
    }

    void compare(const planner::Execution& ex) {
        ++checks;
        for (int i = 0; i < region.size(); ++i) REQUIRE(config.cells[i] == ex.cells()[boardOf[i]]);
        std::set<std::pair<int, rules::Vec>> expected, actual;
        for (const rules::Instance& inst : in.enabled(config)) expected.insert({inst.shape, inst.anchor});
        for (int i = 0; i < region.size(); ++i)
            for (int s = 0; s < problem.engine->shapeCount(); ++s)
                if (ex.enabled(boardOf[i], s)) {
                    const rules::Instance inst = instance(boardOf[i], s);
                    actual.insert({inst.shape, inst.anchor});
                }
        REQUIRE(expected == actual);
    }
};

/// Runs the planner on random problems next to the interpreter. `mayDeadlock`: the system is known
/// to get stuck on some small problems (the general-lock planners, see their rule files), so a
/// stuck run is accepted when the interpreter confirms it; returns how many runs got stuck.
int sideBySide(const std::string& stem, int dimension, planner::Scheduler scheduler, int runs, bool mayDeadlock = false) {
    PlannerSystem sys(stem, dimension);
    planner::Random random(7);
    const planner::Vec box = dimension == 3 ? planner::Vec{4, 3, 3} : planner::Vec{6, 5, 1};
    const bool resources = planner::PlannerSchema::of(sys.model->system()).resource >= 0;
    int compared = 0, stuck = 0;
    for (int run = 0; run < runs; ++run) {
        const planner::Vec common{static_cast<int>(random.below(box.x)), static_cast<int>(random.below(box.y)), static_cast<int>(random.below(box.z))};
        // With resources the target must hold the start's mass: keep the sizes close.
        const int size = 3 + static_cast<int>(random.below(10));
        const int targetSize = resources ? std::max(3, size - 1 + static_cast<int>(random.below(3))) : 3 + static_cast<int>(random.below(10));
        planner::Shape start = randomBlob(random, dimension, box, common, size);
        planner::Shape target = randomBlob(random, dimension, box, common, targetSize);
        planner::Problem problem;
        try {
            problem = planner::makeProblem(*sys.model, start, target, std::nullopt, run);
        } catch (const InputError&) {
            continue;  // a mass the target cannot hold: not a plan
        }
        auto allocator = planner::makeAllocator("random", problem, static_cast<std::uint64_t>(run));
        planner::RunOptions options;
        options.scheduler = scheduler, options.seed = static_cast<std::uint64_t>(run), options.budget = Budget::maxSteps(200000);
        planner::Execution ex(problem, *allocator, options);
        SideBySide both(problem);
        both.compare(ex);
        planner::RunObserver observer;
        observer.fired = [&](std::int64_t anchor, int shape, const planner::BoxEngine::Value*) { both.fired(anchor, shape); };
        observer.roundEnd = [&](const planner::RunStats&) {
            both.compare(ex);
            return true;
        };
        const planner::RunStats stats = ex.run(observer);
        both.compare(ex);
        INFO(stem << " run " << run << " stopped by " << stopReasonName(stats.stopped));
        CHECK(stats.complete == both.in.atGoal(both.config));
        if (mayDeadlock) {
            // A stuck run must be stuck in the reference semantics too: nothing enabled, goal not reached.
            if (!stats.complete) CHECK(both.in.enabled(both.config).empty());
            stuck += !stats.complete;
        } else {
            CHECK(stats.complete);
        }
        compared += both.checks > 1;
    }
    // Most random problems are plans (the rest hold a mass the target cannot): the test is not vacuous.
    CHECK(compared >= runs / 2);
    return stuck;
}

}  // namespace

TEST_CASE("compiled planner = interpreter, step by step: intermediate, async, 2D and 3D") {
    sideBySide("planner_intermediate", 2, planner::Scheduler::Async, 30);
    sideBySide("planner_intermediate", 3, planner::Scheduler::Async, 15);
}

TEST_CASE("compiled planner = interpreter: intermediate, sync rounds replayed as interleavings") {
    sideBySide("planner_intermediate", 2, planner::Scheduler::Sync, 30);
    sideBySide("planner_intermediate", 3, planner::Scheduler::Sync, 15);
}

TEST_CASE("compiled planner = interpreter: general1 with the random allocator, async and sync") {
    sideBySide("planner_general1", 2, planner::Scheduler::Async, 20);
    sideBySide("planner_general1", 2, planner::Scheduler::Sync, 20);
    sideBySide("planner_general1", 3, planner::Scheduler::Sync, 8);
}

TEST_CASE("compiled planner = interpreter: general2/3 and general-lock2/3 (3D: more than 64 rule orientations)") {
    for (const char* stem : {"planner_general2", "planner_general3"}) {
        sideBySide(stem, 2, planner::Scheduler::Sync, 8);
        sideBySide(stem, 2, planner::Scheduler::Async, 6);
        sideBySide(stem, 3, planner::Scheduler::Sync, 4);
    }
    for (const char* stem : {"planner_general_lock2", "planner_general_lock3"}) {
        int stuck = sideBySide(stem, 2, planner::Scheduler::Sync, 40, true);
        stuck += sideBySide(stem, 2, planner::Scheduler::Async, 10, true);
        stuck += sideBySide(stem, 3, planner::Scheduler::Sync, 4, true);
        MESSAGE(std::string(stem) << ": " << stuck << " of 54 small random problems deadlocked");
    }
}

TEST_CASE("compiled planner = interpreter under the adversarial scheduler") {
    sideBySide("planner_intermediate", 2, planner::Scheduler::Adversarial, 15);
    sideBySide("planner_general1", 2, planner::Scheduler::Adversarial, 15);
}

}  // namespace holon::test
