// `holon diff A.holon B.holon --region R (--all | --from CONFIG...)`: compares two designs on one
// region (checker::diff, which explores both with check's set-up): transitions and reachable
// configurations in one and not the other, counted, with the nearest witness of each kind drawn.
// Exit 0 when the graphs are the same, 1 when they differ, 3 when a limit stopped either
// exploration first.

#include "checker/Diff.h"
#include "checker/Draw.h"
#include "cli/Commands.h"
#include "cli/Inputs.h"
#include "cli/Limits.h"
#include "cli/WriteErrors.h"
#include "rules/OutputFile.h"

#include <iostream>

namespace holon::cli {

namespace {

struct DiffArgs {
    std::string a, b, region, svg;
    std::vector<std::string> from, inputs, noWarnings;
    bool all = false, json = false;
    ExploreLimitArgs limits;
};

/// One design's rules, read with its own state names.
struct Design {
    rules::System system;
    std::unique_ptr<rules::Model> model;
    std::unique_ptr<rules::Interpreter> in;
};

int run(const DiffArgs& a) {
    if (a.all == !a.from.empty())
        throw InputError(std::string(a.all ? "--all and --from name both" : "say") + " where both designs start: --from CONFIG (repeatable), or --all for every legal configuration" +
                         (a.all ? "; give one" : ""));
    const rules::Region region = exploreRegion(a.region, a.limits);
    const rules::StopSignals guard(true);  // a signal stops the exploration: undecided, 128 + the signal
    std::optional<rules::OutputFile> svgOut;
    if (!a.svg.empty()) svgOut.emplace("--svg", a.svg);
    checker::DiffOptions options;
    options.limits = a.limits.limits();
    options.all = a.all;
    Design designs[2];
    for (int side = 0; side < 2; ++side) {
        auto system = loadRules(side ? a.b : a.a, a.noWarnings);
        if (!system) return kExitBadInput;
        Design& d = designs[side];
        d.system = std::move(*system);
        d.model = std::make_unique<rules::Model>(d.system, region.lattice());
        d.in = std::make_unique<rules::Interpreter>(*d.model, region);
        options.initial[side] = readStarts(*d.in, a.from, a.inputs, &options.inputs[side]);
        requireSharedInputs(options.initial[side], a.from);
    }
    const checker::DiffReport report = checker::diff(*designs[0].model, *designs[1].model, region, options);
    // Undecided: a limit or a signal stopped an exploration or the comparison after them.
    const auto undecided = [&](const std::string& what, StopReason why, std::optional<std::uint64_t> states) {
        if (svgOut) std::cerr << "holon: note: --svg " << a.svg << " is not written: the comparison is undecided\n";
        if (a.json) {
            nlohmann::json j = {{"a", report.systems[0]}, {"b", report.systems[1]}, {"region", region.spec()}, {"outcome", "undecided"}, {"stopped", stopReasonName(why)}, {"while", what}};
            if (states) j["states"] = *states;
            std::cout << j.dump(2) << '\n';
        } else {
            std::cout << "undecided: " << what << " stopped by " << stopReasonName(why) << (states ? " after " + std::to_string(*states) + " states" : "")
                      << raiseAdvice(why, " to compare whole graphs") << '\n';
        }
        return exitCodeFor(why, caughtSignal());
    };
    if (const int side = report.stopped(); side >= 0) {
        const auto& st = report.explored[side].explorer->stats();
        return undecided(std::string("exploring ") + (side ? "B (" : "A (") + report.systems[side] + ")", st.stopped, st.states);
    }
    if (report.comparisonStopped) return undecided("comparing the two graphs", *report.comparisonStopped, std::nullopt);
    const checker::DesignDifference& d = *report.difference;
    const int code = d.same() ? kExitOk : kExitViolated;
    // The witness drawn: B's extra transition first (a variant's new move), else A's.
    const int shown = d.transitionWitness[1] ? 1 : d.transitionWitness[0] ? 0
                                                                          : -1;
    // A write that fails (a full disk) is said after the comparison, which it no longer takes with it.
    WriteErrors errors;
    if (svgOut && shown >= 0)
        errors.attempt([&] { svgOut->write(checker::drawTraceSvg(*d.transitionWitness[shown], *report.explored[shown].engine, report.witnessText(shown))); }, "--svg " + svgOut->path());
    if (svgOut && shown < 0) std::cerr << "holon: note: --svg " << a.svg << " is not written: no transition differs, so there is nothing to draw\n";
    if (a.json) {
        std::cout << report.toJson().dump(2) << '\n';
        errors.raise();
        return code;
    }
    std::cout << "A " << report.systems[0] << " (" << a.a << ") against B " << report.systems[1] << " (" << a.b << ") on " << region.spec() << ", "
              << (a.all ? "every legal configuration" : "reachable from " + std::to_string(a.from.size()) + " configuration(s)") << '\n';
    for (int side = 0; side < 2; ++side)
        std::cout << "  " << (side ? "B" : "A") << ": " << d.states[side] << " configurations, " << d.transitions[side] << " transitions; only in "
                  << (side ? "B" : "A") << ": " << d.onlyStates[side] << " configurations, " << d.onlyTransitions[side] << " transitions\n";
    if (d.same()) {
        std::cout << "  the same reconfiguration graph\n";
        errors.raise();
        return code;
    }
    for (int side : {1, 0})
        if (d.transitionWitness[side])
            std::cout << "\nnearest transition only in " << (side ? "B" : "A") << ": " << report.witnessText(side) << '\n'
                      << checker::drawTraceAscii(*d.transitionWitness[side], *report.explored[side].engine);
    errors.raise();  // a file that could not be written outranks the verdict, as in plan
    return code;
}

}  // namespace

Run addDiffCommand(CLI::App& app) {
    auto a = std::make_shared<DiffArgs>();
    CLI::App* sub = app.add_subcommand("diff", "Compare two designs' reconfiguration graphs on one region");
    addRulesFile(sub, "a", a->a, "design A")->required();
    addRulesFile(sub, "b", a->b, "design B")->required();
    sub->add_option("--region", a->region, "bounded region: square:WxH, cubic:WxHxD or hex:rR")->required();
    sub->add_flag("--all", a->all, "compare on every legal configuration of the region");
    sub->add_option("--from", a->from, "start configuration for both designs (JSON or ASCII art); repeatable");
    sub->add_option("--input", a->inputs, "set an input from an ASCII mask: NAME=FILE");
    addExploreLimits(sub, a->limits, "each exploration");
    sub->add_flag("--json", a->json, "print the counts and witnesses as JSON");
    sub->add_option("--svg", a->svg, "draw the nearest differing transition as SVG");
    sub->add_option("-W", a->noWarnings, "silence a warning: -W no-NAME");
    return [a] { return run(*a); };
}

}  // namespace holon::cli
