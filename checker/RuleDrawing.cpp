// Rule drawings (checker/RuleDrawing.h). An example firing is found by planting, for each pattern
// cell, a state its left side accepts (Engine::lhsAccepts, so inputs and field atoms count) and
// retrying with other neighbours and inputs until the guard holds; an orientation where that finds
// none takes another's example turned by the symmetry between them. The two configurations are
// drawn by the trace drawer (checker/Draw), one panel per orientation stacked in one document.

#include "checker/RuleDrawing.h"

#include "checker/Draw.h"
#include "rules/Engine.h"
#include "rules/Error.h"
#include "rules/Printer.h"
#include "rules/Svg.h"

#include <algorithm>
#include <optional>
#include <random>

namespace holon::checker {

namespace {

/// The region drawn around a pattern: its bounding box (a hexagon on the hex lattice) grown by one
/// neighbour step, and where the anchor sits in it.
std::pair<rules::Region, rules::Vec> regionAround(const rules::Lattice& lattice, const std::vector<rules::Vec>& offsets) {
    if (lattice.kind() == rules::LatticeKind::Hex2D) {
        int radius = 0;
        for (const rules::Vec& o : offsets) radius = std::max(radius, (std::abs(o.x) + std::abs(o.y) + std::abs(o.x + o.y)) / 2);
        return {rules::Region::hexagon(radius).grown(1), rules::Vec{}};
    }
    rules::Vec lo = offsets.front(), hi = offsets.front();
    for (const rules::Vec& o : offsets)
        lo = {std::min(lo.x, o.x), std::min(lo.y, o.y), std::min(lo.z, o.z)}, hi = {std::max(hi.x, o.x), std::max(hi.y, o.y), std::max(hi.z, o.z)};
    return {rules::Region::box(lattice, hi - lo + rules::Vec{1, 1, 1}).grown(1), rules::Vec{} - lo};
}

/// An example firing of one shape: the configuration before it and the inputs, on the region
/// regionAround draws.
struct Example {
    std::vector<std::uint32_t> inputs;
    std::vector<CellValue> cells;
};

/// The shape's instance at the anchor of its drawing region, on an engine of that shape alone (a
/// drawing per rule stays linear in the rules).
struct Drawn {
    rules::Region region;
    rules::Vec anchor;
    rules::Engine engine;
    int instance;
    Drawn(const rules::Model& model, int shape, const std::vector<std::uint32_t>& inputs, std::pair<rules::Region, rules::Vec> around)
        : region(std::move(around.first)), anchor(around.second), engine(model, region, inputs, false, {shape}) {
        const auto& placed = engine.instances();
        const auto p = std::find_if(placed.begin(), placed.end(), [&](const rules::Engine::Placed& q) { return q.shape == shape && q.anchor == anchor; });
        if (p == placed.end()) throw InternalError("drawRuleSvg: the region is built around the pattern, yet has no instance at its anchor");
        instance = static_cast<int>(p - placed.begin());
    }
};

/// An example firing found by planting states the left side accepts and retrying until the guard
/// holds; none when 20 draws of the inputs with 300 tries each found none.
std::optional<Example> findExample(const rules::Model& model, int shape) {
    const rules::RuleShape& rs = model.shapes()[shape];
    const rules::System& system = model.system();
    const int alphabet = model.alphabet().size();
    std::mt19937 rng(static_cast<unsigned>(1000 + shape));
    const rules::Region region = regionAround(model.lattice(), rs.offsets).first;
    // Twenty draws of the inputs (the first: none set), each with a compiled engine and 300 tries:
    // the first leave every other cell empty (the plainest example), then every other cell holds
    // one state (guards that count many cells of a state), then random states.
    for (int draw = 0; draw < 20; ++draw) {
        std::vector<std::uint32_t> inputs(region.size(), 0);
        if (draw > 0 && !system.inputs.empty())
            for (auto& bits : inputs) bits = static_cast<std::uint32_t>(rng() & ((1u << system.inputs.size()) - 1));
        const Drawn d(model, shape, inputs, regionAround(model.lattice(), rs.offsets));
        const rules::Engine& engine = d.engine;
        const rules::Engine::Placed& p = engine.instances()[d.instance];
        for (int attempt = 0; attempt < 300; ++attempt) {
            std::vector<CellValue> cells(region.size(), 0);
            // Tries 100-199 make each free pattern cell (one that may be empty) hold one state
            // with a random probability, for guards that count the pattern's cells of a state.
            const auto one = static_cast<CellValue>(1 + attempt % (alphabet - 1));
            const bool binary = attempt >= 100 && attempt < 200;
            const double share = std::uniform_real_distribution<double>(0.3, 0.95)(rng);
            if (attempt >= 20 && attempt < 60) std::fill(cells.begin(), cells.end(), one);
            else if (attempt >= 200)
                for (auto& v : cells)
                    if (rng() % 2) v = static_cast<CellValue>(1 + rng() % (alphabet - 1));
            bool planted = true;
            for (int k = 0; k < p.size && planted; ++k) {
                const int cell = p.cells[k];
                std::vector<CellValue> accepted;
                for (int v = 0; v < alphabet; ++v)
                    if (engine.lhsAccepts(d.instance, k, engine.comboOfCell(cell), static_cast<CellValue>(v))) accepted.push_back(static_cast<CellValue>(v));
                const bool free = std::count(accepted.begin(), accepted.end(), 0) && std::count(accepted.begin(), accepted.end(), one);
                if (accepted.empty()) planted = false;
                else if (binary && free) cells[cell] = std::uniform_real_distribution<double>(0, 1)(rng) < share ? one : 0;
                else cells[cell] = accepted[attempt < 20 ? attempt % accepted.size() : rng() % accepted.size()];
            }
            if (planted && engine.matches(cells.data(), d.instance)) return Example{inputs, cells};
        }
    }
    return std::nullopt;
}

/// `from`'s example carried onto shape `to` by a symmetry that maps the one's pattern onto the
/// other's, when the guard holds there too: the random search can miss an orientation whose
/// example is a rotation of one it found (a 19-cell hex rule: 5 of 6 panels said none).
std::optional<Example> carried(const rules::Model& model, int from, const Example& example, int to) {
    const std::vector<rules::Vec>&a = model.shapes()[from].offsets, &b = model.shapes()[to].offsets;
    const auto [source, sourceAnchor] = regionAround(model.lattice(), a);
    for (const rules::LinearMap& t : model.lattice().pointGroup()) {
        bool maps = a.size() == b.size();
        for (std::size_t k = 0; k < a.size() && maps; ++k) maps = t.apply(a[k]) == b[k];
        if (!maps) continue;
        const auto around = regionAround(model.lattice(), b);
        Example moved{std::vector<std::uint32_t>(around.first.size(), 0), std::vector<CellValue>(around.first.size(), 0)};
        for (int i = 0; i < source.size(); ++i)
            if (const int j = around.first.indexOf(around.second + t.apply(source.cell(i) - sourceAnchor)); j >= 0)
                moved.cells[j] = example.cells[i], moved.inputs[j] = example.inputs[i];
        if (const Drawn d(model, to, moved.inputs, around); d.engine.matches(moved.cells.data(), d.instance)) return moved;
    }
    return std::nullopt;
}

/// A panel: the example firing of one orientation, or a line saying none was found.
rules::SvgPicture drawOrientation(const rules::Model& model, int shape, const std::optional<Example>& example, const std::string& head) {
    if (!example) {
        rules::Svg none;
        none.text(10, 22, head + ": no example found whose guard holds", {{"font-size", 14}, {"font-weight", "bold"}});
        return none.picture(520, 40);
    }
    const Drawn d(model, shape, example->inputs, regionAround(model.lattice(), model.shapes()[shape].offsets));
    Trace t;
    std::vector<CellValue> cells = example->cells;
    t.steps.push_back({cells, -1});
    CellValue saved[rules::Engine::kMaxCells];
    d.engine.apply(cells.data(), d.instance, saved);
    t.steps.push_back({cells, d.instance});
    return drawTrace(t, d.engine, head);
}

}  // namespace

std::string drawRuleSvg(const rules::Model& model, int rule) {
    rules::requirePatternsNear(model, "a drawing of a rule");
    std::vector<int> shapes;
    for (int s = 0; s < static_cast<int>(model.shapes().size()); ++s)
        if (model.shapes()[s].rule == rule) shapes.push_back(s);
    const rules::DirectedRule& r = model.rules()[rule];
    const rules::System& system = model.system();
    std::string title = "rule " + r.name + " on " + model.lattice().name() + ": " + std::to_string(shapes.size()) +
                        (shapes.size() == 1 ? " orientation" : " orientations");
    if (r.guard()) title += "; fires only where " + rules::printExpr(system, *r.guard());
    // A drawing shows every cell of the box around the pattern, layer by layer: on cubic3d a rule
    // whose cells lie 16 steps apart laid out 42,875 cells (36 s, 414 MB of SVG), at 64 steps far
    // more than the machine has.
    constexpr int kMaxDrawnCells = 20'000;
    for (int s : shapes)
        if (const int cells = regionAround(model.lattice(), model.shapes()[s].offsets).first.size(); cells > kMaxDrawnCells) {
            const rules::Rule& source = *r.rule;
            throw InputError(system.sourceName + ":" + std::to_string(source.loc.line) + ":" + std::to_string(source.loc.col) + ": rule '" + r.name +
                             "' would be drawn on " + std::to_string(cells) + " cells of " + model.lattice().name() + ", more than " + std::to_string(kMaxDrawnCells) +
                             " for a readable picture; bring its cells nearer");
        }
    rules::Svg body;
    body.text(10, 24, title, {{"font-size", 15}, {"font-weight", "bold"}});
    double y = 36, width = 520;
    std::vector<std::optional<Example>> examples;
    for (int s : shapes) examples.push_back(findExample(model, s));
    for (std::size_t k = 0; k < shapes.size(); ++k)
        for (std::size_t j = 0; j < shapes.size() && !examples[k]; ++j)
            if (examples[j] && j != k) examples[k] = carried(model, shapes[j], *examples[j], shapes[k]);
    for (std::size_t k = 0; k < shapes.size(); ++k) {
        const std::string head = "orientation " + std::to_string(k + 1) + " of " + std::to_string(shapes.size());
        const rules::SvgPicture panel = drawOrientation(model, shapes[k], examples[k], head);
        body.nested(panel.document, 0, y);
        y += panel.height + 8, width = std::max(width, panel.width);
    }
    if (shapes.empty()) body.text(10, 56, "no orientation of its own: every one repeats an earlier rule's", {{"font-size", 13}}), y += 30;
    return body.document(std::max(width, 9.0 * static_cast<double>(title.size()) + 20), y + 10);
}

}  // namespace holon::checker
