#pragma once
// Where a plan that stopped short is stuck, for a person: for a cell the goal does not accept yet,
// the rule of the .holon system that would change it and the condition that keeps it from firing,
// found by the reference interpreter (so it speaks of the rules as written, not of the tables).

#include "planner/Report.h"

#include <string>

namespace holon::planner {

/// The rule instance nearest to changing `cell` (the one with the fewest failing conditions among
/// those whose left side accepts the cell as it is, planner rules before transfers) and what fails: another pattern cell in the
/// wrong state, or a guard conjunct with the cells that make it false. Cells are board points.
/// Says so when no rule changes a cell in this state, or when the nearest instance is enabled
/// (then the allocator, a fault or a constraint held it back, or the run stopped before it fired).
std::string waitingOn(const Problem& problem, const BoardConfiguration& board, std::int64_t cell);

}  // namespace holon::planner
