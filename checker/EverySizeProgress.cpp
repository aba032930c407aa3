// Progress for every region (issue 31; seed 000 Lemma 2 without a bound on the ensemble). A stuck
// configuration is a global fact; the certificate makes it local. The proved invariants give
// measures, each on a set of cells, in a fixed order:
//   reaches(T, f, S), f a pointer field   a T cell's children (T cells pointing at it): walking
//                                         down them ends, since every pointer chain ends in S
//   reaches(T, nbr, S)                    a ghost distance g: S cells 0, a T cell one more than
//                                         some neighbour's (the shortest T path to S); walking to
//                                         a neighbour of smaller g ends
//   connected(X) assumed, some(Y) proved, the same for reaches(X, nbr, Y) (Lemma A: a connected
//   and Y inside X                        set with a Y cell in it has a path to Y from every cell)
// A cell belongs to the first measure whose T (or X) holds it. The certificate, decided on a
// window centred on one cell o: if o is not final (the goal's per-cell condition fails), some
// instance with a cell at o or next to it is enabled, or o has a non-final neighbour d of an
// earlier measure, or of the same one and further along it. Every chain of such steps is
// finite (lexicographic in the measures), so it ends at an enabled instance: outside the goal
// something can fire (Lemma P). The window knows only what a region lets it assume (the proved
// invariants' per-cell conjuncts, each reaches conjunct's one step, the ghost distances' local
// equations, which the true distances satisfy), with which of its points belong to the region
// free: points outside a region are empty without inputs, hold no instance and end no chain.
// Lemmas A and P, and why the ghost distances exist, are proved in proofs/README.md.

#include "checker/EverySizeProgress.h"

#include "checker/EverySizeInvariant.h"
#include "rules/Interpreter.h"
#include "rules/Printer.h"

#include <algorithm>
#include <deque>

namespace holon::checker {

namespace {

using rules::CellPredicate;
using rules::Expr;
using State = SmtEncoding::State;
using K = Expr::Kind;

struct Measure {
    const CellPredicate* along;             // T (X for a derived one)
    const CellPredicate* to;                // S (Y)
    int field;                              // the pointer field, or -1: neighbours (ghost distances)
    const CellPredicate* inside = nullptr;  // derived: Y must lie inside X, decided on the window too
    std::string text;
};

/// Lattice distances from `from` within the window.
std::vector<int> distances(const rules::Region& region, int from) {
    std::vector<int> dist(region.size(), -1);
    std::deque<int> queue{from};
    dist[from] = 0;
    while (!queue.empty()) {
        const int i = queue.front();
        queue.pop_front();
        for (int dir = 0; dir < region.lattice().degree(); ++dir) {
            const int j = region.neighbour(i, dir);
            if (j >= 0 && dist[j] < 0) dist[j] = dist[i] + 1, queue.push_back(j);
        }
    }
    return dist;
}

/// The certificate fails at the window's origin: see the file comment.
smt::Term certificateFails(SmtEncoding& enc, const Window& w, const State& c, const Expr& goal, const std::vector<const Expr*>& local,
                           const std::vector<Measure>& measures, int reach) {
    const rules::Region& region = w.region();
    const rules::Engine& engine = w.engine();
    smt::Context& ctx = c.is[0][0].context();
    const int o = region.indexOf({0, 0, 0}), n = static_cast<int>(region.size()), degree = region.lattice().degree();
    const std::vector<int> dist = distances(region, o);
    auto pred = [&](int i, const CellPredicate& p) { return enc.memberPred(c, i, p); };

    // Which window points are region cells: the others are empty, without inputs.
    std::vector<smt::Term> inRegion;
    smt::Term known = ctx.boolVal(true);
    for (int i = 0; i < n; ++i) {
        inRegion.push_back(ctx.boolConst("in_region_" + std::to_string(i)));
        smt::Term bare = c.is[i][0];
        for (const smt::Term& bit : enc.inputBits()[i]) bare = bare && !bit;
        known = known && (inRegion[i] || bare);
    }
    known = known && inRegion[o];
    for (int i = 0; i < n; ++i) {
        if (!w.interior(i)) continue;
        for (const Expr* x : local) known = known && enc.cellCondition(*x, c, i);
    }

    // Ghost distances and one pointer step per measure, at every cell whose neighbours are here.
    std::vector<std::vector<smt::Term>> ghost(measures.size());
    smt::Term derived = ctx.boolVal(true), outsideX = ctx.boolVal(false);
    for (std::size_t m = 0; m < measures.size(); ++m) {
        const Measure& mu = measures[m];
        if (mu.inside) outsideX = outsideX || (pred(o, *mu.to) && !pred(o, *mu.inside));
        if (mu.field < 0)
            for (int i = 0; i < n; ++i) ghost[m].push_back(ctx.intConst("ghost_" + std::to_string(m) + "_" + std::to_string(i)));
        for (int i = 0; i < n; ++i) {
            if (!w.interior(i)) continue;
            smt::Term next = ctx.boolVal(false);
            for (int dir = 0; dir < degree; ++dir) {
                const int j = region.neighbour(i, dir);
                if (mu.field >= 0)
                    next = next || (stepsAlong(enc, c, i, mu.field, dir) && (pred(j, *mu.along) || pred(j, *mu.to)));
                else
                    next = next || (pred(j, *mu.to) && ghost[m][i] == ctx.intVal(1)) ||
                           (pred(j, *mu.along) && !pred(j, *mu.to) && ghost[m][j] == ghost[m][i] - ctx.intVal(1));
            }
            smt::Term f = mu.field >= 0 ? smt::implies(pred(i, *mu.along), next)
                                        : smt::implies(pred(i, *mu.along) && pred(i, *mu.to), ghost[m][i] == ctx.intVal(0)) &&
                                              smt::implies(pred(i, *mu.along) && !pred(i, *mu.to), ghost[m][i] >= ctx.intVal(1) && next);
            // A derived distance rests on Y lying inside X, which the query checks beside it.
            if (mu.inside) derived = derived && f;
            else known = known && f;
        }
    }

    // The measure a cell belongs to: the first whose set holds it.
    auto belongs = [&](int i, std::size_t m) {
        smt::Term t = pred(i, *measures[m].along);
        for (std::size_t e = 0; e < m; ++e) t = t && !pred(i, *measures[e].along);
        return t;
    };
    auto further = [&](std::size_t m, int d) {
        const Measure& mu = measures[m];
        if (mu.field < 0) return ghost[m][d] < ghost[m][o];
        for (int dir = 0; dir < degree; ++dir)
            if (region.neighbour(d, dir) == o) return stepsAlong(enc, c, d, mu.field, dir);
        return ctx.boolVal(false);
    };
    smt::Term unmeasured = ctx.boolVal(true);  // the origin belongs to no measure
    for (const Measure& mu : measures) unmeasured = unmeasured && !pred(o, *mu.along);
    smt::Term onward = ctx.boolVal(false);
    for (int dir = 0; dir < degree; ++dir) {
        const int d = region.neighbour(o, dir);
        const smt::Term next = inRegion[d] && !enc.cellCondition(goal, c, d);
        smt::Term earlier = ctx.boolVal(false);  // d belongs to a measure before the current one
        for (std::size_t m = 0; m < measures.size(); ++m) {
            onward = onward || (next && belongs(o, m) && (earlier || (belongs(d, m) && further(m, d))));
            earlier = earlier || belongs(d, m);
        }
        onward = onward || (next && unmeasured && earlier);
    }
    smt::Term enabled = ctx.boolVal(false);
    for (int p = 0; p < static_cast<int>(engine.instances().size()); ++p) {
        const rules::Engine::Placed& placed = engine.instances()[p];
        bool near = false, held = true;
        smt::Term cells = ctx.boolVal(true);
        for (int k = 0; k < placed.size; ++k) {
            near = near || dist[placed.cells[k]] <= 1;
            held = held && dist[placed.cells[k]] >= 0 && dist[placed.cells[k]] + reach <= w.margin();
            cells = cells && inRegion[placed.cells[k]];
        }
        if (near && held) enabled = enabled || (cells && enc.matches(p, c));
    }
    return known && ((derived && !enc.cellCondition(goal, c, o) && !enabled && !onward) || outsideX);
}

}  // namespace

ProgressPlan planProgress(const rules::Model& model, const rules::Property& progress, const std::vector<const rules::Property*>& invariants,
                          const rules::Engine& probe) {
    const rules::System& system = model.system();
    ProgressPlan plan;
    if (!system.goal || system.goal->kind != K::All || !notLocal(*system.goal, probe).empty()) {
        plan.undecided = "the local progress certificate needs a goal that is a condition on each cell (all(G))";
        return plan;
    }
    if (!system.constraints.empty()) {
        plan.undecided = "the system has constraints, and whether a step keeps a non-local constraint is not decided on a window";
        return plan;
    }
    auto text = [&](const Expr& x) { return "'" + rules::printExpr(system, x) + "'"; };
    auto rejectsOutside = [&](const CellPredicate& p) { return !probe.predicateAccepts(p, 0, 0); };
    std::vector<const Expr*> local, some;
    std::vector<Measure> pointers, distances;
    for (const rules::Property* inv : invariants)
        for (const Expr* x : rules::conjuncts(inv->exprs[0])) {
            if (notLocal(*x, probe).empty()) local.push_back(x);
            else if (x->kind == K::Reaches && rejectsOutside(x->pred) && rejectsOutside(x->target))
                (x->field >= 0 ? pointers : distances).push_back({&x->pred, &x->target, x->field, nullptr, text(*x)});
            else if (x->kind == K::Some && x->kids.empty() && rejectsOutside(x->pred))
                some.push_back(x);
        }
    std::vector<Measure> measures = pointers;
    measures.insert(measures.end(), distances.begin(), distances.end());
    if (!progress.exprs.empty()) {
        for (const Expr* a : rules::conjuncts(progress.exprs[0])) {
            if (notLocal(*a, probe).empty()) local.push_back(a);
            else if (a->kind == K::Connected && rejectsOutside(a->pred))
                for (const Expr* y : some)
                    measures.push_back({&a->pred, &y->pred, -1, &a->pred,
                                        "reaches(" + rules::printPredicate(system, a->pred) + ", nbr, " + rules::printPredicate(system, y->pred) + ") by Lemma A from the assumption"});
        }
    }
    if (measures.empty()) {
        plan.undecided = "no proved invariant gives a measure (a reaches conjunct) for the local progress certificate";
        return plan;
    }
    for (const Measure& m : measures) plan.measures += (plan.measures.empty() ? "" : ", then ") + m.text;

    // An instance near the origin reads up to the pattern's extent and the guards' radius beyond it.
    int extent = 0;
    for (const rules::RuleShape& s : model.shapes())
        for (rules::Vec a : s.offsets)
            for (rules::Vec b : s.offsets) extent = std::max(extent, std::abs(a.x - b.x) + std::abs(a.y - b.y) + std::abs(a.z - b.z));
    int radius = ruleRadius(model);
    for (const Expr* x : local) radius = std::max(radius, readRadius(*x));
    const Expr* goal = &*system.goal;  // the system's own: the engine knows its expressions by address
    StepObligation ob;
    ob.name = progress.name, ob.kind = "progress", ob.property = &progress, ob.atCell = true;
    ob.margin = 1 + extent + std::max(radius, 1);
    ob.proved = "outside the goal some instance is enabled, on every region: the local progress certificate holds (measures: " + plan.measures +
                "; Lemmas A and P proved on paper, proofs/README.md, not by a solver)";
    ob.broken = "fails the local progress certificate (a non-final cell with no enabled instance near it and no non-final neighbour further along)";
    const int reach = std::max(radius, 1);
    ob.onWindow = [goal, local, measures, reach](SmtEncoding& enc, const Window& w, int, const State& c, const State&) {
        return certificateFails(enc, w, c, *goal, local, measures, reach);
    };
    plan.steps.push_back(std::move(ob));
    return plan;
}

}  // namespace holon::checker
