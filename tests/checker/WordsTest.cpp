// The explorer's word-level machinery against rules::Engine, on random configurations of every
// library system: the matcher that tries every instance of a small region at once finds exactly
// the instances that match one by one, and the constraints decided on words (outright, from a
// legal parent by a fixed change, and by the incremental evaluator) agree with Engine::legal.

#include "TestSupport.h"
#include "checker/Evaluator.h"
#include "checker/WordConstraints.h"
#include "checker/WordMatcher.h"

#include <random>

using namespace holon;
using test::World;

namespace {

/// Random configurations and inputs of a world; a third of the cells empty.
rules::Configuration randomConfiguration(const World& w, std::mt19937& rng) {
    auto c = w.in->empty();
    const int alphabet = w.model->alphabet().size();
    for (int i = 0; i < w.region.size(); ++i) {
        if (rng() % 3) c.cells[i] = static_cast<rules::CellValue>(rng() % alphabet);
        c.inputs[i] = w.system.inputs.empty() ? 0u : static_cast<std::uint32_t>(rng() & 1u);
    }
    return c;
}

void occupiedOf(const rules::Configuration& c, std::uint64_t* occupied) {
    std::fill(occupied, occupied + 64, 0);
    for (std::size_t i = 0; i < c.cells.size(); ++i) occupied[c.cells[i]] |= std::uint64_t{1} << i;
}

}  // namespace

TEST_CASE("matching every instance at once finds exactly the instances that match one by one") {
    std::mt19937 rng(7);
    for (const std::string& file : rules::libraryFiles()) {
        rules::System system = rules::librarySystem(std::filesystem::path(file).stem().string());
        for (const char* spec : {"square:4x3", "square:8x8", "hex:r2", "hex:r4", "cubic:4x4x4"}) {
            rules::Region region = rules::Region::parse(spec);
            if (system.lattice && *system.lattice != region.lattice().kind()) continue;
            INFO(system.name << " on " << std::string(spec));
            World w(system, spec);
            if (!checker::WordMatcher::fits(region.size(), w.model->alphabet().size())) continue;
            for (int round = 0; round < 6; ++round) {
                const auto c = randomConfiguration(w, rng);
                rules::Engine engine(*w.model, w.region, c.inputs);
                checker::WordMatcher matcher(engine);
                matcher.finish();
                std::vector<int> oneByOne, atOnce;
                for (int p = 0; p < static_cast<int>(engine.instances().size()); ++p)
                    if (engine.matches(c.cells.data(), p)) oneByOne.push_back(p);
                std::uint64_t occupied[64];
                occupiedOf(c, occupied);
                matcher.forEachMatch(occupied, nullptr, c.cells.data(), [&](int p) { atOnce.push_back(p); });
                std::sort(atOnce.begin(), atOnce.end());
                CHECK(atOnce == oneByOne);
            }
        }
    }
}

TEST_CASE("the constraints decided on words agree with the engine's cell by cell") {
    std::mt19937 rng(11);
    int onWords = 0, changes = 0;
    for (const std::string& file : rules::libraryFiles()) {
        rules::System system = rules::librarySystem(std::filesystem::path(file).stem().string());
        if (system.constraints.empty()) continue;
        for (const char* spec : {"square:4x3", "square:5x5", "hex:r2", "cubic:3x3x3", "square:9x8"}) {
            rules::Region region = rules::Region::parse(spec);
            if (system.lattice && *system.lattice != region.lattice().kind()) continue;
            INFO(system.name << " on " << std::string(spec));
            World w(system, spec);
            for (int round = 0; round < 20; ++round) {
                const auto c = randomConfiguration(w, rng);
                const rules::Engine engine(*w.model, w.region, c.inputs);
                const checker::WordConstraints constraints(engine);
                const bool legal = engine.legal(c.cells.data());
                checker::Evaluator ev(constraints);
                ev.load(c.cells.data());
                CHECK(ev.legal() == legal);
                if (!constraints.onWords()) continue;
                ++onWords;
                std::uint64_t occupied[64];
                occupiedOf(c, occupied);
                checker::WordConstraints::LegalBefore before;
                constraints.wordsOf(occupied, before.words);
                CHECK(constraints.legalOn(before.words) == legal);
                if (!legal) continue;
                // From a legal configuration: every successor by one instance, three ways.
                constraints.prepare(before);
                std::vector<rules::CellValue> cells = c.cells;
                for (int p = 0; p < static_cast<int>(engine.instances().size()); ++p) {
                    if (!engine.matches(cells.data(), p)) continue;
                    const auto& placed = engine.instances()[p];
                    rules::CellValue saved[rules::Engine::kMaxCells];
                    engine.apply(cells.data(), p, saved);
                    const bool after = engine.legal(cells.data());
                    checker::WordConstraints::WordChange change;
                    for (int k = 0; k < placed.size; ++k) constraints.addChange(placed.cells[k], saved[k], cells[placed.cells[k]], change);
                    const auto checks = constraints.compileChange(change);
                    CHECK(constraints.legalAfter(before, checks.data(), checks.size(), change) == after);
                    rules::Configuration next{cells, c.inputs};
                    occupiedOf(next, occupied);
                    checker::WordConstraints::Words now;
                    constraints.wordsOf(occupied, now);
                    CHECK(constraints.legalOn(now, &before) == after);
                    ev.apply(p, saved);
                    CHECK(ev.legal() == after);
                    ev.undo(p, saved);
                    engine.undo(cells.data(), p, saved);
                    ++changes;
                }
            }
        }
    }
    CHECK(onWords > 50);
    CHECK(changes > 100);
}
