// The explorer's limits: a failure in a worker thread (an allocation that fails, or a bug) never
// aborts the process nor leaves a thread running; --memory and --max-states bound what is stored,
// on small regions and on regions far larger than the states explored; a limit leaves a graph
// whose every state and edge is real.

#include "CheckSupport.h"
#include "checker/Explorer.h"

#include <atomic>
#include <new>
#include <stdexcept>

using namespace holon;

namespace {

/// general1 on square:5x5 from the 2x5 block of D (the explorer benchmark's workload: 591,161 states).
struct Block {
    test::World world{rules::librarySystem("general1"), "square:5x5"};
    rules::Engine engine{*world.model, world.region, {}};
    rules::Configuration start = world.ascii("DDDDD\nDDDDD\n.....\n.....\n.....");
};

/// Every stored state is legal and reached from its parent by its instance's step.
void checkConsistent(const checker::Explorer& ex) {
    for (checker::StateId s : ex.ids()) {
        const auto cells = ex.cells(s);
        CHECK(ex.engine().legal(cells.data()));
        if (ex.parent(s) != checker::kNoState) CHECK(ex.parent(s) < ex.store().capacityUsed());
    }
}

}  // namespace

TEST_CASE("a worker that cannot allocate stops the search as a memory limit, on every thread") {
    Block b;
    for (int threads : {1, 2}) {
        CAPTURE(threads);
        std::atomic<int> stored{0};
        checker::Explorer::Options options;
        options.limits.threads = threads;
        // From the 5,000th new state on, every worker's allocation fails (the helper threads' too).
        options.onState = [&](checker::StateId, const rules::CellValue*) {
            if (++stored > 5000) throw std::bad_alloc();
        };
        checker::Explorer ex(b.engine, options);
        ex.addInitial(b.start.cells.data());
        const checker::ExploreStats& stats = ex.explore();
        CHECK(stats.stopped == StopReason::Memory);
        CHECK(stats.states >= 5000);
        CHECK(stats.states < 591161);
        checkConsistent(ex);
    }
}

TEST_CASE("any other failure in a worker is rethrown once every worker is back") {
    Block b;
    checker::Explorer::Options options;
    options.limits.threads = 2;
    std::atomic<int> stored{0};
    options.onState = [&](checker::StateId, const rules::CellValue*) {
        if (++stored == 3000) throw std::logic_error("a bug in a worker");
    };
    checker::Explorer ex(b.engine, options);
    ex.addInitial(b.start.cells.data());
    CHECK_THROWS_WITH_AS(ex.explore(), "a bug in a worker", std::logic_error);
}

TEST_CASE("--max-states stores at most the limit and stops within one state's successors of it") {
    Block b;
    checker::Explorer::Options options;
    options.limits.maxStates = 1000;
    checker::Explorer ex(b.engine, options);
    ex.addInitial(b.start.cells.data());
    const checker::ExploreStats& stats = ex.explore();
    CHECK(stats.stopped == StopReason::MaxStates);
    CHECK(stats.states <= 1000);
    CHECK(stats.states + b.engine.instances().size() >= 1000);
    checkConsistent(ex);
}

TEST_CASE("--max-states N: an exploration of exactly N states completes, one of N + 1 stops, on any number of threads") {
    test::World world{rules::librarySystem("general1"), "square:4x4"};
    const rules::Engine engine{*world.model, world.region, {}};
    const rules::Configuration start = world.ascii("DDDD\nDDDD\n....\n....");
    const auto explore = [&](std::uint64_t maxStates, int threads) -> checker::ExploreStats {
        checker::Explorer::Options options;
        options.limits.maxStates = maxStates, options.limits.threads = threads;
        checker::Explorer ex(engine, options);
        ex.addInitial(start.cells.data());
        return ex.explore();
    };
    const checker::ExploreStats all = explore(std::uint64_t{1} << 40, 1);
    REQUIRE(all.stopped == StopReason::Finished);
    REQUIRE(all.states > 100);
    for (int threads : {1, 2, 4}) {
        CAPTURE(threads);
        const checker::ExploreStats exact = explore(all.states, threads);
        CHECK(exact.stopped == StopReason::Finished);
        CHECK(exact.states == all.states);
        const checker::ExploreStats over = explore(all.states - 1, threads);
        CHECK(over.stopped == StopReason::MaxStates);
        CHECK(over.states <= all.states - 1);
    }
}

TEST_CASE("--memory bounds what the explorer holds, on a region much larger than the states") {
    // pixel on square:64x64 (4,096 cells, 8,192 instances) from three modules: a state is 512
    // bytes, one state's successors 4,096 configurations. The room reserved for a round's new
    // states was 64 states x 8,192 instances of 512 bytes, 256 MiB, before any was stored.
    const test::World world(rules::librarySystem("pixel"), "square:64x64");
    const rules::Engine engine(*world.model, world.region, {});
    const auto start = world.ascii("MMM");
    for (const std::uint64_t memory : {std::uint64_t{512} << 10, std::uint64_t{8} << 20}) {
        CAPTURE(memory);
        checker::Explorer::Options options;
        options.limits.memoryBytes = memory;
        options.limits.maxStates = 100;
        checker::Explorer ex(engine, options);
        ex.addInitial(start.cells.data());
        const checker::ExploreStats& stats = ex.explore();
        CHECK(stats.bytes <= memory);
        CHECK(stats.states >= 1);
        // 8 MiB holds 100 states and the buffers of two workers (a word per instance); 512 KiB does not.
        CHECK(stats.stopped == (memory == std::uint64_t{8} << 20 ? StopReason::MaxStates : StopReason::Memory));
        checkConsistent(ex);
    }
}
