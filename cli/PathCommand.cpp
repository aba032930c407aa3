// `holon path FILE --region R --from A (--to B | --goal)`: a shortest sequence of rule steps
// between two configurations, or to the nearest goal configuration (checker/Path.h), replayed
// through the reference interpreter before it is shown; "unreachable" comes with the size of the
// space searched, which is every configuration reachable from A (or, when the bidirectional
// search's backward side ran dry first, every configuration from which B is reachable).
// --parallel groups the path's steps into rounds that fire together (checker/PathSchedule.h).

#include "checker/Check.h"
#include "checker/Draw.h"
#include "checker/Path.h"
#include "checker/PathSchedule.h"
#include "cli/Commands.h"
#include "cli/Inputs.h"
#include "cli/Limits.h"
#include "cli/WriteErrors.h"
#include "rules/OutputFile.h"
#include "viewer/Page.h"
#include "viewer/Readers.h"

#include <iomanip>
#include <iostream>
#include <unistd.h>

namespace holon::cli {

namespace {

struct PathArgs {
    std::string file, region, from, to, traceOut, svg, html, search = "auto";
    std::vector<std::string> inputs, noWarnings;
    bool goal = false, json = false, parallel = false;
    ExploreLimitArgs limits;
    const CLI::Option* threadsOption = nullptr;  // given or not: only the forward search uses threads
};

std::string outcomeName(checker::PathOutcome o) {
    switch (o) {
    case checker::PathOutcome::Found: return "found";
    case checker::PathOutcome::Unreachable: return "unreachable";
    case checker::PathOutcome::Undecided: return "undecided";
    }
    return "?";
}

checker::PathSearch searchNamed(const std::string& name) {
    for (auto s : {checker::PathSearch::Auto, checker::PathSearch::Forward, checker::PathSearch::Bidirectional, checker::PathSearch::AStar})
        if (checker::pathSearchName(s) == name) return s;
    throw InputError("--search " + name + ": unknown search; use auto, forward, bidirectional or astar");
}

int run(const PathArgs& a) {
    if (a.to.empty() == !a.goal)
        throw InputError(std::string(a.goal ? "--to and --goal both say" : "say") + " where to go: --to CONFIG (JSON or ASCII art) or --goal (any configuration where the system's goal holds)" +
                         (a.goal ? "; give one" : ""));
    const checker::PathSearch search = searchNamed(a.search);
    auto system = loadRules(a.file, a.noWarnings);
    if (!system) return kExitBadInput;
    const rules::Region region = exploreRegion(a.region, a.limits);
    rules::Model model(*system, region.lattice());
    rules::Interpreter in(model, region);
    std::optional<rules::OutputFile> traceOut, svgOut, htmlOut;
    if (!a.html.empty()) htmlOut.emplace("--html", a.html);
    if (!a.traceOut.empty()) traceOut.emplace("--trace-out", a.traceOut);
    if (!a.svg.empty()) svgOut.emplace("--svg", a.svg);

    checker::PathQuery query;
    // From here: a signal while a large --from is read ended holon with no word (robustness audit 6).
    const rules::StopSignals guard(true);  // a signal stops the search: undecided, 128 + the signal
    query.from = readStarts(in, {a.from}, a.inputs).front();
    if (!a.to.empty()) {
        query.to = readStarts(in, {a.to}, a.inputs, nullptr, "--to").front();
        if (query.to->inputs != query.from.inputs)
            throw InputError("--to " + a.to + ": its inputs differ from those of --from " + a.from + "; a path never changes an input");
    }
    query.limits = a.limits.limits();
    query.search = search;
    const bool terminal = isatty(2) && !a.json;
    if (terminal)
        query.onProgress = [](const checker::ExploreStats& s) {
            std::cerr << "\r  searching: " << s.states << " states, depth " << s.depth << ", " << std::fixed << std::setprecision(1) << s.seconds << " s   "
                      << std::flush;
        };
    const auto engineHeld = checker::engineWithin(model, region, query.from.inputs, query.limits);
    const rules::Engine& engine = *engineHeld;
    const checker::PathResult result = checker::shortestPath(engine, query);
    if (terminal) std::cerr << "\r" << std::string(70, ' ') << "\r";
    if (a.threadsOption && a.threadsOption->count() && result.search != checker::PathSearch::Forward)
        std::cerr << "holon: note: --threads " << a.limits.threads << " is not used: the " << checker::pathSearchName(result.search)
                  << " search runs on one thread (--search forward uses the threads)\n";

    const bool found = result.outcome == checker::PathOutcome::Found;
    std::string why;
    const bool replayed = found && checker::replay(result.trace, engine, in, &why);
    if (found && !replayed)
        reportInternalError("path", "the path does not replay: " + why);
    const std::size_t length = found ? result.trace.steps.size() - 1 : 0;
    std::optional<checker::Schedule> schedule;
    bool scheduled = false;
    if (a.parallel && found && replayed) {
        schedule = checker::compactSteps(result.trace, engine, checker::Footprints(engine));
        scheduled = checker::replaySchedule(*schedule, result.trace, engine, in, &why);
        if (!scheduled)
            reportInternalError("path", "the parallel schedule does not replay: " + why);
    }
    const std::string title = system->name + " on " + region.spec() + ": " + (found ? "a shortest path, " + checker::stepCount(length) : outcomeName(result.outcome));
    // A write that fails (a full disk) is said after the result, which it no longer takes with it.
    WriteErrors errors;
    if (found && traceOut) errors.attempt([&] { traceOut->write(checker::toItf(result.trace, engine, a.file).dump(2) + "\n"); }, "--trace-out " + traceOut->path());
    if (found && svgOut) errors.attempt([&] { svgOut->write(checker::drawTraceSvg(result.trace, engine, title)); }, "--svg " + svgOut->path());
    if (found && htmlOut)
        errors.attempt([&] { htmlOut->write(viewer::page(viewer::readItf(checker::toItf(result.trace, engine, a.file), "the shortest path", *system))); }, "--html " + htmlOut->path());
    if (!found)
        for (const auto& [option, out] : {std::pair{"--trace-out", &traceOut}, std::pair{"--svg", &svgOut}, std::pair{"--html", &htmlOut}})
            if (*out) std::cerr << "holon: note: " << option << " " << (*out)->path() << " is not written: no path was found (" << outcomeName(result.outcome) << ")\n";

    const auto& s = result.stats;
    int code = kExitOk;
    if (!found) code = result.outcome == checker::PathOutcome::Unreachable ? kExitViolated
                       : s.stopped == StopReason::Interrupted              ? exitCodeFor(s.stopped, caughtSignal())
                                                                           : kExitUndecided;
    else if (!replayed || (schedule && !scheduled)) code = kExitInternal;
    if (a.json) {
        nlohmann::json j = {{"system", system->name}, {"region", region.spec()}, {"outcome", outcomeName(result.outcome)}, {"states", s.states}, {"depth", s.depth}, {"seconds", s.seconds}, {"stopped", stopReasonName(s.stopped)}};
        j["search"] = checker::pathSearchName(result.search);
        if (!result.fallback.empty()) j["fallback"] = result.fallback;
        if (result.bound >= 0) j["bound"] = result.bound;
        if (result.outcome == checker::PathOutcome::Unreachable) j["closed"] = {{"side", result.closedFromStart ? "from" : "to"}, {"states", result.closed}};
        if (found) j["length"] = length, j["replayed"] = replayed, j["path"] = traceJson(result.trace, engine, in);
        if (schedule) j["parallel"] = {{"makespan", schedule->makespan()}, {"rounds", schedule->rounds}, {"replayed", scheduled}};
        std::cout << j.dump(2) << '\n';
        errors.raise();
        return code;
    }
    std::cout << system->name << " on " << region.spec() << ", from " << a.from << " to " << (a.goal ? "the goal" : a.to) << '\n'
              << "  search: " << checker::pathSearchName(result.search);
    if (result.bound >= 0) std::cout << " (bound at the start: " << checker::stepCount(static_cast<std::size_t>(result.bound)) << ")";
    if (!result.fallback.empty()) std::cout << ", since " << result.fallback;
    std::cout << '\n';
    switch (result.outcome) {
    case checker::PathOutcome::Found:
        std::cout << "  a shortest path: " << checker::stepCount(length) << " (searched " << s.states << " states, " << std::fixed << std::setprecision(2)
                  << s.seconds << " s" << (replayed ? "; replayed through the reference interpreter)" : "; NOT confirmed by the reference interpreter)") << "\n\n"
                  << checker::drawTraceAscii(result.trace, engine);
        if (schedule) {
            std::cout << "\n  parallel: " << schedule->makespan() << (schedule->makespan() == 1 ? " round" : " rounds") << " for " << checker::stepCount(length)
                      << " (a greedy grouping of this path's steps, not a shortest parallel path" << (scheduled ? "; replayed)" : "; NOT confirmed by the reference interpreter)") << '\n';
            for (std::size_t r = 0; r < schedule->rounds.size(); ++r) {
                std::cout << "    round " << r + 1 << ": step" << (schedule->rounds[r].size() == 1 ? " " : "s ");
                for (std::size_t k = 0; k < schedule->rounds[r].size(); ++k) std::cout << (k ? ", " : "") << schedule->rounds[r][k];
                std::cout << '\n';
            }
        }
        break;
    case checker::PathOutcome::Unreachable:
        if (result.closedFromStart)
            std::cout << "  unreachable: the " << result.closed << (result.closed == 1 ? " configuration" : " configurations") << " reachable from the start include no "
                      << (a.goal ? "goal configuration" : "configuration equal to the target") << '\n';
        else
            std::cout << "  unreachable: the target is reachable from " << result.closed << (result.closed == 1 ? " configuration" : " configurations")
                      << " (all searched backwards), and the start is not one of them\n";
        break;
    case checker::PathOutcome::Undecided:
        std::cout << "  undecided: stopped by " << stopReasonName(s.stopped) << " after " << s.states << " states (none within " << checker::stepCount(static_cast<std::size_t>(s.depth))
                  << ")" << raiseAdvice(s.stopped, " to search further") << '\n';
        break;
    }
    errors.raise();  // a file that could not be written outranks the result, as in plan
    return code;
}

}  // namespace

Run addPathCommand(CLI::App& app) {
    auto a = std::make_shared<PathArgs>();
    CLI::App* sub = app.add_subcommand("path", "A shortest sequence of rule steps from one configuration to another, or to the goal");
    addRulesFile(sub, "file", a->file)->required();
    sub->add_option("--region", a->region, "bounded region: square:WxH, cubic:WxHxD or hex:rR")->required();
    sub->add_option("--from", a->from, "start configuration (JSON, ITF#N or ASCII art)")->required();
    sub->add_option("--to", a->to, "target configuration (JSON, ITF#N or ASCII art)");
    sub->add_flag("--goal", a->goal, "go to the nearest configuration where the system's goal holds");
    sub->add_option("--search", a->search, "auto (bidirectional to --to when the rules run backwards, else forward), forward, bidirectional or astar (with --to)");
    sub->add_flag("--parallel", a->parallel, "also group the path's steps into rounds of instances that fire together, with the makespan");
    sub->add_option("--input", a->inputs, "set an input from an ASCII mask: NAME=FILE (any character but '.' marks a cell)");
    addExploreLimits(sub, a->limits, "the search");
    a->threadsOption = sub->get_option("--threads");
    sub->add_flag("--json", a->json, "print the result as JSON (length: the number of rule steps)");
    sub->add_option("--trace-out", a->traceOut, "write the path as an ITF JSON trace");
    sub->add_option("--svg", a->svg, "draw the path as SVG");
    sub->add_option("--html", a->html, "write the path as a self-contained HTML viewer (docs/viewer.md)");
    sub->add_option("-W", a->noWarnings, "silence a warning: -W no-NAME");
    return [a] { return run(*a); };
}

}  // namespace holon::cli
