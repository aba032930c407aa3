#pragma once
// Loading .holon files: with diagnostics printed, and from the bundled standard library.

#include "rules/Diagnostics.h"
#include "rules/Ir.h"

#include <optional>
#include <ostream>
#include <string>
#include <vector>

namespace holon::rules {

struct LoadOptions {
    std::vector<std::string> silencedWarnings;
};

/// Parses a file, writes its diagnostics to `diagnosticsOut`, and returns the system when there
/// were no errors. Throws InputError when the file cannot be read.
std::optional<System> loadSystem(const std::string& path, std::ostream& diagnosticsOut, const LoadOptions& options = {});

/// The folder of the bundled library, rules/library/.
std::string libraryDir();
/// The path of the bundled system `stem` ("planner_general1"), there or not.
std::string bundledPath(const std::string& stem);
/// A rule file, or the stem of a bundled system ("planner_general1"): the path to read. Every
/// command that takes a rule file takes a bundled name this way. A regular file of that name comes
/// first; a folder of that name does not hide the bundled system. When there is neither, throws
/// InputError naming `option` (as "--rules"; empty for a positional argument) and the bundled names.
std::string rulesPath(const std::string& name, const std::string& option = "");
/// Paths of every bundled .holon file, sorted.
std::vector<std::string> libraryFiles();
/// Loads a bundled system by file stem ("planner_intermediate"); throws InputError when it fails.
System librarySystem(const std::string& stem);

}  // namespace holon::rules
