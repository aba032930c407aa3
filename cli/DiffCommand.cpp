// `holon diff A.holon B.holon --region R (--all | --from CONFIG...)`: compares two designs on one
// region (checker/Diff.h): transitions and reachable configurations in one and not the other,
// counted, with the nearest witness of each kind drawn. Exit 0 when the graphs are the same, 1 when
// they differ, 3 when a limit stopped either exploration first.

#include "checker/Diff.h"
#include "checker/Draw.h"
#include "cli/Commands.h"
#include "cli/Inputs.h"
#include "cli/Limits.h"
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

/// One design on the region, explored from the starts (read with its own state names) or --all.
struct Side {
    std::string file;
    rules::System system;
    std::unique_ptr<rules::Model> model;
    std::unique_ptr<rules::Interpreter> in;
    std::unique_ptr<rules::Engine> engine;
    std::unique_ptr<checker::Explorer> explorer;
};

std::unique_ptr<Side> explore(const DiffArgs& a, const std::string& file, const rules::Region& region, const Budget& budget) {
    auto system = loadRules(file, a.noWarnings);
    if (!system) return nullptr;
    auto side = std::make_unique<Side>();
    side->file = file;
    side->system = std::move(*system);
    side->model = std::make_unique<rules::Model>(side->system, region.lattice());
    side->in = std::make_unique<rules::Interpreter>(*side->model, region);
    std::vector<std::uint32_t> inputs;
    const auto starts = readStarts(*side->in, a.from, a.inputs, &inputs);
    side->engine = std::make_unique<rules::Engine>(*side->model, region, starts.empty() ? inputs : starts.front().inputs);
    checker::Explorer::Options options;
    options.limits = a.limits.limits(2);  // two designs share --memory
    options.budget = budget;              // and one --timeout
    side->explorer = std::make_unique<checker::Explorer>(*side->engine, options);
    if (a.all) side->explorer->addAllLegal();
    for (const auto& s : starts) side->explorer->addInitial(s.cells.data());
    side->explorer->explore();
    return side;
}

int run(const DiffArgs& a) {
    if (a.all == !a.from.empty()) throw InputError("say where both designs start: --from CONFIG (repeatable), or --all for every legal configuration, not both");
    const rules::Region region = rules::Region::parse(a.region, 1u << 22);
    const rules::StopSignals guard(true);  // a signal stops the exploration: undecided, 128 + the signal
    const Budget budget = a.limits.limits().budget();
    std::optional<rules::OutputFile> svgOut;
    if (!a.svg.empty()) svgOut.emplace("--svg", a.svg);
    const auto sideA = explore(a, a.a, region, budget);
    if (!sideA) return kExitBadInput;
    const auto sideB = explore(a, a.b, region, budget);
    if (!sideB) return kExitBadInput;
    const std::string names[2] = {sideA->system.name, sideB->system.name};
    const Side* sides[2] = {sideA.get(), sideB.get()};
    for (const Side* s : sides)
        if (const auto& st = s->explorer->stats(); st.stopped != StopReason::Finished) {
            std::cout << "undecided: exploring " << s->system.name << " stopped by " << stopReasonName(st.stopped) << " after " << st.states << " states"
                      << (limitOption(st.stopped).empty() ? "" : "; raise the limit (--max-states, --timeout or --memory) to compare whole graphs") << '\n';
            return exitCodeFor(st.stopped, caughtSignal());
        }
    const checker::DesignDifference d = checker::compareDesigns({sideA->engine.get(), sideA->explorer.get()}, {sideB->engine.get(), sideB->explorer.get()});
    const int code = d.same() ? kExitOk : kExitViolated;
    // The witness drawn: B's extra transition first (a variant's new move), else A's.
    const int shown = d.transitionWitness[1] ? 1 : d.transitionWitness[0] ? 0
                                                                          : -1;
    const auto describe = [&](int side) {
        const checker::Trace& t = *d.transitionWitness[side];
        const auto& engine = *sides[side]->engine;
        const std::string rule = engine.model().rules()[engine.instances()[t.steps.back().placed].rule].name;
        return names[side] + " fires '" + rule + "' after " + checker::stepCount(t.steps.size() - 2) + "; " + names[1 - side] + " has no such step";
    };
    if (svgOut && shown >= 0) svgOut->write(checker::drawTraceSvg(*d.transitionWitness[shown], *sides[shown]->engine, describe(shown)));
    if (a.json) {
        nlohmann::json j = {{"a", names[0]}, {"b", names[1]}, {"region", region.spec()}, {"same", d.same()}};
        for (int side = 0; side < 2; ++side) {
            nlohmann::json s = {{"system", names[side]},
                                {"states", d.states[side]},
                                {"transitions", d.transitions[side]},
                                {"only_states", d.onlyStates[side]},
                                {"only_transitions", d.onlyTransitions[side]}};
            if (d.transitionWitness[side]) s["witness"] = {{"description", describe(side)}, {"trace", traceJson(*d.transitionWitness[side], *sides[side]->engine, *sides[side]->in)}};
            j[side == 0 ? "in_a" : "in_b"] = s;
        }
        std::cout << j.dump(2) << '\n';
        return code;
    }
    std::cout << "A " << names[0] << " (" << a.a << ") against B " << names[1] << " (" << a.b << ") on " << region.spec() << ", "
              << (a.all ? "every legal configuration" : "reachable from " + std::to_string(a.from.size()) + " configuration(s)") << '\n';
    for (int side = 0; side < 2; ++side)
        std::cout << "  " << (side ? "B" : "A") << ": " << d.states[side] << " configurations, " << d.transitions[side] << " transitions; only in "
                  << (side ? "B" : "A") << ": " << d.onlyStates[side] << " configurations, " << d.onlyTransitions[side] << " transitions\n";
    if (d.same()) {
        std::cout << "  the same reconfiguration graph\n";
        return code;
    }
    for (int side : {1, 0})
        if (d.transitionWitness[side])
            std::cout << "\nnearest transition only in " << (side ? "B" : "A") << ": " << describe(side) << '\n'
                      << checker::drawTraceAscii(*d.transitionWitness[side], *sides[side]->engine);
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
