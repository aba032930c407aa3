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

SmtEncoding::SmtEncoding(z3::context& ctx, const rules::Engine& engine, Use use, Budget budget)
    : ctx_(ctx), engine_(engine), alphabet_(engine.model().alphabet().size()), use_(use), budget_(budget) {
    const int inputs = static_cast<int>(engine.model().system().inputs.size());
    for (int i = 0; i < engine.region().size(); ++i) {
        std::vector<z3::expr> bits;
        for (int k = 0; k < inputs; ++k)
            bits.push_back(ctx_.bool_const(("in_" + engine.model().system().inputs[k] + "_" + std::to_string(i)).c_str()));
        inputBits_.push_back(bits);
    }
    // Many inputs (roombots_reserve's eight walks) and every combination of them: acceptance()
    // expands on the input bits. With one or two inputs the disjunction over combinations is
    // short, and Spacer's strengthenings were found on that form (general2 Progress@reach: 1.5 s).
    const std::uint32_t all = std::uint32_t{1} << inputs;
    for (std::uint32_t b = 0; b < all && inputs >= 3 && inputs <= 16; ++b) comboOfBits_.push_back(engine.tables().comboIndex(b));
    if (std::find(comboOfBits_.begin(), comboOfBits_.end(), -1) != comboOfBits_.end()) comboOfBits_.clear();
}

z3::expr SmtEncoding::fresh(const std::string& prefix, const z3::sort& sort) {
    return ctx_.constant((prefix + "_" + std::to_string(counter_++)).c_str(), sort);
}

SmtEncoding::State SmtEncoding::state(const std::string& name) {
    budget_.check("building the formulas");
    State s;
    for (int i = 0; i < engine_.region().size(); ++i) {
        std::vector<z3::expr> row;
        z3::expr some = ctx_.bool_val(false);
        for (int v = 0; v < alphabet_; ++v) {
            row.push_back(ctx_.bool_const((name + "_" + std::to_string(i) + "_" + std::to_string(v)).c_str()));
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

z3::expr SmtEncoding::sameCell(const State& a, int i, const State& b, int j) const {
    z3::expr all = ctx_.bool_val(true);
    for (int v = 0; v < alphabet_; ++v) all = all && a.is[i][v] == b.is[j][v];
    return all;
}

z3::expr SmtEncoding::inputsAre(const std::vector<std::uint32_t>& inputs) const {
    z3::expr all = ctx_.bool_val(true);
    for (std::size_t i = 0; i < inputBits_.size(); ++i)
        for (std::size_t k = 0; k < inputBits_[i].size(); ++k) all = all && (((inputs[i] >> k) & 1u) ? inputBits_[i][k] : !inputBits_[i][k]);
    return all;
}

z3::expr SmtEncoding::configurationIs(const State& s, const std::vector<CellValue>& cells) const {
    z3::expr all = ctx_.bool_val(true);
    for (std::size_t i = 0; i < cells.size(); ++i) all = all && s.is[i][cells[i]];
    return all;
}

z3::expr SmtEncoding::inputCombo(int cell, int combo) const {
    const std::uint32_t bits = engine_.comboInputs(combo);
    z3::expr all = ctx_.bool_val(true);
    for (std::size_t k = 0; k < inputBits_[cell].size(); ++k) all = all && (((bits >> k) & 1u) ? inputBits_[cell][k] : !inputBits_[cell][k]);
    return all;
}

std::vector<std::pair<int, z3::expr>> SmtEncoding::acceptance(int cell, const std::function<bool(int, CellValue)>& accepts) {
    std::vector<std::pair<int, z3::expr>> out;
    const int combos = engine_.comboCount();
    for (int v = 0; v < alphabet_; ++v) {
        std::vector<int> yes;
        for (int c = 0; c < combos; ++c)
            if (accepts(c, static_cast<CellValue>(v))) yes.push_back(c);
        if (yes.empty()) continue;
        if (static_cast<int>(yes.size()) == combos) {
            out.push_back({v, ctx_.bool_val(true)});
            continue;
        }
        if (comboOfBits_.empty()) {  // some combinations only: one conjunction of input literals each
            z3::expr when = ctx_.bool_val(false);
            for (int c : yes) when = when || inputCombo(cell, c);
            out.push_back({v, when});
            continue;
        }
        // Every combination: Shannon expansion on the input bits, so that a condition on two
        // inputs reads `a and b`, not a disjunction over the 2^k combinations (8 inputs: 64 of them).
        std::vector<char> accepted(comboOfBits_.size());
        for (std::size_t b = 0; b < comboOfBits_.size(); ++b) accepted[b] = std::find(yes.begin(), yes.end(), comboOfBits_[b]) != yes.end();
        std::function<z3::expr(int, std::uint32_t)> expand = [&](int k, std::uint32_t bits) -> z3::expr {
            if (k < 0) return ctx_.bool_val(accepted[bits] != 0);
            const z3::expr off = expand(k - 1, bits), on = expand(k - 1, bits | (std::uint32_t{1} << k));
            if (z3::eq(off, on)) return off;
            return ((inputBits_[cell][k] && on) || (!inputBits_[cell][k] && off)).simplify();
        };
        out.push_back({v, expand(static_cast<int>(inputBits_[cell].size()) - 1, 0)});
    }
    return out;
}

z3::expr SmtEncoding::member(const State& s, int cell, const std::function<bool(int, CellValue)>& accepts) {
    // A cell outside the region (cell < 0) is empty with no inputs.
    if (cell < 0) return ctx_.bool_val(accepts(0, 0));
    return inStateWhen(s, cell, acceptance(cell, accepts));
}

z3::expr SmtEncoding::memberPred(const State& s, int cell, const rules::CellPredicate& pred) {
    if (cell < 0) return ctx_.bool_val(engine_.predicateAccepts(pred, 0, 0));
    auto it = predicateAcceptance_.find({&pred, cell});
    if (it == predicateAcceptance_.end())
        it = predicateAcceptance_.emplace(std::make_pair(&pred, cell), acceptance(cell, [&](int c, CellValue v) { return engine_.predicateAccepts(pred, c, v); })).first;
    return inStateWhen(s, cell, it->second);
}

z3::expr SmtEncoding::inStateWhen(const State& s, int cell, const std::vector<std::pair<int, z3::expr>>& accepted) const {
    z3::expr any = ctx_.bool_val(false);
    for (const auto& [v, when] : accepted) any = any || (s.is[cell][v] && when);
    return any.simplify();
}

z3::expr SmtEncoding::memberCounted(const State& s, std::int32_t cell, const Expr& quantifier) {
    z3::expr m = memberPred(s, cell, quantifier.pred);
    return quantifier.kids.empty() ? m : m && guard(engine_.cellGuardOf(quantifier), &cell, s);
}

z3::expr SmtEncoding::cellMassUnits(const State& s, int cell) const {
    // One term per distinct mass, not per state: a planner over general-lock has 91 states and 4
    // masses, and a sum of 91 if-then-elses per cell made a one-step mass-conservation query take
    // 10 s (32 s for general-lock3) where this takes well under one.
    std::map<std::int64_t, z3::expr> byMass;
    for (int v = 0; v < alphabet_; ++v)
        if (const std::int64_t m = engine_.massUnitsOf(static_cast<CellValue>(v))) {
            auto [at, fresh] = byMass.try_emplace(m, s.is[cell][v]);
            if (!fresh) at->second = at->second || s.is[cell][v];
        }
    z3::expr total = ctx_.int_val(0);
    for (const auto& [m, any] : byMass) total = total + z3::ite(any, ctx_.int_val(static_cast<int64_t>(m)), ctx_.int_val(0));
    return total;
}

z3::expr SmtEncoding::massUnits(const State& s) {
    z3::expr total = ctx_.int_val(0);
    for (std::size_t i = 0; i < s.is.size(); ++i) total = total + cellMassUnits(s, static_cast<int>(i));
    return total;
}

z3::expr SmtEncoding::number(const Expr& e, const State& s) {
    switch (e.kind) {
    case Expr::Kind::Number: return ctx_.real_val(static_cast<int64_t>(e.value.num()), static_cast<int64_t>(e.value.den()));
    case Expr::Kind::Mass: return z3::to_real(massUnits(s)) / ctx_.real_val(static_cast<int64_t>(engine_.massDenominator()));
    case Expr::Kind::Add: return number(e.kids[0], s) + number(e.kids[1], s);
    case Expr::Kind::Sub: return number(e.kids[0], s) - number(e.kids[1], s);
    case Expr::Kind::Neg: return -number(e.kids[0], s);
    case Expr::Kind::Count: {
        z3::expr n = ctx_.int_val(0);
        for (int i = 0; i < engine_.region().size(); ++i) n = n + z3::ite(memberCounted(s, i, e), ctx_.int_val(1), ctx_.int_val(0));
        return z3::to_real(n);
    }
    default: throw InputError("internal: not a number expression");
    }
}

namespace {
z3::expr compareExprs(rules::CmpOp op, const z3::expr& a, const z3::expr& b) {
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

std::optional<z3::expr> SmtEncoding::cellwise(const Expr& e, const State& s) {
    // a op b as sum_i d(cell i) op c, with d = a - b per cell and c = b - a in constants, in integers.
    auto d = difference(perCell(e.kids[0]), perCell(e.kids[1]), -1);
    if (!d) return std::nullopt;
    std::int64_t scale = d->constant.den();
    for (const rules::Rational& t : d->term) scale = std::lcm(scale, t.den());
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
    z3::expr sum = ctx_.int_val(0);
    std::vector<z3::expr> pos, neg;
    for (int i = 0; i < n; ++i) {
        for (std::int64_t w : values)
            if (w != 0) sum = sum + z3::ite(where(i, [w](std::int64_t t) { return t == w; }), ctx_.int_val(w), ctx_.int_val(0));
        pos.push_back(where(i, [](std::int64_t t) { return t > 0; }));
        neg.push_back(where(i, [](std::int64_t t) { return t < 0; }));
    }
    const z3::expr atom = compareExprs(e.op, sum, ctx_.int_val(c));
    // Sign lemmas: a sum at most 0 with a positive cell has a negative one, and so on. The solver
    // finds these pigeonhole facts only by trying every cell (Progress over general1: if the
    // mass fits the target and a metamodule lies outside it, some target cell is empty).
    auto atMost = [&](std::int64_t bound) {  // sum <= bound
        z3::expr f = ctx_.bool_val(true);
        if (bound > 0) return f;
        for (int j = 0; j < n; ++j) {
            z3::expr other = ctx_.bool_val(false);
            for (int k = 0; k < n; ++k)
                if (k != j) other = other || neg[k];
            f = f && z3::implies(pos[j], other);
        }
        if (bound < 0) {
            z3::expr any = ctx_.bool_val(false);
            for (int k = 0; k < n; ++k) any = any || neg[k];
            f = f && any;
        }
        return f;
    };
    auto atLeast = [&](std::int64_t bound) {  // sum >= bound: the mirror image
        std::swap(pos, neg);
        z3::expr f = atMost(-bound);
        std::swap(pos, neg);
        return f;
    };
    auto signs = [&](rules::CmpOp op) {
        switch (op) {
        case rules::CmpOp::Eq: return atMost(c) && atLeast(c);
        case rules::CmpOp::Ne: return ctx_.bool_val(true);
        case rules::CmpOp::Lt: return atMost(c - 1);
        case rules::CmpOp::Le: return atMost(c);
        case rules::CmpOp::Gt: return atLeast(c + 1);
        case rules::CmpOp::Ge: return atLeast(c);
        }
        return ctx_.bool_val(true);
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
    signLemmas_.push_back(z3::implies(atom, signs(e.op)) && z3::implies(!atom, signs(negated(e.op))));
    return atom;
}

z3::expr SmtEncoding::holds(const Expr& e, const State& s, bool positive) {
    budget_.check("building the formulas");
    const int n = engine_.region().size();
    switch (e.kind) {
    case Expr::Kind::Bool: return ctx_.bool_val(e.value.num() != 0);
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
        z3::expr any = ctx_.bool_val(false), all = ctx_.bool_val(true);
        for (int i = 0; i < n; ++i) {
            z3::expr m = memberCounted(s, i, e);
            any = any || m, all = all && (e.kids.empty() ? m : z3::implies(memberPred(s, i, e.pred), m));
        }
        return e.kind == Expr::Kind::Some ? any : e.kind == Expr::Kind::No ? !any : all;
    }
    case Expr::Kind::Connected: return connected(e.pred, s, positive);
    case Expr::Kind::Reaches: return reaches(e, s, positive);
    default: throw InputError("internal: not a condition");
    }
}

z3::expr SmtEncoding::isCut(const std::vector<z3::expr>& members, const std::vector<z3::expr>& in) const {
    // A non-empty proper subset of the members, closed under adjacency among them.
    const rules::Region& region = engine_.region();
    z3::expr closed = ctx_.bool_val(true), inside = ctx_.bool_val(false), outside = ctx_.bool_val(false);
    for (int i = 0; i < region.size(); ++i) {
        closed = closed && z3::implies(in[i], members[i]);
        inside = inside || in[i];
        outside = outside || (members[i] && !in[i]);
        for (int d = 0; d < region.lattice().degree(); ++d)
            if (int j = region.neighbour(i, d); j >= 0) closed = closed && z3::implies(in[i] && members[j], in[j]);
    }
    return closed && inside && outside;
}

z3::expr SmtEncoding::isStray(const Reachability& r, const std::vector<z3::expr>& in) const {
    // A non-empty set of `from` cells, each stepping to no target and only into the set.
    const rules::Region& region = engine_.region();
    z3::expr f = ctx_.bool_val(true), some = ctx_.bool_val(false);
    for (int i = 0; i < region.size(); ++i) {
        some = some || in[i];
        z3::expr next = ctx_.bool_val(true);
        for (int d = 0; d < region.lattice().degree(); ++d) {
            const int j = region.neighbour(i, d);
            if (j < 0) continue;  // pointing out of the region is bad in itself
            next = next && z3::implies(r.steps[i][d], !r.to[j] && (!r.from[j] || in[j]));
        }
        f = f && z3::implies(in[i], r.from[i] && next);
    }
    return f && some;
}

std::vector<z3::expr> SmtEncoding::freshSet(const std::string& prefix, const std::vector<z3::expr>& members) {
    std::vector<z3::expr> in, rest;
    for (std::size_t i = 0; i < members.size(); ++i) {
        in.push_back(fresh(prefix, ctx_.bool_sort()));
        rest.push_back(members[i] && !in.back());
    }
    refutationSets_.push_back(in);
    refutationSets_.push_back(rest);
    return in;
}

z3::expr SmtEncoding::hypothesis(const z3::expr& witness, Hypothesis h) {
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
    z3::expr kept = ctx_.bool_val(true), reach = ctx_.bool_val(true);
    bool differ = false;
    for (const Hypothesis& h : hypotheses_) {
        budget_.check("building the lemmas");
        std::vector<std::pair<const std::vector<z3::expr>*, bool>> sets;  // (set, a named predicate)
        for (const std::vector<z3::expr>& set : refutationSets_) sets.push_back({&set, false});
        for (const auto& [state, set] : predicateSets_)
            if (state == h.state && refutationSets_.empty()) sets.push_back({&set, true});
        const std::vector<z3::expr>& own = h.members;  // for reaches: the `from` cells
        for (const auto& [set, named] : sets) {
            std::vector<z3::expr> restricted;
            for (std::size_t i = 0; i < set->size(); ++i) restricted.push_back((*set)[i] && own[i]);
            const z3::expr lemma = z3::implies(h.witness, !(h.reach ? isStray(*h.reach, restricted) : isCut(h.members, restricted)));
            if (h.reach && named) reach = reach && lemma, differ = true;
            else kept = kept && lemma;
        }
    }
    for (const z3::expr& l : signLemmas_) kept = kept && l;
    signLemmas_.clear();
    hypotheses_.clear();
    refutationSets_.clear();
    predicateSets_.clear();
    return {kept && reach, differ ? kept : kept && reach, differ};
}

void SmtEncoding::candidate(const State& s, const std::vector<z3::expr>& members) {
    for (const auto& [state, set] : predicateSets_)
        if (state == s.is[0][0].id() && std::equal(set.begin(), set.end(), members.begin(), [](const z3::expr& a, const z3::expr& b) { return z3::eq(a, b); }))
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
            std::vector<z3::expr> cells;
            for (int i = 0; i < n; ++i)
                cells.push_back(member(s, i, [&](int c, CellValue v) { return table[static_cast<std::size_t>(c * alphabet_ + v)] != 0; }));
            candidate(s, cells);
        }
    }
}

z3::expr SmtEncoding::connected(const rules::CellPredicate& pred, const State& s, bool positive) {
    const rules::Region& region = engine_.region();
    const int n = region.size();
    std::vector<z3::expr> m;
    for (int i = 0; i < n; ++i) m.push_back(memberPred(s, i, pred));
    candidate(s, m);
    if (!positive) return !isCut(m, freshSet("cut", m));
    // One root among the members; every other member has a member neighbour of lower rank.
    z3::expr f = ctx_.bool_val(true), someMember = ctx_.bool_val(false), someRoot = ctx_.bool_val(false);
    z3::expr roots = ctx_.int_val(0);
    std::vector<z3::expr> rank, root;
    for (int i = 0; i < n; ++i) {
        rank.push_back(fresh("rank", ctx_.int_sort())), root.push_back(fresh("root", ctx_.bool_sort()));
        facts_.push_back(rank.back() >= 0 && rank.back() < n);  // bounded ranks help the solver
    }
    for (int i = 0; i < n; ++i) {
        someMember = someMember || m[i];
        someRoot = someRoot || root[i];
        roots = roots + z3::ite(root[i], ctx_.int_val(1), ctx_.int_val(0));
        f = f && z3::implies(root[i], m[i]);
        z3::expr down = ctx_.bool_val(false);
        for (int d = 0; d < region.lattice().degree(); ++d)
            if (int j = region.neighbour(i, d); j >= 0) down = down || (m[j] && rank[j] < rank[i]);
        f = f && z3::implies(m[i] && !root[i], down);
    }
    return hypothesis(f && z3::implies(someMember, someRoot) && roots <= 1, {m, std::nullopt, ctx_.bool_val(true), s.is[0][0].id()});
}

z3::expr SmtEncoding::reaches(const Expr& e, const State& s, bool positive) {
    const rules::Region& region = engine_.region();
    const rules::Alphabet& alphabet = engine_.model().alphabet();
    const int n = region.size(), degree = region.lattice().degree();
    Reachability r;
    for (int i = 0; i < n; ++i) {
        r.from.push_back(memberPred(s, i, e.pred)), r.to.push_back(memberPred(s, i, e.target));
        // A step from i in direction d is possible: along the pointer, or to any neighbour (`nbr`).
        std::vector<z3::expr> steps;
        for (int d = 0; d < degree; ++d)
            steps.push_back(e.field < 0 ? ctx_.bool_val(true)
                                        : member(s, i, [&](int, CellValue v) { return v != 0 && alphabet.fields(v)[e.field] == d; }));
        r.steps.push_back(steps);
    }
    candidate(s, r.from), candidate(s, r.to);
    if (!positive) return !isStray(r, freshSet("stray", r.from));
    // Ranks fall along pointers (or adjacency) until a target cell.
    std::vector<z3::expr> rank;
    for (int i = 0; i < n; ++i) {
        rank.push_back(fresh("prank", ctx_.int_sort()));
        facts_.push_back(rank.back() >= 0 && rank.back() < n);
    }
    // The witness also names the lowest and the highest rank among the `from` cells, which every
    // rank assignment has: a cell of lowest rank steps straight to a target cell, and nothing steps
    // onto a cell of highest rank (a P leaf, in the planner's Progress argument). Without them the
    // solver finds these extremes by descent through the ranks.
    std::optional<z3::expr> lowest, highest;
    if (use_ == Use::Queries) lowest = fresh("prank_low", ctx_.int_sort()), highest = fresh("prank_high", ctx_.int_sort());
    z3::expr f = ctx_.bool_val(true), some = ctx_.bool_val(false), atLowest = ctx_.bool_val(false), atHighest = ctx_.bool_val(false);
    for (int i = 0; i < n; ++i) {
        z3::expr ok = ctx_.bool_val(false);
        for (int d = 0; d < degree; ++d) {
            const int j = region.neighbour(i, d);
            if (j < 0) continue;
            ok = ok || (r.steps[i][d] && (r.to[j] || (r.from[j] && rank[j] < rank[i])));
        }
        if (use_ != Use::Queries) {
            f = f && z3::implies(r.from[i], ok);
            continue;
        }
        f = f && z3::implies(r.from[i], ok && *lowest <= rank[i] && rank[i] <= *highest);
        some = some || r.from[i];
        atLowest = atLowest || (r.from[i] && rank[i] == *lowest);
        atHighest = atHighest || (r.from[i] && rank[i] == *highest);
    }
    if (use_ == Use::Queries) f = f && z3::implies(some, atLowest && atHighest);
    return hypothesis(f, {r.from, r, ctx_.bool_val(true), s.is[0][0].id()});
}

z3::expr SmtEncoding::legal(const State& s, bool positive) {
    z3::expr all = ctx_.bool_val(true);
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
            z3::expr becomes = ctx_.bool_val(false);
            for (int v = 0; v < alphabet_; ++v)
                if (engine_.rhsValue(placed, k, static_cast<CellValue>(v)) == w) becomes = becomes || s.is[cell][v];
            t.is[cell][w] = becomes;
        }
    }
    return t;
}

std::vector<z3::expr> SmtEncoding::acceptedSites(const rules::Engine::GuardNode& g, const std::int32_t* cells, const State& s) {
    std::vector<z3::expr> out;
    for (int d = 0; d < static_cast<int>(g.perSite.size()); ++d) {
        const int cell = g.around >= 0 ? engine_.region().neighbour(cells[g.around], d) : cells[d];
        out.push_back(member(s, cell, [&](int c, CellValue v) { return engine_.guardAccepts(g, d, c, v); }));
    }
    return out;
}

z3::expr SmtEncoding::guardNumber(const rules::Engine::GuardNode& g, const std::int32_t* cells, const State& s) {
    switch (g.kind) {
    case Expr::Kind::Number: return ctx_.real_val(static_cast<int64_t>(g.value.num()), static_cast<int64_t>(g.value.den()));
    case Expr::Kind::Add: return guardNumber(g.kids[0], cells, s) + guardNumber(g.kids[1], cells, s);
    case Expr::Kind::Sub: return guardNumber(g.kids[0], cells, s) - guardNumber(g.kids[1], cells, s);
    case Expr::Kind::Neg: return -guardNumber(g.kids[0], cells, s);
    case Expr::Kind::Count: {
        z3::expr count = ctx_.int_val(0);
        for (const z3::expr& accepted : acceptedSites(g, cells, s)) count = count + z3::ite(accepted, ctx_.int_val(1), ctx_.int_val(0));
        return z3::to_real(count);
    }
    default: throw InputError("internal: not a guard number");
    }
}

z3::expr SmtEncoding::guard(const rules::Engine::GuardNode& g, const std::int32_t* cells, const State& s) {
    switch (g.kind) {
    case Expr::Kind::Bool: return ctx_.bool_val(g.value.num() != 0);
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
        z3::expr c = guardNumber(count, cells, s);
        const int sites = static_cast<int>(g.perSite.size());
        return g.kind == Expr::Kind::Some ? c > 0 : g.kind == Expr::Kind::No ? c == 0 : c == sites;
    }
    case Expr::Kind::Connected: {
        // The accepted neighbours form a connected set: one of the (at most 2^6) connected sets.
        const int degree = static_cast<int>(g.perSite.size());
        const std::vector<z3::expr> accepted = acceptedSites(g, cells, s);
        z3::expr any = ctx_.bool_val(false);
        for (std::uint32_t set = 0; set < (1u << degree); ++set) {
            if (!engine_.tables().directionsConnected(set)) continue;
            z3::expr exactly = ctx_.bool_val(true);
            for (int d = 0; d < degree; ++d) exactly = exactly && ((set >> d) & 1u ? accepted[d] : !accepted[d]);
            any = any || exactly;
        }
        return any;
    }
    default: throw InputError("internal: not a guard condition");
    }
}

z3::expr SmtEncoding::matches(int placed, const State& s) {
    budget_.check("building the formulas");
    const auto& p = engine_.instances()[placed];
    z3::expr all = ctx_.bool_val(true);
    for (int k = 0; k < p.size; ++k)
        all = all && member(s, p.cells[k], [&](int c, CellValue v) { return engine_.lhsAccepts(placed, k, c, v); });
    if (const auto* g = engine_.guardOf(placed)) all = all && guard(*g, engine_.instances()[placed].cells, s);
    return all;
}

z3::expr SmtEncoding::rewritten(int placed, int k, const State& before, int fromCell, const State& after, int toCell) const {
    // One implication per old state: that state's rewrite is the new state.
    z3::expr all = ctx_.bool_val(true);
    for (int v = 0; v < alphabet_; ++v) {
        const int w = engine_.rhsValue(placed, k, static_cast<CellValue>(v));
        all = all && z3::implies(before.is[fromCell][v], after.is[toCell][w]);
    }
    return all;
}

z3::expr SmtEncoding::fires(int placed, const State& from, const State& to) {
    const auto& p = engine_.instances()[placed];
    z3::expr f = matches(placed, from);
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

z3::expr SmtEncoding::step(const State& from, const State& to, const z3::expr& selector) {
    // The selected instance matches and rewrites its cells; a cell no selected instance touches
    // keeps its state.
    const int count = static_cast<int>(engine_.instances().size());
    z3::expr f = selector >= 0 && selector < count;
    std::vector<z3::expr> touchedBy(from.is.size(), ctx_.bool_val(false));
    for (int placed = 0; placed < count; ++placed) {
        const auto& p = engine_.instances()[placed];
        z3::expr body = matches(placed, from);
        for (int k = 0; k < p.size; ++k) {
            const int copy = engine_.rhsCopyFrom(placed, k);
            body = body && (copy >= 0 ? sameCell(from, p.cells[copy], to, p.cells[k]) : rewritten(placed, k, from, p.cells[k], to, p.cells[k]));
            touchedBy[p.cells[k]] = touchedBy[p.cells[k]] || selector == placed;
        }
        f = f && z3::implies(selector == placed, body);
    }
    for (std::size_t i = 0; i < from.is.size(); ++i) f = f && (touchedBy[i] || sameCell(from, static_cast<int>(i), to, static_cast<int>(i)));
    return f && legal(to);
}

z3::expr SmtEncoding::delta(const Expr& e, int placed, const State& after, const State& before) {
    const auto& p = engine_.instances()[placed];
    switch (e.kind) {
    case Expr::Kind::Number: return ctx_.real_val(0);
    case Expr::Kind::Add: return delta(e.kids[0], placed, after, before) + delta(e.kids[1], placed, after, before);
    case Expr::Kind::Sub: return delta(e.kids[0], placed, after, before) - delta(e.kids[1], placed, after, before);
    case Expr::Kind::Neg: return -delta(e.kids[0], placed, after, before);
    case Expr::Kind::Count: {
        // A cell guard reads neighbours, so a rewrite changes counts beyond its own cells.
        if (!e.kids.empty()) return number(e, after) - number(e, before);
        z3::expr d = ctx_.int_val(0);
        for (int k = 0; k < p.size; ++k)
            d = d + z3::ite(memberPred(after, p.cells[k], e.pred), ctx_.int_val(1), ctx_.int_val(0)) -
                z3::ite(memberPred(before, p.cells[k], e.pred), ctx_.int_val(1), ctx_.int_val(0));
        return z3::to_real(d);
    }
    case Expr::Kind::Mass: {
        z3::expr d = ctx_.int_val(0);
        for (int k = 0; k < p.size; ++k) d = d + cellMassUnits(after, p.cells[k]) - cellMassUnits(before, p.cells[k]);
        return z3::to_real(d) / ctx_.real_val(static_cast<int64_t>(engine_.massDenominator()));
    }
    default: throw InputError("internal: not a number expression");
    }
}

z3::expr SmtEncoding::lexLessAfter(const std::vector<Expr>& ranking, int placed, const State& after, const State& before) {
    z3::expr less = ctx_.bool_val(false);
    for (int k = static_cast<int>(ranking.size()) - 1; k >= 0; --k) {
        z3::expr d = delta(ranking[k], placed, after, before);
        less = d < 0 || (d == 0 && less);
    }
    return less;
}

z3::expr SmtEncoding::keptAfter(const std::vector<Expr>& ranking, int placed, const State& after, const State& before) {
    z3::expr same = ctx_.bool_val(true);
    for (const Expr& component : ranking) same = same && delta(component, placed, after, before) == 0;
    return same;
}

std::vector<CellValue> SmtEncoding::decode(const z3::model& m, const State& s) const {
    std::vector<CellValue> cells;
    for (const auto& row : s.is) {
        CellValue value = 0;
        for (int v = 0; v < alphabet_; ++v)
            if (m.eval(row[v], true).is_true()) value = static_cast<CellValue>(v);
        cells.push_back(value);
    }
    return cells;
}

}  // namespace holon::checker
