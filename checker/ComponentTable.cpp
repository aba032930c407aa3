// Summaries of the reconfiguration graph's weak components (checker/ComponentTable.h), computed
// from the BGL components of checker/Graph in one pass over the stored states.

#include "checker/ComponentTable.h"

#include <algorithm>

namespace holon::checker {

std::vector<ComponentRow> componentTable(const Explorer& explorer, const Components& components) {
    const rules::Engine& engine = explorer.engine();
    std::vector<ComponentRow> rows(static_cast<std::size_t>(components.count));
    std::vector<std::vector<CellValue>> smallest(rows.size());
    for (StateId s : explorer.ids()) {
        const int c = components.of[s];
        if (c < 0) continue;
        ComponentRow& row = rows[static_cast<std::size_t>(c)];
        const std::vector<CellValue> cells = explorer.cells(s);
        const int count = static_cast<int>(std::count_if(cells.begin(), cells.end(), [](CellValue v) { return v != 0; }));
        const std::int64_t mass = engine.massUnits(cells.data());
        if (row.states++ == 0) {
            row.minCount = row.maxCount = count, row.minMass = row.maxMass = mass;
        } else {
            row.minCount = std::min(row.minCount, count), row.maxCount = std::max(row.maxCount, count);
            row.minMass = std::min(row.minMass, mass), row.maxMass = std::max(row.maxMass, mass);
        }
        auto& best = smallest[static_cast<std::size_t>(c)];
        if (row.representative == kNoState || cells < best) row.representative = s, best = cells;
    }
    std::vector<std::size_t> order(rows.size());
    for (std::size_t k = 0; k < order.size(); ++k) order[k] = k;
    std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
        return rows[a].states != rows[b].states ? rows[a].states > rows[b].states : smallest[a] < smallest[b];
    });
    std::vector<ComponentRow> sorted;
    for (std::size_t k : order) sorted.push_back(rows[k]);
    return sorted;
}

}  // namespace holon::checker
