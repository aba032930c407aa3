// holon path against an independent breadth-first search through the reference interpreter: on
// every library system, from random legal configurations, the shortest path to a reachable
// configuration (and to the goal) has exactly the interpreter's BFS distance and replays, by each
// search (forward, bidirectional, A*); a configuration outside the reachable set is
// "unreachable", and a limit makes the answer undecided. Rule steps run backwards are compared
// with every forward step of tiny regions, and the parallel schedules of the paths are replayed.

#include "TestSupport.h"
#include "checker/Path.h"
#include "checker/PathSchedule.h"
#include "rules/Engine.h"

#include <set>

#include <map>
#include <random>

using namespace holon;
using test::World;

namespace {

/// Distances from `start` by the interpreter alone, level by level until a level ends with more
/// than `cap` states: every state found then has its exact distance. `complete`: nothing left.
struct ReferenceBfs {
    std::map<std::vector<rules::CellValue>, int> distance;
    bool complete = false;
    ReferenceBfs(const rules::Interpreter& in, const rules::Configuration& start, std::size_t cap) {
        std::vector<rules::Configuration> level{start};
        distance[start.cells] = 0;
        for (int d = 1; !level.empty(); ++d) {
            if (distance.size() > cap) return;
            std::vector<rules::Configuration> next;
            for (const auto& c : level)
                for (const auto& i : in.enabled(c)) {
                    auto s = *in.successor(c, i);
                    if (distance.emplace(s.cells, d).second) next.push_back(std::move(s));
                }
            level = std::move(next);
        }
        complete = true;
    }
};

/// Random inputs for a round (each cell's bits at random), fixed while its configurations are drawn.
std::vector<std::uint32_t> randomInputs(const World& w, std::mt19937& rng) {
    std::vector<std::uint32_t> inputs(w.region.size(), 0);
    if (!w.system.inputs.empty())
        for (auto& bits : inputs) bits = static_cast<std::uint32_t>(rng() & ((1u << w.system.inputs.size()) - 1));
    return inputs;
}

/// A random configuration the engine finds legal (the reference search checks it again), or
/// nothing after many tries.
std::optional<rules::Configuration> randomLegal(const World& w, const rules::Engine& engine, std::mt19937& rng) {
    const int alphabet = w.model->alphabet().size();
    for (int attempt = 0; attempt < 3000; ++attempt) {
        rules::Configuration c{std::vector<rules::CellValue>(w.region.size(), 0), engine.inputs()};
        const double density = std::uniform_real_distribution<double>(0.1, 0.9)(rng);
        for (auto& cell : c.cells)
            if (std::uniform_real_distribution<double>(0, 1)(rng) < density)
                cell = static_cast<rules::CellValue>(std::uniform_int_distribution<int>(1, alphabet - 1)(rng));
        if (engine.legal(c.cells.data())) return c;
    }
    return std::nullopt;
}

constexpr checker::PathSearch kSearches[] = {checker::PathSearch::Forward, checker::PathSearch::Bidirectional, checker::PathSearch::AStar};

/// The path's schedule replays, puts no two interfering steps in one round and takes at most one
/// round per step.
void checkSchedule(const checker::Trace& path, const rules::Engine& engine, const rules::Interpreter& in) {
    const checker::Footprints footprints(engine);
    const checker::Schedule schedule = checker::compactSteps(path, engine, footprints);
    std::string why;
    CHECK_MESSAGE(checker::replaySchedule(schedule, path, engine, in, &why), why);
    CHECK(schedule.makespan() <= path.steps.size() - 1);
    for (const auto& round : schedule.rounds)
        for (std::size_t a = 0; a < round.size(); ++a)
            for (std::size_t b = a + 1; b < round.size(); ++b) CHECK_FALSE(checker::Footprints::interfere(footprints.of(path.steps[round[a]].placed), footprints.of(path.steps[round[b]].placed)));
}

}  // namespace

TEST_CASE("shortest paths have the reference interpreter's BFS distances on every library system") {
    std::mt19937 rng(29), pairRng(2930);  // pairs of their own, so that the starts stay those of seed 29
    int systemsCovered = 0, pathsChecked = 0, goalsChecked = 0, unreachableChecked = 0, randomPairs = 0;
    int bidirectionalPaths[2] = {0, 0};  // [ran bidirectionally]
    for (const std::string& file : rules::libraryFiles()) {
        const rules::System system = rules::librarySystem(std::filesystem::path(file).stem().string());
        bool covered = false;
        for (const char* spec : {"square:3x3", "hex:r2", "cubic:2x2x2"}) {
            if (system.lattice && *system.lattice != rules::Region::parse(spec).lattice().kind()) continue;
            INFO(system.name << " on " << spec);
            World w(system, spec);
            for (int round = 0; round < 3; ++round) {
                const rules::Engine engine(*w.model, w.region, randomInputs(w, rng));
                const auto start = randomLegal(w, engine, rng);
                if (!start) continue;
                REQUIRE(w.in->legal(*start));
                const ReferenceBfs reference(*w.in, *start, 300);
                if (reference.distance.size() < 2) continue;  // no rule enabled: nothing to find
                checker::PathQuery query;
                query.from = *start;
                query.limits.threads = 1;
                // Targets: the farthest state found, and a few at random.
                std::vector<std::pair<std::vector<rules::CellValue>, int>> found(reference.distance.begin(), reference.distance.end());
                std::vector<std::size_t> picks{static_cast<std::size_t>(std::max_element(found.begin(), found.end(), [](auto& a, auto& b) { return a.second < b.second; }) - found.begin())};
                for (int k = 0; k < 3; ++k) picks.push_back(std::uniform_int_distribution<std::size_t>(0, found.size() - 1)(rng));
                for (std::size_t pick : picks)
                    for (const auto search : kSearches) {
                        INFO(checker::pathSearchName(search));
                        query.to = rules::Configuration{found[pick].first, start->inputs};
                        query.search = search;
                        const auto result = checker::shortestPath(engine, query);
                        REQUIRE(result.outcome == checker::PathOutcome::Found);
                        CHECK((result.search == search || !result.fallback.empty()));
                        CHECK(static_cast<int>(result.trace.steps.size()) - 1 == found[pick].second);
                        std::string why;
                        CHECK_MESSAGE(checker::replay(result.trace, engine, *w.in, &why), why);
                        CHECK(result.trace.steps.back().cells == found[pick].first);
                        if (search == checker::PathSearch::AStar) CHECK(result.bound <= found[pick].second);
                        if (search == checker::PathSearch::Bidirectional) checkSchedule(result.trace, engine, *w.in), ++bidirectionalPaths[result.search == search];
                        ++pathsChecked;
                    }
                query.search = checker::PathSearch::Auto;
                int nearest = -1;
                if (system.goal)
                    for (const auto& [cells, d] : found)
                        if (w.in->atGoal({cells, start->inputs}) && (nearest < 0 || d < nearest)) nearest = d;
                // (A goal beyond the reference's levels would need the whole space searched.)
                if (system.goal && (nearest >= 0 || reference.complete)) {
                    query.to.reset();
                    const auto result = checker::shortestPath(engine, query);
                    if (nearest >= 0) {
                        REQUIRE(result.outcome == checker::PathOutcome::Found);
                        CHECK(static_cast<int>(result.trace.steps.size()) - 1 == nearest);
                        CHECK(w.in->atGoal({result.trace.steps.back().cells, start->inputs}));
                        ++goalsChecked;
                    } else if (reference.complete) {
                        CHECK(result.outcome == checker::PathOutcome::Unreachable);
                        CHECK(result.stats.states == reference.distance.size());
                        ++goalsChecked;
                    }
                }
                // A legal configuration the complete reference search did not reach.
                if (reference.complete)
                    for (int attempt = 0; attempt < 20; ++attempt) {
                        const auto other = randomLegal(w, engine, rng);
                        if (!other) break;
                        if (reference.distance.count(other->cells)) continue;
                        query.to = *other;
                        REQUIRE(w.in->legal(*query.to));
                        for (const auto search : kSearches) {
                            INFO(checker::pathSearchName(search));
                            query.search = search;
                            const auto result = checker::shortestPath(engine, query);
                            CHECK(result.outcome == checker::PathOutcome::Unreachable);
                            // The side that ran dry was searched whole: from the start, every reachable configuration.
                            if (result.closedFromStart) CHECK(result.closed == reference.distance.size());
                            if (search == checker::PathSearch::Forward) CHECK(result.stats.states == reference.distance.size());
                        }
                        query.search = checker::PathSearch::Auto;
                        ++unreachableChecked;
                        break;
                    }
                // Seeded random targets, reachable or not: every search agrees with the reference
                // where it is complete, and with the others where it is not.
                for (int pair = 0; pair < 2; ++pair) {
                    const auto other = randomLegal(w, engine, pairRng);
                    if (!other) break;
                    query.to = *other;
                    query.limits.maxStates = 100'000;
                    const auto known = reference.distance.find(other->cells);
                    std::optional<std::size_t> length;
                    for (const auto search : kSearches) {
                        INFO(checker::pathSearchName(search) << ", random target " << pair);
                        query.search = search;
                        const auto result = checker::shortestPath(engine, query);
                        if (known != reference.distance.end() || reference.complete)
                            REQUIRE(result.outcome == (known != reference.distance.end() ? checker::PathOutcome::Found : checker::PathOutcome::Unreachable));
                        if (result.outcome != checker::PathOutcome::Found) continue;
                        const std::size_t steps = result.trace.steps.size() - 1;
                        if (known != reference.distance.end()) CHECK(static_cast<int>(steps) == known->second);
                        if (length) CHECK(steps == *length);
                        length = steps;
                        std::string why;
                        CHECK_MESSAGE(checker::replay(result.trace, engine, *w.in, &why), why);
                    }
                    query.search = checker::PathSearch::Auto;
                    query.limits.maxStates = checker::Limits{}.maxStates;
                    ++randomPairs;
                }
                covered = true;
            }
        }
        systemsCovered += covered;
        if (!covered) MESSAGE(system.name << " not covered: no random legal start with an enabled rule");
    }
    MESSAGE(systemsCovered << " systems, " << pathsChecked << " paths, " << goalsChecked << " goal searches, " << unreachableChecked << " unreachable targets, "
                           << randomPairs << " random pairs; bidirectional asked " << bidirectionalPaths[0] + bidirectionalPaths[1] << " times, fell back " << bidirectionalPaths[0]);
    CHECK(systemsCovered >= 16);  // all but the hex systems whose rules need more than hex:r2
    CHECK(goalsChecked >= 5);
    CHECK(unreachableChecked >= 3);
    CHECK(randomPairs >= 30);
    CHECK(bidirectionalPaths[0] == 0);  // every covered library system runs backwards
}

TEST_CASE("a start at the goal is a path of no steps, though a smaller goal configuration lies one step away") {
    // The forward search kept the smallest target of the levels it had stored, and level 1 is
    // stored while the start's level is expanded: 'A..' lost to '.A.' (an audit).
    World w(test::parse("system g\nlattice square2d\nstates A\nrule r: A _ => _ A\ngoal some(A)\n"), "square:3x1");
    checker::PathQuery query;
    query.from = w.ascii("A..\n");
    const rules::Engine engine(*w.model, w.region, query.from.inputs);
    for (const auto search : {checker::PathSearch::Auto, checker::PathSearch::Forward}) {
        query.search = search;
        const auto result = checker::shortestPath(engine, query);
        REQUIRE(result.outcome == checker::PathOutcome::Found);
        CHECK(result.trace.steps.size() == 1);
        CHECK(result.trace.steps[0].cells == query.from.cells);
    }
}

TEST_CASE("a path search stopped by a limit is undecided, not unreachable, and claims no path within d steps only when the shortest is longer") {
    World w = World::library("pixel", "square:4x4");
    checker::PathQuery query;
    query.from = w.ascii("M...\n....\n....\n....\n");
    query.to = w.ascii("....\n....\n....\n...M\n");
    const rules::Engine engine(*w.model, w.region, query.from.inputs);
    for (const auto search : kSearches) {
        INFO(checker::pathSearchName(search));
        query.search = search;
        query.limits.maxStates = 20;
        const auto stopped = checker::shortestPath(engine, query);
        CHECK(stopped.outcome == checker::PathOutcome::Undecided);
        CHECK(stopped.stats.stopped == StopReason::MaxStates);
        query.limits.maxStates = 1'000'000;
        const auto found = checker::shortestPath(engine, query);
        REQUIRE(found.outcome == checker::PathOutcome::Found);
        CHECK(found.search == search);
        CHECK(found.trace.steps.size() - 1 == 12);  // grow 6 cells along an L to the corner, shrink 6 behind
        // How far a stopped search got (stats.depth steps with no path), under every cap: a
        // bidirectional search cut off in the middle of a level counted that level as finished
        // and claimed one step too many ("none within 12 steps" with a 12-step path).
        for (std::uint64_t cap = 1; cap < found.stats.states; ++cap) {
            CAPTURE(cap);
            query.limits.maxStates = cap;
            const auto capped = checker::shortestPath(engine, query);
            if (capped.outcome == checker::PathOutcome::Undecided) CHECK(capped.stats.depth < 12);
        }
    }
}

TEST_CASE("a path search that stores exactly Limits::maxStates states decides, one that needs one more is undecided") {
    World w = World::library("pixel", "square:4x4");
    checker::PathQuery query;
    query.from = w.ascii("M...\n....\n....\n....\n");
    const rules::Engine engine(*w.model, w.region, query.from.inputs);
    query.to = w.ascii("....\n....\n....\n...M\n");
    // The searches of SearchMeter; the forward search runs on the explorer, whose boundary
    // LimitsTest holds (and may find the target before the level that stored it ends).
    for (const auto search : {checker::PathSearch::Bidirectional, checker::PathSearch::AStar}) {
        INFO(checker::pathSearchName(search));
        query.search = search;
        query.limits.maxStates = 1'000'000;
        const auto free = checker::shortestPath(engine, query);
        REQUIRE(free.outcome == checker::PathOutcome::Found);
        query.limits.maxStates = free.stats.states;
        const auto exact = checker::shortestPath(engine, query);
        CHECK(exact.outcome == checker::PathOutcome::Found);
        CHECK(exact.stats.states == free.stats.states);
        query.limits.maxStates = free.stats.states - 1;
        const auto over = checker::shortestPath(engine, query);
        CHECK(over.outcome == checker::PathOutcome::Undecided);
        CHECK(over.stats.stopped == StopReason::MaxStates);
        CHECK(over.stats.states <= free.stats.states - 1);
    }
}

TEST_CASE("rule steps run backwards are exactly the forward steps into a configuration, on every library system") {
    std::mt19937 rng(2929);
    int systems = 0;
    std::uint64_t configurations = 0, steps = 0;
    for (const std::string& file : rules::libraryFiles()) {
        const rules::System system = rules::librarySystem(std::filesystem::path(file).stem().string());
        for (const char* spec : {"square:2x2", "square:3x2", "hex:r1", "cubic:2x2x2"}) {
            if (system.lattice && *system.lattice != rules::Region::parse(spec).lattice().kind()) continue;
            INFO(system.name << " on " << spec);
            World w(system, spec);
            const std::uint64_t alphabet = static_cast<std::uint64_t>(w.model->alphabet().size());
            std::uint64_t total = 1;
            for (int i = 0; i < w.region.size() && total <= 60'000; ++i) total *= alphabet;
            if (total > 60'000) continue;
            const rules::Engine engine(*w.model, w.region, randomInputs(w, rng));
            const checker::Predecessors predecessors(engine);
            REQUIRE_MESSAGE(predecessors.irreversible().empty(), predecessors.irreversible());
            std::map<std::pair<int, std::tuple<int, int, int>>, int> placedOf;  // (shape, anchor) -> engine instance
            for (std::size_t p = 0; p < engine.instances().size(); ++p) {
                const auto i = engine.instance(static_cast<int>(p));
                placedOf[{i.shape, {i.anchor.x, i.anchor.y, i.anchor.z}}] = static_cast<int>(p);
            }
            // Every forward step between legal configurations, through the interpreter, by target.
            using Step = std::pair<std::vector<rules::CellValue>, int>;
            std::map<std::vector<rules::CellValue>, std::set<Step>> into;
            std::vector<std::vector<rules::CellValue>> legal;
            for (std::uint64_t index = 0; index < total; ++index) {
                rules::Configuration c{std::vector<rules::CellValue>(w.region.size()), engine.inputs()};
                for (std::uint64_t i = 0, rest = index; i < c.cells.size(); ++i, rest /= alphabet) c.cells[i] = static_cast<rules::CellValue>(rest % alphabet);
                if (!w.in->legal(c)) continue;
                legal.push_back(c.cells);
                for (const auto& instance : w.in->enabled(c))
                    into[w.in->successor(c, instance)->cells].insert({c.cells, placedOf.at({instance.shape, {instance.anchor.x, instance.anchor.y, instance.anchor.z}})});
            }
            for (const auto& after : legal) {
                std::set<Step> found;
                predecessors.forEach(after.data(), [&](int placed, const rules::CellValue* before) {
                    const std::vector<rules::CellValue> cells(before, before + after.size());
                    CHECK(found.insert({cells, placed}).second);                               // each once
                    if (!w.in->legal({cells, engine.inputs()})) found.erase({cells, placed});  // the search's part
                });
                const auto expected = into.find(after);
                CHECK(found == (expected == into.end() ? std::set<Step>{} : expected->second));
                steps += found.size();
            }
            configurations += legal.size();
            ++systems;
        }
    }
    MESSAGE(systems << " systems and regions, " << configurations << " legal configurations, " << steps << " steps run backwards");
    CHECK(systems >= 16);
    CHECK(steps >= 10'000);
}

TEST_CASE("a rule whose steps have too many possible origins is not run backwards: the forward search runs and says why") {
    World w(test::parse("system wipe\nstates A | B | C | D | E | F | G | H\nrule wipe: # # # # => _ _ _ _\nrule grow: _ => A\n"), "square:4x1");
    checker::PathQuery query;
    query.from = w.ascii("AAAA\n");
    query.to = w.ascii("....\n");
    query.search = checker::PathSearch::Bidirectional;
    const rules::Engine engine(*w.model, w.region, query.from.inputs);
    CHECK_FALSE(checker::Predecessors(engine).irreversible().empty());
    const auto result = checker::shortestPath(engine, query);
    REQUIRE(result.outcome == checker::PathOutcome::Found);
    CHECK(result.search == checker::PathSearch::Forward);
    CHECK(result.fallback.find("'wipe'") != std::string::npos);
    CHECK(result.trace.steps.size() - 1 == 1);
}

TEST_CASE("parallel steps: the greedy compaction of a pixel path replays, and a schedule with interfering steps in one round does not") {
    World w = World::library("pixel", "square:4x4");
    checker::PathQuery query;
    query.from = w.ascii("M...\n....\n....\n....\n");
    query.to = w.ascii("....\n....\n....\n...M\n");
    const rules::Engine engine(*w.model, w.region, query.from.inputs);
    const auto result = checker::shortestPath(engine, query);
    REQUIRE(result.outcome == checker::PathOutcome::Found);
    const checker::Schedule schedule = checker::compactSteps(result.trace, engine, checker::Footprints(engine));
    std::string why;
    CHECK_MESSAGE(checker::replaySchedule(schedule, result.trace, engine, *w.in, &why), why);
    // Growing along the L and shrinking behind can go on at both ends at once.
    CHECK(schedule.makespan() < result.trace.steps.size() - 1);
    checker::Schedule together;
    together.rounds.emplace_back();
    for (std::size_t k = 1; k < result.trace.steps.size(); ++k) together.rounds[0].push_back(static_cast<int>(k));
    CHECK_FALSE(checker::replaySchedule(together, result.trace, engine, *w.in, &why));
    CHECK(why.find("round 1") != std::string::npos);
    checker::Schedule missing = schedule;
    missing.rounds.back().pop_back();
    CHECK_FALSE(checker::replaySchedule(missing, result.trace, engine, *w.in, &why));
}
