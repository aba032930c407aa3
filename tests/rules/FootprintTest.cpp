// The footprint stencil (RuleTables::readSites: the read side of the planner's conflict test and
// influence, and of the path search's interference) against the reference interpreter: a cell
// outside an instance's read sites never changes whether the instance is enabled, and every site
// outside its pattern does in some configuration. A stencil that misses a cell a guard reads fails
// the first; one that adds cells no guard reads (the neighbours of every pattern cell of a guarded
// rule, not only of those its guard quantifies around, as the planner's rounds count) fails the
// second.

#include "TestSupport.h"
#include "rules/Engine.h"

#include <random>
#include <set>

using namespace holon;
using test::World;

TEST_CASE("an instance reads exactly its read sites: the cells whose state can change whether it is enabled") {
    std::mt19937 rng(27);
    const std::pair<const char*, const char*> cases[] = {{"planner_general1", "square:5x5"}, {"planner_intermediate", "square:5x5"}, {"hex_collapse", "hex:r3"}};
    for (const auto& [stem, spec] : cases) {
        INFO(stem << " on " << spec);
        const World w = World::library(stem, spec);
        const rules::Engine engine(*w.model, w.region, std::vector<std::uint32_t>(w.region.size(), 0));
        const rules::RuleTables& tables = engine.tables();
        const int alphabet = tables.alphabet();
        std::vector<char> done(tables.shapeCount(), 0);
        int guardSites = 0;
        for (int p = 0; p < static_cast<int>(engine.instances().size()); ++p) {
            const auto& inst = engine.instances()[p];
            if (done[inst.shape]) continue;
            // One instance per shape with every read site in the region, and states its left side accepts.
            std::set<int> sites;
            bool inside = true;
            for (const rules::RuleTables::Site site : tables.readSites(inst.shape)) {
                const int n = site.direction < 0 ? inst.cells[site.cell] : w.region.neighbour(inst.cells[site.cell], site.direction);
                inside = inside && n >= 0;
                sites.insert(n);
            }
            std::vector<std::vector<rules::CellValue>> accepted(inst.size);
            for (int k = 0; k < inst.size; ++k)
                for (int v = 0; v < alphabet; ++v)
                    if (engine.lhsAccepts(p, k, 0, static_cast<rules::CellValue>(v))) accepted[k].push_back(static_cast<rules::CellValue>(v));
            if (!inside || std::any_of(accepted.begin(), accepted.end(), [](const auto& a) { return a.empty(); })) continue;
            done[inst.shape] = 1;
            const std::set<int> pattern(inst.cells, inst.cells + inst.size);
            const rules::Instance instance = engine.instance(p);
            std::set<int> influence;
            rules::Configuration c{std::vector<rules::CellValue>(w.region.size()), std::vector<std::uint32_t>(w.region.size(), 0)};
            for (int sample = 0; sample < 300; ++sample) {
                for (auto& v : c.cells) v = static_cast<rules::CellValue>(rng() % 3 ? 0 : 1 + rng() % (alphabet - 1));
                for (int k = 0; k < inst.size; ++k) c.cells[inst.cells[k]] = accepted[k][rng() % accepted[k].size()];
                const bool enabled = w.in->matches(c, instance);
                for (int cell = 0; cell < w.region.size(); ++cell) {
                    if (pattern.count(cell)) continue;
                    const rules::CellValue old = c.cells[cell];
                    c.cells[cell] = static_cast<rules::CellValue>((old + 1 + rng() % (alphabet - 1)) % alphabet);
                    if (w.in->matches(c, instance) != enabled) influence.insert(cell);
                    c.cells[cell] = old;
                }
            }
            INFO("rule " << w.model->rules()[inst.rule].name);
            for (int cell : influence) CHECK_MESSAGE(sites.count(cell), "cell " << cell << " changes the guard but is no read site");
            for (int cell : sites)
                if (!pattern.count(cell)) {
                    ++guardSites;
                    CHECK_MESSAGE(influence.count(cell), "read site " << cell << " never changes whether the instance is enabled");
                }
        }
        CHECK(guardSites > 0);
    }
}
