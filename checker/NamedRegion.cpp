// Moving a window counterexample onto a named region. The window (checker/Window.h) is rebuilt from
// the radius the counterexample's witness records, grown by one as checker/EverySize.cpp grows it
// (the spec it was confirmed on must come out the same); each cell is translated into the named
// region (square and cubic: by the lower corner of the bounding box; hex: so that the cells lie
// nearest the origin, around which a hexagon lies), and each step's instance is found again by its shape and
// first cell. Lattices are translation invariant and the added cells are empty without inputs, as a
// point outside a region reads; but constraints and properties quantify over them, so the
// interpreter confirms the moved trace instead of taking that on trust. Then it is made smaller,
// one cell at a time with the interpreter as the oracle (one greedy pass of delta debugging's
// reduction, Zeller and Hildebrandt 2002, over the cells no step reads or writes).

#include "checker/NamedRegion.h"

#include "checker/Property.h"
#include "checker/Window.h"
#include "rules/Error.h"

#include <algorithm>
#include <cstdlib>

namespace holon::checker {

namespace {

/// The smallest named region holding `cells` and the offset that moves them into it.
std::pair<rules::Region, rules::Vec> namedAround(const rules::Lattice& lattice, const std::vector<rules::Vec>& cells) {
    switch (lattice.kind()) {
    case rules::LatticeKind::Square2D:
    case rules::LatticeKind::Cubic3D: {
        rules::Vec lo = cells.front(), hi = cells.front();
        for (rules::Vec v : cells) lo = {std::min(lo.x, v.x), std::min(lo.y, v.y), std::min(lo.z, v.z)}, hi = {std::max(hi.x, v.x), std::max(hi.y, v.y), std::max(hi.z, v.z)};
        return {rules::Region::box(lattice, hi - lo + rules::Vec{1, 1, 1}), rules::Vec{} - lo};
    }
    case rules::LatticeKind::Hex2D: {
        // A hexagon is centred on the origin: the cells are moved by whichever of 0 and minus one
        // of them puts them nearest it.
        auto radiusAfter = [&](rules::Vec shift) {
            int radius = 0;
            for (rules::Vec v : cells) radius = std::max({radius, std::abs(v.x + shift.x), std::abs(v.y + shift.y), std::abs(v.x + shift.x + v.y + shift.y)});
            return radius;
        };
        rules::Vec best{};
        int radius = radiusAfter(best);
        for (rules::Vec v : cells)
            if (const int r = radiusAfter(rules::Vec{} - v); r < radius) radius = r, best = rules::Vec{} - v;
        return {rules::Region::hexagon(std::max(radius, 1)), best};  // hex:r0 is no region --region takes
    }
    }
    throw InternalError("a lattice without a named region");
}

/// The trace moved from `from` onto `onto`, each cell translated by `shift`; nothing when a cell
/// that holds something or has an input, or an instance, falls outside `onto`.
std::optional<NamedCounterexample> moved(const rules::Model& model, const rules::Region& from, const std::vector<std::uint32_t>& fromInputs, const Trace& t,
                                         rules::Region onto, rules::Vec shift) {
    std::vector<int> to(from.size());
    std::vector<std::uint32_t> inputs(onto.size(), 0);
    for (int i = 0; i < from.size(); ++i) {
        to[i] = onto.indexOf(from.cell(i) + shift);
        bool used = fromInputs[i] != 0;
        for (const Trace::Step& step : t.steps) used = used || step.cells[i] != 0;
        if (to[i] < 0 && used) return std::nullopt;
        if (to[i] >= 0) inputs[to[i]] = fromInputs[i];
    }
    const rules::Engine before(model, from, fromInputs), engine(model, onto, inputs);
    Trace trace = t;
    for (Trace::Step& step : trace.steps) {
        std::vector<rules::CellValue> cells(onto.size(), 0);
        for (int i = 0; i < from.size(); ++i)
            if (to[i] >= 0) cells[to[i]] = step.cells[i];
        step.cells = std::move(cells);
        if (step.placed >= 0) {
            const rules::Engine::Placed& p = before.instances()[step.placed];
            if (to[p.cells[0]] < 0 || (step.placed = engine.instanceAt(to[p.cells[0]], p.shape)) < 0) return std::nullopt;
        }
    }
    for (int& i : trace.marked)
        if ((i = to[i]) < 0) return std::nullopt;
    return NamedCounterexample{std::move(onto), std::move(trace), std::move(inputs)};
}

/// Whether the reference interpreter confirms `c` as a counterexample to `r`'s property; the reason
/// it does not in `why`.
bool confirmed(const rules::Model& model, const PropertyResult& r, const NamedCounterexample& c, std::string* why) {
    PropertyResult moved = r;
    moved.trace = c.trace;
    moved.inputs = c.inputs;
    const rules::Engine engine(model, c.region, c.inputs);
    confirmInto(moved, *propertyType(*model.system().property(r.name)), Evidence::Obligation, rules::Interpreter(model, c.region), engine, "confirmed");
    if (why) *why = moved.whyNotConfirmed();
    return moved.confirmed();
}

/// A smaller counterexample that still breaks the property: the solver fills cells no step reads
/// or writes, and sets their inputs, with whatever satisfies the hypotheses, which hides the step
/// in a person's drawing and makes `holon check --from TRACE#0` explore a large region. Each such
/// cell is emptied in every state, and its inputs cleared, where the interpreter still confirms the
/// trace; then the trace moves onto the smallest named region around what is left. Greedy, one
/// cell at a time: a few hundred replays of a one-step trace on a window.
NamedCounterexample smaller(const rules::Model& model, const PropertyResult& r, NamedCounterexample c) {
    const rules::Engine engine(model, c.region, c.inputs);
    std::vector<char> keep(static_cast<std::size_t>(c.region.size()), 0);
    for (std::size_t k = 0; k < c.trace.steps.size(); ++k) {
        const Trace::Step& step = c.trace.steps[k];
        if (step.placed >= 0) {
            const rules::Engine::Placed& p = engine.instances()[step.placed];
            for (int j = 0; j < p.size; ++j) keep[p.cells[j]] = 1;
        }
        for (int i = 0; k > 0 && i < c.region.size(); ++i) keep[i] = keep[i] || step.cells[i] != c.trace.steps[k - 1].cells[i];
    }
    for (int i : c.trace.marked) keep[i] = 1;
    for (int i = 0; i < c.region.size(); ++i) {
        if (keep[i]) continue;
        if (c.trace.steps.front().cells[i] != 0) {
            NamedCounterexample tried = c;
            for (Trace::Step& step : tried.trace.steps) step.cells[i] = 0;
            if (confirmed(model, r, tried, nullptr)) c = std::move(tried);
        }
        if (c.inputs[i] != 0) {
            NamedCounterexample tried = c;
            tried.inputs[i] = 0;
            if (confirmed(model, r, tried, nullptr)) c = std::move(tried);
        }
    }
    std::vector<rules::Vec> used;
    for (int i = 0; i < c.region.size(); ++i)
        if (keep[i] || c.inputs[i] || c.trace.steps.front().cells[i]) used.push_back(c.region.cell(i));
    if (used.empty()) return c;
    auto [region, shift] = namedAround(model.lattice(), used);
    if (region.size() >= c.region.size()) return c;
    std::optional<NamedCounterexample> tighter = moved(model, c.region, c.inputs, c.trace, std::move(region), shift);
    return tighter && confirmed(model, r, *tighter, nullptr) ? std::move(*tighter) : c;
}

}  // namespace

std::optional<NamedCounterexample> onNamedRegion(const rules::Model& model, const PropertyResult& r, std::string& why) {
    const rules::Property* property = model.system().property(r.name);
    if (!r.trace || !r.confirmed() || !property || !r.witness.is_object() || !r.witness.contains("window_radius"))
        throw InternalError("'" + r.name + "' is not a confirmed window counterexample");
    const Window window(model, r.witness["window_radius"].get<int>());
    const rules::Region concrete = window.region().grown(1);
    if (concrete.spec() != r.witness.value("confirmed_on", std::string()))
        throw InternalError("the window of '" + r.name + "' rebuilt as " + concrete.spec() + ", not " + r.witness.value("confirmed_on", std::string()));
    const std::vector<std::uint32_t> concreteInputs = r.inputs.value_or(std::vector<std::uint32_t>(concrete.size(), 0));
    auto [region, shift] = namedAround(model.lattice(), concrete.cells());
    std::optional<NamedCounterexample> named = moved(model, concrete, concreteInputs, *r.trace, std::move(region), shift);
    if (!named) throw InternalError("the window of '" + r.name + "' does not fit the named region around it");
    std::string reason;
    if (!confirmed(model, r, *named, &reason)) {
        why = "moved onto " + named->region.spec() + ", the reference interpreter does not confirm it: " + reason;
        return std::nullopt;
    }
    return smaller(model, r, std::move(*named));
}

}  // namespace holon::checker
