// The constraints compiled onto predicate words (see WordConstraints.h). Each constraint becomes a
// tree whose predicates are word numbers; on words the trees are split at `and` into conjuncts,
// and a conjunct that is a linear comparison (counts, the mass and integers on both sides) keeps
// its sum, so that a rule step with fixed states changes it by a constant: the explorer's
// successors of one configuration are then judged by a comparison each, and a connectivity
// conjunct by its parent's cut cells or a flood from the cells that changed.

#include "checker/WordConstraints.h"

#include "rules/Components.h"

#include <algorithm>
#include <bit>
#include <functional>

namespace holon::checker {

using rules::Expr;

WordConstraints::WordConstraints(const rules::Engine& engine) : engine_(&engine) {
    const rules::Region& region = engine.region();
    const rules::RuleTables& tables = engine.tables();
    for (const rules::Constraint& c : engine.model().system().constraints) trees_.push_back(compile(c.expr));
    acceptedStates_.assign(static_cast<std::size_t>(tables.comboCount()) * masks_.size(), 0);
    for (int combo = 0; combo < tables.comboCount(); ++combo)
        for (std::size_t k = 0; k < masks_.size(); ++k)
            for (int v = 0; v < std::min(64, tables.alphabet()); ++v)
                if (tables.test(*masks_[k], combo, static_cast<CellValue>(v))) acceptedStates_[combo * masks_.size() + k] |= std::uint64_t{1} << v;
    if (WordAdjacency::fits(region)) adjacency_ = std::make_unique<WordAdjacency>(region);
    std::function<bool(const Tree&)> onWords = [&](const Tree& e) {
        return !e.cellGuard && e.kind != Expr::Kind::Reaches && std::all_of(e.kids.begin(), e.kids.end(), onWords);
    };
    onWords_ = region.size() <= 64 && tables.alphabet() <= 64 && std::all_of(trees_.begin(), trees_.end(), onWords) &&
               masks_.size() <= static_cast<std::size_t>(Words::kMax);
    if (!onWords_) return;
    std::function<void(const Tree&)> split = [&](const Tree& e) {
        if (e.kind == Expr::Kind::And) {
            std::for_each(e.kids.begin(), e.kids.end(), split);
            return;
        }
        Conjunct c;
        c.expr = &e;
        // Masses are in units of 1/massDenominator(): a linear form with a mass is exact only
        // when the denominator is 1.
        const bool linear = e.kind == Expr::Kind::Compare && addLinear(e.kids[0], 1, c) && addLinear(e.kids[1], -1, c) &&
                            (c.massCoefficient == 0 || tables.massDenominator() == 1);
        const int sums = static_cast<int>(std::count_if(conjuncts_.begin(), conjuncts_.end(), [](const Conjunct& k) { return k.sum >= 0; }));
        if (linear && sums < LegalBefore::kMaxSums) c.sum = sums;
        conjuncts_.push_back(std::move(c));
    };
    std::for_each(trees_.begin(), trees_.end(), split);
    const int a = tables.alphabet();
    cellsInState_.assign(masks_.size() * a, 0);
    for (int c = 0; c < region.size(); ++c)
        for (std::size_t w = 0; w < masks_.size(); ++w)
            for (int v = 0; v < a; ++v)
                if ((acceptedStates_[engine.comboOfCell(c) * masks_.size() + w] >> v) & 1u) cellsInState_[w * a + v] |= std::uint64_t{1} << c;
}

WordConstraints::Tree WordConstraints::compile(const Expr& e) {
    Tree t{e.kind, e.op, e.value, -1, &e, {}, rules::hasCellGuard(e)};
    if (t.cellGuard || e.kind == Expr::Kind::Reaches) return t;  // decided on the cells
    if (!e.pred.empty()) {
        const rules::RuleTables::Mask* mask = &engine_->predicateMask(e.pred);  // equal predicates share one
        auto it = std::find(masks_.begin(), masks_.end(), mask);
        t.predicate = static_cast<int>(it - masks_.begin());
        if (it == masks_.end()) masks_.push_back(mask);
    }
    for (const Expr& k : e.kids) t.kids.push_back(compile(k));
    return t;
}

bool WordConstraints::addLinear(const Tree& e, std::int64_t sign, Conjunct& c) {
    switch (e.kind) {
    case Expr::Kind::Number:
        if (!e.value.isInteger()) return false;
        c.constant += sign * e.value.num();
        return true;
    case Expr::Kind::Count:
        if (e.cellGuard) return false;
        c.counts.push_back({e.predicate, sign});
        return true;
    case Expr::Kind::Mass: c.massCoefficient += sign; return true;
    case Expr::Kind::Add: return addLinear(e.kids[0], sign, c) && addLinear(e.kids[1], sign, c);
    case Expr::Kind::Sub: return addLinear(e.kids[0], sign, c) && addLinear(e.kids[1], -sign, c);
    case Expr::Kind::Neg: return addLinear(e.kids[0], -sign, c);
    case Expr::Kind::Bool:
    case Expr::Kind::And:
    case Expr::Kind::Or:
    case Expr::Kind::Not:
    case Expr::Kind::Implies:
    case Expr::Kind::Compare:
    case Expr::Kind::All:
    case Expr::Kind::Some:
    case Expr::Kind::No:
    case Expr::Kind::Connected:
    case Expr::Kind::Reaches:
        break;  // conditions: no number
    }
    return false;
}

bool WordConstraints::holdsOn(const std::uint64_t* members, std::int64_t mass, const CellValue* cells) const {
    for (const Tree& t : trees_)
        if (!holdsOn(t, members, mass, cells)) return false;
    return true;
}

rules::Rational WordConstraints::numberOn(const Tree& e, const std::uint64_t* members, std::int64_t mass, const CellValue* cells) const {
    auto kid = [&](int k) -> const Tree& { return e.kids[k]; };
    if (e.cellGuard) return engine_->number(*e.source, cells);
    switch (e.kind) {
    case Expr::Kind::Number: return e.value;
    case Expr::Kind::Count: return std::popcount(members[e.predicate]);
    case Expr::Kind::Mass: return rules::Rational(mass, engine_->massDenominator());
    case Expr::Kind::Add: return numberOn(kid(0), members, mass, cells) + numberOn(kid(1), members, mass, cells);
    case Expr::Kind::Sub: return numberOn(kid(0), members, mass, cells) - numberOn(kid(1), members, mass, cells);
    case Expr::Kind::Neg: return -numberOn(kid(0), members, mass, cells);
    case Expr::Kind::Bool:
    case Expr::Kind::And:
    case Expr::Kind::Or:
    case Expr::Kind::Not:
    case Expr::Kind::Implies:
    case Expr::Kind::Compare:
    case Expr::Kind::All:
    case Expr::Kind::Some:
    case Expr::Kind::No:
    case Expr::Kind::Connected:
    case Expr::Kind::Reaches:
        break;
    }
    return engine_->number(*e.source, cells);
}

bool WordConstraints::holdsOn(const Tree& e, const std::uint64_t* members, std::int64_t mass, const CellValue* cells) const {
    auto kid = [&](int k) -> const Tree& { return e.kids[k]; };
    if (e.cellGuard) return engine_->holds(*e.source, cells);
    switch (e.kind) {
    case Expr::Kind::Bool: return e.value.num() != 0;
    case Expr::Kind::And: return holdsOn(kid(0), members, mass, cells) && holdsOn(kid(1), members, mass, cells);
    case Expr::Kind::Or: return holdsOn(kid(0), members, mass, cells) || holdsOn(kid(1), members, mass, cells);
    case Expr::Kind::Implies: return !holdsOn(kid(0), members, mass, cells) || holdsOn(kid(1), members, mass, cells);
    case Expr::Kind::Not: return !holdsOn(kid(0), members, mass, cells);
    case Expr::Kind::Compare: return compare(e.op, numberOn(kid(0), members, mass, cells), numberOn(kid(1), members, mass, cells));
    case Expr::Kind::Some: return members[e.predicate] != 0;
    case Expr::Kind::No: return members[e.predicate] == 0;
    case Expr::Kind::All: {
        const int n = engine_->region().size();
        const std::uint64_t all = n == 64 ? ~std::uint64_t{0} : (std::uint64_t{1} << n) - 1;
        return members[e.predicate] == all;
    }
    case Expr::Kind::Connected: return adjacency_->connected(members[e.predicate]);
    case Expr::Kind::Reaches:  // a walk over the cells
    case Expr::Kind::Number:
    case Expr::Kind::Mass:
    case Expr::Kind::Add:
    case Expr::Kind::Sub:
    case Expr::Kind::Neg:
    case Expr::Kind::Count:
        break;
    }
    return engine_->holds(*e.source, cells);
}

void WordConstraints::wordsOf(const std::uint64_t* occupied, Words& out) const {
    const int a = engine_->tables().alphabet();
    for (std::size_t w = 0; w < masks_.size(); ++w) {
        const std::uint64_t* byState = &cellsInState_[w * a];
        std::uint64_t m = 0;
        for (int v = 0; v < a; ++v) m |= occupied[v] & byState[v];
        out.members[w] = m;
    }
    out.mass = 0;
    for (int v = 0; v < a; ++v) out.mass += std::popcount(occupied[v]) * engine_->massUnitsOf(static_cast<CellValue>(v));
}

const rules::CellPredicate* WordConstraints::connectedConjunct() const {
    std::function<const rules::CellPredicate*(const Expr&)> find = [&](const Expr& e) -> const rules::CellPredicate* {
        if (e.kind == Expr::Kind::Connected) return &e.pred;
        if (e.kind != Expr::Kind::And) return nullptr;
        for (const Expr& k : e.kids)
            if (const rules::CellPredicate* p = find(k)) return p;
        return nullptr;
    };
    for (const rules::Constraint& c : engine_->model().system().constraints)
        if (const rules::CellPredicate* p = find(c.expr)) return p;
    return nullptr;
}

int WordConstraints::connectedConjunctWord() const {
    const rules::CellPredicate* connected = connectedConjunct();
    for (const Conjunct& c : conjuncts_)
        if (c.expr->kind == Expr::Kind::Connected && &c.expr->source->pred == connected) return c.expr->predicate;
    return -1;
}

std::int64_t WordConstraints::linearSum(const Conjunct& c, const Words& w) const {
    std::int64_t sum = c.constant + c.massCoefficient * w.mass;
    for (const auto& [word, coefficient] : c.counts) sum += coefficient * std::popcount(w.members[word]);
    return sum;
}

void WordConstraints::prepare(LegalBefore& before) const {
    for (const Conjunct& c : conjuncts_)
        if (c.sum >= 0) before.sums[c.sum] = linearSum(c, before.words);
    before.cutsKnown = 0;
}

bool WordConstraints::legalOn(const Words& now, const LegalBefore* before, int connectedWord) const {
    for (const Conjunct& c : conjuncts_) {
        bool holds;
        if (c.expr->kind == Expr::Kind::Connected && c.expr->predicate == connectedWord) {
            holds = true;
        } else if (c.sum >= 0) {
            holds = rules::compare<std::int64_t>(c.expr->op, linearSum(c, now), 0);
        } else if (c.expr->kind == Expr::Kind::Connected && before) {
            const std::uint64_t was = before->words.members[c.expr->predicate], is = now.members[c.expr->predicate];
            holds = stillConnected(*before, c.expr->predicate, was & ~is, is & ~was);
        } else {
            holds = holdsOn(*c.expr, now.members, now.mass, nullptr);
        }
        if (!holds) return false;
    }
    return true;
}

void WordConstraints::addChange(int cell, CellValue from, CellValue to, WordChange& change) const {
    const int a = engine_->tables().alphabet();
    const std::uint64_t bit = std::uint64_t{1} << cell;
    for (std::size_t w = 0; w < masks_.size(); ++w) {
        const std::uint64_t* byState = &cellsInState_[w * a];
        if ((byState[from] & bit) && !(byState[to] & bit)) change.removed[w] |= bit;
        if (!(byState[from] & bit) && (byState[to] & bit)) change.added[w] |= bit;
    }
    change.mass += engine_->massUnitsOf(to) - engine_->massUnitsOf(from);
}

std::vector<WordConstraints::Check> WordConstraints::compileChange(const WordChange& change) const {
    std::vector<Check> checks;
    for (const Conjunct& c : conjuncts_) {
        Check k{Check::Kind::General};
        k.expr = c.expr;
        k.op = c.expr->op;
        if (c.sum >= 0) {
            k.kind = Check::Kind::Sum, k.index = c.sum;
            k.delta = c.massCoefficient * change.mass;
            for (const auto& [word, coefficient] : c.counts)
                k.delta += coefficient * (std::popcount(change.added[word]) - std::popcount(change.removed[word]));
            if (k.delta == 0) continue;
        } else if (c.expr->kind == Expr::Kind::Connected) {
            const int w = c.expr->predicate;
            const std::uint64_t removed = change.removed[w], added = change.added[w];
            if (!removed && !added) continue;
            k.index = w, k.bits = added, k.removed = removed;
            k.kind = removed && !(removed & (removed - 1)) && !added ? Check::Kind::Removed
                     : !removed                                      ? Check::Kind::Attached
                                                                     : Check::Kind::Connected;
            if (k.kind == Check::Kind::Removed) k.bits = removed;
        }
        checks.push_back(k);
    }
    return checks;
}

bool WordConstraints::legalAfter(const LegalBefore& before, const Check* checks, std::size_t count, const WordChange& change) const {
    for (std::size_t i = 0; i < count; ++i) {
        const Check& k = checks[i];
        bool holds = true;
        switch (k.kind) {
        case Check::Kind::Sum: holds = rules::compare<std::int64_t>(k.op, before.sums[k.index] + k.delta, 0); break;
        case Check::Kind::Removed: holds = !(cutsOf(before, k.index) & k.bits); break;
        case Check::Kind::Attached:
        case Check::Kind::Connected: holds = stillConnected(before, k.index, k.removed, k.bits); break;
        case Check::Kind::General: {
            Words now;
            for (std::size_t w = 0; w < masks_.size(); ++w) now.members[w] = (before.words.members[w] & ~change.removed[w]) | change.added[w];
            now.mass = before.words.mass + change.mass;
            holds = holdsOn(*k.expr, now.members, now.mass, nullptr);
            break;
        }
        }
        if (!holds) return false;
    }
    return true;
}

bool WordConstraints::stillConnected(const LegalBefore& legal, int w, std::uint64_t removed, std::uint64_t added) const {
    const std::uint64_t before = legal.words.members[w], now = (before & ~removed) | added;
    if (!removed && !added) return true;
    if (!now) return true;
    const WordAdjacency& adjacency = *adjacency_;
    // Removing one cell keeps a connected set connected unless it is a cut cell. Whatever is
    // kept connected, each added cell must join through added cells.
    std::uint64_t kept = removed ? 0 : before;
    if (!kept && !removed) return adjacency.connected(now);  // nothing before: the added cells alone
    if (removed && !(removed & (removed - 1))) {
        if (!(removed & cutsOf(legal, w))) kept = before & ~removed;
        else if (!added) return false;
    }
    if (kept) return !(added & ~rules::reachedWithin(kept, kept | added, [&](std::uint64_t r) { return adjacency.around(r); }));
    // Every component of `now` holds a neighbour of a removed cell (the components of before
    // minus the removed cells each touch one, before being connected) or an added cell.
    return adjacency.targetsJoined(now, (adjacency.around(removed) & now) | added);
}

}  // namespace holon::checker
