#pragma once
// Rule drawings (`holon rules FILE --svg DIR`): every orientation a rule becomes after closing it
// under the system's symmetry group, each drawn as an example firing: the pattern's cells before
// and after, with the cells it changes outlined and the context it reads (required-occupied and
// required-empty, i.e. blocking cells) dashed, the guard in words in the title.

#include "rules/Model.h"

#include <string>

namespace holon::checker {

/// One SVG for directed rule `rule` of `model`: a panel per instance orientation (Model::shapes()
/// of that rule), each an example configuration around the pattern (its cells and their
/// neighbours) in which the instance is enabled, and its successor. An orientation whose guard no
/// example of a few thousand tries satisfies is drawn by its left side alone, and says so.
std::string drawRuleSvg(const rules::Model& model, int rule);

}  // namespace holon::checker
