#pragma once
// The meaning of one cell term on one cell: does a state match it, and what does it rewrite to.

#include "rules/Model.h"

#include <cstdint>
#include <vector>

namespace holon::rules {

/// Where a term is evaluated: the cell's position and inputs, and the absolute positions of the
/// rule's pattern cells that `@k` references resolve against (null outside rules).
struct CellContext {
    const Alphabet* alphabet = nullptr;
    const Lattice* lattice = nullptr;
    Vec position;
    std::uint32_t inputs = 0;
    const std::vector<Vec>* pattern = nullptr;
    bool ignoreInputs = false;  // static checks: inputs are unknown, treat input atoms as satisfied
};

bool matchesTerm(const CellTerm& term, CellValue value, const CellContext& at);
bool matchesPredicate(const CellPredicate& pred, CellValue value, const CellContext& at);
/// The state a right-side term turns `value` into, or -1 when the result is not a complete state
/// (a field that must be set was left unset). `missingField` receives that field's index.
int rewriteTerm(const CellTerm& rhs, CellValue value, const CellContext& at, int* missingField = nullptr);

}  // namespace holon::rules
