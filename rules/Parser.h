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

/// Reads a whole file; throws InputError naming the file when it cannot be read, is a folder, or
/// holds more than `maxBytes` (so /dev/zero or a wrong file stops with a message, not the machine).
std::string readTextFile(const std::string& path, std::size_t maxBytes = kMaxFileBytes);

}  // namespace holon::rules
