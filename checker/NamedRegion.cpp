// Moving a window counterexample onto a named region. The window (checker/Window.h) is rebuilt from
// the radius the counterexample's witness records, grown by one as checker/EverySize.cpp grows it
// (the spec it was confirmed on must come out the same); each cell is translated into the named
// region (square and cubic: by the lower corner of the bounding box; hex: none, the window is
// around the origin and a hexagon is too), and each step's instance is found again by its shape and
// first cell. Lattices are translation invariant and the added cells are empty without inputs, as a
// point outside a region reads; but constraints and properties quantify over them, so the
// interpreter confirms the moved trace instead of taking that on trust.

#include "checker/NamedRegion.h"

#include "checker/Property.h"
#include "checker/Window.h"
#include "rules/Error.h"

#include <algorithm>
#include <cstdlib>

namespace holon::checker {

namespace {

/// The named region holding the cells of `concrete` and the offset that moves them into it.
std::pair<rules::Region, rules::Vec> namedAround(const rules::Region& concrete) {
    const rules::Lattice& lattice = concrete.lattice();
    switch (lattice.kind()) {
    case rules::LatticeKind::Square2D:
    case rules::LatticeKind::Cubic3D: return {rules::Region::box(lattice, concrete.extent()), rules::Vec{} - concrete.lower()};
    case rules::LatticeKind::Hex2D: {
        int radius = 0;
        for (rules::Vec v : concrete.cells()) radius = std::max({radius, std::abs(v.x), std::abs(v.y), std::abs(v.x + v.y)});
        return {rules::Region::hexagon(radius), rules::Vec{}};
    }
    }
    throw InternalError("a lattice without a named region");
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
    const rules::Engine before(model, concrete, concreteInputs);
    auto [region, shift] = namedAround(concrete);
    std::vector<int> to(concrete.size());
    std::vector<std::uint32_t> inputs(region.size(), 0);
    for (int i = 0; i < concrete.size(); ++i) {
        to[i] = region.indexOf(concrete.cell(i) + shift);
        inputs[to[i]] = concreteInputs[i];
    }
    const rules::Engine engine(model, region, inputs);
    Trace trace = *r.trace;
    for (Trace::Step& step : trace.steps) {
        std::vector<rules::CellValue> cells(region.size(), 0);
        for (int i = 0; i < concrete.size(); ++i) cells[to[i]] = step.cells[i];
        step.cells = std::move(cells);
        if (step.placed >= 0) {
            const rules::Engine::Placed& p = before.instances()[step.placed];
            step.placed = engine.instanceAt(to[p.cells[0]], p.shape);
        }
    }
    for (int& i : trace.marked) i = to[i];
    PropertyResult moved = r;
    moved.trace = trace;
    moved.inputs = inputs;
    confirmInto(moved, *propertyType(*property), Evidence::Obligation, rules::Interpreter(model, region), engine, "confirmed");
    if (!moved.confirmed()) {
        why = "moved onto " + region.spec() + ", the reference interpreter does not confirm it: " + moved.whyNotConfirmed();
        return std::nullopt;
    }
    return NamedCounterexample{std::move(region), std::move(trace), std::move(inputs)};
}

}  // namespace holon::checker
