// The viewer's readers. An ITF trace is one JSON document whose states are whole configurations
// (each decoded by rules::itfStateJson, the library's ITF walker); plans, hex runs and Roombots
// runs are JSON Lines in one format (holon plan --plan-out's, read by rules::PlanLineReader as
// holon replay reads it): a first line with the start configuration, then one line per rule
// instance fired, {"round", "rule", "cells", "after"}, the cells' states after it ({} for an
// emptied cell). A step of the viewer is a state of a trace and a round of the others (a hex
// timestep, a Roombots action). Cell states are checked against the system the file names, so a
// state the rules cannot produce is an error with its line, not a grey cell.

#include "viewer/Readers.h"

#include "checker/Draw.h"
#include "rules/ConfigIo.h"
#include "rules/Error.h"
#include "rules/Library.h"
#include "rules/Model.h"
#include "rules/OutputFile.h"
#include "rules/PlanLines.h"
#include "rules/Region.h"
#include "rules/StopSignals.h"

#include <algorithm>
#include <cctype>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <map>
#include <memory>
#include <optional>
#include <sstream>

namespace holon::viewer {

namespace {

const char* const kFormats =
    "holon view reads an ITF trace (holon check --trace-out), a plan (holon plan --plan-out), a hex run (holon hex --steps-out) or a Roombots run (holon roombots --out: steps_*.jsonl)";

std::string text(const nlohmann::json& j, const char* key) { return j.is_object() && j.contains(key) && j[key].is_string() ? j[key].get<std::string>() : ""; }

/// The system a file's states belong to: --rules, else the file it names, else the bundled one.
rules::System loadNamed(const std::string& rulesFile, const std::string& source, const std::string& name, const std::string& where) {
    // A "source" the file names is followed only to a regular file: a FIFO there hung view. Its
    // "system" is a name, looked up among the bundled systems only: as a path it found a folder
    // or file of that name in the working directory first.
    std::error_code error;
    const bool plainName = !name.empty() && name.find_first_of("/\\") == std::string::npos && name != "." && name != "..";
    const std::string path = !rulesFile.empty()                                                   ? rules::rulesPath(rulesFile, "--rules")
                             : !source.empty() && std::filesystem::is_regular_file(source, error) ? source
                             : plainName                                                          ? rules::bundledPath(name)
                                                                                                  : std::string();
    if (!std::filesystem::exists(path))
        throw InputError(where + ": the rule file it names ('" + (source.empty() ? name : source) + "') is not there" +
                         (source.empty() && plainName ? " (a system's name is looked up among the bundled systems only, not in the working directory)" : "") +
                         "; give it with --rules FILE");
    rules::OutputClaims::reading("the rule file", path);  // -o must not replace it
    std::optional<rules::System> system = rules::loadSystem(path, std::cerr);
    if (!system) throw InputError(path + ": the rule file has errors (above); fix it or give another with --rules FILE");
    if (!name.empty() && system->name != name)
        throw InputError(where + ": the file is of system '" + name + "', but " + path + " declares '" + system->name + "'; give its rule file with --rules FILE");
    return std::move(*system);
}

/// Cell states by their fields (compact JSON, sorted keys): either those of a rule system, each
/// filled as the SVG pictures fill it, or a Roombots run's metamodules, each in its colour.
class States {
public:
    States(Run& run, const rules::System& system, const rules::Lattice& lattice) : run_(&run), model_(std::make_unique<rules::Model>(system, lattice)) {
        const rules::Alphabet& a = model_->alphabet();
        for (std::size_t f = 0; f < system.fields.size() && fill_ < 0; ++f)
            if (system.fields[f].kind == rules::FieldKind::Enum) fill_ = static_cast<int>(f);
        for (int v = 1; v < a.size(); ++v) valid_[rules::stateFields(*model_, static_cast<rules::CellValue>(v)).dump()] = v;
        what_ = "a state of system " + system.name;
    }
    States(Run& run, std::vector<std::string> colours) : run_(&run), colours_(std::move(colours)) {
        what_ = "a metamodule of the run, {\"module\": 0 to " + std::to_string(static_cast<int>(colours_.size()) - 1) + "}";
    }

    /// The run's state index of these fields; throws naming `where` when it is no state.
    int of(const nlohmann::json& fields, const std::string& where) {
        if (!fields.is_object()) throw InputError(where + ": a cell state is a JSON object of its fields, found " + fields.dump());
        if (fields.empty()) return 0;
        std::string key = fields.dump();
        if (auto it = cache_.find(key); it != cache_.end()) return it->second;
        std::string colour, label, words;
        if (model_) {
            const auto it = valid_.find(key);
            if (it == valid_.end()) throw InputError(where + ": " + key + " is not " + what_ + "; give the rule file the run was made with (--rules FILE)");
            const std::vector<int>& values = model_->alphabet().fields(static_cast<rules::CellValue>(it->second));
            const rules::System& system = model_->system();
            const bool filled = fill_ >= 0 && values[fill_] != rules::kAbsent;
            colour = checker::stateColour(*model_, static_cast<rules::CellValue>(it->second));  // as the SVG traces fill it
            label = filled ? system.fields[fill_].name + " = " + system.fields[fill_].values[values[fill_]] : "no " + (fill_ >= 0 ? system.fields[fill_].name : "fill field");
            words = checker::cellText(system, values);
        } else {
            // Compared as 64-bit (one past INT64_MAX reads negative): narrowed first, 2^32 + 1 was
            // read as metamodule 1.
            const std::int64_t wide = fields.size() == 1 && fields.contains("module") && fields["module"].is_number_integer() ? fields["module"].get<std::int64_t>() : -1;
            if (wide < 0 || wide >= static_cast<std::int64_t>(colours_.size())) throw InputError(where + ": " + key + " is not " + what_);
            const int m = static_cast<int>(wide);
            colour = colours_[m], label = "metamodule " + std::to_string(m), words = std::to_string(m);
        }
        const int s = run_->state(key, colour, words);
        if (std::none_of(run_->legend.begin(), run_->legend.end(), [&](const auto& l) { return l.second == label; })) run_->legend.push_back({colour, label});
        return cache_[key] = s;
    }

private:
    Run* run_;
    std::unique_ptr<rules::Model> model_;
    int fill_ = -1;
    std::map<std::string, int> valid_, cache_;
    std::vector<std::string> colours_;
    std::string what_;
};

/// Lattice positions to cell indices.
class Cells {
public:
    explicit Cells(const Run& run) : lattice_(&rules::Lattice::get(run.lattice)) {
        for (std::size_t i = 0; i < run.cells.size(); ++i) index_[key(run.cells[i])] = static_cast<int>(i);
    }
    /// [x, y] or [x, y, z]: its cell, or an error naming `where`.
    int of(const nlohmann::json& j, const std::string& where) const { return at(point(j, where), j, where); }
    /// The cell at lattice point v, written `j` in the file.
    int at(Vec v, const nlohmann::json& j, const std::string& where) const {
        // [x, y] on a cubic region read as [x, y, 0]: a square plan edited to name one was drawn in 3D.
        const nlohmann::json& p = j.is_object() && j.contains("#tup") ? j["#tup"] : j;
        if (p.is_array() && static_cast<int>(p.size()) != lattice_->dimension())
            throw InputError(where + ": cell " + j.dump() + " has " + std::to_string(p.size()) + " coordinates; a cell of " + lattice_->name() + " has " +
                             std::to_string(lattice_->dimension()) + "; write the file again with the holon command that made it");
        const auto it = index_.find(key(v));
        if (it == index_.end()) throw InputError(where + ": cell " + j.dump() + " lies outside the run's cells (its region or points); the file was edited by hand or mixes two runs: write it again with the holon command that made it");
        return it->second;
    }
    static Vec point(const nlohmann::json& j, const std::string& where) {
        return rules::pointFromJson(j.is_object() && j.contains("#tup") ? j["#tup"] : j, where);
    }
    std::size_t size() const { return index_.size(); }

private:
    static std::tuple<int, int, int> key(Vec v) { return {v.x, v.y, v.z}; }
    const rules::Lattice* lattice_;
    std::map<std::tuple<int, int, int>, int> index_;
};

void limitCells(const Run& run, const std::string& where) {
    if (static_cast<std::int64_t>(run.cells.size()) > kMaxCells)
        throw LimitError(where + ": " + std::to_string(run.cells.size()) + " cells, more than the viewer's " + std::to_string(kMaxCells) + " (docs/viewer.md)");
}

/// The box of lattice points spanning `points` (the cells of a run that names no region).
void boxAround(Run& run, const std::vector<Vec>& points) {
    if (points.empty()) return;
    Vec lo = points[0], hi = points[0];
    for (Vec p : points) lo = {std::min(lo.x, p.x), std::min(lo.y, p.y), std::min(lo.z, p.z)}, hi = {std::max(hi.x, p.x), std::max(hi.y, p.y), std::max(hi.z, p.z)};
    const std::int64_t count = std::int64_t(hi.x - lo.x + 1) * (hi.y - lo.y + 1) * (hi.z - lo.z + 1);
    if (count > kMaxCells) throw LimitError("the run spans " + std::to_string(count) + " cells, more than the viewer's " + std::to_string(kMaxCells) + " (docs/viewer.md)");
    for (int z = lo.z; z <= hi.z; ++z)
        for (int y = lo.y; y <= hi.y; ++y)
            for (int x = lo.x; x <= hi.x; ++x) run.cells.push_back({x, y, z});
}

void regionCells(Run& run, const std::string& spec, const std::string& where) {
    try {
        const rules::Region region = rules::Region::parse(spec, static_cast<std::size_t>(kMaxCells));
        run.lattice = region.lattice().kind();
        run.cells = region.cells();
    } catch (const InputError& e) {
        throw InputError(where + ": region '" + spec + "': " + e.what());
    }
}

void addInputs(Run& run, const Cells& cells, const nlohmann::json& inputs, const std::string& where) {
    if (inputs.is_null()) return;
    if (!inputs.is_object()) throw InputError(where + ": \"inputs\" must be an object {NAME: [cell, ...]}");
    const auto colours = checker::traceColours().inputs;
    for (const auto& [name, list] : inputs.items()) {
        if (!list.is_array()) throw InputError(where + ": input '" + name + "' must be a list of cells");
        Run::Input input{name, colours[run.inputs.size() % colours.size()], {}};
        for (const auto& c : list) input.cells.push_back(cells.of(c, where + ": input '" + name + "'"));
        run.inputs.push_back(std::move(input));
    }
}

/// A configuration's JSON ({"cells": [{"at": CELL, FIELD: VALUE, ...}, ...]}: a plan's start, an
/// ITF state decoded by rules::itfStateJson) as the run's state of each cell.
std::vector<int> configuration(const Cells& cells, States& states, const nlohmann::json& config, const std::string& where) {
    if (!config.contains("cells") || !config["cells"].is_array()) throw InputError(where + ": the configuration has no \"cells\" list");
    std::vector<int> c(cells.size(), 0);
    std::vector<bool> listed(cells.size(), false);
    for (const auto& cell : config["cells"]) {
        if (!cell.is_object() || !cell.contains("at")) throw InputError(where + ": a cell is {\"at\": [x, y], FIELD: VALUE, ...}, found " + cell.dump());
        nlohmann::json fields = cell;
        fields.erase("at");
        const int at = cells.of(cell["at"], where);
        // As check --from refuses it: which of the two states would the page show?
        if (listed[at]) throw InputError(where + ": cell " + cell["at"].dump() + " is listed twice; list each cell once");
        listed[at] = true;
        c[at] = states.of(fields, where);
    }
    return c;
}

/// Where a JSON syntax error lies, as line:column of `text`.
std::string lineColumn(const std::string& text, std::size_t byte) {
    byte = std::min(byte, text.size());
    const std::size_t line = 1 + static_cast<std::size_t>(std::count(text.begin(), text.begin() + static_cast<std::ptrdiff_t>(byte), '\n'));
    const std::size_t start = text.rfind('\n', byte == 0 ? 0 : byte - 1);
    return std::to_string(line) + ":" + std::to_string(start == std::string::npos ? byte + 1 : byte - start);
}

// ---------------------------------------------------------------------------------------------
// JSON Lines: plans, hex runs, Roombots runs

Run readLines(const std::string& path, std::istream& in, const std::string& rulesFile) {
    Run run;
    const std::string where1 = path + ":1";
    rules::PlanLineReader lines(in, path);
    const nlohmann::json& head = lines.head();
    const std::string kind = lines.kind();
    if (kind != "plan" && kind != "hex" && kind != "roombots") throw InputError(where1 + ": not a holon run: " + kFormats);
    run.kind = kind;
    const nlohmann::json& start = lines.start();
    // The cells: the start's region (plans, Roombots runs) or its list of points (hex runs).
    if (start.contains("region") && start["region"].is_string()) {
        regionCells(run, start["region"], where1);
    } else if (start.contains("points") && start["points"].is_array() && start.contains("lattice") && start["lattice"].is_string()) {
        const rules::Lattice* lattice = rules::Lattice::byName(start["lattice"].get<std::string>());
        if (!lattice) throw InputError(where1 + ": unknown lattice '" + start["lattice"].get<std::string>() + "'");
        run.lattice = lattice->kind();
        if (start["points"].size() > static_cast<std::size_t>(kMaxCells)) throw LimitError(where1 + ": more cells than the viewer's " + std::to_string(kMaxCells) + " (docs/viewer.md)");
        for (const auto& p : start["points"]) run.cells.push_back(Cells::point(p, where1));
    } else {
        throw InputError(where1 + ": the start configuration names no \"region\" (or \"points\" and \"lattice\"); write the file again with the holon command that made it");
    }
    limitCells(run, path);
    const Cells cells(run);
    std::optional<rules::System> system;
    std::optional<States> states;
    if (kind == "roombots" && !rulesFile.empty())
        throw InputError("--rules " + rulesFile + ": a Roombots run has no rule system (its metamodules are drawn in their colours); leave --rules out");
    if (kind == "roombots") {
        const nlohmann::json colours = head.contains("colours") ? head["colours"] : nlohmann::json();
        // A colour goes into the page's styles: only #rrggbb, never markup a file could smuggle in.
        const auto hexColour = [](const nlohmann::json& c) {
            if (!c.is_string()) return false;
            const std::string& t = c.get_ref<const std::string&>();
            return t.size() == 7 && t[0] == '#' && std::all_of(t.begin() + 1, t.end(), [](char h) { return std::isxdigit(static_cast<unsigned char>(h)) != 0; });
        };
        if (!colours.is_array() || !std::all_of(colours.begin(), colours.end(), hexColour))
            throw InputError(where1 + ": a Roombots run's first line lists its metamodules' \"colours\" as \"#rrggbb\" strings; write it again with holon roombots --out");
        states.emplace(run, head["colours"].get<std::vector<std::string>>());
    } else {
        system.emplace(loadNamed(rulesFile, text(head, "source"), text(head, "system"), where1));
        // A system fixed to one lattice, drawn on another (a hex region has 2D cells too, so the
        // cells' dimension does not tell; replay refuses it).
        if (system->lattice && *system->lattice != run.lattice)
            throw InputError(where1 + ": the run lies on " + rules::Lattice::get(run.lattice).name() + ", but system " + system->name + " is for " +
                             rules::Lattice::get(*system->lattice).name() + "; write the file again with the holon command that made it");
        states.emplace(run, *system, rules::Lattice::get(run.lattice));
        // The commands that write runs write every input; one missing would be drawn as nowhere.
        for (const std::string& name : system->inputs)
            if (!start.contains("inputs") || !start["inputs"].is_object() || !start["inputs"].contains(name))
                throw InputError(where1 + ": the start configuration does not set input '" + name + "' of system " + system->name +
                                 "; write the file again with the holon command that made it");
    }
    run.title = (kind == "plan" ? "plan " : kind == "hex" ? "hex run "
                                                          : "Roombots run ") +
                path + (system ? " (" + system->name + ")" : "");
    if (head.contains("title") && head["title"].is_string()) run.notes.push_back(head["title"].get<std::string>());
    run.start = configuration(cells, *states, start, where1);
    addInputs(run, cells, start.contains("inputs") ? start["inputs"] : nlohmann::json(), where1);

    // One step per round: every instance of the round, its cells changed or only looked at.
    run.steps.push_back({"start", {}, {}, {}});
    std::vector<int> now = run.start, seenAt(run.cells.size(), -1);
    std::map<std::string, int> fired;
    std::vector<int> looked;
    std::optional<std::int64_t> round;
    std::int64_t instances = 0;
    const auto close = [&] {
        if (!round) return;
        Run::Step& step = run.steps.back();
        std::string counts;
        for (const auto& [rule, n] : fired) counts += (counts.empty() ? "" : ", ") + rule + " " + std::to_string(n);
        step.label = (kind == "roombots" ? "action " : kind == "hex" ? "timestep "
                                                                     : "round ") +
                     std::to_string(*round) + ": " + counts;
        for (const auto& change : step.changes) seenAt[change.first] = -2;
        for (int c : looked)
            if (seenAt[c] != -2) step.context.push_back(c), seenAt[c] = -2;
        for (int c : looked) seenAt[c] = -1;
        for (const auto& change : step.changes) seenAt[change.first] = -1;
        fired.clear(), looked.clear();
    };
    rules::PlanLine j;
    while (lines.next(j)) {
        // holon plan --html builds the page after its run, within its --timeout and signal catcher.
        rules::StopSignals::checkJob("building the page");
        const std::string where = lines.where();
        if (!round || j.round != *round) {
            close();
            run.steps.push_back({});
            round = j.round;
        }
        Run::Step& step = run.steps.back();
        ++fired[j.fault ? "lost" : j.rule];
        ++instances;
        for (std::size_t k = 0; k < j.cells.size(); ++k) {
            const int c = cells.at(j.cells[k], j.json["cells"][k], where);
            const int s = j.fault ? 0 : states->of(j.json["after"][k], where);
            if (s == now[c]) {
                looked.push_back(c);
                continue;
            }
            now[c] = s;
            if (seenAt[c] >= 0) step.changes[static_cast<std::size_t>(seenAt[c])].second = s;
            else seenAt[c] = static_cast<int>(step.changes.size()), step.changes.push_back({c, s});
        }
    }
    close();
    run.notes.push_back(std::to_string(instances) + " rule instances in " + std::to_string(run.steps.size() - 1) + (kind == "roombots" ? " actions" : kind == "hex" ? " timesteps"
                                                                                                                                                                    : " rounds"));
    return run;
}

}  // namespace

// ---------------------------------------------------------------------------------------------
// ITF

Run readItf(const nlohmann::json& itf, const std::string& path, const rules::System& system) {
    Run run;
    run.kind = "trace";
    const nlohmann::json meta = itf.contains("#meta") ? itf["#meta"] : nlohmann::json::object();
    const auto stateWhere = [&](std::size_t k) { return path + ": state " + std::to_string(k); };
    const nlohmann::json* statesOf = nullptr;
    try {
        statesOf = &rules::itfStates(itf);
    } catch (const InputError& e) {
        throw InputError(path + ": " + e.what() + " (" + kFormats + ")");
    }
    const nlohmann::json& states = *statesOf;
    // Each state as a configuration's JSON, read by the library's ITF walker.
    const auto decoded = [&](std::size_t k) {
        try {
            return rules::itfStateJson(states[k]);
        } catch (const InputError& e) {
            throw InputError(stateWhere(k) + ": " + e.what());
        }
    };
    // The cells: the trace's region, or the box around every cell it names (a monitor's trace).
    if (const std::string region = text(meta, "region"); !region.empty()) {
        regionCells(run, region, path);
    } else {
        std::vector<Vec> points;
        bool three = false;
        for (std::size_t k = 0; k < states.size(); ++k) {
            const nlohmann::json config = decoded(k);
            for (const auto& cell : config["cells"]) {
                points.push_back(Cells::point(cell["at"], stateWhere(k)));
                three = three || cell["at"].size() == 3;
            }
        }
        run.lattice = system.lattice ? *system.lattice : three ? rules::LatticeKind::Cubic3D
                                                               : rules::LatticeKind::Square2D;
        boxAround(run, points);
    }
    limitCells(run, path);
    const Cells cells(run);
    States table(run, system, rules::Lattice::get(run.lattice));
    const auto instanceCells = [&](const nlohmann::json& m, std::size_t k) {
        std::vector<int> out;
        const auto add = [&](const nlohmann::json& list) {
            if (list.is_array())
                for (const auto& c : list) out.push_back(cells.of(c, stateWhere(k) + ": #meta"));
        };
        if (m.contains("cells")) add(m["cells"]);
        if (m.contains("fired") && m["fired"].is_array())
            for (const auto& f : m["fired"]) add(f.contains("cells") ? f["cells"] : nlohmann::json());
        return out;
    };
    const nlohmann::json first = decoded(0);
    run.start = configuration(cells, table, first, stateWhere(0));
    if (first.contains("inputs")) addInputs(run, cells, first["inputs"], stateWhere(0));
    run.steps.push_back({"0: initial", {}, {}, {}});
    std::vector<int> before = run.start;
    for (std::size_t k = 1; k < states.size(); ++k) {
        const std::vector<int> after = configuration(cells, table, decoded(k), stateWhere(k));
        const nlohmann::json m = states[k].contains("#meta") && states[k]["#meta"].is_object() ? states[k]["#meta"] : nlohmann::json::object();
        Run::Step step;
        for (std::size_t i = 0; i < after.size(); ++i)
            if (after[i] != before[i]) step.changes.push_back({static_cast<int>(i), after[i]});
        for (int c : instanceCells(m, k))
            if (after[c] == before[c] && std::find(step.context.begin(), step.context.end(), c) == step.context.end()) step.context.push_back(c);
        std::string label = text(m, "rule");
        if (!label.empty() && m.contains("cells") && m["cells"].is_array() && !m["cells"].empty()) label += " at " + m["cells"][0].dump();
        if (m.contains("fired") && m["fired"].is_array()) label = std::to_string(m["fired"].size()) + " instances fired";
        step.label = std::to_string(k) + ": " + (label.empty() ? "adjacent, not one rule step away" : label);
        if (m.contains("marked") && m["marked"].is_array())
            for (const auto& c : m["marked"]) step.marked.push_back(cells.of(c, stateWhere(k) + ": #meta.marked"));
        run.steps.push_back(std::move(step));
        before = after;
    }
    const std::string property = text(meta, "property"), description = text(meta, "description");
    run.title = "trace " + path + " (" + system.name + (text(meta, "region").empty() ? "" : " on " + text(meta, "region")) + ")";
    if (!property.empty()) {
        run.violation = static_cast<int>(run.steps.size()) - 1;
        run.notes.push_back("property " + property + " violated at step " + std::to_string(run.violation) + (description.empty() ? "" : ": " + description));
    } else if (!description.empty()) {
        run.notes.push_back(description);
    }
    if (itf.contains("loop")) {
        const nlohmann::json& loop = itf["loop"];
        if (!loop.is_number_integer() || loop.get<std::int64_t>() < 0 || loop.get<std::int64_t>() >= static_cast<std::int64_t>(states.size()))
            throw InputError(path + ": \"loop\" is the index of the state the last one loops back to, 0 to " + std::to_string(states.size() - 1) +
                             "; found " + loop.dump());
        run.notes.push_back("the last state loops back to state " + std::to_string(loop.get<std::int64_t>()));
    }
    return run;
}

Run readRun(const std::string& path, const std::string& rulesFile, std::uint64_t memoryBytes) {
    // Only a file: /dev/zero or a pipe has no end to read to.
    std::error_code error;
    if (std::filesystem::is_directory(path, error)) throw InputError(path + ": a folder, not a file; " + kFormats);
    if (!std::filesystem::is_regular_file(path, error)) throw InputError(path + ": no such file (or not a regular file); " + kFormats);
    if (std::filesystem::file_size(path, error) > kMaxFileBytes)
        throw LimitError(path + ": larger than the viewer's " + std::to_string(kMaxFileBytes >> 20) + " MiB (docs/viewer.md)");
    std::ifstream in(path, std::ios::binary);
    if (!in) throw InputError(path + ": cannot open the file");
    std::string first;
    std::getline(in, first);
    // What a JSON value read whole takes is about 33 bytes per byte of its text (a plan whose
    // start line is 78 MB peaked at 2.5 GB, a 67 MB ITF trace at 2.4 GB); the lines after the
    // first are read one at a time (a 24 MB plan of 10^6 lines: 25 MB). A 2 GiB file was read
    // until the machine ran out of memory.
    const std::uintmax_t size = std::filesystem::file_size(path, error);
    auto require = [&](std::uint64_t wholeBytes) {
        rules::requireMemory(rules::checkedProduct({wholeBytes, kBytesPerJsonByte}) + rules::checkedProduct({size, 4}), memoryBytes,
                             "reading " + path + " (" + std::to_string(size) + " bytes, " + std::to_string(wholeBytes) + " of them one JSON value)");
    };
    require(first.size());
    nlohmann::json head;
    bool line = false;
    try {
        head = rules::parseJsonOnceEach(first);
        line = head.is_object() && !head.contains("states");
    } catch (const nlohmann::json::exception&) {
    } catch (const InputError&) {
    }
    if (line) {
        in.clear();
        in.seekg(0);
        return readLines(path, in, rulesFile);
    }
    // One JSON document: an ITF trace (pretty-printed over many lines). An empty file is said to
    // be one (its parse error pointed at line 2 of a file with none).
    if (first.find_first_not_of(" \t\r\n") == std::string::npos && in.peek() == std::char_traits<char>::eof())
        throw InputError(path + ": the file is empty; " + std::string(kFormats));
    require(size);
    std::stringstream rest;
    rest << first << '\n'
         << in.rdbuf();
    const std::string all = rest.str();
    nlohmann::json itf;
    try {
        itf = rules::parseJsonOnceEach(all);
    } catch (const nlohmann::json::parse_error& e) {
        throw InputError(path + ":" + lineColumn(all, e.byte == 0 ? 0 : e.byte - 1) + ": not JSON (" + rules::jsonErrorText(e) + "); " + kFormats);
    } catch (const nlohmann::json::exception& e) {
        throw InputError(path + ":1: not JSON (" + rules::jsonErrorText(e) + "); " + kFormats);
    } catch (const InputError& e) {  // a key given twice, a NUL byte, too deep
        throw InputError(path + ": " + e.what());
    }
    if (!itf.is_object() || !itf.contains("states")) throw InputError(path + ":1: neither an ITF trace (no \"states\") nor JSON Lines; " + std::string(kFormats));
    const nlohmann::json meta = itf.contains("#meta") ? itf["#meta"] : nlohmann::json::object();
    return readItf(itf, path, loadNamed(rulesFile, text(meta, "source"), text(meta, "system"), path));
}

}  // namespace holon::viewer
