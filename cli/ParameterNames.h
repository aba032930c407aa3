#pragma once
// The CLI's names for the library's parameters (rules/Parameter.h): the option that sets each.

#include "rules/Parameter.h"

#include <string>

namespace holon::cli {

/// The option that sets `p` ("--memory").
std::string optionName(rules::Parameter p);

/// Has the library's messages name the options; runHolon calls it first.
void installOptionNames();

}  // namespace holon::cli
