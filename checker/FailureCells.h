#pragma once
// The cells that show why a condition is false, for a counterexample's picture.

#include "rules/Engine.h"

#include <vector>

namespace holon::checker {

/// For each false conjunct of a condition of the engine's system (and every disjunct of a false
/// `or`): the T cells of a false `no(T)`, the T cells outside the largest connected part of a
/// false `connected(T)`, the T cells where G fails in `all(T: G)`. Sorted; empty where the
/// condition is true or its failure has no cells (a comparison).
std::vector<int> failureCells(const rules::Engine& engine, const rules::Expr& e, const rules::CellValue* cells);

}  // namespace holon::checker
