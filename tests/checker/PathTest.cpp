// holon path against an independent breadth-first search through the reference interpreter: on
// every library system, from random legal configurations, the shortest path to a reachable
// configuration (and to the goal) has exactly the interpreter's BFS distance and replays; a
// configuration outside the reachable set is "unreachable", and a limit makes the answer undecided.

#include "TestSupport.h"
#include "checker/Path.h"
#include "rules/Engine.h"

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

}  // namespace

TEST_CASE("shortest paths have the reference interpreter's BFS distances on every library system") {
    std::mt19937 rng(29);
    int systemsCovered = 0, pathsChecked = 0, goalsChecked = 0, unreachableChecked = 0;
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
                for (std::size_t pick : picks) {
                    query.to = rules::Configuration{found[pick].first, start->inputs};
                    const auto result = checker::shortestPath(engine, query);
                    REQUIRE(result.outcome == checker::PathOutcome::Found);
                    CHECK(static_cast<int>(result.trace.steps.size()) - 1 == found[pick].second);
                    std::string why;
                    CHECK_MESSAGE(checker::replay(result.trace, engine, *w.in, &why), why);
                    CHECK(result.trace.steps.back().cells == found[pick].first);
                    ++pathsChecked;
                }
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
                        const auto result = checker::shortestPath(engine, query);
                        CHECK(result.outcome == checker::PathOutcome::Unreachable);
                        CHECK(result.stats.states == reference.distance.size());
                        ++unreachableChecked;
                        break;
                    }
                covered = true;
            }
        }
        systemsCovered += covered;
        if (!covered) MESSAGE(system.name << " not covered: no random legal start with an enabled rule");
    }
    MESSAGE(systemsCovered << " systems, " << pathsChecked << " paths, " << goalsChecked << " goal searches, " << unreachableChecked << " unreachable targets");
    CHECK(systemsCovered >= 16);  // all but the hex systems whose rules need more than hex:r2
    CHECK(goalsChecked >= 5);
    CHECK(unreachableChecked >= 3);
}

TEST_CASE("a path search stopped by a limit is undecided, not unreachable") {
    World w = World::library("pixel", "square:4x4");
    checker::PathQuery query;
    query.from = w.ascii("M...\n....\n....\n....\n");
    query.to = w.ascii("....\n....\n....\n...M\n");
    query.limits.maxStates = 20;
    const rules::Engine engine(*w.model, w.region, query.from.inputs);
    CHECK(checker::shortestPath(engine, query).outcome == checker::PathOutcome::Undecided);
    query.limits.maxStates = 1'000'000;
    const auto found = checker::shortestPath(engine, query);
    REQUIRE(found.outcome == checker::PathOutcome::Found);
    CHECK(found.trace.steps.size() - 1 == 12);  // grow 6 cells along an L to the corner, shrink 6 behind
}
