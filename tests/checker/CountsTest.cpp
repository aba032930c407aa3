// State-count oracles: the explorer's counts of legal configurations, edges and components for
// pixel with connectivity are compared with an independent brute force (every subset, flood fill,
// union-find) on square regions up to 4x4 and small hex and cubic regions.

#include "BruteForce.h"
#include "CheckSupport.h"
#include "checker/Graph.h"
#include "rules/TextFile.h"
#include <set>

using namespace holon;

TEST_CASE("explorer counts agree with brute force for pixel with connectivity") {
    for (const char* spec : {"square:2x2", "square:3x2", "square:3x3", "square:4x3", "square:4x4", "hex:r1", "hex:r2", "cubic:2x2x2", "cubic:3x2x2"}) {
        CAPTURE(spec);
        auto c = test::checkAll(rules::librarySystem("pixel"), spec);
        const auto oracle = test::pixelBruteForce(c.world.region);
        CHECK(c.report.stats.states == oracle.legal);
        CHECK(c.report.stats.edges == oracle.edges);
        CHECK(c.report.components == static_cast<int>(oracle.components));
    }
}

TEST_CASE("the --all graph is the same whether its states are ranked or hashed") {
    for (const char* stem : {"pixel", "intermediate", "general2"}) {
        CAPTURE(stem);
        const test::World world(rules::librarySystem(stem), stem == std::string("pixel") ? "hex:r2" : "square:3x2");
        const rules::Engine engine(*world.model, world.region, {});
        std::vector<std::set<std::pair<std::vector<rules::CellValue>, std::vector<rules::CellValue>>>> graphs;
        for (bool ranked : {true, false}) {
            checker::Explorer::Options options;
            options.rankAllLegal = ranked;
            checker::Explorer ex(engine, options);
            ex.addAllLegal();
            ex.explore();
            std::set<std::pair<std::vector<rules::CellValue>, std::vector<rules::CellValue>>> edges;
            for (checker::StateId s : ex.ids()) {
                CHECK(ex.find(ex.cells(s).data()) == s);
                for (std::uint64_t e = ex.rowStart()[s]; e < ex.rowStart()[s + 1]; ++e) edges.insert({ex.cells(s), ex.cells(ex.successors()[e])});
            }
            graphs.push_back(std::move(edges));
        }
        CHECK(graphs[0].size() > 100);
        CHECK(graphs[0] == graphs[1]);
    }
}

TEST_CASE("the explored graph is the same on one thread and on two") {
    checker::Limits one, two;
    one.threads = 1, two.threads = 2;
    for (const char* stem : {"intermediate", "general2"}) {
        auto a = test::checkAll(rules::librarySystem(stem), "square:3x2", one);
        auto b = test::checkAll(rules::librarySystem(stem), "square:3x2", two);
        CHECK(a.report.stats.states == b.report.stats.states);
        CHECK(a.report.stats.edges == b.report.stats.edges);
        CHECK(a.report.components == b.report.components);
    }
}

TEST_CASE("reachable exploration: the explorer's successors are the interpreter's") {
    auto c = test::checkFrom(rules::librarySystem("planner_intermediate"), "square:4x2", "UFU.\nUUU.", ".###\n.###");
    const checker::Explorer& ex = *c.kept.explorer;
    std::size_t checked = 0;
    for (checker::StateId s : ex.ids()) {
        rules::Configuration config = c.world.in->empty();
        config.inputs = ex.engine().inputs();
        config.cells = ex.cells(s);
        std::set<std::vector<rules::CellValue>> mine, reference;
        for (std::uint64_t e = ex.rowStart()[s]; e < ex.rowStart()[s + 1]; ++e) mine.insert(ex.cells(ex.successors()[e]));
        for (const auto& i : c.world.in->enabled(config)) reference.insert(c.world.in->successor(config, i)->cells);
        CHECK(mine == reference);
        if (++checked > 2000) break;
    }
    CHECK(checked > 100);
}

TEST_CASE("limits stop the search cleanly with a partial report") {
    checker::Limits limits;
    limits.maxStates = 1000;
    auto c = test::checkFrom(rules::librarySystem("planner_intermediate"), "square:4x3", "UFU.\nUUU.\nUUU.", ".###\n.###\n.###", limits);
    CHECK(c.report.stats.stopped == StopReason::MaxStates);
    CHECK(c.report.stats.frontier > 0);
    CHECK(c.report.stats.states <= 1000);  // at most the cap is stored
    CHECK(c.report.components == -1);
    for (const auto& p : c.report.properties) CHECK(p.verdict == checker::Verdict::Unknown);
    limits = {};
    limits.timeoutSeconds = 1e-9;
    auto t = test::checkAll(rules::librarySystem("intermediate"), "square:4x3", limits);
    CHECK(t.report.stats.stopped == StopReason::Timeout);
}

TEST_CASE("a region too large for --all is refused with a message") {
    CHECK_THROWS_WITH_AS(test::checkAll(rules::librarySystem("general2"), "square:8x8"), doctest::Contains("too many to enumerate"), holon::InputError);
}

TEST_CASE("successors and legality on words give the graph the cell-by-cell path gives") {
    // Every kind of rule the library has: guards, inputs, pointers, integer fields, copies (moves),
    // pattern quantifiers, 19-cell shapes on a hex disk (no word shifts there); from random full
    // configurations, so the legality of new states is decided (a complete --all store never asks).
    struct Case {
        std::string stem, spec, start;  // start: a picture in examples/hex/checker, else random
    };
    const std::vector<Case> cases = {{"pixel", "square:4x3", ""}, {"general1", "square:3x3", ""}, {"general_lock2", "square:3x2", ""}, {"planner_intermediate", "square:3x3", ""}, {"planner_general2", "square:3x2", ""}, {"roombots_reserve", "square:4x3", ""}, {"hex_holes", "hex:r4", "neck.txt"}, {"hex_collapse", "hex:r3", "blob.txt"}, {"pixel", "cubic:3x2x2", ""}};
    for (const auto& [stem, spec, start] : cases) {
        CAPTURE(stem);
        CAPTURE(spec);
        const test::World world(rules::librarySystem(stem), spec);
        std::uint64_t seed = 12345;
        auto next = [&] { return seed = seed * 6364136223846793005ull + 1442695040888963407ull, seed >> 33; };
        std::vector<std::uint32_t> inputs(world.region.size());
        for (auto& in : inputs) in = static_cast<std::uint32_t>(next() & ((1u << world.system.inputs.size()) - 1));
        const rules::Engine engine(*world.model, world.region, inputs);
        const int a = world.model->alphabet().size();
        std::vector<std::vector<rules::CellValue>> starts;
        if (!start.empty()) starts.push_back(world.ascii(rules::readTextFile(std::string(HOLON_TEST_DIR) + "/../examples/hex/checker/" + start)).cells);
        for (int k = 0; start.empty() && starts.size() < 3 && k < 1000; ++k) {
            std::vector<rules::CellValue> cells(world.region.size());
            for (auto& c : cells) c = static_cast<rules::CellValue>(1 + next() % (a - 1));
            if (k % 2) cells[next() % cells.size()] = 0;
            if (engine.legal(cells.data())) starts.push_back(cells);
        }
        REQUIRE(!starts.empty());
        std::vector<std::set<std::pair<std::vector<rules::CellValue>, std::vector<rules::CellValue>>>> graphs;
        for (bool onWords : {true, false}) {
            checker::Explorer::Options options;
            options.onWords = onWords;
            options.limits.maxStates = 200000;
            checker::Explorer ex(engine, options);
            for (const auto& s : starts) ex.addInitial(s.data());
            ex.explore();
            std::set<std::pair<std::vector<rules::CellValue>, std::vector<rules::CellValue>>> edges;
            for (checker::StateId s : ex.ids()) {
                CHECK(engine.legal(ex.cells(s).data()));
                for (std::uint64_t e = ex.rowStart()[s]; e < ex.rowStart()[s + 1]; ++e) edges.insert({ex.cells(s), ex.cells(ex.successors()[e])});
            }
            graphs.push_back(std::move(edges));
        }
        CHECK(graphs[0].size() > 10);
        CHECK(graphs[0] == graphs[1]);
    }
}

TEST_CASE("--all stores the same states whether threads keep a bitmap each or list indices") {
    // hex:r2 has 2^19 candidates. A quarter of 450 KiB (115,200 bytes) holds the ranking (98,304
    // bytes) and one thread's 64 KiB bitmap, not two: two threads list indices. At most two
    // modules: 191 states, which the memory bound holds (--memory counts them too).
    const test::World world(test::parse("system two\nstates M\nrule create / destroy: _ <=> M\nconstraint count(#) <= 2\n"), "hex:r2");
    const rules::Engine engine(*world.model, world.region, {});
    std::vector<std::vector<std::vector<rules::CellValue>>> stored;
    for (int threads : {1, 2}) {
        checker::Explorer::Options options;
        options.limits.threads = threads;
        options.limits.memoryBytes = 450 << 10;
        checker::Explorer ex(engine, options);
        ex.addAllLegal();
        std::vector<std::vector<rules::CellValue>> states;
        for (checker::StateId s : ex.ids()) {
            CHECK(ex.find(ex.cells(s).data()) == s);
            states.push_back(ex.cells(s));
        }
        stored.push_back(std::move(states));
    }
    CHECK(stored[0].size() == 191);
    CHECK(stored[0] == stored[1]);  // ids are ranks either way: the same order
}
