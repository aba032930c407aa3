// The component table of `holon check --components` against the BGL components it summarises:
// every state counted once, each row's counts and masses those of its states, the representative
// the smallest configuration of its component, rows largest first.

#include "CheckSupport.h"
#include "checker/ComponentTable.h"

using namespace holon;

TEST_CASE("the component table summarises every component exactly") {
    for (const auto& [stem, spec] : {std::pair{"pixel", "square:3x3"}, {"hex_pivot", "hex:r1"}, {"general1", "square:3x2"}}) {
        CAPTURE(stem);
        const auto c = test::checkAll(rules::librarySystem(stem), spec);
        const checker::Explorer& ex = *c.kept.explorer;
        const checker::Components comps = checker::components(ex);
        const auto rows = checker::componentTable(ex, comps);
        REQUIRE(static_cast<int>(rows.size()) == comps.count);
        std::uint64_t total = 0;
        for (std::size_t k = 0; k < rows.size(); ++k) {
            const auto& r = rows[k];
            total += r.states;
            if (k) CHECK(rows[k - 1].states >= r.states);
            const int component = comps.of[r.representative];
            const auto smallest = ex.cells(r.representative);
            std::uint64_t members = 0;
            for (checker::StateId s : ex.ids()) {
                if (comps.of[s] != component) continue;
                ++members;
                const auto cells = ex.cells(s);
                const int count = static_cast<int>(std::count_if(cells.begin(), cells.end(), [](rules::CellValue v) { return v != 0; }));
                CHECK(count >= r.minCount);
                CHECK(count <= r.maxCount);
                CHECK(ex.engine().massUnits(cells.data()) >= r.minMass);
                CHECK(ex.engine().massUnits(cells.data()) <= r.maxMass);
                CHECK_FALSE(cells < smallest);
            }
            CHECK(members == r.states);
        }
        CHECK(total == ex.stats().states);
    }
}
