// `holon rules FILE...`: parse rule files, report diagnostics like a compiler, and summarise each
// system: fields, cell states per lattice, masses, the symmetry group, the rules and their
// instances after closing them under that group, constraints and properties.

#include "checker/RuleDrawing.h"
#include "cli/Commands.h"
#include "cli/Inputs.h"
#include "rules/Diagnostics.h"
#include "rules/Error.h"
#include "rules/Escape.h"
#include "rules/Library.h"
#include "rules/Model.h"
#include "rules/OutputFile.h"
#include "rules/Printer.h"

#include <filesystem>
#include <iomanip>
#include <iostream>
#include <map>
#include <nlohmann/json.hpp>

namespace holon::cli {

namespace {

struct RulesOptions {
    std::vector<std::string> files;
    std::vector<std::string> noWarnings;
    std::string svgDir, lattice;
    bool json = false;
};

std::vector<const rules::Lattice*> latticesOf(const rules::System& s) {
    if (s.lattice) return {&rules::Lattice::get(*s.lattice)};
    return rules::Lattice::all();
}

nlohmann::ordered_json summarise(const rules::System& s) {
    using json = nlohmann::ordered_json;
    json j{{"file", s.sourceName}, {"system", s.name}, {"lattice", s.lattice ? rules::Lattice::get(*s.lattice).name() : "any"}};
    json fields = json::array();
    for (const rules::Field& f : s.fields) {
        json fj{{"name", f.name}};
        if (f.kind == rules::FieldKind::Enum) fj["values"] = f.values;
        else if (f.kind == rules::FieldKind::Dir) fj["values"] = "dir";
        else fj["values"] = std::to_string(f.lo) + ".." + std::to_string(f.hi);
        if (f.whenField >= 0) {
            json when = json::array();
            for (int v : f.whenValues) when.push_back(s.fields[f.whenField].values[v]);
            fj["if"] = when;
        }
        fields.push_back(fj);
    }
    j["fields"] = fields;
    j["inputs"] = s.inputs;
    json masses = json::object();
    for (const rules::MassEntry& m : s.masses) masses[s.fields[m.field].values[m.value]] = m.mass.str();
    j["masses"] = masses;
    json states = json::object(), rulesJson = json::array();
    std::vector<rules::Model> models;
    for (const rules::Lattice* l : latticesOf(s)) {
        models.emplace_back(s, *l);
        states[l->name()] = models.back().alphabet().size();
    }
    j["states"] = states;
    json order = json::object(), total = json::object();
    for (const rules::Model& m : models) {
        order[m.lattice().name()] = m.symmetries().size();
        total[m.lattice().name()] = m.shapes().size();
    }
    j["symmetry"] = {{"group", rules::symmetryName(s.symmetry)}, {"order", order}};
    j["instances"] = total;
    for (std::size_t r = 0; r < models.front().rules().size(); ++r) {
        const rules::DirectedRule& dr = models.front().rules()[r];
        // The reverse of a self-inverse '<=>' rule (transfer: C D <=> D C) adds no instance.
        if (dr.reversed && models.front().shapeCount(static_cast<int>(r)) == 0) {
            rulesJson.back()["self_inverse"] = true;
            continue;
        }
        json instances = json::object();
        for (const rules::Model& m : models) instances[m.lattice().name()] = m.shapeCount(static_cast<int>(r));
        rulesJson.push_back({{"name", dr.name}, {"cells", dr.lhs().size()}, {"instances", instances}, {"guarded", dr.guard() != nullptr}, {"self_inverse", false}});
    }
    j["rules"] = rulesJson;
    json constraints = json::array();
    for (const rules::Constraint& c : s.constraints) constraints.push_back(rules::printExpr(s, c.expr));
    j["constraints"] = constraints;
    j["goal"] = s.goal ? json(rules::printExpr(s, *s.goal)) : json(nullptr);
    json props = json::array();
    for (const rules::Property& p : s.properties) props.push_back({{"name", p.name}, {"kind", rules::propertyKindName(p.kind)}});
    j["properties"] = props;
    return j;
}

/// `--svg DIR`: one drawing per directed rule that has orientations of its own, on the system's
/// lattice (or `--lattice`, or square2d for a system that fixes none), named SYSTEM.RULE.svg.
void drawRules(const rules::System& s, const RulesOptions& o) {
    const rules::Lattice* lattice = s.lattice ? &rules::Lattice::get(*s.lattice) : &rules::Lattice::get(rules::LatticeKind::Square2D);
    if (!o.lattice.empty()) {
        std::string names;
        const auto all = rules::Lattice::all();
        const auto named = std::find_if(all.begin(), all.end(), [&](const rules::Lattice* l) { return l->name() == o.lattice; });
        for (const rules::Lattice* l : all) names += (names.empty() ? "" : ", ") + l->name();
        if (named == all.end()) throw InputError("--lattice " + o.lattice + ": no such lattice; give one of " + names);
        lattice = *named;
        if (s.lattice && *s.lattice != lattice->kind())
            throw InputError("--lattice " + o.lattice + ": system '" + s.name + "' is written for the " + rules::Lattice::get(*s.lattice).name() + " lattice; leave --lattice out");
    }
    const rules::Model model(s, *lattice);  // throws InputError when the system is fixed to another lattice
    // Created if missing, its parent not (a mistyped path made /nonexist/x), as every --out folder.
    rules::prepareOutputDir("--svg", o.svgDir, {"*.svg"});
    const auto fileName = [](const std::string& name) {
        std::string out;
        for (char c : name) out += std::isalnum(static_cast<unsigned char>(c)) || c == '_' || c == '-' ? c : '_';
        return out;
    };
    int written = 0;
    for (int r = 0; r < static_cast<int>(model.rules().size()); ++r) {
        if (model.shapeCount(r) == 0) continue;
        const rules::OutputFile file("--svg", o.svgDir + "/" + fileName(s.name) + "." + fileName(model.rules()[r].name) + ".svg");
        file.write(checker::drawRuleSvg(model, r));
        ++written;
    }
    (o.json ? std::cerr : std::cout) << "  drawings     " << written << (written == 1 ? " rule" : " rules") << " on " << lattice->name() << " in " << o.svgDir << "/\n";
}

void printHuman(const nlohmann::ordered_json& j, std::ostream& out) {
    out << "system " << j["system"].get<std::string>() << "  (" << j["file"].get<std::string>() << ")\n";
    out << "  lattice      " << j["lattice"].get<std::string>() << '\n';
    for (const auto& f : j["fields"]) {
        out << "  field        " << f["name"].get<std::string>() << ": ";
        if (f["values"].is_array()) {
            bool first = true;
            for (const auto& v : f["values"]) out << (first ? "" : " | ") << v.get<std::string>(), first = false;
        } else {
            out << f["values"].get<std::string>();
        }
        if (f.contains("if")) {
            out << " if ";
            bool first = true;
            for (const auto& v : f["if"]) out << (first ? "" : " | ") << v.get<std::string>(), first = false;
        }
        out << '\n';
    }
    for (const auto& in : j["inputs"]) out << "  input        " << in.get<std::string>() << '\n';
    out << "  mass         ";
    if (j["masses"].empty()) out << "1 per occupied cell";
    bool first = true;
    for (const auto& [name, m] : j["masses"].items()) out << (first ? "" : ", ") << name << " = " << m.get<std::string>(), first = false;
    out << "\n  cell states  ";
    first = true;
    for (const auto& [lattice, n] : j["states"].items()) out << (first ? "" : ", ") << lattice << " " << n.get<int>(), first = false;
    out << "  (with the vacuum)\n  symmetry     " << j["symmetry"]["group"].get<std::string>() << " (";
    first = true;
    for (const auto& [lattice, n] : j["symmetry"]["order"].items())
        out << (first ? "" : ", ") << n.get<int>() << " on " << lattice, first = false;
    out << ")\n  rules        instances under the group (";
    first = true;
    for (const auto& [lattice, n] : j["states"].items()) out << (first ? "" : " / ") << lattice, first = false;
    out << "): ";
    first = true;
    for (const auto& [lattice, n] : j["instances"].items()) out << (first ? "" : " / ") << n.get<int>(), first = false;
    out << " in all\n";
    for (const auto& r : j["rules"]) {
        out << "    " << std::left << std::setw(22) << r["name"].get<std::string>() << r["cells"].get<int>() << " cells  ";
        first = true;
        for (const auto& [lattice, n] : r["instances"].items()) out << (first ? "" : " / ") << n.get<int>(), first = false;
        if (r["guarded"].get<bool>()) out << "  guarded";
        if (r["self_inverse"].get<bool>()) out << "  self-inverse";
        out << '\n';
    }
    for (const auto& c : j["constraints"]) out << "  constraint   " << c.get<std::string>() << '\n';
    if (!j["goal"].is_null()) out << "  goal         " << j["goal"].get<std::string>() << '\n';
    for (const auto& p : j["properties"])
        out << "  property     " << p["name"].get<std::string>() << " (" << p["kind"].get<std::string>() << ")\n";
}

}  // namespace

Run addRulesCommand(CLI::App& app) {
    auto opts = std::make_shared<RulesOptions>();
    CLI::App* sub = app.add_subcommand("rules", "Parse .holon rule files, report diagnostics and summarise each system");
    addRulesFiles(sub, "files", opts->files)->required();
    sub->add_option("-W", opts->noWarnings,
                    "silence a warning: -W no-NAME (names: unused-value, unused-input, "
                    "unmassed-value, duplicate-rule, no-rules)");
    sub->add_flag("--json", opts->json, "print the summaries as JSON");
    sub->add_option("--svg", opts->svgDir, "draw every rule, one SVG per rule with a panel per orientation, into this folder");
    sub->add_option("--lattice", opts->lattice, "the lattice to draw on (square2d, hex2d, cubic3d; default: the system's, else square2d)");
    return [opts]() {
        const rules::LoadOptions load = loadOptions(opts->noWarnings);
        nlohmann::ordered_json all = nlohmann::ordered_json::array();
        int failed = 0;
        std::map<std::string, std::string> drawn;  // system name -> the file --svg drew it from
        // Every rule file is an input before --svg writes: x.r.svg in the folder was replaced by
        // its own drawing (audit 7). A file that cannot be found is reported in the loop below.
        if (!opts->svgDir.empty())
            for (const std::string& file : opts->files) try {
                    rules::OutputClaims::reading("the rule file", rules::rulesPath(file));
                } catch (const InputError&) {
                }
        for (const std::string& file : opts->files) {
            // --lattice only says where --svg draws: alone it was ignored without a word.
            if (!opts->lattice.empty() && opts->svgDir.empty()) throw InputError("--lattice chooses the lattice --svg draws the rules on; add --svg DIR, or leave out --lattice");
            // A file that cannot be read is reported like one with errors: the others still get
            // their summaries, and the exit code says something failed.
            std::optional<rules::System> system;
            try {
                system = rules::loadSystem(rules::rulesPath(file), std::cerr, load);
            } catch (const InputError& e) {
                std::cerr << "holon: error: " << rules::escapeText(e.what(), true) << '\n';
            }
            if (!system) {
                ++failed;
                continue;
            }
            nlohmann::ordered_json j = summarise(*system);
            if (opts->json) all.push_back(j);
            else printHuman(j, std::cout);
            // Drawings are named SYSTEM.RULE.svg: a second file of the same system replaced the
            // first one's, and both were reported as drawn.
            if (!opts->svgDir.empty()) {
                if (const auto [it, fresh] = drawn.emplace(system->name, file); !fresh && it->second != file)
                    throw InputError("--svg " + opts->svgDir + ": " + it->second + " and " + file + " both declare system '" + system->name +
                                     "', and its drawings are named after it; draw them into two folders (one --svg each)");
                drawRules(*system, *opts);
            }
        }
        if (opts->json) std::cout << all.dump(2) << '\n';
        return failed ? 2 : 0;
    };
}

}  // namespace holon::cli
