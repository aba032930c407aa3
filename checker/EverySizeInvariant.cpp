// Invariants for every region (issue 31), conjunct by conjunct. A condition on every cell
// (`all(T: G)`, `no(T)`) is decided on the window as it stands. The non-local forms the planner's
// Safety is made of are kept by a step when a *frame condition* holds on the cells the step
// rewrites and their neighbours -- a local fact, so decided on the same window:
//   some(T)           no rewritten T cell stops being T, or some rewritten cell is T afterwards
//   connected(T)      no rewritten T cell stops being T, and every new T cell has a T neighbour before
//   reaches(T, f, S)  a rewritten cell that starts following f steps to an S cell or to an unchanged
//                     T cell, and a rewritten cell an unchanged T cell steps onto becomes S
//                     (pointers: the T cell points at it; nbr: the T cell is its neighbour)
// Each frame lemma ("the conjunct before the step and the frame condition give the conjunct
// after") is proved on paper in proofs/README.md; holon checks its side conditions (T and S reject
// the empty points outside a region). A `connected(X)` follows from connected(A) and reaches
// conjuncts before it (every T hangs from the A component through T cells) when the predicates
// cover X exactly: decided by enumerating every state under every input combination. No ghost
// ranks are needed: acyclicity after the step comes from acyclicity before it (the proof inducts
// on the old ranks).

#include "checker/EverySizeInvariant.h"

#include "rules/Interpreter.h"
#include "rules/Printer.h"

#include <algorithm>

namespace holon::checker {

namespace {

using rules::CellPredicate;
using rules::CellValue;
using rules::Expr;
using State = SmtEncoding::State;
using K = Expr::Kind;

/// Why conjunct x has no frame lemma here; empty when it has one.
std::string frameless(const Expr& x, const rules::Engine& e) {
    const std::string text = "'" + rules::printExpr(e.model().system(), x) + "'";
    // The frame condition reads the neighbours of rewritten cells; outside a region they are
    // empty without inputs, and the conjunct's predicates must not count them.
    auto outside = [&](const CellPredicate& pred) { return e.predicateAccepts(pred, 0, 0); };
    switch (x.kind) {
    case K::Some:
        if (!x.kids.empty()) return text + " has a cell guard, which no frame lemma covers";
        return "";
    case K::Connected:
        if (outside(x.pred)) return text + " counts empty cells, and a region leaves out the empty points outside it";
        return "";
    case K::Reaches:
        if (outside(x.pred) || outside(x.target)) return text + " accepts empty cells, and a region leaves out the empty points outside it";
        return "";
    case K::Bool:
    case K::Number:
    case K::Mass:
    case K::And:
    case K::Or:
    case K::Not:
    case K::Implies:
    case K::Compare:
    case K::Add:
    case K::Sub:
    case K::Neg:
    case K::Count:
    case K::All:
    case K::No: break;
    }
    return text + " is neither a condition on each cell nor some(T), connected(T) or reaches(T, f, S), which have frame lemmas";
}

/// The cells (state, input combination) a predicate accepts, over the whole alphabet.
std::vector<char> accepted(const CellPredicate& pred, const rules::Engine& e) {
    const int combos = e.tables().comboCount(), values = e.model().alphabet().size();
    std::vector<char> set(static_cast<std::size_t>(combos * values));
    for (int c = 0; c < combos; ++c)
        for (int v = 0; v < values; ++v) set[c * values + v] = e.predicateAccepts(pred, c, static_cast<CellValue>(v));
    return set;
}

bool subset(const std::vector<char>& a, const std::vector<char>& b) {
    for (std::size_t i = 0; i < a.size(); ++i)
        if (a[i] && !b[i]) return false;
    return true;
}

/// Lemma C: the conjuncts before k (those with a window obligation) that give connected(X), or
/// none. Start from one connected(A) and join each reaches(T, f, S) whose S cells are joined
/// already (a T cell's path runs through T cells, each step to a lattice neighbour, to an S cell);
/// X follows when its cells are exactly the joined ones.
std::vector<int> impliedBy(const std::vector<const Expr*>& parts, std::size_t k, const std::vector<bool>& decided, const rules::Engine& e) {
    const std::vector<char> x = accepted(parts[k]->pred, e);
    for (std::size_t a = 0; a < k; ++a) {
        if (!decided[a] || parts[a]->kind != K::Connected) continue;
        std::vector<char> joined = accepted(parts[a]->pred, e);
        if (!subset(joined, x)) continue;
        std::vector<int> used = {static_cast<int>(a)};
        for (bool grew = true; grew;) {
            grew = false;
            for (std::size_t j = 0; j < k; ++j) {
                if (!decided[j] || parts[j]->kind != K::Reaches || std::find(used.begin(), used.end(), static_cast<int>(j)) != used.end()) continue;
                const std::vector<char> t = accepted(parts[j]->pred, e);
                if (!subset(accepted(parts[j]->target, e), joined) || !subset(t, x)) continue;
                for (std::size_t i = 0; i < t.size(); ++i) joined[i] = joined[i] || t[i];
                used.push_back(static_cast<int>(j)), grew = true;
            }
        }
        if (subset(x, joined)) {
            std::sort(used.begin(), used.end());
            return used;
        }
    }
    return {};
}

/// What the window may assume before the step: the per-cell conjuncts at every cell whose
/// neighbourhood they read lies in the window, and, for each reaches(T, f, S), that a T cell
/// steps to a T or S cell (a consequence of the conjunct at every cell of a region, and vacuous at
/// the empty points outside one). Both hold at every point of a region's embedding.
/// Conjoined to `f` (the step), in the order the exported obligations have always had.
smt::Term before(SmtEncoding& enc, const Window& w, int q, const State& c, const std::vector<const Expr*>& local, int g, const std::vector<const Expr*>& reaching,
                 smt::Term f) {
    const rules::Region& region = w.region();
    for (int i : w.around(q, w.margin())) {
        const bool whole = w.interior(i);
        if (g == 0 || whole)
            for (const Expr* x : local) f = f && enc.cellCondition(*x, c, i);
        if (!whole) continue;
        for (const Expr* x : reaching) {
            smt::Term next = c.is[0][0].context().boolVal(false);
            for (int dir = 0; dir < region.lattice().degree(); ++dir) {
                const int j = region.neighbour(i, dir);
                next = next || (stepsAlong(enc, c, i, x->field, dir) && (enc.memberPred(c, j, x->pred) || enc.memberPred(c, j, x->target)));
            }
            f = f && smt::implies(enc.memberPred(c, i, x->pred), next);
        }
    }
    return f;
}

/// The frame condition of a non-local conjunct for one step of instance q (the header's table).
smt::Term frame(SmtEncoding& enc, const Window& w, int q, const State& c, const State& d, const Expr& x) {
    const rules::Region& region = w.region();
    const auto& placed = w.engine().instances()[q];
    const std::vector<int> pattern(placed.cells, placed.cells + placed.size);
    smt::Context& ctx = c.is[0][0].context();
    const int degree = region.lattice().degree();
    auto in = [&](const State& s, int i, const CellPredicate& pred) { return enc.memberPred(s, i, pred); };
    smt::Term f = ctx.boolVal(true);
    switch (x.kind) {
    case K::Some: {
        smt::Term kept = ctx.boolVal(true), some = ctx.boolVal(false);
        for (int z : pattern) kept = kept && smt::implies(in(c, z, x.pred), in(d, z, x.pred)), some = some || in(d, z, x.pred);
        return kept || some;
    }
    case K::Connected:
        for (int z : pattern) {
            smt::Term touches = ctx.boolVal(false);
            for (int dir = 0; dir < degree; ++dir) touches = touches || in(c, region.neighbour(z, dir), x.pred);
            f = f && smt::implies(in(c, z, x.pred), in(d, z, x.pred)) && smt::implies(in(d, z, x.pred) && !in(c, z, x.pred), touches);
        }
        return f;
    case K::Reaches: {
        // Changed: T or S membership, or (a T cell afterwards) where it points.
        auto changed = [&](int i) {
            smt::Term ch = in(c, i, x.pred) != in(d, i, x.pred) || in(c, i, x.target) != in(d, i, x.target);
            if (x.field < 0) return ch;
            smt::Term moved = ctx.boolVal(false);
            for (int dir = 0; dir < degree; ++dir) moved = moved || (stepsAlong(enc, c, i, x.field, dir) != stepsAlong(enc, d, i, x.field, dir));
            return ch || (in(d, i, x.pred) && moved);
        };
        auto unchangedT = [&](int i) { return in(c, i, x.pred) && !changed(i); };
        for (int z : pattern) {
            // (b) a changed cell that is T afterwards steps to an S cell or an unchanged T cell.
            smt::Term onward = ctx.boolVal(false), leanedOn = ctx.boolVal(false);
            for (int dir = 0; dir < degree; ++dir) {
                const int y = region.neighbour(z, dir);
                if (y < 0) continue;  // outside the window (margin 0): not T, not S, no pointer
                onward = onward || (stepsAlong(enc, d, z, x.field, dir) && (in(d, y, x.target) || (in(d, y, x.pred) && !changed(y))));
                // (c) an unchanged T cell steps onto z: along its pointer back to z, or as a neighbour.
                smt::Term back = ctx.boolVal(x.field < 0);
                if (x.field >= 0) {
                    back = ctx.boolVal(false);
                    for (int b = 0; b < degree; ++b)
                        if (region.neighbour(y, b) == z) back = stepsAlong(enc, c, y, x.field, b);
                }
                leanedOn = leanedOn || (unchangedT(y) && back);
            }
            const smt::Term ch = changed(z);
            f = f && smt::implies(ch && in(d, z, x.pred), onward);
            f = f && smt::implies(ch && (in(c, z, x.pred) || in(c, z, x.target)) && leanedOn, in(d, z, x.target));
        }
        return f;
    }
    case K::Bool:
    case K::Number:
    case K::Mass:
    case K::And:
    case K::Or:
    case K::Not:
    case K::Implies:
    case K::Compare:
    case K::Add:
    case K::Sub:
    case K::Neg:
    case K::Count:
    case K::All:
    case K::No: break;
    }
    throw std::logic_error("no frame condition for this conjunct");
}

}  // namespace

smt::Term stepsAlong(SmtEncoding& enc, const SmtEncoding::State& s, int i, int field, int dir) {
    if (field < 0) return s.is[0][0].context().boolVal(true);
    const rules::Alphabet& alphabet = enc.engine().model().alphabet();
    return enc.member(s, i, [&](int, CellValue v) { return v != 0 && alphabet.fields(v)[field] == dir; });
}

InvariantPlan planInvariant(const rules::Model& model, const rules::Property& p, const rules::Engine& probe) {
    const std::vector<const Expr*> parts = rules::conjuncts(p.exprs[0]);
    InvariantPlan plan;
    std::vector<const Expr*> local, reaching;
    std::vector<bool> decided(parts.size()), isLocal(parts.size());
    std::vector<std::string> why(parts.size());
    int g = 0;
    bool anyFrame = false;
    for (std::size_t k = 0; k < parts.size(); ++k) {
        const std::string n = notLocal(*parts[k], probe);
        if (n.empty()) {
            decided[k] = isLocal[k] = true, local.push_back(parts[k]), g = std::max(g, readRadius(*parts[k]));
            continue;
        }
        // A per-cell form that fails only at empty points keeps notLocal's reason.
        why[k] = parts[k]->kind == K::All || parts[k]->kind == K::No ? n : frameless(*parts[k], probe);
        if (!why[k].empty()) continue;
        decided[k] = true, anyFrame = true;
        if (parts[k]->kind == K::Reaches) reaching.push_back(parts[k]);
    }
    // A connected(X) the conjuncts before it give needs no obligation of its own (Lemma C).
    std::vector<bool> implied(parts.size());
    for (std::size_t k = 0; k < parts.size(); ++k) {
        if (parts[k]->kind != K::Connected || !decided[k]) continue;
        const std::vector<int> from = impliedBy(parts, k, decided, probe);
        if (from.empty()) continue;
        implied[k] = true;
        std::string list;
        for (int j : from) list += (list.empty() ? "" : ", ") + std::to_string(j + 1);
        plan.implied.push_back("conjunct " + std::to_string(k + 1) + " follows from conjuncts " + list + " (Lemma C)");
    }
    const int margin = std::max({ruleRadius(model), 2 * g, anyFrame ? 1 : 0});
    std::string undecidedList;
    for (std::size_t k = 0; k < parts.size(); ++k) {
        if (!decided[k]) {
            if (plan.undecided.empty()) plan.undecided = "conjunct " + std::to_string(k + 1) + ", " + why[k];
            else undecidedList += (undecidedList.empty() ? "" : ", ") + std::to_string(k + 1);
            continue;
        }
        if (implied[k]) continue;
        StepObligation ob;
        ob.name = parts.size() > 1 ? p.name + "." + std::to_string(k + 1) : p.name;
        ob.property = &p;
        ob.kind = "invariant", ob.margin = margin;
        ob.proved = "inductive: every step from a state where it holds keeps it, on every region";
        ob.broken = "breaks it" + std::string(parts.size() > 1 ? " (conjunct " + std::to_string(k + 1) + ")" : "");
        const Expr* x = parts[k];
        if (isLocal[k]) {
            // Only cells within the conjunct's radius of the pattern can change their condition.
            const int r = readRadius(*x);
            ob.onWindow = [local, reaching, g, x, r](SmtEncoding& enc, const Window& w, int q, const State& c, const State& d) {
                const smt::Term f = before(enc, w, q, c, local, g, reaching, enc.fires(q, c, d));
                smt::Term fails = c.is[0][0].context().boolVal(false);
                for (int i : w.around(q, r)) fails = fails || !enc.cellCondition(*x, d, i);
                return f && fails;
            };
        } else {
            ob.broken = "breaks it (" + std::string(parts.size() > 1 ? "conjunct " + std::to_string(k + 1) + ": " : "") + "its frame condition fails)";
            ob.onWindow = [local, reaching, g, x](SmtEncoding& enc, const Window& w, int q, const State& c, const State& d) {
                const smt::Term f = before(enc, w, q, c, local, g, reaching, enc.fires(q, c, d));
                return f && !frame(enc, w, q, c, d, *x);
            };
        }
        ob.onRegion = [&p, x](SmtEncoding& enc, int q, const State& c, const State& d) {
            return enc.legal(c) && enc.legal(d) && enc.holds(p.exprs[0], c, true) && enc.fires(q, c, d) && !enc.holds(*x, d, false);
        };
        plan.steps.push_back(std::move(ob));
    }
    std::string framed;
    for (std::size_t k = 0; k < parts.size(); ++k)
        if (decided[k] && !isLocal[k] && !implied[k]) framed += (framed.empty() ? "" : ", ") + std::to_string(k + 1);
    if (!framed.empty() || !plan.implied.empty()) {
        plan.trusted = framed.empty() ? "" : "conjunct" + std::string(framed.find(',') == std::string::npos ? " " : "s ") + framed + " through frame lemmas";
        for (const std::string& i : plan.implied) plan.trusted += (plan.trusted.empty() ? "" : "; ") + i;
        plan.trusted += ": lemmas proved on paper (proofs/README.md), not by a solver";
    }
    if (!undecidedList.empty())
        plan.undecided += "; " + std::string(undecidedList.find(',') == std::string::npos ? "conjunct " + undecidedList + " is" : "conjuncts " + undecidedList + " are") + " not decided either";
    return plan;
}

}  // namespace holon::checker
