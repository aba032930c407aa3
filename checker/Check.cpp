// The explicit-state checks of `holon check` (seed 000 §II and §IV-C on a bounded region):
// invariants on every stored state (the first violation has a shortest trace, since the search is
// breadth-first), conservation and ranking on every edge, deadlocks as terminal states outside the
// goal, livelocks as cycles of the graph on which the ranking never decreases (BGL strong
// components of the non-decreasing edges), states from which the goal is unreachable (BGL
// breadth-first search on the reversed graph), and holonomy (Holonomy.cpp). A property that needs the
// whole graph is "unknown" when a limit stopped the search before a violation was found.

#include "checker/Check.h"

#include "checker/FailureCells.h"
#include "checker/Graph.h"
#include "checker/Holonomy.h"
#include "rules/Budget.h"
#include "rules/Error.h"
#include "rules/Printer.h"

#include <algorithm>
#include <chrono>
#include <mutex>
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
    for (const rules::Property& p : system.properties) names.push_back(p.name);
    // Deadlock is relative to a goal: without one, a state with no enabled rule is merely final.
    if (system.goal) names.push_back("deadlock"), names.push_back("goal_reachable");
    return names;
}

namespace {

using Clock = std::chrono::steady_clock;
double since(Clock::time_point t) { return std::chrono::duration<double>(Clock::now() - t).count(); }

bool lexLess(const std::vector<rules::Rational>& a, const std::vector<rules::Rational>& b) {
    return std::lexicographical_compare(a.begin(), a.end(), b.begin(), b.end());
}

/// Among `states`, those `bad` accepts make `r` violated: how many, and a shortest trace to the
/// nearest. False when there is none.
template <class Bad>
bool violatedAtNearest(PropertyResult& r, const Explorer& ex, const std::vector<StateId>& states, Bad bad, const std::string& which,
                       const std::string& description, const char* countKey) {
    std::uint64_t count = 0;
    StateId first = kNoState;
    for (StateId s : states)
        if (bad(s) && (count++ == 0 || ex.pathTo(s).size() < ex.pathTo(first).size())) first = s;
    if (count == 0) return false;
    r.verdict = Verdict::Violated;
    r.trace = traceTo(ex, first);
    r.trace->property = r.name;
    r.summary = std::to_string(count) + (count == 1 ? " state " : " states ") + which;
    r.trace->description = description;
    r.witness = {{countKey, count}, {"distance", r.trace->steps.size() - 1}};
    return true;
}

/// How far a rule instance reaches, in lattice steps: the largest pattern, twice its radius (an
/// instance touching the region lies within this of it).
int ruleReach(const rules::Model& model) {
    int radius = 0;
    for (const rules::RuleShape& s : model.shapes())
        for (rules::Vec v : s.offsets) radius = std::max(radius, std::abs(v.x) + std::abs(v.y) + std::abs(v.z));
    return std::max(1, 2 * radius);
}

/// States with no enabled rule, outside the goal and where `assume` holds, split into deadlocks and
/// edge effects of the bounded region: on the region grown by the rules' reach (outside cells empty,
/// inputs false) some instance is enabled, so only the region's bound stops the system, not the
/// design. At most kClassified states are tried on the grown region, within the budget; the rest
/// stay unclassified (never called deadlocks: an edge effect reported as a flaw is a wrong answer).
struct Stuck {
    std::vector<StateId> deadlocks, edgeEffects;
    std::uint64_t unclassified = 0;
};

Stuck stuckStates(const Explorer& ex, const rules::Engine& e, const rules::Expr* assume, const Budget& budget) {
    constexpr std::size_t kClassified = 10'000;
    const rules::Model& model = e.model();
    const rules::Region& region = e.region();
    const rules::Region grown = region.grown(ruleReach(model));
    const rules::Interpreter wide(model, grown);
    Stuck out;
    std::size_t tried = 0;
    for (StateId s : ex.terminal()) {
        const auto cells = ex.cells(s);
        if (model.system().goal && e.holds(*model.system().goal, cells.data())) continue;
        if (assume && !e.holds(*assume, cells.data())) continue;
        if (tried++ >= kClassified || budget.expired()) {
            ++out.unclassified;
            continue;
        }
        rules::Configuration c = wide.empty();
        std::copy(cells.begin(), cells.end(), c.cells.begin());
        std::copy(e.inputs().begin(), e.inputs().end(), c.inputs.begin());
        (wide.enabled(c).empty() ? out.deadlocks : out.edgeEffects).push_back(s);
    }
    return out;
}

/// What a verdict adds about edge effects: ", except 3 states stuck only at the region's edge ...".
std::string edgeText(const Stuck& stuck) {
    if (stuck.edgeEffects.empty()) return "";
    return "; " + std::to_string(stuck.edgeEffects.size()) + " states are stuck only at the region's edge (a rule instance needs cells outside it)";
}

/// A property decided by stuck states: violated by a deadlock (the nearest has a trace), else
/// unknown while the search or the classification is incomplete, else holds.
void judgeStuck(PropertyResult& r, const Explorer& ex, const Stuck& stuck, bool complete, const std::string& which,
                const std::string& description, const char* countKey, const std::string& holdsText) {
    r.witness = nullptr;
    if (!violatedAtNearest(
            r, ex, stuck.deadlocks, [](StateId) { return true; }, which, description, countKey)) {
        r.verdict = complete && stuck.unclassified == 0 ? Verdict::Holds : Verdict::Unknown;
        r.summary = !complete            ? "no violation among the " + std::to_string(ex.stats().states) + " states explored before the limit"
                    : stuck.unclassified ? std::to_string(stuck.unclassified) + " stuck states not classified (deadlock or edge effect) within the limits"
                                         : holdsText;
        r.summary += edgeText(stuck);
    }
    r.witness["edge_effects"] = stuck.edgeEffects.size();
    r.witness["unclassified"] = stuck.unclassified;
}

const char* kindName(rules::Property::Kind kind) {
    switch (kind) {
    case rules::Property::Kind::Invariant: return "invariant";
    case rules::Property::Kind::Conserves: return "conserves";
    case rules::Property::Kind::Ranking: return "ranking";
    case rules::Property::Kind::Progress: return "progress";
    case rules::Property::Kind::Holonomic: return "holonomic";
    }
    return "";
}

/// What a phase after the exploration needs beside the explored graph, per state and per edge,
/// from its containers (a BGL compressed-sparse-row copy of the graph is 8 bytes a state and 4
/// an edge; its algorithms' maps a few words a state).
struct PhaseCost {
    double perState = 0, perEdge = 0;
};

/// Why a phase cannot start within the limits (empty: it can): the deadline has passed, or what it
/// needs beside the explored graph exceeds --memory.
std::string beyondLimits(const ExploreStats& stats, const Limits& limits, const Budget& budget, PhaseCost cost) {
    if (budget.expired()) return "not checked: the timeout expired before this phase; raise --timeout";
    const double need = static_cast<double>(stats.bytes) + cost.perState * static_cast<double>(stats.states) + cost.perEdge * static_cast<double>(stats.edges);
    if (need <= static_cast<double>(limits.memoryBytes)) return "";
    const auto mib = [](double bytes) { return std::to_string(static_cast<std::uint64_t>(bytes / (1 << 20)) + 1); };
    return "not checked: with the explored graph it needs about " + mib(need) + " MiB, more than --memory " + mib(static_cast<double>(limits.memoryBytes) - 1) +
           "; raise --memory";
}

constexpr PhaseCost kComponentsCost{16, 0}, kConservesCost{8, 0}, kHolonomyCost{64 + kComponentsCost.perState, 4}, kGoalCost{32, 12};
/// Two strong-component runs and a shortest path, a flag per edge, and per state a vector of
/// `terms` ranking values.
PhaseCost rankingCost(std::size_t terms) { return {128.0 + 16.0 * static_cast<double>(terms), 13}; }

}  // namespace

CheckReport check(const rules::Model& model, const rules::Region& region, const CheckOptions& options, Exploration* keep) {
    const Budget budget = options.limits.budget();
    const rules::System& system = model.system();
    const auto known = checkableProperties(system);
    for (const std::string& name : options.properties)
        if (std::find(known.begin(), known.end(), name) == known.end()) {
            std::string list;
            for (const auto& k : known) list += (list.empty() ? "" : ", ") + k;
            throw InputError("system '" + system.name + "' has no property '" + name + "'; it has: " + list +
                             (name == "deadlock" || name == "goal_reachable" ? " (deadlock and goal_reachable are relative to a goal: declare one with 'goal EXPR')" : ""));
        }
    auto selected = [&](const std::string& name) {
        return options.properties.empty() || std::find(options.properties.begin(), options.properties.end(), name) != options.properties.end();
    };

    std::vector<std::uint32_t> inputs = options.inputs;
    if (!options.all && !options.initial.empty()) inputs = options.initial.front().inputs;
    auto engine = std::make_unique<rules::Engine>(model, region, inputs);
    const rules::Engine& e = *engine;

    // Invariants are checked on every state as it is stored.
    std::vector<const rules::Property*> invariants;
    for (const rules::Property& p : system.properties)
        if (p.kind == rules::Property::Kind::Invariant && selected(p.name)) invariants.push_back(&p);
    std::vector<std::vector<StateId>> invariantViolations(invariants.size());
    std::mutex violationMutex;

    Explorer::Options xo;
    xo.limits = options.limits;
    xo.budget = budget;
    xo.recordEdges = true;
    xo.onProgress = options.onProgress;
    if (!invariants.empty())
        xo.onState = [&](StateId id, const CellValue* cells) {
            for (std::size_t k = 0; k < invariants.size(); ++k)
                if (!e.holds(invariants[k]->exprs[0], cells)) {
                    std::lock_guard<std::mutex> lock(violationMutex);
                    if (invariantViolations[k].size() < 64) invariantViolations[k].push_back(id);
                }
        };
    // Asked only about invariants: once each is violated, the shortest violations are known (the
    // states of the next level are checked as they are stored) and the rest of the graph can wait.
    const bool onlyInvariants = !options.properties.empty() && invariants.size() == options.properties.size();
    if (onlyInvariants)
        xo.decided = [&] {
            std::lock_guard<std::mutex> lock(violationMutex);
            return std::all_of(invariantViolations.begin(), invariantViolations.end(), [](const auto& v) { return !v.empty(); });
        };
    auto ex = std::make_unique<Explorer>(e, xo);
    if (options.all) {
        ex->addAllLegal();
    } else {
        if (options.initial.empty()) throw InputError("give initial configurations with --from, or explore every legal configuration with --all");
        for (const rules::Configuration& c : options.initial) {
            if (!e.legal(c.cells.data())) throw InputError("the initial configuration violates a constraint of '" + system.name + "'");
            ex->addInitial(c.cells.data());
        }
    }
    CheckReport report;
    report.system = system.name;
    report.region = region.spec();
    report.stats = ex->explore();
    report.bytesPerState = ex->bytesPerState();
    const bool complete = report.stats.stopped == StopReason::Finished;
    // Each phase after the exploration starts only within the limits; one that cannot is unknown
    // with the limit to raise.
    auto beyond = [&](PhaseCost cost) { return beyondLimits(report.stats, options.limits, budget, cost); };
    Components comps;
    const bool componentsFit = complete && beyond(kComponentsCost).empty();  // only a whole graph's count is shown
    if (componentsFit) comps = components(*ex);
    report.components = componentsFit ? comps.count : -1;

    const auto ids = ex->ids();
    const auto& row = ex->rowStart();
    const auto& succ = ex->successors();
    auto unknownOr = [&](PropertyResult& r, const std::string& holdsText) {
        r.verdict = complete ? Verdict::Holds : Verdict::Unknown;
        r.summary = complete ? holdsText : "no violation among the " + std::to_string(report.stats.states) + " states explored before the limit";
    };

    for (const rules::Property& p : system.properties) {
        if (!selected(p.name)) continue;
        const auto t0 = Clock::now();
        PropertyResult r;
        r.name = p.name;
        r.kind = kindName(p.kind);
        // The phases that need the whole graph, or walk it, with what they hold beside it.
        std::optional<PhaseCost> cost;
        switch (p.kind) {
        case rules::Property::Kind::Invariant:
        case rules::Property::Kind::Progress: break;  // on the stored states; stuck states have their own budget
        case rules::Property::Kind::Conserves: cost = kConservesCost; break;
        case rules::Property::Kind::Ranking: cost = rankingCost(p.exprs.size()); break;
        case rules::Property::Kind::Holonomic:
            if (complete) cost = kHolonomyCost;  // beyond when the components were: it holds them too
            break;
        }
        if (const std::string why = cost ? beyond(*cost) : ""; !why.empty()) {
            r.verdict = Verdict::Unknown;
            r.summary = why;
            r.seconds = since(t0);
            report.properties.push_back(std::move(r));
            continue;
        }
        switch (p.kind) {
        case rules::Property::Kind::Invariant: {
            const auto& bad = invariantViolations[std::find(invariants.begin(), invariants.end(), &p) - invariants.begin()];
            if (bad.empty()) {
                unknownOr(r, "holds in all " + std::to_string(report.stats.states) + " states");
                break;
            }
            // The violation closest to an initial state.
            StateId best = bad[0];
            for (StateId s : bad)
                if (ex->pathTo(s).size() < ex->pathTo(best).size()) best = s;
            r.verdict = Verdict::Violated;
            r.trace = traceTo(*ex, best);
            // Mark what a person should look at: the cells that make it false.
            const auto last = ex->cells(best);
            r.trace->marked = failureCells(e, p.exprs[0], last.data());
            r.witness = {{"distance", r.trace->steps.size() - 1}};
            r.summary = "violated after " + stepCount(r.trace->steps.size() - 1);
            const std::string which = nameFailingConjunct(r, p, rules::Interpreter(model, region), {last, e.inputs()});
            r.trace->description = "invariant '" + p.name + "' fails after " + stepCount(r.trace->steps.size() - 1) + which +
                                   (r.trace->marked.empty() ? "" : "; crossed cells show where");
            break;
        }
        case rules::Property::Kind::Conserves: {
            const bool byMass = p.quantity == rules::Property::Quantity::Mass;
            std::vector<std::int64_t> amount(ex->store().capacityUsed(), 0);
            for (StateId s : ids) {
                const auto cells = ex->cells(s);
                amount[s] = byMass ? e.massUnits(cells.data()) : std::count_if(cells.begin(), cells.end(), [](CellValue v) { return v != 0; });
            }
            for (StateId s : ids)
                for (std::uint64_t k = row[s]; k < row[s + 1] && r.verdict != Verdict::Violated; ++k)
                    if (amount[succ[k]] != amount[s]) {
                        r.verdict = Verdict::Violated;
                        r.trace = traceWithStep(*ex, s, k);
                        const auto& rule = e.model().rules()[e.instances()[ex->successorVia()[k]].rule];
                        r.summary = "rule '" + rule.name + "' changes the " + (byMass ? "mass" : "count");
                        r.trace->description = r.summary;
                        r.witness = {{"rule", rule.name}, {"before", rules::Rational(amount[s], byMass ? e.massDenominator() : 1).str()}, {"after", rules::Rational(amount[succ[k]], byMass ? e.massDenominator() : 1).str()}};
                    }
            if (r.verdict != Verdict::Violated) unknownOr(r, "every one of the " + std::to_string(report.stats.edges) + " steps keeps it");
            break;
        }
        case rules::Property::Kind::Ranking: {
            std::vector<std::vector<rules::Rational>> rank(ex->store().capacityUsed());
            for (StateId s : ids) {
                const auto cells = ex->cells(s);
                for (const rules::Expr& x : p.exprs) rank[s].push_back(e.number(x, cells.data()));
            }
            // A step of an excepted rule (a resource move) must keep the ranking; every other step decreases it.
            std::vector<char> excepted(model.rules().size());
            for (std::size_t q = 0; q < excepted.size(); ++q) excepted[q] = model.ruleNamed(static_cast<int>(q), p.except);
            auto keptBy = [&](std::uint64_t k) { return excepted[e.instances()[ex->successorVia()[k]].rule] != 0; };
            std::vector<char> flat(succ.size(), 0);
            std::uint64_t badEdges = 0, firstBad = 0;
            StateId firstFrom = kNoState;
            for (StateId s : ids)
                for (std::uint64_t k = row[s]; k < row[s + 1]; ++k)
                    if (keptBy(k) ? rank[succ[k]] != rank[s] : !lexLess(rank[succ[k]], rank[s])) {
                        flat[k] = 1;
                        if (badEdges++ == 0) firstBad = k, firstFrom = s;
                    }
            if (badEdges == 0) {
                unknownOr(r, "every step decreases it" + exceptText(p));
                break;
            }
            r.verdict = Verdict::Violated;
            // Termination fails exactly when the reachable graph has a cycle through a step of a
            // covered rule (one not excepted), whatever mix of decreasing and non-decreasing steps
            // it takes; a cycle of excepted steps that keep the ranking is the allocator's (seed
            // 000 Lemma 3). A cycle on which the ranking never decreases (a livelock) is shown first.
            const Components flatScc = strongComponents(*ex, flat);
            const Components whole = strongComponents(*ex, std::vector<char>(succ.size(), 1));
            StateId cycleFrom = kNoState;
            std::uint64_t cycleEdge = 0;
            bool livelock = false;
            for (StateId s : ids)
                for (std::uint64_t k = row[s]; k < row[s + 1] && !livelock; ++k) {
                    if (flat[k] && flatScc.of[succ[k]] == flatScc.of[s]) cycleFrom = s, cycleEdge = k, livelock = true;
                    else if (cycleFrom == kNoState && !keptBy(k) && whole.of[succ[k]] == whole.of[s]) cycleFrom = s, cycleEdge = k;
                }
            if (cycleFrom == kNoState) {
                r.trace = traceWithStep(*ex, firstFrom, firstBad);
                r.summary = std::to_string(badEdges) + " steps do not decrease it; the reachable graph has no cycle, so runs still terminate here";
                r.trace->description = "the last step " + std::string(keptBy(firstBad) ? "changes" : "does not decrease") + " '" + p.name + "'";
                r.witness = {{"non_decreasing_steps", badEdges}, {"cycle", false}, {"livelock", false}};
                break;
            }
            // Lasso: reach the cycle, take its step, and come back by a shortest path inside the
            // same strong component (of the non-decreasing steps for a livelock); a self-loop is a
            // cycle of one step.
            const StateId next = succ[cycleEdge];
            std::vector<StateId> loop{cycleFrom};
            if (next == cycleFrom) loop.push_back(cycleFrom);
            else
                for (StateId b : GraphView(*ex, livelock ? &flat : nullptr).shortestPath(next, cycleFrom)) loop.push_back(b);
            const Trace cycle = traceAlong(*ex, loop);
            Trace t = traceTo(*ex, cycleFrom);
            t.loop = static_cast<int>(t.steps.size()) - 1;
            // ITF: the last state steps back to states[loop], so the repeated state is not written twice.
            t.steps.insert(t.steps.end(), cycle.steps.begin() + 1, cycle.steps.end() - 1);
            // Can a fair scheduler leave a livelock? Only if some step from its strong component (in
            // the whole graph) decreases the ranking; and a mixed cycle only if a step leaves its component.
            bool escapable = false;
            for (StateId s : ids)
                if (whole.of[s] == whole.of[cycleFrom])
                    for (std::uint64_t k = row[s]; k < row[s + 1] && !escapable; ++k)
                        escapable = livelock ? !flat[k] : whole.of[succ[k]] != whole.of[s];
            r.trace = t;
            const std::size_t length = loop.size() - 1;
            r.summary = "not terminating: " +
                        (livelock ? "a cycle of " + stepCount(length) + " on which it never decreases"
                                  : "a cycle of " + stepCount(length) + " that undoes what it decreases") +
                        (escapable ? " (a fair scheduler can leave it)" : " (trapped: no step leaves it)");
            r.trace->description = r.summary;
            r.witness = {{"non_decreasing_steps", badEdges}, {"cycle", true}, {"livelock", livelock}, {"length", length}, {"escapable", escapable}};
            break;
        }
        case rules::Property::Kind::Progress: {
            judgeStuck(r, *ex, stuckStates(*ex, e, p.exprs.empty() ? nullptr : &p.exprs[0], budget), complete,
                       "outside the goal with no enabled rule", "stuck outside the goal: no rule is enabled", "stuck",
                       "some rule is enabled in every state outside the goal");
            break;
        }
        case rules::Property::Kind::Holonomic:
            if (!complete) {
                r.summary = "needs the whole graph; the search stopped at a limit";
            } else {
                r = checkHolonomy(*ex, comps, p, budget);
            }
            break;
        }
        if (r.trace) r.trace->property = p.name;
        r.seconds = since(t0);
        report.properties.push_back(std::move(r));
    }
    if (system.goal && selected("deadlock")) {
        const auto t0 = Clock::now();
        PropertyResult r;
        r.name = "deadlock";
        r.kind = "deadlock";
        judgeStuck(r, *ex, stuckStates(*ex, e, nullptr, budget), complete, "with no enabled rule outside the goal",
                   "a deadlock: no rule is enabled and the goal is not reached", "deadlocks",
                   "every state outside the goal has an enabled rule");
        r.seconds = since(t0);
        report.properties.push_back(std::move(r));
    }
    // The goal stays reachable from every reachable state (AG EF goal): then a scheduler that picks
    // enabled instances at random reaches it with probability 1, even where the ranking admits
    // cycles. A deadlock outside the goal violates it; so does a trap of cycles with no way out.
    if (system.goal && selected("goal_reachable")) {
        const auto t0 = Clock::now();
        PropertyResult r;
        r.name = "goal_reachable";
        r.kind = "goal_reachable";
        if (!complete) {
            r.summary = "needs the whole graph; the search stopped at a limit";
        } else if (const std::string why = beyond(kGoalCost); !why.empty()) {
            r.summary = why;
        } else {
            std::vector<StateId> goals;
            const std::vector<StateId> ids = ex->ids();
            for (StateId s : ids)
                if (e.holds(*system.goal, ex->cells(s).data())) goals.push_back(s);
            const std::vector<char> reach = canReach(*ex, goals);
            if (!violatedAtNearest(
                    r, *ex, ids, [&](StateId s) { return !reach[s]; }, "from which no run reaches the goal",
                    "no run from here reaches the goal", "trapped")) {
                r.verdict = Verdict::Holds;
                r.summary = "from every state some run reaches the goal (" + std::to_string(goals.size()) + " goal states)";
            }
        }
        r.seconds = since(t0);
        report.properties.push_back(std::move(r));
    }
    if (keep) {
        keep->explorer = std::move(ex);
        keep->engine = std::move(engine);
    }
    return report;
}

}  // namespace holon::checker
