// The plan monitor checks each round from what it changed (planner/Monitor.cpp); here it must stop
// at exactly the round where a from-scratch check of the whole configuration first fails — on
// broken planners that do disconnect (at any round, not only the rounds the monitor re-checks from
// scratch) and on correct ones that never do, in 2D and 3D, with every scheduler.

#include "PlannerSupport.h"

#include "planner/Monitor.h"

#include <sstream>
#include <string>

namespace holon::test {

namespace {

/// Face connectivity of the occupied cells, by a plain search over the whole board.
bool connectedFromScratch(const planner::Problem& problem, const std::vector<planner::BoxEngine::Value>& cells) {
    std::vector<char> seen(cells.size(), 0);
    std::vector<std::int64_t> stack;
    std::int64_t total = 0;
    for (std::size_t i = 0; i < cells.size(); ++i)
        if (cells[i]) ++total, stack.assign(1, static_cast<std::int64_t>(i));
    if (total == 0) return true;
    seen[stack[0]] = 1;
    std::int64_t reached = 0;
    while (!stack.empty()) {
        const std::int64_t i = stack.back();
        stack.pop_back();
        ++reached;
        for (int d = 0; d < problem.board->lattice().degree(); ++d) {
            const std::int64_t j = i + problem.board->step(d);
            if (cells[j] && !seen[j]) seen[j] = 1, stack.push_back(j);
        }
    }
    return reached == total;
}

bool isPowerOfFour(std::int64_t n) {
    while (n > 1 && n % 4 == 0) n /= 4;
    return n == 1;
}

struct Watched {
    std::int64_t monitorStop = -1, firstDisconnected = -1;  // the check (round or step) of each, counted from 1; -1: never
};

Watched watch(const planner::Problem& problem, planner::Scheduler scheduler, std::uint64_t seed) {
    auto allocator = planner::makeAllocator("random", problem, seed);
    planner::RunOptions options;
    options.scheduler = scheduler, options.seed = seed, options.budget = Budget::maxRounds(20000);
    planner::Execution ex(problem, *allocator, options);
    planner::Monitor monitor(problem, ex);
    Watched o;
    std::int64_t checks = 0;
    planner::RunObserver observer;
    observer.fired = [&](std::int64_t a, int s, const planner::BoxEngine::Value* old) { monitor.fired(a, s, old); };
    observer.roundEnd = [&](const planner::RunStats& stats) {
        ++checks;
        if (o.firstDisconnected < 0 && !connectedFromScratch(problem, ex.cells())) o.firstDisconnected = checks;
        const bool ok = monitor.roundEnd(stats);
        if (!ok) o.monitorStop = checks;
        return ok;
    };
    const planner::RunStats stats = ex.run(observer);
    if (o.monitorStop < 0 && !monitor.finish(stats)) o.monitorStop = checks;
    return o;
}

}  // namespace

TEST_CASE("the monitor stops at the first disconnected round, as a check from scratch would") {
    int disconnected = 0, late = 0;
    for (const char* rules : {"planner_no_guard", "planner_intermediate"})
        for (int dimension : {2, 3})
            for (std::uint64_t seed = 1; seed <= 12; ++seed) {
                const std::string path = std::string(HOLON_TEST_DIR) + "/checker/broken/" + rules + ".holon";
                std::ostringstream diagnostics;
                const rules::System system = std::string(rules) == "planner_no_guard" ? *rules::loadSystem(path, diagnostics) : rules::librarySystem(rules);
                const rules::Model model(system, rules::Lattice::get(dimension == 3 ? rules::LatticeKind::Cubic3D : rules::LatticeKind::Square2D));
                planner::Random random(seed);
                const planner::Vec box = dimension == 3 ? planner::Vec{6, 6, 6} : planner::Vec{16, 16, 1};
                const planner::Shape a = randomBlob(random, dimension, box, {0, 0, 0}, dimension == 3 ? 90 : 120);
                const planner::Shape b = randomBlob(random, dimension, box, {0, 0, 0}, dimension == 3 ? 90 : 120);
                const planner::Problem problem = planner::makeProblem(model, a, b, planner::Vec{0, 0, 0}, seed);
                for (planner::Scheduler scheduler : {planner::Scheduler::Sync, planner::Scheduler::Async}) {
                    CAPTURE(rules);
                    CAPTURE(dimension);
                    CAPTURE(seed);
                    const Watched o = watch(problem, scheduler, seed);
                    CHECK(o.monitorStop == o.firstDisconnected);
                    disconnected += o.firstDisconnected >= 0;
                    // a check the monitor makes only from the changes: not a power of four
                    late += o.firstDisconnected > 0 && !isPowerOfFour(o.firstDisconnected);
                }
            }
    CHECK(disconnected >= 20);  // the broken planner does disconnect, so the comparison means something
    CHECK(late >= 10);
}

}  // namespace holon::test
