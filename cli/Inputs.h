#pragma once
// Helpers every subcommand shares: loading a rule file with diagnostics, reading input masks.

#include "checker/Trace.h"
#include "rules/Interpreter.h"
#include "rules/Library.h"

#include <CLI/CLI.hpp>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace holon::cli {

/// The load options of -W arguments ("no-unused-value"); an unknown name throws InputError.
rules::LoadOptions loadOptions(const std::vector<std::string>& noWarnings);
/// Registers the rule file argument or option `name` ("file", "--rules") of a subcommand, with the
/// one help text every subcommand shares: a file or a bundled name. `what` says whose rules they are
/// ("design A"); a default already in `file` is stated.
CLI::Option* addRulesFile(CLI::App* sub, const std::string& name, std::string& file, const std::string& what = "");
CLI::Option* addRulesFiles(CLI::App* sub, const std::string& name, std::vector<std::string>& files);
/// Parses a rule file or bundled system (rulesPath), printing diagnostics to stderr; nothing when
/// it has errors. `option` ("--rules"; empty for a positional argument) names where it was given.
std::optional<rules::System> loadRules(const std::string& file, const std::vector<std::string>& noWarnings, const std::string& option = "");
/// Per-cell input bits from NAME=FILE arguments (FILE: an ASCII mask; `none`: the input holds
/// nowhere, `all`: everywhere, so a file by either name is written ./none). `named`, if given,
/// gets bit k set for each input k an argument names.
std::vector<std::uint32_t> readInputs(const rules::Interpreter& in, const std::vector<std::string>& specs, std::uint32_t* named = nullptr);

/// What a JSON configuration or an ITF trace says of itself, from its text (rules::readConfigText):
/// its top-level `key` ("system", "region") or its "#meta" one ("source", the rule file of a
/// trace); "" for ASCII art or a file that does not say.
std::string namedInText(const std::string& text, const std::string& key);
/// Where the trace of one of several violated properties goes: "out/t.itf.json" becomes
/// "out/t.safety.itf.json"; with one violated property, the path as given.
std::string pathFor(const std::string& path, const std::string& property, bool several);

/// Says on stderr that the counterexample outputs asked for (the options given among
/// `options`, each an option's name and its path, empty when not given) are not written, as no
/// counterexample was found: a file left at that path by an earlier run looked current.
void noteNoCounterexample(const std::string& command, const std::vector<std::pair<std::string, std::string>>& options);

/// A picture smaller than the region is read as its top-left corner, the rest empty: said on
/// stderr (once per option and file), not done silently, since a start or mask drawn for another
/// region is otherwise taken as it is.
void notePictureShortfall(const std::string& option, const std::string& path, const rules::Region& region, const std::string& text);

/// The start configurations of --from, each with the inputs of `inputSpecs` (--input) added, every
/// declared input set by one or the other (an input left out is not silently false everywhere), and
/// each legal (else the error names the constraint that fails, with its line). With no --from,
/// the inputs alone must still be complete (--all): `inputsOut` gets them either way. `option`
/// names the configurations in messages (`holon path` reads its --to this way too).
std::vector<rules::Configuration> readStarts(const rules::Interpreter& in, const std::vector<std::string>& from,
                                             const std::vector<std::string>& inputSpecs, std::vector<std::uint32_t>* inputsOut = nullptr,
                                             const std::string& option = "--from");

/// For an exploration (check, diff), which runs every start under one set of inputs: starts
/// whose inputs differ are refused, naming the first two files (all were explored under the
/// first's inputs, and the verdict hung on the order of --from).
void requireSharedInputs(const std::vector<rules::Configuration>& starts, const std::vector<std::string>& from);

}  // namespace holon::cli
