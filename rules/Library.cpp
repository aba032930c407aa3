// File loading shared by every command, and access to the bundled standard library in
// rules/library/ (seed 000's systems pixel ... general-lock_n, the U/P/F planners, the hex pivot).
// The library path is compiled in and can be overridden with HOLON_LIBRARY.

#include "rules/Library.h"

#include "rules/Error.h"
#include "rules/Parser.h"
#include "rules/Sha256.h"
#include "rules/TextFile.h"

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <sstream>

namespace holon::rules {

std::optional<System> loadSystem(const std::string& path, std::ostream& out, const LoadOptions& options) {
    const std::string text = readTextFile(path, kMaxRuleFileBytes);
    Diagnostics diagnostics(path, text);
    for (const std::string& w : options.silencedWarnings) diagnostics.silence(w);
    auto system = parseSystem(text, diagnostics, path);
    if (system) system->sourceSha256 = sha256Hex(text);
    out << diagnostics.render();
    if (diagnostics.hasErrors())
        out << path << ": " << diagnostics.errorCount() << (diagnostics.errorCount() == 1 ? " error" : " errors") << '\n';
    return system;
}

std::string libraryDir() {
    if (const char* env = std::getenv("HOLON_LIBRARY")) return env;
    return HOLON_LIBRARY_DIR;
}

std::string bundledPath(const std::string& stem) { return libraryDir() + "/" + stem + ".holon"; }

std::string rulesPath(const std::string& name, const std::string& option) {
    // A regular file, not anything of that name: a folder called planner_intermediate in the
    // working directory (an --out folder named after its system) was read as the rule file.
    std::error_code error;
    if (std::filesystem::is_regular_file(name, error)) return name;
    if (const std::string bundled = bundledPath(name); std::filesystem::is_regular_file(bundled, error)) return bundled;
    if (std::filesystem::exists(name, error)) return name;  // a folder or a FIFO: the reader says what it is
    const std::string where = (option.empty() ? "" : option + " ") + "'" + name + "'";
    if (name.find('/') != std::string::npos || std::filesystem::path(name).extension() == ".holon") throw InputError(where + ": no such rule file");
    // "cannot read 'nosuch'" named neither the option nor that a bundled name would have done.
    std::string stems;
    try {
        for (const std::string& file : libraryFiles()) stems += (stems.empty() ? "" : ", ") + std::filesystem::path(file).stem().string();
    } catch (const std::filesystem::filesystem_error&) {
        stems = "(none: the library folder " + libraryDir() + " cannot be read)";
    }
    throw InputError(where + ": no such rule file, and no bundled system of that name; give a .holon file or one of: " + stems);
}

std::vector<std::string> libraryFiles() {
    std::vector<std::string> files;
    for (const auto& entry : std::filesystem::directory_iterator(libraryDir()))
        if (entry.path().extension() == ".holon") files.push_back(entry.path().string());
    std::sort(files.begin(), files.end());
    return files;
}

System librarySystem(const std::string& stem) {
    const std::string path = bundledPath(stem);
    std::ostringstream messages;
    auto system = loadSystem(path, messages);
    if (!system) throw InputError("library system '" + stem + "' failed to load:\n" + messages.str());
    return *system;
}

}  // namespace holon::rules
