#pragma once
// Reading what the viewer shows: an ITF trace (holon check/path/verify --trace-out, holon plan
// --trace-out), a plan (holon plan --plan-out), a hex sculpting run (holon hex --steps-out) or a
// Roombots run (holon roombots --out, steps_*.jsonl). The kind is told from the content; a file
// that is none of them, or breaks its format, throws InputError naming FILE:LINE and the fix.

#include "rules/Ir.h"
#include "rules/Limits.h"
#include "viewer/Run.h"

#include <nlohmann/json.hpp>

#include <string>

namespace holon::viewer {

/// `rules`: the rule file to read the states with, or "" for the one the input names (its
/// "source" when that file exists, else the bundled system of its name). A file whose reading
/// would take more than `memoryBytes` by the estimate below is refused (LimitError), before it is
/// parsed.
Run readRun(const std::string& path, const std::string& rules = "", std::uint64_t memoryBytes = rules::kDefaultMemoryBytes);

/// An ITF trace already in memory, of `system` (`where` names it in messages): check, path --html.
Run readItf(const nlohmann::json& itf, const std::string& where, const rules::System& system);

}  // namespace holon::viewer
