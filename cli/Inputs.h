#pragma once
// Helpers every subcommand shares: loading a rule file with diagnostics, reading input masks.

#include "rules/Interpreter.h"

#include <optional>
#include <string>
#include <vector>

namespace holon::cli {

/// Parses a rule file, printing diagnostics to stderr; nothing when it has errors. `noWarnings`
/// are -W arguments ("no-unused-value"); an unknown name throws InputError.
std::optional<rules::System> loadRules(const std::string& file, const std::vector<std::string>& noWarnings);
/// Per-cell input bits from NAME=FILE arguments (FILE: an ASCII mask, or a JSON list of cells).
std::vector<std::uint32_t> readInputs(const rules::Interpreter& in, const std::vector<std::string>& specs);

}  // namespace holon::cli
