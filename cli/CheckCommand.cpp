// `holon check FILE --region SPEC [--all | --from CONFIG]`: explore the reconfiguration graph on a
// bounded region and report each property with a verdict and evidence; a violation comes with a
// shortest counterexample trace, replayed through the reference interpreter (by checker::check) before
// it is shown.

#include "checker/Check.h"
#include "checker/ComponentTable.h"
#include "checker/Draw.h"
#include "checker/Graph.h"
#include "cli/Commands.h"
#include "cli/Inputs.h"
#include "cli/Limits.h"
#include "cli/WriteErrors.h"
#include "rules/ConfigIo.h"
#include "rules/Error.h"
#include "rules/Library.h"
#include "rules/OutputFile.h"
#include "viewer/Page.h"
#include "viewer/Readers.h"

#include <algorithm>
#include <iomanip>
#include <iostream>
#include <map>
#include <unistd.h>

namespace holon::cli {

namespace {

struct CheckArgs {
    std::string file, region, traceOut, svg, dot, html;
    std::vector<std::string> from, inputs, properties, noWarnings;
    bool all = false, json = false, components = false;
    ExploreLimitArgs limits;
};

/// `--components`: the graph's components as a table, whether the design is complete on the region
/// (one component per conserved amount), and the representatives drawn; JSON when `json` is given.
/// False when the exploration stopped at a limit, so the table would be of part of the graph.
bool printComponents(const checker::Explorer& explorer, const rules::System& system, nlohmann::json* json) {
    const rules::Engine& engine = explorer.engine();
    if (explorer.stats().stopped != StopReason::Finished) {
        if (json) (*json)["component_table"] = nullptr;
        else std::cout << "\ncomponents: not computed, the exploration stopped at a limit before the whole graph was seen\n";
        return false;
    }
    const auto rows = checker::componentTable(explorer, checker::components(explorer));
    // The amount the design conserves: the one it declares, else the count of metamodules when no
    // component changes it.
    bool conserves = false;  // GCC 12 warns (wrongly) of an uninitialised std::optional here
    auto quantity = rules::Property::Quantity::Mass;
    for (const rules::Property& p : system.properties)
        if (p.kind == rules::Property::Kind::Conserves) conserves = true, quantity = p.quantity;
    const bool countKept = std::all_of(rows.begin(), rows.end(), [](const auto& r) { return r.minCount == r.maxCount; });
    const bool massKept = std::all_of(rows.begin(), rows.end(), [](const auto& r) { return r.minMass == r.maxMass; });
    if (!conserves && countKept) conserves = true, quantity = rules::Property::Quantity::Count;
    const bool byMass = quantity == rules::Property::Quantity::Mass;
    if (conserves && !(byMass ? massKept : countKept)) conserves = false;
    std::map<std::int64_t, int> perAmount;
    if (conserves)
        for (const auto& r : rows) ++perAmount[byMass ? r.minMass : r.minCount];
    // One component is complete whatever is conserved: every configuration reaches every other
    // (the JSON said false where the text said so).
    const bool complete = rows.size() == 1 || (conserves && std::all_of(perAmount.begin(), perAmount.end(), [](const auto& a) { return a.second == 1; }));
    const std::string amount = !conserves ? "" : byMass ? "mass"
                                                        : "number of metamodules";
    const auto massText = [&](std::int64_t units) { return rules::Rational(units, engine.massDenominator()).str(); };
    const auto range = [](const std::string& lo, const std::string& hi) { return lo == hi ? lo : lo + "-" + hi; };
    if (json) {
        nlohmann::json table = nlohmann::json::array();
        for (const auto& r : rows)
            table.push_back({{"states", r.states}, {"metamodules", {r.minCount, r.maxCount}}, {"mass", {massText(r.minMass), massText(r.maxMass)}}, {"representative", rules::configToJson(rules::Interpreter(engine.model(), engine.region()), {explorer.cells(r.representative), engine.inputs()})}});
        (*json)["component_table"] = table;
        (*json)["conserved"] = conserves ? nlohmann::json(amount) : nlohmann::json(nullptr);
        (*json)["complete"] = complete;
        return true;
    }
    std::cout << "\ncomponents: " << rows.size() << "; ";
    if (rows.size() == 1) std::cout << "one component: every configuration reaches every other\n";
    else if (!conserves) std::cout << "the design conserves neither mass nor the number of metamodules within a component\n";
    else if (complete) std::cout << "complete: one component per " << amount << " (" << perAmount.size() << (perAmount.size() == 1 ? " value" : " values") << ")\n";
    else {
        const auto split = std::find_if(perAmount.begin(), perAmount.end(), [](const auto& a) { return a.second > 1; });
        std::cout << "not complete: " << amount << " " << (byMass ? massText(split->first) : std::to_string(split->first))
                  << " has " << split->second << " components (configurations of the same " << amount << " that cannot reach each other)\n";
    }
    std::cout << "  " << std::left << std::setw(4) << "#" << std::setw(12) << "states" << std::setw(13) << "metamodules"
              << "mass\n";
    for (std::size_t k = 0; k < rows.size() && k < 20; ++k)
        std::cout << "  " << std::setw(4) << k + 1 << std::setw(12) << rows[k].states << std::setw(13)
                  << range(std::to_string(rows[k].minCount), std::to_string(rows[k].maxCount)) << range(massText(rows[k].minMass), massText(rows[k].maxMass)) << '\n';
    if (rows.size() > 20) std::cout << "  ... and " << rows.size() - 20 << " more (--json lists them all)\n";
    for (std::size_t k = 0; k < rows.size() && k < 6; ++k)
        std::cout << "-- representative of component " << k + 1 << " (its smallest configuration):\n"
                  << checker::drawAscii(engine, explorer.cells(rows[k].representative));
    return true;
}

int run(const CheckArgs& a) {
    auto system = loadRules(a.file, a.noWarnings);
    if (!system) return 2;
    const rules::Region region = exploreRegion(a.region, a.limits);
    rules::Model model(*system, region.lattice());
    rules::Interpreter in(model, region);
    // Output paths are checked before the work, so a finished check is never lost to a bad path.
    std::optional<rules::OutputFile> traceOut, svgOut, dotOut, htmlOut;
    if (!a.html.empty()) htmlOut.emplace("--html", a.html);
    if (!a.traceOut.empty()) traceOut.emplace("--trace-out", a.traceOut);
    if (!a.svg.empty()) svgOut.emplace("--svg", a.svg);
    if (!a.dot.empty()) dotOut.emplace("--dot", a.dot);

    checker::CheckOptions options;
    options.limits = a.limits.limits();
    options.all = a.all;
    options.properties = a.properties;
    if (a.all && !a.from.empty()) throw InputError("give either --all or --from, not both");
    if (!a.all && a.from.empty()) throw InputError("say where to start: --from CONFIG (JSON or ASCII art), or --all for every legal configuration");
    // From here: a signal while a large --from is read ended holon with no word (robustness audit 6).
    const rules::StopSignals guard(true);  // a signal stops the exploration: the report so far, 128 + the signal
    options.initial = readStarts(in, a.from, a.inputs, &options.inputs);
    requireSharedInputs(options.initial, a.from);
    const bool terminal = isatty(2) && !a.json;
    if (terminal)
        options.onProgress = [](const checker::ExploreStats& s) {
            std::cerr << "\r  exploring: " << s.states << " states, " << s.edges << " edges, frontier " << s.frontier << ", depth "
                      << s.depth << ", " << std::fixed << std::setprecision(1) << s.seconds << " s   " << std::flush;
        };
    checker::Exploration kept;
    const checker::CheckReport report = checker::check(model, region, options, &kept);
    if (terminal) std::cerr << "\r" << std::string(90, ' ') << "\r";
    const rules::Engine& engine = *kept.engine;

    // check() replays every trace through the reference interpreter; one that does not replay is
    // a bug in holon, shown for the report and said by the exit code.
    bool unreplayed = false;
    std::vector<const checker::PropertyResult*> violated;
    for (const checker::PropertyResult& p : report.properties) {
        if (!p.trace) continue;
        if (!p.confirmed()) {
            unreplayed = true;
            reportInternalError("check", "the trace for '" + p.name + "' does not replay: " + p.whyNotConfirmed());
        }
        if (p.verdict == checker::Verdict::Violated) violated.push_back(&p);
    }
    const auto exitCode = [&] {
        // A signal during any phase (the exploration, or a property's pass over it) is 128 + it.
        return unreplayed ? kExitInternal : caughtSignal() != 0 ? exitCodeFor(StopReason::Interrupted, caughtSignal())
                                                                : exitCodeFor(report.overall());
    };
    // Every violated property gets its own trace file (named after it when there are several).
    // A write that fails (a full disk) is said after the report, which it no longer takes with it.
    WriteErrors errors;
    std::vector<std::string> written;
    for (const checker::PropertyResult* p : violated) {
        const bool several = violated.size() > 1;
        if (traceOut) errors.write(
            "--trace-out", pathFor(traceOut->path(), p->name, several), [&] { return checker::toItf(*p->trace, engine, a.file).dump(2) + "\n"; }, written);
        if (htmlOut)
            errors.write(
                "--html", pathFor(htmlOut->path(), p->name, several), [&] {
                    return viewer::page(viewer::readItf(checker::toItf(*p->trace, engine, a.file), "the counterexample for '" + p->name + "'", *system));
                },
                written);
        if (svgOut)
            errors.write(
                "--svg", pathFor(svgOut->path(), p->name, several), [&] {
                    return checker::drawTraceSvg(*p->trace, engine, system->name + " on " + region.spec() + ": " + p->name + " " + checker::verdictName(p->verdict) + " -- " + p->trace->description);
                },
                written);
    }
    if (violated.empty()) noteNoCounterexample("check", {{"--trace-out", a.traceOut}, {"--html", a.html}, {"--svg", a.svg}});
    if (dotOut) {
        // A graph cut short (a limit, or every property asked for already violated) is part of
        // one, which the file would not say (an empty digraph came out of --max-states 50): as
        // --components, none is drawn.
        if (kept.explorer->stats().stopped != StopReason::Finished)
            std::cerr << "holon check: --dot not written: the exploration stopped before the whole graph was seen (" << stopReasonName(kept.explorer->stats().stopped) << ")\n";
        else if (report.stats.states > 5000) std::cerr << "holon check: --dot not written: " << report.stats.states << " states is too many to draw (at most 5000)\n";
        else errors.attempt([&] { dotOut->write([&](std::ostream& out) { checker::writeDot(*kept.explorer, in, out); }); }, "--dot " + dotOut->path());
    }

    // A table asked for and not computed (a limit) leaves the run undecided.
    const auto exitWith = [&](bool componentsShown) { return componentsShown || exitCode() != kExitOk ? exitCode() : static_cast<int>(kExitUndecided); };
    if (a.json) {
        nlohmann::json j = report.toJson();
        const bool shown = !a.components || printComponents(*kept.explorer, *system, &j);
        std::cout << j.dump(2) << '\n';
        errors.raise();
        return exitWith(shown);
    }
    const auto& s = report.stats;
    std::cout << system->name << " on " << region.spec() << (a.all ? ", every legal configuration" : ", reachable from " + std::to_string(a.from.size()) + " configuration(s)") << '\n';
    std::cout << "  " << s.states << " states, " << s.edges << " edges, "
              << (report.components < 0 ? std::string("? components") : std::to_string(report.components) + (report.components == 1 ? " component" : " components"))
              << ", depth " << s.depth << ", " << std::fixed << std::setprecision(2) << s.seconds << " s, " << report.bytesPerState << " bytes/state";
    if (s.stopped == StopReason::Decided) std::cout << "\n  stopped early: every property asked for is violated; explored " << s.states << ", frontier " << s.frontier;
    else if (s.stopped != StopReason::Finished)
        std::cout << "\n  stopped by " << stopReasonName(s.stopped)
                  << (s.enumerating ? " while listing the legal configurations of the region (" + std::to_string(s.frontier) + " found)"
                                    : ": explored " + std::to_string(s.states) + ", frontier " + std::to_string(s.frontier))
                  << raiseAdvice(s.stopped, " to go further");
    std::cout << "\n\n  " << std::left << std::setw(20) << "property" << std::setw(10) << "verdict" << std::setw(10) << "time"
              << "evidence\n";
    for (const auto& p : report.properties)
        std::cout << "  " << std::setw(20) << p.name << std::setw(10) << checker::verdictName(p.verdict) << std::setw(10)
                  << (std::to_string(static_cast<int>(p.seconds * 1000)) + " ms ") << p.summary << '\n';
    for (const checker::PropertyResult* p : violated)
        std::cout << "\ncounterexample for '" << p->name << "'" << (p->trace->description.empty() ? "" : ": " + p->trace->description)
                  << (p->confirmed() ? " (replayed through the reference interpreter)" : " (NOT confirmed by the reference interpreter)") << '\n'
                  << checker::drawTraceAscii(*p->trace, engine);
    if (violated.size() > 1 && !written.empty()) {
        std::cout << "\ntraces written:";
        for (const std::string& w : written) std::cout << ' ' << w;
        std::cout << '\n';
    }
    const bool shown = !a.components || printComponents(*kept.explorer, *system, nullptr);
    errors.raise();  // a file that could not be written outranks the verdict, as in plan
    return exitWith(shown);
}

}  // namespace

Run addCheckCommand(CLI::App& app) {
    auto a = std::make_shared<CheckArgs>();
    CLI::App* sub = app.add_subcommand("check", "Explore the reconfiguration graph on a bounded region and check properties");
    addRulesFile(sub, "file", a->file)->required();
    sub->add_option("--region", a->region, "bounded region: square:WxH, cubic:WxHxD or hex:rR")->required();
    sub->add_flag("--all", a->all, "explore every legal configuration of the region");
    sub->add_option("--from", a->from, "initial configuration (JSON or ASCII art); repeatable");
    sub->add_option("--input", a->inputs, "set an input from an ASCII mask: NAME=FILE (any character but '.' marks a cell)");
    sub->add_option("--property", a->properties, "check only this property (repeatable); 'deadlock' and 'goal_reachable' are built in");
    addExploreLimits(sub, a->limits);
    sub->add_flag("--json", a->json, "print the report as JSON");
    sub->add_flag("--components", a->components, "list the reconfiguration graph's components (sizes, metamodules, mass, a drawn representative) and say whether the design is complete");
    sub->add_option("--trace-out", a->traceOut, "write the counterexample as an ITF JSON trace");
    sub->add_option("--svg", a->svg, "draw the counterexample as SVG");
    sub->add_option("--html", a->html, "write the counterexample as a self-contained HTML viewer (docs/viewer.md)");
    sub->add_option("--dot", a->dot, "write the explored graph as Graphviz (small graphs)");
    sub->add_option("-W", a->noWarnings, "silence a warning: -W no-NAME");
    return [a] { return run(*a); };
}

}  // namespace holon::cli
