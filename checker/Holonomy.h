#pragma once
// Holonomy of a reconfiguration graph (seed 000 §II-C): configurations adjacent in state space are
// one rule step apart, or unreachable from each other.

#include "checker/Explorer.h"
#include "checker/Graph.h"
#include "checker/Verdict.h"
#include "rules/Budget.h"
#include "rules/Ir.h"

namespace holon::checker {

/// Checks holonomy over every explored configuration. Adjacency is one cell's occupancy toggled
/// (by occupancy) or one module moved to an adjacent empty cell (by move). For systems with more
/// than one occupied state, "by occupancy" is checked on the projected occupancy: every pixel step
/// must be realisable by a path whose other steps leave the occupancy unchanged (transfers), the
/// claim that general_n reduces to pixel (seed 000 §III-C). When `budget` expires first, a violation
/// found so far is still reported; otherwise the verdict is unknown.
PropertyResult checkHolonomy(const Explorer& explorer, const Components& components, const rules::Property& property, const Budget& budget);

}  // namespace holon::checker
