// `holon check` (seed 000 §II and §IV-C on a bounded region): one breadth-first exploration of the
// reconfiguration graph, then each selected property's explicit-state check over it (each kind's
// own, checker/properties/), every phase after the exploration within the limits, and every
// counterexample confirmed by the reference interpreter before it is returned. A property that
// needs the whole graph is "unknown" when a limit stopped the search before a violation was found.

#include "checker/Check.h"

#include "checker/Graph.h"
#include "checker/Property.h"
#include "rules/Budget.h"
#include "rules/Error.h"
#include "rules/Limits.h"
#include "rules/Parameter.h"
#include "rules/StopSignals.h"

#include <algorithm>
#include <chrono>
#include <map>
#include <optional>

namespace holon::checker {

bool CheckReport::violated() const {
    return std::any_of(properties.begin(), properties.end(), [](const PropertyResult& p) { return p.verdict == Verdict::Violated; });
}

Verdict CheckReport::overall() const {
    Verdict v = Verdict::Holds;
    for (const PropertyResult& p : properties) v = combine(v, p.verdict);
    return v;
}

nlohmann::json CheckReport::toJson() const {
    nlohmann::json props = nlohmann::json::array();
    for (const PropertyResult& p : properties)
        props.push_back({{"name", p.name}, {"kind", p.kind}, {"verdict", verdictName(p.verdict)}, {"summary", p.summary}, {"witness", p.witness}, {"seconds", p.seconds}});
    return {{"system", system},
            {"region", region},
            {"states", stats.states},
            {"edges", stats.edges},
            {"components", components < 0 ? nlohmann::json(nullptr) : nlohmann::json(components)},
            {"depth", stats.depth},
            {"seconds", stats.seconds},
            {"stopped", stopReasonName(stats.stopped)},
            {"enumerating", stats.enumerating},
            {"frontier", stats.frontier},
            {"bytes_per_state", bytesPerState},
            {"properties", props}};
}

std::vector<std::string> checkableProperties(const rules::System& system) {
    std::vector<std::string> names;
    for (const auto& type : checkablePropertyTypes(system)) names.push_back(type->name());
    return names;
}

namespace {

using Clock = std::chrono::steady_clock;
double since(Clock::time_point t) { return std::chrono::duration<double>(Clock::now() - t).count(); }

/// Why a phase cannot start within the limits (empty: it can): the deadline has passed, or what it
/// needs beside the explored graph exceeds --memory.
std::string beyondLimits(const ExploreStats& stats, const Limits& limits, const Budget& budget, PhaseCost cost) {
    if (budget.interrupted()) return "not checked: a signal stopped the check before this phase";
    if (budget.expired()) return "not checked: the timeout expired before this phase; raise " + rules::parameterName(rules::Parameter::Timeout);
    const double need = static_cast<double>(stats.bytes) + cost.perState * static_cast<double>(stats.states) + cost.perEdge * static_cast<double>(stats.edges);
    if (need <= static_cast<double>(limits.memoryBytes)) return "";
    const auto mib = [](double bytes) { return std::to_string(static_cast<std::uint64_t>(bytes / (1 << 20)) + 1); };
    const std::string memory = rules::parameterName(rules::Parameter::Memory);
    return "not checked: with the explored graph it needs about " + mib(need) + " MiB, more than " + memory + " " + mib(static_cast<double>(limits.memoryBytes) - 1) +
           "; raise " + memory;
}

}  // namespace

std::unique_ptr<rules::Engine> engineWithin(const rules::Model& model, const rules::Region& region, const std::vector<std::uint32_t>& inputs, Limits& limits) {
    rules::requireMemory(rules::Engine::bytesFor(model, region), limits.memoryBytes,
                         "the rule engine on region " + region.spec() + " (" + std::to_string(region.size()) + " cells, " + std::to_string(model.shapes().size()) +
                             " rule shapes)");
    // The build polls the job's deadline and the signal catcher: on 4 million cells it takes a
    // minute, and --timeout 1 ran 65 s.
    auto engine = std::make_unique<rules::Engine>(model, region, inputs, false, std::vector<int>{}, [] {
        rules::StopSignals::checkJob("building the rule engine");
    });
    limits.memoryBytes -= std::min(limits.memoryBytes, engine->regionBytes());
    return engine;
}

std::unique_ptr<rules::Engine> checkEngine(const rules::Model& model, const rules::Region& region, const CheckOptions& options, Limits& limits) {
    // One engine, one set of inputs: a start under other inputs was explored under the first's.
    for (const rules::Configuration& c : options.initial)
        if (c.inputs != options.initial.front().inputs)
            throw InputError("the initial configurations (" + rules::parameterName(rules::Parameter::Initial) +
                             ") hold different inputs; an exploration runs under one set of inputs: explore them one at a time");
    return engineWithin(model, region, !options.all && !options.initial.empty() ? options.initial.front().inputs : options.inputs, limits);
}

std::unique_ptr<Explorer> startExplorer(const rules::Engine& engine, const CheckOptions& options, Explorer::Options xo) {
    auto ex = std::make_unique<Explorer>(engine, std::move(xo));
    if (options.all) {
        ex->addAllLegal();
        return ex;
    }
    if (options.initial.empty())
        throw InputError("give initial configurations with " + rules::parameterName(rules::Parameter::Initial) + ", or explore every legal configuration with " +
                             rules::parameterName(rules::Parameter::All),
                         rules::Parameter::Initial);
    for (const rules::Configuration& c : options.initial) {
        if (!engine.legal(c.cells.data())) throw InputError("the initial configuration violates a constraint of '" + engine.model().system().name + "'");
        ex->addInitial(c.cells.data());
    }
    return ex;
}

CheckReport check(const rules::Model& model, const rules::Region& region, const CheckOptions& options, Exploration* keep) {
    const Budget budget = options.limits.budget();
    const rules::System& system = model.system();
    auto types = checkablePropertyTypes(system);
    for (const std::string& name : options.properties)
        if (std::none_of(types.begin(), types.end(), [&](const auto& t) { return t->name() == name; })) {
            std::string list;
            for (const auto& t : types) list += (list.empty() ? "" : ", ") + t->name();
            throw InputError("system '" + system.name + "' has no property '" + name + "'; it has: " + list +
                             (name == "deadlock" || name == "goal_reachable" ? " (deadlock and goal_reachable are relative to a goal: declare one with 'goal EXPR')" : ""));
        }
    auto selected = [&](const std::string& name) {
        return options.properties.empty() || std::find(options.properties.begin(), options.properties.end(), name) != options.properties.end();
    };
    std::erase_if(types, [&](const auto& t) { return !selected(t->name()); });

    Limits limits = options.limits;
    auto engine = checkEngine(model, region, options, limits);
    const rules::Engine& e = *engine;

    // Properties of single states (invariants) are checked on every state as it is stored.
    std::vector<PropertyType*> watchers;
    for (const auto& t : types)
        if (t->watchesStates()) watchers.push_back(t.get());
    Explorer::Options xo;
    xo.limits = limits;
    xo.budget = budget;
    xo.recordEdges = true;
    xo.onProgress = options.onProgress;
    if (!watchers.empty())
        xo.onState = [&](StateId id, const CellValue* cells) {
            for (PropertyType* w : watchers) w->onState(e, id, cells);
        };
    // Asked only about such properties: once each is decided, the rest of the graph can wait.
    if (!options.properties.empty() && watchers.size() == options.properties.size())
        xo.decided = [&] { return std::all_of(watchers.begin(), watchers.end(), [](const PropertyType* w) { return w->decided(); }); };
    auto ex = startExplorer(e, options, std::move(xo));
    CheckReport report;
    report.system = system.name;
    report.region = region.spec();
    report.stats = ex->explore();
    report.bytesPerState = ex->bytesPerState();
    const bool complete = report.stats.stopped == StopReason::Finished;
    Components comps;
    const bool componentsFit = complete && beyondLimits(report.stats, limits, budget, kComponentsCost).empty();  // only a whole graph's count is shown
    if (componentsFit) comps = components(*ex);
    report.components = componentsFit ? comps.count : -1;

    // Each phase after the exploration starts only within the limits; one that cannot is unknown
    // with the limit to raise.
    std::map<const rules::Expr*, Stuck> stuck;
    const ExploredGraph graph{model, region, e, *ex, comps, budget, complete, stuck};
    const rules::Interpreter in(model, region);
    for (const auto& t : types) {
        const auto t0 = Clock::now();
        const std::optional<PhaseCost> cost = t->cost(complete);
        const std::string why = cost ? beyondLimits(report.stats, limits, budget, *cost) : "";
        PropertyResult r = why.empty() ? t->check(graph) : t->named();
        if (!why.empty()) r.summary = why;
        if (r.trace) r.trace->property = t->name();
        r.seconds = since(t0);
        // Every trace is replayed through the reference interpreter before anyone sees it.
        if (r.trace) confirmInto(r, *t, Evidence::Path, in, e, "replayed");
        report.properties.push_back(std::move(r));
    }
    if (keep) {
        keep->explorer = std::move(ex);
        keep->engine = std::move(engine);
    }
    return report;
}

}  // namespace holon::checker
