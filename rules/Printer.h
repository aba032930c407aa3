#pragma once
// Printing the rule IR back to .holon text; the output re-parses to an equal IR.

#include "rules/Ir.h"

#include <functional>
#include <string>

namespace holon::rules {

/// How a reference to pattern cell k is printed; the default writes "@k".
using RefPrinter = std::function<std::string(int k)>;

std::string printSystem(const System& system);
std::string printTerm(const System& system, const CellTerm& term, const RefPrinter& ref = {});
std::string printPredicate(const System& system, const CellPredicate& pred, const RefPrinter& ref = {});
std::string printExpr(const System& system, const Expr& expr, const RefPrinter& ref = {});
std::string printRule(const System& system, const Rule& rule);
/// The keyword a property kind is declared with ("invariant", "ranking", ...), as reports name it.
const char* propertyKindName(Property::Kind kind);

}  // namespace holon::rules
