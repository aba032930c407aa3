#pragma once
// Parsing .holon text into the rule IR, with compiler-style diagnostics.

#include "rules/Diagnostics.h"
#include "rules/Ir.h"
#include "rules/Limits.h"

#include <optional>
#include <string>
#include <string_view>

namespace holon::rules {

/// Parses and validates one system. Returns nothing when any error was reported; warnings may be
/// reported either way. Each phase (syntax and names, then semantics) reports all its errors.
std::optional<System> parseSystem(std::string_view source, Diagnostics& diagnostics, std::string sourceName = "");

}  // namespace holon::rules
