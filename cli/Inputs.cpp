// Shared CLI plumbing: rule loading with -W handling, and --input NAME=FILE|none|all masks.

#include "cli/Inputs.h"

#include "rules/ConfigIo.h"
#include "rules/Diagnostics.h"
#include "rules/Error.h"
#include "rules/Escape.h"
#include "rules/Library.h"
#include "rules/OutputFile.h"
#include "rules/Printer.h"
#include "rules/TextFile.h"

#include <algorithm>
#include <filesystem>
#include <iostream>
#include <set>

namespace holon::cli {

rules::LoadOptions loadOptions(const std::vector<std::string>& noWarnings) {
    rules::LoadOptions load;
    // As a compiler's -W: every warning is on, -W no-NAME turns one off, -W NAME on again, the
    // last one given wins (-W NAME used to silence it like -W no-NAME).
    auto& silenced = load.silencedWarnings;
    for (const std::string& w : noWarnings) {
        const bool off = w.rfind("no-", 0) == 0;
        const std::string name = off ? w.substr(3) : w;
        const auto& known = rules::Diagnostics::warningNames();
        if (std::find(known.begin(), known.end(), name) == known.end())
            throw InputError("unknown warning '" + w + "'; try -W no-unused-value");
        silenced.erase(std::remove(silenced.begin(), silenced.end(), name), silenced.end());
        if (off) silenced.push_back(name);
    }
    return load;
}

namespace {
const char* const kRulesHelp = "rule file (.holon), or the name of a bundled system (planner_general1 reads rules/library/planner_general1.holon)";
}  // namespace

CLI::Option* addRulesFile(CLI::App* sub, const std::string& name, std::string& file, const std::string& what) {
    return sub->add_option(name, file, (what.empty() ? "" : what + ": ") + kRulesHelp + (file.empty() ? "" : " (default " + file + ")"));
}

CLI::Option* addRulesFiles(CLI::App* sub, const std::string& name, std::vector<std::string>& files) {
    return sub->add_option(name, files, std::string(kRulesHelp) + "; several may be given");
}

std::optional<rules::System> loadRules(const std::string& file, const std::vector<std::string>& noWarnings, const std::string& option) {
    const std::string path = rules::rulesPath(file, option);
    rules::OutputClaims::reading("the rule file", path);
    return rules::loadSystem(path, std::cerr, loadOptions(noWarnings));
}

void notePictureShortfall(const std::string& option, const std::string& path, const rules::Region& region, const std::string& text) {
    // Once per file: diff reads each start for both designs, and said so twice.
    static std::set<std::pair<std::string, std::string>> noted;
    if (const std::string shortfall = rules::pictureShortfall(region, text); !shortfall.empty() && noted.insert({option, path}).second)
        std::cerr << "holon: note: " << option << " " << path << " is smaller than region " << region.spec() << " (" << shortfall
                  << "); it is read as the region's top-left corner, the rest empty\n";
}

std::vector<std::uint32_t> readInputs(const rules::Interpreter& in, const std::vector<std::string>& specs, std::uint32_t* named) {
    const rules::Region& region = in.region();
    std::vector<std::uint32_t> bits(region.size(), 0);
    std::uint32_t given = 0;
    for (const std::string& spec : specs) {
        const auto eq = spec.find('=');
        if (eq == std::string::npos) throw InputError("--input takes NAME=FILE, NAME=none or NAME=all, as in --input target=target.txt");
        const std::string name = spec.substr(0, eq), path = spec.substr(eq + 1);
        const int k = in.model().system().inputIndex(name);
        if (k < 0) throw InputError("--input " + spec + ": system '" + in.model().system().name + "' has no input '" + name + "'");
        if (given >> k & 1u) throw InputError("--input " + name + " is given twice; give each input once");
        given |= 1u << k;
        // An input false (or true) everywhere is a value to state, not what a forgotten mask means.
        std::vector<bool> mask(region.size(), path == "all");
        if (path != "none" && path != "all") {
            rules::OutputClaims::reading("--input " + name, path);
            try {
                const std::string text = rules::readTextFile(path);
                // An empty file is a mistake (a failed redirection), not a way to say "nowhere".
                if (text.find_first_not_of(" \t\r\n") == std::string::npos)
                    throw InputError("the file is empty; an input that holds nowhere is given as " + name + "=none");
                mask = rules::maskFromAscii(region, text);
                notePictureShortfall("--input " + name, path, region, text);
            } catch (const InputError& e) {
                throw InputError(path + ": " + e.what());
            }
        }
        for (int i = 0; i < region.size(); ++i)
            if (mask[i]) bits[i] |= 1u << k;
    }
    if (named) *named = given;
    return bits;
}

void noteNoCounterexample(const std::string& command, const std::vector<std::pair<std::string, std::string>>& options) {
    std::string given;
    for (const auto& [option, path] : options)
        if (!path.empty()) given += (given.empty() ? "" : ", ") + option + " " + path;
    if (!given.empty()) std::cerr << "holon " << command << ": no counterexample found, so not written: " << given << '\n';
}

std::string pathFor(const std::string& path, const std::string& property, bool several) {
    if (!several) return path;
    const std::size_t slash = path.find_last_of('/');
    const std::size_t dot = path.find('.', slash == std::string::npos ? 0 : slash + 1);
    return dot == std::string::npos ? path + "." + property : path.substr(0, dot) + "." + property + path.substr(dot);
}

namespace {

std::string missingInput(const rules::System& system, int k, const std::string& where) {
    const std::string& name = system.inputs[k];
    return where + "system '" + system.name + "' has input '" + name + "', which " +
           (where.empty() ? "no --input sets" : "neither --input nor the configuration sets") + "; give it as --input " + name +
           "=FILE (an ASCII mask), or " + name + "=none / " + name + "=all";
}

}  // namespace

std::string namedInText(const std::string& text, const std::string& key) {
    if (text.find_first_not_of(" \t\r\n") == std::string::npos || text[text.find_first_not_of(" \t\r\n")] != '{') return "";
    // Only the top level's `key` and "#meta" (and the key inside it) are kept: the whole tree of a
    // large configuration took 14 bytes per byte of its text, read three times (source, system, region).
    const nlohmann::json::parser_callback_t wanted = [&](int depth, nlohmann::json::parse_event_t event, nlohmann::json& parsed) {
        if (event != nlohmann::json::parse_event_t::key) return true;
        return (depth == 1 && (parsed == key || parsed == "#meta")) || (depth == 2 && parsed == key);
    };
    const nlohmann::json j = nlohmann::json::parse(text, wanted, false);  // a parse error reads as "names nothing"
    if (!j.is_object()) return "";
    const nlohmann::json* name = j.contains(key) ? &j[key] : j.contains("#meta") && j["#meta"].is_object() && j["#meta"].contains(key) ? &j["#meta"][key]
                                                                                                                                       : nullptr;
    return name && name->is_string() ? name->get<std::string>() : "";
}

namespace {

/// The system a JSON configuration or ITF trace says it was written for, or "" (ASCII art names none).
std::string writtenFor(const std::string& text) { return namedInText(text, "system"); }

}  // namespace

std::vector<rules::Configuration> readStarts(const rules::Interpreter& in, const std::vector<std::string>& from,
                                             const std::vector<std::string>& inputSpecs, std::vector<std::uint32_t>* inputsOut,
                                             const std::string& option) {
    const rules::System& system = in.model().system();
    std::uint32_t named = 0;
    const std::vector<std::uint32_t> inputs = readInputs(in, inputSpecs, &named);
    if (inputsOut) *inputsOut = inputs;
    if (from.empty())
        for (std::size_t k = 0; k < system.inputs.size(); ++k)
            if (!(named >> k & 1u)) throw InputError(missingInput(system, static_cast<int>(k), ""));
    std::vector<rules::Configuration> starts;
    for (const std::string& path : from) {
        std::uint32_t namedInFile = 0;
        // Read once: a pipe or FIFO gives its text once (a second read waited for ever).
        const rules::ConfigText file = rules::readConfigText(path);
        rules::Configuration c = rules::configFromText(in, file, &namedInFile);
        if (!file.index) notePictureShortfall(option, path, in.region(), file.text);  // FILE#N is an ITF trace, not a picture
        // A configuration of another system reads by field and value names (a design's variant is
        // checked from the reference design's starts); the reader refused any name this system
        // lacks, and the user is told which system the file was written for.
        if (const std::string other = writtenFor(file.text); !other.empty() && other != system.name)
            std::cerr << "holon: note: " << path << " was written for system '" << rules::excerpt(other) << "'; reading it as '" << system.name
                      << "' by field and value names\n";
        for (std::size_t k = 0; k < system.inputs.size(); ++k)
            if (!((named | namedInFile) >> k & 1u)) throw InputError(missingInput(system, static_cast<int>(k), option + " " + path + ": "));
        // --input replaces the configuration's own value of that input; OR-ing the two gave a mask
        // that was neither (and NAME=none changed nothing).
        if (named & namedInFile)
            std::cerr << "holon: note: " << path << " sets inputs that --input also gives; --input's values are used\n";
        for (int i = 0; i < in.region().size(); ++i) c.inputs[i] = (c.inputs[i] & ~named) | inputs[i];
        for (const rules::Constraint& constraint : system.constraints)
            if (!in.holds(constraint.expr, c))
                throw InputError(path + ": this configuration violates the constraint '" + rules::printExpr(system, constraint.expr) + "' (" +
                                 system.sourceName + ":" + std::to_string(constraint.loc.line) + "); every configuration given with " + option + " must be legal");
        starts.push_back(std::move(c));
    }
    return starts;
}

void requireSharedInputs(const std::vector<rules::Configuration>& starts, const std::vector<std::string>& from) {
    for (std::size_t k = 1; k < starts.size(); ++k)
        if (starts[k].inputs != starts[0].inputs)
            throw InputError("--from " + from[k] + ": its inputs differ from those of --from " + from[0] +
                             "; an exploration runs every start under one set of inputs: check them one at a time, or give the inputs with --input");
}

}  // namespace holon::cli
