// The window of a proof for every region (issue 31). A holon rule reads and writes a bounded
// pattern: its left side, plus the neighbours its guard counts. Lattices are translation
// invariant, so an instance anywhere in any region is a translate of the one whose first pattern
// cell is the origin, and what one step can change or read lies within a fixed distance of that
// pattern. The window is those cells for every shape at once, each cell's state and inputs free;
// an obligation about one step proved on it holds for every region (proofs/README.md).

#include "checker/Window.h"

#include "rules/Error.h"
#include "rules/Printer.h"

#include <algorithm>
#include <set>
#include <tuple>

namespace holon::checker {

int readRadius(const rules::Expr& e) {
    if (e.around >= 0) return 1;
    int r = 0;
    for (const rules::Expr& k : e.kids) r = std::max(r, readRadius(k));
    return r;
}

int ruleRadius(const rules::Model& model) {
    int r = 0;
    for (const rules::DirectedRule& rule : model.rules())
        if (const rules::Expr* g = rule.guard()) r = std::max(r, readRadius(*g));
    return r;
}

std::string notLocal(const rules::Expr& conjunct, const rules::Engine& engine) {
    const std::string text = "'" + rules::printExpr(engine.model().system(), conjunct) + "'";
    using K = rules::Expr::Kind;
    if (conjunct.kind == K::Bool) return "";
    if (conjunct.kind != K::All && conjunct.kind != K::No)
        return text + " is not a condition on each cell and its neighbours (only all(T: G), all(T), no(T: G) and no(T) are)";
    // A point outside a region is empty with no inputs (input combination 0), and the region's
    // quantifier does not range over it; the window's does, so there the condition must hold
    // whatever its neighbours are.
    const bool emptyIsT = engine.predicateAccepts(conjunct.pred, 0, 0);
    const bool vacuous = conjunct.kind == K::All && conjunct.kids.empty() ? emptyIsT : !emptyIsT;
    if (!vacuous) return text + " asks something of empty cells, and a region does not quantify over the empty points outside it";
    return "";
}

std::string notLocalNumber(const rules::Expr& number, const rules::Engine& engine) {
    if (number.kind == rules::Expr::Kind::Count && !number.kids.empty() && engine.predicateAccepts(number.pred, 0, 0))
        return "'" + rules::printExpr(engine.model().system(), number) + "' counts empty cells by their neighbours, and a region does not count the empty points outside it";
    for (const rules::Expr& k : number.kids)
        if (std::string why = notLocalNumber(k, engine); !why.empty()) return why;
    return "";
}

namespace {

/// The points within `margin` steps of `centres`, centres first, without repeats.
std::vector<rules::Vec> ball(const rules::Lattice& lattice, const std::vector<rules::Vec>& centres, int margin) {
    std::vector<rules::Vec> cells;
    std::set<std::tuple<int, int, int>> seen;
    auto add = [&](rules::Vec v) {
        if (seen.insert({v.x, v.y, v.z}).second) cells.push_back(v);
    };
    for (rules::Vec c : centres) add(c);
    std::size_t layerStart = 0;
    for (int step = 0; step < margin; ++step) {
        const std::size_t layerEnd = cells.size();
        for (std::size_t k = layerStart; k < layerEnd; ++k)
            for (rules::Vec d : lattice.directions()) add(cells[k] + d);
        layerStart = layerEnd;
    }
    return cells;
}

std::vector<rules::Vec> patternsAtOrigin(const rules::Model& model) {
    std::vector<rules::Vec> cells{{0, 0, 0}};
    for (const rules::RuleShape& s : model.shapes())
        for (rules::Vec o : s.offsets) cells.push_back(o - s.offsets[0]);
    return cells;
}

}  // namespace

Window::Window(const rules::Model& model, int margin)
    : region_(rules::Region::of(model.lattice(), model.lattice().name() + "-window-r" + std::to_string(margin),
                                ball(model.lattice(), patternsAtOrigin(model), margin))),
      engine_(model, region_, {}, true), margin_(margin) {
    const int origin = region_.indexOf({0, 0, 0});
    for (int s = 0; s < static_cast<int>(model.shapes().size()); ++s) {
        const std::int32_t p = engine_.instanceAt(origin, s);
        if (p < 0) throw InternalError("the window has no instance of shape " + std::to_string(s) + " at the origin");
        focus_.push_back(p);
    }
}

std::vector<int> Window::around(int placed, int radius) const {
    const rules::Engine::Placed& p = engine_.instances()[placed];
    std::vector<rules::Vec> pattern;
    for (int k = 0; k < p.size; ++k) pattern.push_back(region_.cell(p.cells[k]));
    std::vector<int> out;
    for (rules::Vec v : ball(region_.lattice(), pattern, radius)) {
        const int i = region_.indexOf(v);
        if (i < 0) throw InternalError("a window cell within the margin is missing");
        out.push_back(i);
    }
    return out;
}

bool Window::interior(int cell) const {
    for (int dir = 0; dir < region_.lattice().degree(); ++dir)
        if (region_.neighbour(cell, dir) < 0) return false;
    return true;
}

}  // namespace holon::checker
