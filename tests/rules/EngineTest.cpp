// The compiled engine against the reference interpreter: on random configurations and inputs of
// every library system, on every lattice (half of them planted with an instance's left side), the same instances are enabled with the same successors,
// and every constraint, goal and property evaluates the same. The matcher that tries the shapes
// cell by cell agrees with the one that tries the instances one by one.

#include "TestSupport.h"
#include "rules/Engine.h"

#include <random>

using namespace holon;
using test::World;

TEST_CASE("the compiled engine agrees with the reference interpreter on every library system") {
    std::mt19937 rng(2026);
    for (const std::string& file : rules::libraryFiles()) {
        rules::System system = rules::librarySystem(std::filesystem::path(file).stem().string());
        for (const char* spec : {"square:4x3", "hex:r2", "hex:r3", "cubic:2x2x2"}) {
            rules::Region region = rules::Region::parse(spec);
            if (system.lattice && *system.lattice != region.lattice().kind()) continue;
            // hex:r3 only for a system none of whose rules fits in hex:r2 (a growth node's third ring).
            if (std::string(spec).rfind("hex:", 0) == 0) {
                const World r2(system, "hex:r2");
                const bool fits = !rules::Engine(*r2.model, r2.region, std::vector<std::uint32_t>(r2.region.size(), 0)).instances().empty();
                if (fits != (std::string(spec) == "hex:r2")) continue;
            }
            INFO(system.name << " on " << std::string(spec));
            World w(system, spec);
            const int alphabet = w.model->alphabet().size();
            int enabledSeen = 0;
            // Rounds go on while no instance has been enabled (rare for a guard that counts many cells).
            for (int round = 0; round < 40 || (enabledSeen == 0 && round < 2000); ++round) {
                auto c = w.in->empty();
                const double density = std::uniform_real_distribution<double>(0.3, 1.0)(rng);
                // Every fourth round uses one occupied state only, so that guards counting many
                // cells of one state (a hex growth node's 12 modules) are met too.
                const int only = round % 4 == 3 ? std::uniform_int_distribution<int>(1, alphabet - 1)(rng) : 0;
                for (int i = 0; i < region.size(); ++i) {
                    if (std::uniform_real_distribution<double>(0, 1)(rng) < density)
                        c.cells[i] = static_cast<rules::CellValue>(only ? only : std::uniform_int_distribution<int>(1, alphabet - 1)(rng));
                    c.inputs[i] = system.inputs.empty() ? 0u : static_cast<std::uint32_t>(rng() & 1u);
                }
                rules::Engine engine(*w.model, w.region, c.inputs);
                // Every other round plants a random instance's left side, so that rules with large
                // patterns (a hex hole move reads 19 cells) are exercised too.
                if (round % 2 && !engine.instances().empty()) {
                    const int p = std::uniform_int_distribution<int>(0, static_cast<int>(engine.instances().size()) - 1)(rng);
                    const auto& placed = engine.instances()[p];
                    for (int k = 0; k < placed.size; ++k) {
                        const int cell = placed.cells[k];
                        std::vector<rules::CellValue> accepted;
                        for (int v = 0; v < alphabet; ++v)
                            if (engine.lhsAccepts(p, k, engine.comboOfCell(cell), static_cast<rules::CellValue>(v))) accepted.push_back(static_cast<rules::CellValue>(v));
                        if (only && std::find(accepted.begin(), accepted.end(), c.cells[cell]) != accepted.end()) continue;
                        if (!accepted.empty()) c.cells[cell] = accepted[std::uniform_int_distribution<std::size_t>(0, accepted.size() - 1)(rng)];
                    }
                }
                CHECK(engine.legal(c.cells.data()) == w.in->legal(c));
                if (w.system.goal) CHECK(engine.holds(*w.system.goal, c.cells.data()) == w.in->atGoal(c));
                for (const auto& p : w.system.properties)
                    for (const auto& e : p.exprs) {
                        if (p.kind == rules::Property::Kind::Ranking) CHECK(engine.number(e, c.cells.data()) == w.in->number(e, c));
                        else CHECK(engine.holds(e, c.cells.data()) == w.in->holds(e, c));
                    }
                CHECK(rules::Rational(engine.massUnits(c.cells.data()), engine.massDenominator()) == w.in->mass(c));
                // Instance by instance: enabled and successor agree.
                std::vector<rules::CellValue> cells = c.cells;
                rules::CellValue saved[rules::Engine::kMaxCells];
                std::vector<rules::Instance> engineEnabled;
                std::vector<int> matching, atOnce;
                engine.forEachMatch(c.cells.data(), [&](int p) { atOnce.push_back(p); });
                for (int p = 0; p < static_cast<int>(engine.instances().size()); ++p) {
                    const auto reference = w.in->successor(c, engine.instance(p));
                    bool enabled = engine.matches(cells.data(), p);
                    if (enabled) {
                        matching.push_back(p);
                        engine.apply(cells.data(), p, saved);
                        enabled = engine.legal(cells.data());
                        if (enabled && reference) CHECK(cells == reference->cells);
                        engine.undo(cells.data(), p, saved);
                    }
                    CHECK(enabled == reference.has_value());
                    if (enabled) engineEnabled.push_back(engine.instance(p));
                    enabledSeen += enabled;
                }
                CHECK(cells == c.cells);
                std::sort(atOnce.begin(), atOnce.end());
                CHECK(atOnce == matching);
                // The interpreter enables exactly the instances the engine enables, no more.
                CHECK(w.in->enabled(c) == engineEnabled);
            }
            CHECK(enabledSeen > 0);
        }
    }
}
