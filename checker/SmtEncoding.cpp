// The SMT encoding of a system on a bounded region (issue: Z3 proofs). A configuration is one-hot:
// a Boolean per (cell, state), exactly one true per cell, which keeps matching, rewriting and the
// frame propositional (integer cells with if-then-else chains were an order of magnitude slower). Every test of a cell -- a rule's left side, a guard's neighbour, a
// predicate of a constraint -- comes from the compiled engine's tables as the set of (input
// combination, state) pairs it accepts, so the encoding cannot drift from the reference semantics
// the engine is tested against. The transition relation is interleaving: a selector picks one placed
// instance, whose cells are rewritten while every other cell keeps its state (frame condition),
// and the successor must satisfy the non-local constraints. Connectivity and pointer reachability
// are existential: ranks that strictly decrease towards a root (or along pointers to a target) when
// they must hold; a cut, or a set of pointer cells closed under following, when they must fail.
// Ranks alone make the solver find descent arguments by search, so hypotheses are also restated
// for the few sets a proof is likely to need (`instantiate`); with them the U/P/F planner's three
// lemmas on square:5x5 take 24 s instead of timing out (verify_bench, proofs/README.md).

#include "checker/SmtEncoding.h"

#include "rules/Error.h"

#include <algorithm>
#include <numeric>
#include <optional>

namespace holon::checker {

using rules::CellValue;
using rules::Expr;

SmtEncoding::SmtEncoding(smt::Context& ctx, const rules::Engine& engine, Use use, Budget budget)
    : ctx_(ctx), engine_(engine), alphabet_(engine.model().alphabet().size()), use_(use), budget_(budget) {
    const int inputs = static_cast<int>(engine.model().system().inputs.size());
    for (int i = 0; i < engine.region().size(); ++i) {
        std::vector<smt::Term> bits;
        for (int k = 0; k < inputs; ++k)
            bits.push_back(ctx_.boolConst("in_" + engine.model().system().inputs[k] + "_" + std::to_string(i)));
        inputBits_.push_back(bits);
    }
    // Many inputs (roombots_reserve's eight walks) and every combination of them: acceptance()
    // expands on the input bits. With one or two inputs the disjunction over combinations is
    // short, and Spacer's strengthenings were found on that form (general2 Progress@reach: 1.5 s).
    const std::uint32_t all = std::uint32_t{1} << inputs;
    for (std::uint32_t b = 0; b < all && inputs >= 3 && inputs <= 16; ++b) comboOfBits_.push_back(engine.tables().comboIndex(b));
    if (std::find(comboOfBits_.begin(), comboOfBits_.end(), -1) != comboOfBits_.end()) comboOfBits_.clear();
}

smt::Term SmtEncoding::fresh(const std::string& prefix, smt::Sort sort) {
    return ctx_.constant(prefix + "_" + std::to_string(counter_++), sort);
}

SmtEncoding::State SmtEncoding::state(const std::string& name) {
    budget_.check("building the formulas");
    State s;
    for (int i = 0; i < engine_.region().size(); ++i) {
        std::vector<smt::Term> row;
        smt::Term some = ctx_.boolVal(false);
        for (int v = 0; v < alphabet_; ++v) {
            row.push_back(ctx_.boolConst(name + "_" + std::to_string(i) + "_" + std::to_string(v)));
            some = some || row.back();
        }
        // Exactly one state per cell, in plain SMT-LIB (no pseudo-Boolean extension) so that
        // every solver reads the exported obligations.
        facts_.push_back(some);
        for (int v = 0; v < alphabet_; ++v)
            for (int w = v + 1; w < alphabet_; ++w) facts_.push_back(!(row[v] && row[w]));
        s.is.push_back(row);
    }
    return s;
}

smt::Term SmtEncoding::sameCell(const State& a, int i, const State& b, int j) const {
    smt::Term all = ctx_.boolVal(true);
    for (int v = 0; v < alphabet_; ++v) all = all && a.is[i][v] == b.is[j][v];
    return all;
}

smt::Term SmtEncoding::inputsAre(const std::vector<std::uint32_t>& inputs) const {
    smt::Term all = ctx_.boolVal(true);
    for (std::size_t i = 0; i < inputBits_.size(); ++i)
        for (std::size_t k = 0; k < inputBits_[i].size(); ++k) all = all && (((inputs[i] >> k) & 1u) ? inputBits_[i][k] : !inputBits_[i][k]);
    return all;
}

smt::Term SmtEncoding::configurationIs(const State& s, const std::vector<CellValue>& cells) const {
    smt::Term all = ctx_.boolVal(true);
    for (std::size_t i = 0; i < cells.size(); ++i) all = all && s.is[i][cells[i]];
    return all;
}

smt::Term SmtEncoding::inputCombo(int cell, int combo) const {
    const std::uint32_t bits = engine_.comboInputs(combo);
    smt::Term all = ctx_.boolVal(true);
    for (std::size_t k = 0; k < inputBits_[cell].size(); ++k) all = all && (((bits >> k) & 1u) ? inputBits_[cell][k] : !inputBits_[cell][k]);
    return all;
}

std::vector<std::pair<int, smt::Term>> SmtEncoding::acceptance(int cell, const std::function<bool(int, CellValue)>& accepts) {
    std::vector<std::pair<int, smt::Term>> out;
    const int combos = engine_.comboCount();
    for (int v = 0; v < alphabet_; ++v) {
        std::vector<int> yes;
        for (int c = 0; c < combos; ++c)
            if (accepts(c, static_cast<CellValue>(v))) yes.push_back(c);
        if (yes.empty()) continue;
        if (static_cast<int>(yes.size()) == combos) {
            out.push_back({v, ctx_.boolVal(true)});
            continue;
        }
        if (comboOfBits_.empty()) {  // some combinations only: one conjunction of input literals each
            smt::Term when = ctx_.boolVal(false);
            for (int c : yes) when = when || inputCombo(cell, c);
            out.push_back({v, when});
            continue;
        }
        // Every combination: Shannon expansion on the input bits, so that a condition on two
        // inputs reads `a and b`, not a disjunction over the 2^k combinations (8 inputs: 64 of them).
        std::vector<char> accepted(comboOfBits_.size());
        for (std::size_t b = 0; b < comboOfBits_.size(); ++b) accepted[b] = std::find(yes.begin(), yes.end(), comboOfBits_[b]) != yes.end();
        std::function<smt::Term(int, std::uint32_t)> expand = [&](int k, std::uint32_t bits) -> smt::Term {
            if (k < 0) return ctx_.boolVal(accepted[bits] != 0);
            const smt::Term off = expand(k - 1, bits), on = expand(k - 1, bits | (std::uint32_t{1} << k));
            if (smt::same(off, on)) return off;
            return ((inputBits_[cell][k] && on) || (!inputBits_[cell][k] && off)).simplify();
        };
        out.push_back({v, expand(static_cast<int>(inputBits_[cell].size()) - 1, 0)});
    }
    return out;
}

smt::Term SmtEncoding::member(const State& s, int cell, const std::function<bool(int, CellValue)>& accepts) {
    // A cell outside the region (cell < 0) is empty with no inputs.
    if (cell < 0) return ctx_.boolVal(accepts(0, 0));
    return inStateWhen(s, cell, acceptance(cell, accepts));
}

smt::Term SmtEncoding::memberPred(const State& s, int cell, const rules::CellPredicate& pred) {
    if (cell < 0) return ctx_.boolVal(engine_.predicateAccepts(pred, 0, 0));
    auto it = predicateAcceptance_.find({&pred, cell});
    if (it == predicateAcceptance_.end())
        it = predicateAcceptance_.emplace(std::make_pair(&pred, cell), acceptance(cell, [&](int c, CellValue v) { return engine_.predicateAccepts(pred, c, v); })).first;
    return inStateWhen(s, cell, it->second);
}

smt::Term SmtEncoding::inStateWhen(const State& s, int cell, const std::vector<std::pair<int, smt::Term>>& accepted) const {
    smt::Term any = ctx_.boolVal(false);
    for (const auto& [v, when] : accepted) any = any || (s.is[cell][v] && when);
    return any.simplify();
}

smt::Term SmtEncoding::memberCounted(const State& s, std::int32_t cell, const Expr& quantifier) {
    smt::Term m = memberPred(s, cell, quantifier.pred);
    return quantifier.kids.empty() ? m : m && guard(engine_.cellGuardOf(quantifier), &cell, s);
}

smt::Term SmtEncoding::cellMassUnits(const State& s, int cell) const {
    // One term per distinct mass, not per state: a planner over general-lock has 91 states and 4
    // masses, and a sum of 91 if-then-elses per cell made a one-step mass-conservation query take
    // 10 s (32 s for general-lock3) where this takes well under one.
    std::map<std::int64_t, smt::Term> byMass;
    for (int v = 0; v < alphabet_; ++v)
        if (const std::int64_t m = engine_.massUnitsOf(static_cast<CellValue>(v))) {
            auto [at, fresh] = byMass.try_emplace(m, s.is[cell][v]);
            if (!fresh) at->second = at->second || s.is[cell][v];
        }
    smt::Term total = ctx_.intVal(0);
    for (const auto& [m, any] : byMass) total = total + smt::ite(any, ctx_.intVal(static_cast<int64_t>(m)), ctx_.intVal(0));
    return total;
}

smt::Term SmtEncoding::massUnits(const State& s) {
    smt::Term total = ctx_.intVal(0);
    for (std::size_t i = 0; i < s.is.size(); ++i) total = total + cellMassUnits(s, static_cast<int>(i));
    return total;
}

smt::Term SmtEncoding::number(const Expr& e, const State& s) {
    switch (e.kind) {
    case Expr::Kind::Number: return ctx_.realVal(static_cast<int64_t>(e.value.num()), static_cast<int64_t>(e.value.den()));
    case Expr::Kind::Mass: return smt::toReal(massUnits(s)) / ctx_.realVal(static_cast<int64_t>(engine_.massDenominator()));
    case Expr::Kind::Add: return number(e.kids[0], s) + number(e.kids[1], s);
    case Expr::Kind::Sub: return number(e.kids[0], s) - number(e.kids[1], s);
    case Expr::Kind::Neg: return -number(e.kids[0], s);
    case Expr::Kind::Count: {
        smt::Term n = ctx_.intVal(0);
        for (int i = 0; i < engine_.region().size(); ++i) n = n + smt::ite(memberCounted(s, i, e), ctx_.intVal(1), ctx_.intVal(0));
        return smt::toReal(n);
    }
    default: throw InputError("internal: not a number expression");
    }
}

namespace {
smt::Term compareExprs(rules::CmpOp op, const smt::Term& a, const smt::Term& b) {
    switch (op) {
    case rules::CmpOp::Eq: return a == b;
    case rules::CmpOp::Ne: return a != b;
    case rules::CmpOp::Lt: return a < b;
    case rules::CmpOp::Le: return a <= b;
    case rules::CmpOp::Gt: return a > b;
    case rules::CmpOp::Ge: return a >= b;
    }
    return a == b;
}
}  // namespace

namespace {
/// l + sign * r, term by term.
std::optional<SmtEncoding::PerCell> difference(std::optional<SmtEncoding::PerCell> l, const std::optional<SmtEncoding::PerCell>& r, int sign) {
    if (!l || !r) return std::nullopt;
    for (std::size_t k = 0; k < l->term.size(); ++k) l->term[k] = l->term[k] + rules::Rational(sign) * r->term[k];
    l->constant = l->constant + rules::Rational(sign) * r->constant;
    return l;
}
}  // namespace

std::optional<SmtEncoding::PerCell> SmtEncoding::perCell(const Expr& e) const {
    const std::size_t size = static_cast<std::size_t>(engine_.comboCount() * alphabet_);
    auto each = [&](const std::function<rules::Rational(int, CellValue)>& value) {
        PerCell p{0, std::vector<rules::Rational>(size)};
        for (int c = 0; c < engine_.comboCount(); ++c)
            for (int v = 0; v < alphabet_; ++v) p.term[static_cast<std::size_t>(c * alphabet_ + v)] = value(c, static_cast<CellValue>(v));
        return p;
    };
    auto combine = [&](const Expr& a, const Expr& b, int sign) { return difference(perCell(a), perCell(b), sign); };
    switch (e.kind) {
    case Expr::Kind::Number: return PerCell{e.value, std::vector<rules::Rational>(size)};
    case Expr::Kind::Mass: {
        const auto den = static_cast<std::int64_t>(engine_.massDenominator());
        return each([&](int, CellValue v) { return rules::Rational(engine_.massUnitsOf(v), den); });
    }
    case Expr::Kind::Count:
        if (!e.kids.empty() || e.around != -1) return std::nullopt;  // a cell guard looks at neighbours
        return each([&](int c, CellValue v) { return rules::Rational(engine_.predicateAccepts(e.pred, c, v) ? 1 : 0); });
    case Expr::Kind::Add: return combine(e.kids[0], e.kids[1], 1);
    case Expr::Kind::Sub: return combine(e.kids[0], e.kids[1], -1);
    case Expr::Kind::Neg: return difference(PerCell{0, std::vector<rules::Rational>(size)}, perCell(e.kids[0]), -1);
    default: return std::nullopt;
    }
}

std::optional<smt::Term> SmtEncoding::cellwise(const Expr& e, const State& s) {
    // a op b as sum_i d(cell i) op c, with d = a - b per cell and c = b - a in constants, in integers.
    auto d = difference(perCell(e.kids[0]), perCell(e.kids[1]), -1);
    if (!d) return std::nullopt;
    std::int64_t scale = d->constant.den();
    for (const rules::Rational& t : d->term) scale = rules::checkedLcm(scale, t.den());
    auto integer = [&](rules::Rational r) { return (r * rules::Rational(scale)).num(); };
    std::vector<std::int64_t> term;
    for (const rules::Rational& t : d->term) term.push_back(integer(t));
    const std::int64_t c = -integer(d->constant);
    std::vector<std::int64_t> values(term.begin(), term.end());
    std::sort(values.begin(), values.end());
    values.erase(std::unique(values.begin(), values.end()), values.end());
    const int n = engine_.region().size();
    auto where = [&](int i, const std::function<bool(std::int64_t)>& ok) {
        return member(s, i, [&](int combo, CellValue v) { return ok(term[static_cast<std::size_t>(combo * alphabet_ + v)]); });
    };
    smt::Term sum = ctx_.intVal(0);
    std::vector<smt::Term> pos, neg;
    for (int i = 0; i < n; ++i) {
        for (std::int64_t w : values)
            if (w != 0) sum = sum + smt::ite(where(i, [w](std::int64_t t) { return t == w; }), ctx_.intVal(w), ctx_.intVal(0));
        pos.push_back(where(i, [](std::int64_t t) { return t > 0; }));
        neg.push_back(where(i, [](std::int64_t t) { return t < 0; }));
    }
    const smt::Term atom = compareExprs(e.op, sum, ctx_.intVal(c));
    // Sign lemmas: a sum at most 0 with a positive cell has a negative one, and so on. The solver
    // finds these pigeonhole facts only by trying every cell (Progress over general1: if the
    // mass fits the target and a metamodule lies outside it, some target cell is empty).
    // A cell is never both positive and negative (it has one state), so "a positive cell j has a
    // negative cell k != j" is "some positive cell -> some negative cell": linear in the cells. Each
    // j with its own disjunction over the others was quadratic, and cellwise runs once per
    // instance's successor under a constraint (progress under count(#) >= 1 on hex:r3: 6 s of
    // building for a 0.1 s proof).
    auto any = [&](const std::vector<smt::Term>& cells) { return smt::anyOf(ctx_, cells); };
    auto atMost = [&](std::int64_t bound) {  // sum <= bound
        if (bound > 0) return ctx_.boolVal(true);
        return bound < 0 ? any(neg) : smt::implies(any(pos), any(neg));  // below 0: some cell is negative
    };
    auto atLeast = [&](std::int64_t bound) {  // sum >= bound: the mirror image
        std::swap(pos, neg);
        smt::Term f = atMost(-bound);
        std::swap(pos, neg);
        return f;
    };
    auto signs = [&](rules::CmpOp op) {
        switch (op) {
        case rules::CmpOp::Eq: return atMost(c) && atLeast(c);
        case rules::CmpOp::Ne: return ctx_.boolVal(true);
        case rules::CmpOp::Lt: return atMost(c - 1);
        case rules::CmpOp::Le: return atMost(c);
        case rules::CmpOp::Gt: return atLeast(c + 1);
        case rules::CmpOp::Ge: return atLeast(c);
        }
        return ctx_.boolVal(true);
    };
    auto negated = [](rules::CmpOp op) {
        switch (op) {
        case rules::CmpOp::Eq: return rules::CmpOp::Ne;
        case rules::CmpOp::Ne: return rules::CmpOp::Eq;
        case rules::CmpOp::Lt: return rules::CmpOp::Ge;
        case rules::CmpOp::Le: return rules::CmpOp::Gt;
        case rules::CmpOp::Gt: return rules::CmpOp::Le;
        case rules::CmpOp::Ge: return rules::CmpOp::Lt;
        }
        return op;
    };
    signLemmas_.push_back(smt::implies(atom, signs(e.op)) && smt::implies(!atom, signs(negated(e.op))));
    return atom;
}

smt::Term SmtEncoding::holds(const Expr& e, const State& s, bool positive) {
    budget_.check("building the formulas");
    const int n = engine_.region().size();
    switch (e.kind) {
    case Expr::Kind::Bool: return ctx_.boolVal(e.value.num() != 0);
    case Expr::Kind::And: return holds(e.kids[0], s, positive) && holds(e.kids[1], s, positive);
    case Expr::Kind::Or: return holds(e.kids[0], s, positive) || holds(e.kids[1], s, positive);
    case Expr::Kind::Implies: return !holds(e.kids[0], s, !positive) || holds(e.kids[1], s, positive);
    case Expr::Kind::Not: return !holds(e.kids[0], s, !positive);
    case Expr::Kind::Compare:
        if (use_ == Use::Queries)
            if (auto f = cellwise(e, s)) return *f;
        return compareExprs(e.op, number(e.kids[0], s), number(e.kids[1], s));
    case Expr::Kind::Some:
    case Expr::Kind::No:
    case Expr::Kind::All: {
        // With a cell guard, all(T: G) asks every T cell to satisfy G; some/no count T cells where G holds.
        smt::Term any = ctx_.boolVal(false), all = ctx_.boolVal(true);
        for (int i = 0; i < n; ++i) {
            smt::Term m = memberCounted(s, i, e);
            any = any || m, all = all && (e.kids.empty() ? m : smt::implies(memberPred(s, i, e.pred), m));
        }
        return e.kind == Expr::Kind::Some ? any : e.kind == Expr::Kind::No ? !any
                                                                           : all;
    }
    case Expr::Kind::Connected: return connected(e.pred, s, positive);
    case Expr::Kind::Reaches: return reaches(e, s, positive);
    default: throw InputError("internal: not a condition");
    }
}

smt::Term SmtEncoding::cellCondition(const Expr& e, const State& s, int cell) {
    const smt::Term m = memberCounted(s, cell, e);
    if (e.kind == Expr::Kind::No) return !m;
    if (e.kind != Expr::Kind::All) throw InputError("internal: not a quantifier over cells");
    return e.kids.empty() ? m : smt::implies(memberPred(s, cell, e.pred), m);
}

smt::Term SmtEncoding::isCut(const std::vector<smt::Term>& members, const std::vector<smt::Term>& in) const {
    // A non-empty proper subset of the members, closed under adjacency among them.
    const rules::Region& region = engine_.region();
    smt::Term closed = ctx_.boolVal(true), inside = ctx_.boolVal(false), outside = ctx_.boolVal(false);
    for (int i = 0; i < region.size(); ++i) {
        closed = closed && smt::implies(in[i], members[i]);
        inside = inside || in[i];
        outside = outside || (members[i] && !in[i]);
        for (int d = 0; d < region.lattice().degree(); ++d)
            if (int j = region.neighbour(i, d); j >= 0) closed = closed && smt::implies(in[i] && members[j], in[j]);
    }
    return closed && inside && outside;
}

smt::Term SmtEncoding::isStray(const Reachability& r, const std::vector<smt::Term>& in) const {
    // A non-empty set of `from` cells, each stepping to no target and only into the set.
    const rules::Region& region = engine_.region();
    smt::Term f = ctx_.boolVal(true), some = ctx_.boolVal(false);
    for (int i = 0; i < region.size(); ++i) {
        some = some || in[i];
        smt::Term next = ctx_.boolVal(true);
        for (int d = 0; d < region.lattice().degree(); ++d) {
            const int j = region.neighbour(i, d);
            if (j < 0) continue;  // pointing out of the region is bad in itself
            next = next && smt::implies(r.steps[i][d], !r.to[j] && (!r.from[j] || in[j]));
        }
        f = f && smt::implies(in[i], r.from[i] && next);
    }
    return f && some;
}

std::vector<smt::Term> SmtEncoding::freshSet(const std::string& prefix, const std::vector<smt::Term>& members) {
    std::vector<smt::Term> in, rest;
    for (std::size_t i = 0; i < members.size(); ++i) {
        in.push_back(fresh(prefix, smt::Sort::Bool));
        rest.push_back(members[i] && !in.back());
    }
    refutationSets_.push_back(in);
    refutationSets_.push_back(rest);
    return in;
}

smt::Term SmtEncoding::hypothesis(const smt::Term& witness, Hypothesis h) {
    h.witness = witness;
    hypotheses_.push_back(h);
    return witness;
}

SmtEncoding::Lemmas SmtEncoding::instantiate() {
    // Connectivity of X means no cut of X exists at all; reachability, no stray set. The solver
    // would have to rediscover that from the ranks by a descent argument (the planner's Safety on
    // square:4x4 took 88 s, 74 s of it in `connected`), so each hypothesis is also stated for the
    // sets a proof is likely to need, restricted to the hypothesis' own cells: the sets the
    // refutations build and their complements (the cut of a successor, restricted to its
    // predecessor, is typically a cut there too), or, in a query without refutations, the cells
    // of the predicates it names in the same state (Progress: the F cells, inside a connected
    // target, have a neighbour in the target that is not F). Both together slowed Safety down.
    // Reachability restated for named predicates is what Progress on hex:r2 needs (a U next to
    // the tree) and what keeps it from finishing on cubic:3x3x3 (the P-leaf case drowns in stray
    // sets), so the caller gets the lemmas with and without that part.
    smt::Term kept = ctx_.boolVal(true), reach = ctx_.boolVal(true);
    bool differ = false;
    for (const Hypothesis& h : hypotheses_) {
        budget_.check("building the lemmas");
        std::vector<std::pair<const std::vector<smt::Term>*, bool>> sets;  // (set, a named predicate)
        for (const std::vector<smt::Term>& set : refutationSets_) sets.push_back({&set, false});
        for (const auto& [state, set] : predicateSets_)
            if (state == h.state && refutationSets_.empty()) sets.push_back({&set, true});
        const std::vector<smt::Term>& own = h.members;  // for reaches: the `from` cells
        for (const auto& [set, named] : sets) {
            std::vector<smt::Term> restricted;
            for (std::size_t i = 0; i < set->size(); ++i) restricted.push_back((*set)[i] && own[i]);
            const smt::Term lemma = smt::implies(h.witness, !(h.reach ? isStray(*h.reach, restricted) : isCut(h.members, restricted)));
            if (h.reach && named) reach = reach && lemma, differ = true;
            else kept = kept && lemma;
        }
    }
    for (const smt::Term& l : signLemmas_) kept = kept && l;
    signLemmas_.clear();
    hypotheses_.clear();
    refutationSets_.clear();
    predicateSets_.clear();
    return {kept && reach, differ ? kept : kept && reach, differ};
}

void SmtEncoding::candidate(const State& s, const std::vector<smt::Term>& members) {
    for (const auto& [state, set] : predicateSets_)
        if (state == s.is[0][0].id() && std::equal(set.begin(), set.end(), members.begin(), [](const smt::Term& a, const smt::Term& b) { return smt::same(a, b); }))
            return;
    predicateSets_.emplace_back(s.is[0][0].id(), members);
}

void SmtEncoding::leftSideSets(const State& s) {
    // A test is its acceptance table; shapes (rule and orientation) share most tests.
    const int combos = engine_.comboCount(), n = engine_.region().size();
    std::vector<std::vector<char>> seen;
    std::vector<char> shapeDone;
    for (int placed = 0; placed < static_cast<int>(engine_.instances().size()); ++placed) {
        const rules::Engine::Placed& p = engine_.instances()[placed];
        if (p.shape >= static_cast<int>(shapeDone.size())) shapeDone.resize(p.shape + 1, 0);
        if (shapeDone[p.shape]) continue;
        shapeDone[p.shape] = 1;
        for (int k = 0; k < p.size; ++k) {
            std::vector<char> table;
            for (int c = 0; c < combos; ++c)
                for (int v = 0; v < alphabet_; ++v) table.push_back(engine_.lhsAccepts(placed, k, c, static_cast<CellValue>(v)));
            if (std::find(seen.begin(), seen.end(), table) != seen.end()) continue;
            seen.push_back(table);
            std::vector<smt::Term> cells;
            for (int i = 0; i < n; ++i)
                cells.push_back(member(s, i, [&](int c, CellValue v) { return table[static_cast<std::size_t>(c * alphabet_ + v)] != 0; }));
            candidate(s, cells);
        }
    }
}

smt::Term SmtEncoding::connected(const rules::CellPredicate& pred, const State& s, bool positive) {
    const rules::Region& region = engine_.region();
    const int n = region.size();
    std::vector<smt::Term> m;
    for (int i = 0; i < n; ++i) m.push_back(memberPred(s, i, pred));
    candidate(s, m);
    if (!positive) return !isCut(m, freshSet("cut", m));
    // One root among the members; every other member has a member neighbour of lower rank.
    smt::Term f = ctx_.boolVal(true), someMember = ctx_.boolVal(false), someRoot = ctx_.boolVal(false);
    smt::Term roots = ctx_.intVal(0);
    std::vector<smt::Term> rank, root;
    for (int i = 0; i < n; ++i) {
        rank.push_back(fresh("rank", smt::Sort::Int)), root.push_back(fresh("root", smt::Sort::Bool));
        facts_.push_back(rank.back() >= 0 && rank.back() < n);  // bounded ranks help the solver
    }
    for (int i = 0; i < n; ++i) {
        someMember = someMember || m[i];
        someRoot = someRoot || root[i];
        roots = roots + smt::ite(root[i], ctx_.intVal(1), ctx_.intVal(0));
        f = f && smt::implies(root[i], m[i]);
        smt::Term down = ctx_.boolVal(false);
        for (int d = 0; d < region.lattice().degree(); ++d)
            if (int j = region.neighbour(i, d); j >= 0) down = down || (m[j] && rank[j] < rank[i]);
        f = f && smt::implies(m[i] && !root[i], down);
    }
    return hypothesis(f && smt::implies(someMember, someRoot) && roots <= 1, {m, std::nullopt, ctx_.boolVal(true), s.is[0][0].id()});
}

smt::Term SmtEncoding::reaches(const Expr& e, const State& s, bool positive) {
    const rules::Region& region = engine_.region();
    const rules::Alphabet& alphabet = engine_.model().alphabet();
    const int n = region.size(), degree = region.lattice().degree();
    Reachability r;
    for (int i = 0; i < n; ++i) {
        r.from.push_back(memberPred(s, i, e.pred)), r.to.push_back(memberPred(s, i, e.target));
        // A step from i in direction d is possible: along the pointer, or to any neighbour (`nbr`).
        std::vector<smt::Term> steps;
        for (int d = 0; d < degree; ++d)
            steps.push_back(e.field < 0 ? ctx_.boolVal(true)
                                        : member(s, i, [&](int, CellValue v) { return v != 0 && alphabet.fields(v)[e.field] == d; }));
        r.steps.push_back(steps);
    }
    candidate(s, r.from), candidate(s, r.to);
    if (!positive) return !isStray(r, freshSet("stray", r.from));
    // Ranks fall along pointers (or adjacency) until a target cell.
    std::vector<smt::Term> rank;
    for (int i = 0; i < n; ++i) {
        rank.push_back(fresh("prank", smt::Sort::Int));
        facts_.push_back(rank.back() >= 0 && rank.back() < n);
    }
    // The witness also names the lowest and the highest rank among the `from` cells, which every
    // rank assignment has: a cell of lowest rank steps straight to a target cell, and nothing steps
    // onto a cell of highest rank (a P leaf, in the planner's Progress argument). Without them the
    // solver finds these extremes by descent through the ranks.
    std::optional<smt::Term> lowest, highest;
    if (use_ == Use::Queries) lowest = fresh("prank_low", smt::Sort::Int), highest = fresh("prank_high", smt::Sort::Int);
    smt::Term f = ctx_.boolVal(true), some = ctx_.boolVal(false), atLowest = ctx_.boolVal(false), atHighest = ctx_.boolVal(false);
    for (int i = 0; i < n; ++i) {
        smt::Term ok = ctx_.boolVal(false);
        for (int d = 0; d < degree; ++d) {
            const int j = region.neighbour(i, d);
            if (j < 0) continue;
            ok = ok || (r.steps[i][d] && (r.to[j] || (r.from[j] && rank[j] < rank[i])));
        }
        if (use_ != Use::Queries) {
            f = f && smt::implies(r.from[i], ok);
            continue;
        }
        f = f && smt::implies(r.from[i], ok && *lowest <= rank[i] && rank[i] <= *highest);
        some = some || r.from[i];
        atLowest = atLowest || (r.from[i] && rank[i] == *lowest);
        atHighest = atHighest || (r.from[i] && rank[i] == *highest);
    }
    if (use_ == Use::Queries) f = f && smt::implies(some, atLowest && atHighest);
    return hypothesis(f, {r.from, r, ctx_.boolVal(true), s.is[0][0].id()});
}

smt::Term SmtEncoding::legal(const State& s, bool positive) {
    smt::Term all = ctx_.boolVal(true);
    for (const rules::Constraint& c : engine_.model().system().constraints) all = all && holds(c.expr, s, positive);
    return all;
}

SmtEncoding::State SmtEncoding::successor(int placed, const State& s) const {
    State t = s;
    const auto& p = engine_.instances()[placed];
    for (int k = 0; k < p.size; ++k) {
        const int cell = p.cells[k], copy = engine_.rhsCopyFrom(placed, k);
        if (copy >= 0) {
            t.is[cell] = s.is[p.cells[copy]];
            continue;
        }
        for (int w = 0; w < alphabet_; ++w) {
            smt::Term becomes = ctx_.boolVal(false);
            for (int v = 0; v < alphabet_; ++v)
                if (engine_.rhsValue(placed, k, static_cast<CellValue>(v)) == w) becomes = becomes || s.is[cell][v];
            t.is[cell][w] = becomes;
        }
    }
    return t;
}

std::vector<smt::Term> SmtEncoding::acceptedSites(const rules::Engine::GuardNode& g, const std::int32_t* cells, const State& s) {
    std::vector<smt::Term> out;
    for (int d = 0; d < static_cast<int>(g.perSite.size()); ++d) {
        const int cell = g.around >= 0 ? engine_.region().neighbour(cells[g.around], d) : cells[d];
        out.push_back(member(s, cell, [&](int c, CellValue v) { return engine_.guardAccepts(g, d, c, v); }));
    }
    return out;
}

smt::Term SmtEncoding::guardNumber(const rules::Engine::GuardNode& g, const std::int32_t* cells, const State& s) {
    switch (g.kind) {
    case Expr::Kind::Number: return ctx_.realVal(static_cast<int64_t>(g.value.num()), static_cast<int64_t>(g.value.den()));
    case Expr::Kind::Add: return guardNumber(g.kids[0], cells, s) + guardNumber(g.kids[1], cells, s);
    case Expr::Kind::Sub: return guardNumber(g.kids[0], cells, s) - guardNumber(g.kids[1], cells, s);
    case Expr::Kind::Neg: return -guardNumber(g.kids[0], cells, s);
    case Expr::Kind::Count: {
        smt::Term count = ctx_.intVal(0);
        for (const smt::Term& accepted : acceptedSites(g, cells, s)) count = count + smt::ite(accepted, ctx_.intVal(1), ctx_.intVal(0));
        return smt::toReal(count);
    }
    default: throw InputError("internal: not a guard number");
    }
}

smt::Term SmtEncoding::guard(const rules::Engine::GuardNode& g, const std::int32_t* cells, const State& s) {
    switch (g.kind) {
    case Expr::Kind::Bool: return ctx_.boolVal(g.value.num() != 0);
    case Expr::Kind::And: return guard(g.kids[0], cells, s) && guard(g.kids[1], cells, s);
    case Expr::Kind::Or: return guard(g.kids[0], cells, s) || guard(g.kids[1], cells, s);
    case Expr::Kind::Implies: return !guard(g.kids[0], cells, s) || guard(g.kids[1], cells, s);
    case Expr::Kind::Not: return !guard(g.kids[0], cells, s);
    case Expr::Kind::Compare: return compareExprs(g.op, guardNumber(g.kids[0], cells, s), guardNumber(g.kids[1], cells, s));
    case Expr::Kind::Some:
    case Expr::Kind::No:
    case Expr::Kind::All: {
        rules::Engine::GuardNode count = g;
        count.kind = Expr::Kind::Count;
        smt::Term c = guardNumber(count, cells, s);
        const int sites = static_cast<int>(g.perSite.size());
        return g.kind == Expr::Kind::Some ? c > 0 : g.kind == Expr::Kind::No ? c == 0
                                                                             : c == sites;
    }
    case Expr::Kind::Connected: {
        // The accepted neighbours form a connected set: one of the (at most 2^6) connected sets.
        const int degree = static_cast<int>(g.perSite.size());
        const std::vector<smt::Term> accepted = acceptedSites(g, cells, s);
        smt::Term any = ctx_.boolVal(false);
        for (std::uint32_t set = 0; set < (1u << degree); ++set) {
            if (!engine_.tables().directionsConnected(set)) continue;
            smt::Term exactly = ctx_.boolVal(true);
            for (int d = 0; d < degree; ++d) exactly = exactly && ((set >> d) & 1u ? accepted[d] : !accepted[d]);
            any = any || exactly;
        }
        return any;
    }
    default: throw InputError("internal: not a guard condition");
    }
}

smt::Term SmtEncoding::matches(int placed, const State& s) {
    budget_.check("building the formulas");
    const auto& p = engine_.instances()[placed];
    smt::Term all = ctx_.boolVal(true);
    for (int k = 0; k < p.size; ++k)
        all = all && member(s, p.cells[k], [&](int c, CellValue v) { return engine_.lhsAccepts(placed, k, c, v); });
    if (const auto* g = engine_.guardOf(placed)) all = all && guard(*g, engine_.instances()[placed].cells, s);
    return all;
}

smt::Term SmtEncoding::rewritten(int placed, int k, const State& before, int fromCell, const State& after, int toCell) const {
    // One implication per old state: that state's rewrite is the new state.
    smt::Term all = ctx_.boolVal(true);
    for (int v = 0; v < alphabet_; ++v) {
        const int w = engine_.rhsValue(placed, k, static_cast<CellValue>(v));
        all = all && smt::implies(before.is[fromCell][v], after.is[toCell][w]);
    }
    return all;
}

smt::Term SmtEncoding::fires(int placed, const State& from, const State& to) {
    const auto& p = engine_.instances()[placed];
    smt::Term f = matches(placed, from);
    std::vector<char> touched(from.is.size(), 0);
    for (int k = 0; k < p.size; ++k) {
        touched[p.cells[k]] = 1;
        const int copy = engine_.rhsCopyFrom(placed, k);
        f = f && (copy >= 0 ? sameCell(from, p.cells[copy], to, p.cells[k]) : rewritten(placed, k, from, p.cells[k], to, p.cells[k]));
    }
    for (std::size_t i = 0; i < from.is.size(); ++i)
        if (!touched[i]) f = f && sameCell(from, static_cast<int>(i), to, static_cast<int>(i));
    return f;
}

smt::Term SmtEncoding::step(const State& from, const State& to, const smt::Term& selector) {
    // The selected instance matches and rewrites its cells; a cell no selected instance touches
    // keeps its state.
    const int count = static_cast<int>(engine_.instances().size());
    smt::Term f = selector >= 0 && selector < count;
    std::vector<smt::Term> touchedBy(from.is.size(), ctx_.boolVal(false));
    for (int placed = 0; placed < count; ++placed) {
        const auto& p = engine_.instances()[placed];
        smt::Term body = matches(placed, from);
        for (int k = 0; k < p.size; ++k) {
            const int copy = engine_.rhsCopyFrom(placed, k);
            body = body && (copy >= 0 ? sameCell(from, p.cells[copy], to, p.cells[k]) : rewritten(placed, k, from, p.cells[k], to, p.cells[k]));
            touchedBy[p.cells[k]] = touchedBy[p.cells[k]] || selector == placed;
        }
        f = f && smt::implies(selector == placed, body);
    }
    for (std::size_t i = 0; i < from.is.size(); ++i) f = f && (touchedBy[i] || sameCell(from, static_cast<int>(i), to, static_cast<int>(i)));
    return f && legal(to);
}

smt::Term SmtEncoding::delta(const Expr& e, int placed, const State& after, const State& before) {
    const auto& p = engine_.instances()[placed];
    switch (e.kind) {
    case Expr::Kind::Number: return ctx_.realVal(0);
    case Expr::Kind::Add: return delta(e.kids[0], placed, after, before) + delta(e.kids[1], placed, after, before);
    case Expr::Kind::Sub: return delta(e.kids[0], placed, after, before) - delta(e.kids[1], placed, after, before);
    case Expr::Kind::Neg: return -delta(e.kids[0], placed, after, before);
    case Expr::Kind::Count: {
        // A cell guard reads neighbours, so a rewrite changes counts beyond its own cells.
        if (!e.kids.empty()) return number(e, after) - number(e, before);
        smt::Term d = ctx_.intVal(0);
        for (int k = 0; k < p.size; ++k)
            d = d + smt::ite(memberPred(after, p.cells[k], e.pred), ctx_.intVal(1), ctx_.intVal(0)) -
                smt::ite(memberPred(before, p.cells[k], e.pred), ctx_.intVal(1), ctx_.intVal(0));
        return smt::toReal(d);
    }
    case Expr::Kind::Mass: {
        smt::Term d = ctx_.intVal(0);
        for (int k = 0; k < p.size; ++k) d = d + cellMassUnits(after, p.cells[k]) - cellMassUnits(before, p.cells[k]);
        return smt::toReal(d) / ctx_.realVal(static_cast<int64_t>(engine_.massDenominator()));
    }
    default: throw InputError("internal: not a number expression");
    }
}

smt::Term SmtEncoding::lexLessAfter(const std::vector<Expr>& ranking, int placed, const State& after, const State& before) {
    smt::Term less = ctx_.boolVal(false);
    for (int k = static_cast<int>(ranking.size()) - 1; k >= 0; --k) {
        smt::Term d = delta(ranking[k], placed, after, before);
        less = d < 0 || (d == 0 && less);
    }
    return less;
}

smt::Term SmtEncoding::keptAfter(const std::vector<Expr>& ranking, int placed, const State& after, const State& before) {
    smt::Term same = ctx_.boolVal(true);
    for (const Expr& component : ranking) same = same && delta(component, placed, after, before) == 0;
    return same;
}

smt::Term SmtEncoding::rankingBroken(const rules::Property& r, int placed, const State& after, const State& before) {
    const int shape = engine_.instances()[placed].shape;
    const bool excepted = engine_.model().shapeRule(shape, r.except, true) >= 0, covered = engine_.model().shapeRule(shape, r.except, false) >= 0;
    if (!covered) return !keptAfter(r.exprs, placed, after, before);
    if (!excepted) return !lexLessAfter(r.exprs, placed, after, before);
    return !keptAfter(r.exprs, placed, after, before) || !lexLessAfter(r.exprs, placed, after, before);
}

std::vector<CellValue> SmtEncoding::decode(const smt::Model& m, const State& s) const {
    std::vector<CellValue> cells;
    for (const auto& row : s.is) {
        CellValue value = 0;
        for (int v = 0; v < alphabet_; ++v)
            if (m.isTrue(row[v])) value = static_cast<CellValue>(v);
        cells.push_back(value);
    }
    return cells;
}

}  // namespace holon::checker
