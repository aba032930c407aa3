#pragma once
// Helpers every subcommand shares: loading a rule file with diagnostics, reading input masks.

#include "rules/Interpreter.h"

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace holon::cli {

/// Parses a rule file, printing diagnostics to stderr; nothing when it has errors. `noWarnings`
/// are -W arguments ("no-unused-value"); an unknown name throws InputError.
std::optional<rules::System> loadRules(const std::string& file, const std::vector<std::string>& noWarnings);
/// Per-cell input bits from NAME=FILE arguments (FILE: an ASCII mask; `none`: the input holds
/// nowhere, `all`: everywhere, so a file by either name is written ./none). `named`, if given,
/// gets bit k set for each input k an argument names.
std::vector<std::uint32_t> readInputs(const rules::Interpreter& in, const std::vector<std::string>& specs, std::uint32_t* named = nullptr);

}  // namespace holon::cli
