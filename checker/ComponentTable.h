#pragma once
// The connected components of an explored reconfiguration graph for a person (`holon check
// --components`): per component its size, the number of metamodules and the mass its
// configurations hold, and a representative to draw. A design is complete on a region when each
// conserved amount (mass, or the count of metamodules) has one component: any configuration
// reaches any other of the same amount.

#include "checker/Explorer.h"
#include "checker/Graph.h"

#include <cstdint>
#include <vector>

namespace holon::checker {

struct ComponentRow {
    std::uint64_t states = 0;
    int minCount = 0, maxCount = 0;         // metamodules (occupied cells)
    std::int64_t minMass = 0, maxMass = 0;  // in units of the engine's massDenominator()
    StateId representative = kNoState;      // the smallest configuration, cell by cell
};

/// One row per component, largest first (ties: smallest representative first), so the table does
/// not depend on the threads' timing.
std::vector<ComponentRow> componentTable(const Explorer& explorer, const Components& components);

}  // namespace holon::checker
