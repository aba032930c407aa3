// Counterexample traces in the Informal Trace Format of Apalache (ITF: a JSON object with "vars",
// "states" and an optional "loop"), so other tools can read them. Every trace holon produces can be
// replayed through the reference interpreter, which is independent of the engine and explorer that
// found it: the certificate is checked by something other than its producer (CaDiCaL's discipline).

#include "checker/Trace.h"

#include "checker/Verdict.h"
#include "rules/Printer.h"

#include "rules/ConfigIo.h"
#include "rules/ItfWriter.h"

#include <algorithm>

namespace holon::checker {

Trace traceTo(const Explorer& ex, StateId id) {
    Trace t;
    for (auto [s, via] : ex.pathTo(id)) t.steps.push_back({ex.cells(s), ex.isInitial(s) ? -1 : via});
    return t;
}

Trace traceWithStep(const Explorer& explorer, StateId from, std::uint64_t edge) {
    Trace t = traceTo(explorer, from);
    t.steps.push_back({explorer.cells(explorer.successors()[edge]), explorer.successorVia()[edge]});
    return t;
}

Trace traceAlong(const Explorer& ex, const std::vector<StateId>& states) {
    Trace t;
    const auto& row = ex.rowStart();
    for (std::size_t k = 0; k < states.size(); ++k) {
        int via = -1;
        if (k > 0)
            for (std::uint64_t e = row[states[k - 1]]; e < row[states[k - 1] + 1]; ++e)
                if (ex.successors()[e] == states[k]) via = ex.successorVia()[e];
        t.steps.push_back({ex.cells(states[k]), via});
    }
    return t;
}

nlohmann::json toItf(const Trace& trace, const rules::Engine& engine, const std::string& source) {
    const rules::Region& region = engine.region();
    const rules::Model& model = engine.model();
    const rules::System& system = model.system();
    rules::ItfWriter itf(model, {source, system.name, region.spec(), trace.property, trace.description}, !system.inputs.empty());
    // Inputs are constant along a trace: {"target": {"#set": [{"#tup": [x, y]}, ...]}}.
    nlohmann::json inputs = nlohmann::json::object();
    for (std::size_t k = 0; k < system.inputs.size(); ++k) {
        nlohmann::json cells = nlohmann::json::array();
        for (int i = 0; i < region.size(); ++i)
            if ((engine.inputs()[i] >> k) & 1u) cells.push_back(itf.tuple(region.cell(i)));
        inputs[system.inputs[k]] = {{"#set", cells}};
    }
    for (std::size_t k = 0; k < trace.steps.size(); ++k) {
        const auto& step = trace.steps[k];
        nlohmann::json meta{{"index", k}};
        if (step.placed >= 0) {
            const auto& p = engine.instances()[step.placed];
            meta["rule"] = model.rules()[p.rule].name;
            nlohmann::json cells = nlohmann::json::array();
            for (int c = 0; c < p.size; ++c) cells.push_back(rules::pointJson(region.lattice(), region.cell(p.cells[c])));
            meta["cells"] = cells;
        }
        // The cells the violated property points at (the part cut off, a blocking cell).
        if (k + 1 == trace.steps.size() && !trace.marked.empty()) {
            nlohmann::json marked = nlohmann::json::array();
            for (int i : trace.marked) marked.push_back(rules::pointJson(region.lattice(), region.cell(i)));
            meta["marked"] = marked;
        }
        itf.state(
            meta,
            [&](auto&& f) {
                for (int i = 0; i < region.size(); ++i)
                    if (step.cells[i]) f(region.cell(i), step.cells[i]);
            },
            inputs);
    }
    return itf.json(trace.loop);
}

bool replay(const Trace& trace, const rules::Engine& engine, const rules::Interpreter& in, std::string* why) {
    auto fail = [&](const std::string& message) {
        if (why) *why = message;
        return false;
    };
    if (trace.steps.empty()) return fail("empty trace");
    rules::Configuration c = in.empty();
    c.inputs = engine.inputs();
    c.cells = trace.steps[0].cells;
    if (!in.legal(c)) return fail("the first state violates a constraint");
    for (std::size_t k = 1; k < trace.steps.size(); ++k) {
        const int placed = trace.steps[k].placed;
        if (placed < 0) return fail("step " + std::to_string(k) + " names no rule instance");
        auto next = in.successor(c, engine.instance(placed));
        if (!next) return fail("step " + std::to_string(k) + ": the instance is not enabled");
        if (next->cells != trace.steps[k].cells) return fail("step " + std::to_string(k) + ": the successor differs");
        c = *next;
    }
    return true;
}

std::string nameFailingConjunct(PropertyResult& r, const rules::Property& invariant, const rules::Interpreter& in, const rules::Configuration& last) {
    const auto parts = rules::conjuncts(invariant.exprs[0]);
    const int failing = in.firstFalseConjunct(invariant.exprs[0], last);
    if (failing < 0) return "";
    const std::string text = rules::printExpr(in.model().system(), *parts[failing]);
    if (!r.witness.is_object()) r.witness = nlohmann::json::object();
    r.witness["conjunct"] = {{"index", failing + 1}, {"of", parts.size()}, {"text", text}};
    const std::string which = parts.size() > 1 ? ": conjunct " + std::to_string(failing + 1) + " of " + std::to_string(parts.size()) + ", '" + text + "', is false"
                                               : ": '" + text + "' is false";
    r.summary += which;
    return which;
}

nlohmann::json traceJson(const Trace& trace, const rules::Engine& engine, const rules::Interpreter& in) {
    nlohmann::json states = nlohmann::json::array();
    for (const Trace::Step& step : trace.steps) {
        nlohmann::json state = {{"configuration", rules::configToJson(in, {step.cells, engine.inputs()})}};
        if (step.placed >= 0) state["rule"] = engine.model().rules()[engine.instances()[step.placed].rule].name;
        states.push_back(std::move(state));
    }
    nlohmann::json j = {{"states", states}};
    if (trace.loop) j["loop"] = *trace.loop;
    return j;
}

}  // namespace holon::checker
