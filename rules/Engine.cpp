// The compiled rule engine. Each rule shape is compiled, once per load, into decision tables: for
// every pattern cell a bit mask over (input combination, cell state) for its left side, and a
// state -> state table for its right side; guards become per-direction masks over the neighbours.
// Testing an instance is then a handful of table look-ups with no allocation. Non-local
// expressions (constraints, goals, properties) are evaluated over the same masks. The semantics are
// exactly the reference interpreter's (tests/rules/EngineTest.cpp runs both side by side).

#include "rules/Engine.h"

#include "rules/Components.h"

#include "rules/Error.h"
#include "rules/Printer.h"

#include <algorithm>
#include <bit>
#include <functional>
#include <numeric>

namespace holon::rules {

namespace {

bool hasCellGuard(const Expr& e) {
    const bool quantifier = e.kind == Expr::Kind::Count || e.kind == Expr::Kind::All || e.kind == Expr::Kind::Some || e.kind == Expr::Kind::No;
    return quantifier && e.around < 0 && !e.kids.empty();
}

/// The predicates of the non-local expressions, and the quantifiers with a cell guard (whose
/// guard is compiled as a one-cell pattern's, not as predicates over the region).
void collectPredicates(const Expr& e, std::vector<const CellPredicate*>& out, std::vector<const Expr*>& guarded) {
    if (!e.pred.empty()) out.push_back(&e.pred);
    if (!e.target.empty()) out.push_back(&e.target);
    if (hasCellGuard(e)) {
        guarded.push_back(&e);
        return;
    }
    for (const Expr& k : e.kids) collectPredicates(k, out, guarded);
}

/// The input combinations the tables must cover: those present in the region, or all of them.
std::vector<std::uint32_t> combosFor(const Model& model, const std::vector<std::uint32_t>& inputs, bool everyInputCombination) {
    std::vector<std::uint32_t> combos;
    if (everyInputCombination) {
        if (model.system().inputs.size() > 8) throw InputError("more than 8 inputs cannot be left open");
        for (std::uint32_t c = 1; c < (1u << model.system().inputs.size()); ++c) combos.push_back(c);
    }
    std::vector<bool> seen;
    for (std::uint32_t in : inputs) {
        if (in >= seen.size()) seen.resize(in + 1, false);
        if (!seen[in]) seen[in] = true, combos.push_back(in);
    }
    return combos;
}

/// Region cells as seen by a compiled guard.
struct RegionCells {
    const Region* region;
    const CellValue* cells;
    const int* combos;
    CellValue value(int i) const { return cells[i]; }
    int combo(int i) const { return combos[i]; }
    int neighbour(int i, int d) const { return region->neighbour(i, d); }
};

}  // namespace

Engine::Engine(const Model& model, const Region& region, const std::vector<std::uint32_t>& inputs, bool everyInputCombination)
    : model_(&model), region_(&region), inputs_(inputs.size() == static_cast<std::size_t>(region.size()) ? inputs : std::vector<std::uint32_t>(region.size(), 0)),
      tables_(model, combosFor(model, inputs_, everyInputCombination)) {
    combo_.resize(region.size());
    for (int i = 0; i < region.size(); ++i) combo_[i] = tables_.comboIndex(inputs_[i]);
    const Lattice& lattice = model.lattice();
    byCell_.resize(region.size());
    for (int s = 0; s < static_cast<int>(model.shapes().size()); ++s) {
        const RuleShape& shape = model.shapes()[s];
        for (Vec cell : region.cells()) {
            Placed p;
            p.shape = s, p.rule = shape.rule, p.anchor = cell - shape.offsets[0];
            p.size = static_cast<std::uint8_t>(shape.offsets.size());
            std::int32_t at[kMaxCells];
            bool inside = true;
            for (std::size_t k = 0; k < shape.offsets.size() && inside; ++k) {
                at[k] = region.indexOf(p.anchor + shape.offsets[k]);
                inside = at[k] >= 0;
            }
            if (!inside) continue;
            for (int k = 0; k < p.size; ++k) byCell_[at[k]].push_back(static_cast<std::int32_t>(placed_.size()));
            cellPool_.insert(cellPool_.end(), at, at + p.size);
            placed_.push_back(p);
        }
    }
    // The instances' cell lists, one pool in instance order: small instances, dense in cache.
    for (std::size_t p = 0, first = 0; p < placed_.size(); first += placed_[p].size, ++p) placed_[p].cells = cellPool_.data() + first;
    for (int s = 0; s < tables_.shapeCount(); ++s) {
        firstCellTest_.push_back(static_cast<int>(cellTests_.size()));
        for (const Mask& m : tables_.shape(s).lhs) {
            const auto [any, all] = tables_.acceptedStates(m.bits);
            cellTests_.push_back({any, all});
        }
    }
    placedIndex_.assign(static_cast<std::size_t>(region.size()) * tables_.shapeCount(), -1);
    for (int p = 0; p < static_cast<int>(placed_.size()); ++p)
        placedIndex_[static_cast<std::size_t>(placed_[p].cells[0]) * tables_.shapeCount() + placed_[p].shape] = p;
    if (WordMatcher::fits(region.size(), tables_.alphabet())) {
        words_ = newWordMatcher();
        words_->finish();
    }
    std::vector<const CellPredicate*> preds;
    std::vector<const Expr*> guarded;
    const System& s = model.system();
    for (const Constraint& c : s.constraints) collectPredicates(c.expr, preds, guarded);
    if (s.goal) collectPredicates(*s.goal, preds, guarded);
    for (const Property& p : s.properties)
        for (const Expr& e : p.exprs) collectPredicates(e, preds, guarded);
    for (const Expr* e : guarded) cellGuards_.emplace(e, tables_.compileCellGuard(e->kids[0]));
    std::unordered_map<std::string, int> byText;
    for (const CellPredicate* p : preds) {
        const std::string text = printPredicate(s, *p);
        auto [it, fresh] = byText.emplace(text, static_cast<int>(predicateMasks_.size()));
        if (fresh) predicateMasks_.push_back(tables_.compilePredicate(*p, nullptr, {}));
        predicateIndex_.emplace(p, it->second);
    }
    for (const Constraint& c : s.constraints) compiledConstraints_.push_back(compileExpr(c.expr));
    predicateStates_.assign(static_cast<std::size_t>(tables_.comboCount()) * predicateMasks_.size(), 0);
    for (int combo = 0; combo < tables_.comboCount(); ++combo)
        for (std::size_t k = 0; k < predicateMasks_.size(); ++k)
            for (int v = 0; v < std::min(64, tables_.alphabet()); ++v)
                if (test(predicateMasks_[k], combo, static_cast<CellValue>(v))) predicateStates_[combo * predicateMasks_.size() + k] |= std::uint64_t{1} << v;
    // Which constraints words decide, and the words each of their predicates needs.
    std::function<bool(const CompiledExpr&)> onWords = [&](const CompiledExpr& e) {
        if (e.cellGuard || e.kind == Expr::Kind::Reaches) return false;
        if (e.predicate >= 0 && std::find(constraintPredicates_.begin(), constraintPredicates_.end(), e.predicate) == constraintPredicates_.end())
            constraintPredicates_.push_back(e.predicate);
        return std::all_of(e.kids.begin(), e.kids.end(), onWords);
    };
    constraintsOnWords_ = region.size() <= 64 && tables_.alphabet() <= 64 &&
                          std::all_of(compiledConstraints_.begin(), compiledConstraints_.end(), onWords) &&
                          constraintPredicates_.size() <= static_cast<std::size_t>(ConstraintWords::kMax);
    if (constraintsOnWords_) {
        std::function<CompiledExpr(const CompiledExpr&)> renumber = [&](const CompiledExpr& e) {
            CompiledExpr w = e;
            if (e.predicate >= 0)
                w.predicate = static_cast<int>(std::find(constraintPredicates_.begin(), constraintPredicates_.end(), e.predicate) - constraintPredicates_.begin());
            for (CompiledExpr& k : w.kids) k = renumber(k);
            return w;
        };
        for (const CompiledExpr& c : compiledConstraints_) wordConstraints_.push_back(renumber(c));
        std::function<void(const CompiledExpr&)> split = [&](const CompiledExpr& e) {
            if (e.kind == Expr::Kind::And) {
                std::for_each(e.kids.begin(), e.kids.end(), split);
                return;
            }
            Conjunct c;
            c.expr = &e;
            // Masses are in units of 1/massDenominator(): a linear form with a mass is exact only
            // when the denominator is 1.
            const bool linear = e.kind == Expr::Kind::Compare && addLinear(e.kids[0], 1, c) && addLinear(e.kids[1], -1, c) &&
                                (c.massCoefficient == 0 || tables_.massDenominator() == 1);
            const int sums = static_cast<int>(std::count_if(conjuncts_.begin(), conjuncts_.end(), [](const Conjunct& k) { return k.sum >= 0; }));
            if (linear && sums < LegalBefore::kMaxSums) c.sum = sums;
            conjuncts_.push_back(std::move(c));
        };
        std::for_each(wordConstraints_.begin(), wordConstraints_.end(), split);
        const int a = tables_.alphabet();
        const std::size_t all = predicateMasks_.size();
        predicateCells_.assign(constraintPredicates_.size() * a, 0);
        for (int c = 0; c < region.size(); ++c)
            for (std::size_t w = 0; w < constraintPredicates_.size(); ++w)
                for (int v = 0; v < a; ++v)
                    if ((predicateStates_[combo_[c] * all + constraintPredicates_[w]] >> v) & 1u) predicateCells_[w * a + v] |= std::uint64_t{1} << c;
    }
    if (region.size() <= 64) {
        neighbourBits_.assign(region.size(), 0);
        for (int i = 0; i < region.size(); ++i)
            for (int d = 0; d < lattice.degree(); ++d)
                if (int j = region.neighbour(i, d); j >= 0) {
                    neighbourBits_[i] |= std::uint64_t{1} << j;
                    const auto left = static_cast<std::uint8_t>(std::max(0, j - i)), right = static_cast<std::uint8_t>(std::max(0, i - j));
                    auto it = std::find_if(shifts_.begin(), shifts_.end(), [&](const Shift& s) { return s.left == left && s.right == right; });
                    if (it == shifts_.end()) it = shifts_.insert(shifts_.end(), {0, left, right});
                    it->from |= std::uint64_t{1} << i;
                }
        // An irregular region needs many shifts; then the cell-by-cell walk is cheaper.
        if (static_cast<int>(shifts_.size()) > 2 * lattice.degree()) shifts_.clear();
    }
}

std::unique_ptr<WordMatcher> Engine::newWordMatcher() const {
    auto matcher = std::make_unique<WordMatcher>(tables_, combo_);
    for (const Placed& p : placed_) matcher->addInstance(p.shape, p.cells, p.size);
    return matcher;
}

const CellPredicate* Engine::connectedConjunct() const {
    std::function<const CellPredicate*(const Expr&)> find = [&](const Expr& e) -> const CellPredicate* {
        if (e.kind == Expr::Kind::Connected) return &e.pred;
        if (e.kind != Expr::Kind::And) return nullptr;
        for (const Expr& k : e.kids)
            if (const CellPredicate* p = find(k)) return p;
        return nullptr;
    };
    for (const Constraint& c : model_->system().constraints)
        if (const CellPredicate* p = find(c.expr)) return p;
    return nullptr;
}

bool Engine::hasGuards() const {
    for (int s = 0; s < tables_.shapeCount(); ++s)
        if (tables_.shape(s).hasGuard) return true;
    return false;
}

void Engine::constraintWords(const std::uint64_t* occupied, ConstraintWords& out) const {
    const int a = tables_.alphabet();
    for (std::size_t w = 0; w < constraintPredicates_.size(); ++w) {
        const std::uint64_t* byState = &predicateCells_[w * a];
        std::uint64_t m = 0;
        for (int v = 0; v < a; ++v) m |= occupied[v] & byState[v];
        out.members[w] = m;
    }
    out.mass = 0;
    for (int v = 0; v < a; ++v) out.mass += std::popcount(occupied[v]) * tables_.massUnitsOf(static_cast<CellValue>(v));
}

void Engine::addChange(int cell, CellValue from, CellValue to, WordChange& change) const {
    const int a = tables_.alphabet();
    const std::uint64_t bit = std::uint64_t{1} << cell;
    for (std::size_t w = 0; w < constraintPredicates_.size(); ++w) {
        const std::uint64_t* byState = &predicateCells_[w * a];
        if ((byState[from] & bit) && !(byState[to] & bit)) change.removed[w] |= bit;
        if (!(byState[from] & bit) && (byState[to] & bit)) change.added[w] |= bit;
    }
    change.mass += tables_.massUnitsOf(to) - tables_.massUnitsOf(from);
}

std::int64_t Engine::linearSum(const Conjunct& c, const ConstraintWords& w) const {
    std::int64_t sum = c.constant + c.massCoefficient * w.mass;
    for (const auto& [word, coefficient] : c.counts) sum += coefficient * std::popcount(w.members[word]);
    return sum;
}

void Engine::prepare(LegalBefore& before) const {
    for (const Conjunct& c : conjuncts_)
        if (c.sum >= 0) before.sums[c.sum] = linearSum(c, before.words);
    before.cutsKnown = 0;
}

int Engine::connectedConjunctWord() const {
    const CellPredicate* connected = connectedConjunct();
    for (const Conjunct& c : conjuncts_)
        if (c.expr->kind == Expr::Kind::Connected && &c.expr->source->pred == connected) return c.expr->predicate;
    return -1;
}

bool Engine::legalOn(const ConstraintWords& now, const LegalBefore* before, int connectedWord) const {
    for (const Conjunct& c : conjuncts_) {
        bool holds;
        if (c.expr->kind == Expr::Kind::Connected && c.expr->predicate == connectedWord) {
            holds = true;
        } else if (c.sum >= 0) {
            holds = compare<std::int64_t>(c.expr->op, linearSum(c, now), 0);
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

std::vector<Engine::Check> Engine::compileChange(const WordChange& change) const {
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

bool Engine::legalAfter(const LegalBefore& before, const Check* checks, std::size_t count, const WordChange& change) const {
    for (std::size_t i = 0; i < count; ++i) {
        const Check& k = checks[i];
        bool holds = true;
        switch (k.kind) {
        case Check::Kind::Sum: holds = compare<std::int64_t>(k.op, before.sums[k.index] + k.delta, 0); break;
        case Check::Kind::Removed: holds = !(cutsOf(before, k.index) & k.bits); break;
        case Check::Kind::Attached:
        case Check::Kind::Connected: holds = stillConnected(before, k.index, k.removed, k.bits); break;
        case Check::Kind::General: {
            ConstraintWords now;
            for (std::size_t w = 0; w < constraintPredicates_.size(); ++w)
                now.members[w] = (before.words.members[w] & ~change.removed[w]) | change.added[w];
            now.mass = before.words.mass + change.mass;
            holds = holdsOn(*k.expr, now.members, now.mass, nullptr);
            break;
        }
        }
        if (!holds) return false;
    }
    return true;
}

bool Engine::stillConnected(const LegalBefore& legal, int w, std::uint64_t removed, std::uint64_t added) const {
    const std::uint64_t before = legal.words.members[w], now = (before & ~removed) | added;
    if (!removed && !added) return true;
    if (!now) return true;
    // Removing one cell keeps a connected set connected unless it is a cut cell. Whatever is
    // kept connected, each added cell must join through added cells.
    std::uint64_t kept = removed ? 0 : before;
    if (!kept && !removed) return connectedCells(now);  // nothing before: the added cells alone
    if (removed && !(removed & (removed - 1))) {
        if (!(removed & cutsOf(legal, w))) kept = before & ~removed;
        else if (!added) return false;
    }
    if (kept) {
        return !(added & ~reachedWithin(kept, kept | added, [this](std::uint64_t r) { return around(r); }));
    }
    return reconnected(now, (around(removed) & now) | added);
}

bool Engine::reconnected(std::uint64_t now, std::uint64_t targets) const {
    // Every component of `now` holds a neighbour of a removed cell (the components of before minus
    // the removed cells each touch one, before being connected) or an added cell: the targets.
    // So `now` is connected exactly when one of these reaches all the others, and a flood from
    // one of them can stop as soon as it has.
    // Two floods, from the lowest and the highest target, a layer each in turn: a part cut off is
    // usually small, and its flood dies out after a few layers; otherwise they meet, and the
    // merged flood goes on until it holds every target.
    std::uint64_t a = targets & (~targets + 1), b = std::uint64_t{1} << (63 - std::countl_zero(targets));
    std::uint64_t frontA = a, frontB = b;
    while (!(a & b)) {
        frontA = around(frontA) & now & ~a;
        if (!frontA) return false;
        a |= frontA;
        if (a & b) break;
        frontB = around(frontB) & now & ~b;
        if (!frontB) return false;
        b |= frontB;
    }
    std::uint64_t reached = a | b, frontier = frontA | frontB;
    while (frontier && (targets & ~reached)) {
        frontier = around(frontier) & now & ~reached;
        reached |= frontier;
    }
    return !(targets & ~reached);
}

bool Engine::lhsAccepts(int placed, int k, int combo, CellValue v) const { return test(tables_.shape(placed_[placed].shape).lhs[k], combo, v); }
int Engine::rhsCopyFrom(int placed, int k) const { return tables_.shape(placed_[placed].shape).copyFrom[k]; }
CellValue Engine::rhsValue(int placed, int k, CellValue v) const { return tables_.shape(placed_[placed].shape).rhs[k][v]; }
const Engine::GuardNode* Engine::guardOf(int placed) const {
    const RuleTables::Shape& t = tables_.shape(placed_[placed].shape);
    return t.hasGuard ? &t.guard : nullptr;
}
bool Engine::guardAccepts(const GuardNode& node, int site, int combo, CellValue v) const { return tables_.guardAccepts(node, site, combo, v); }

Engine::~Engine() = default;
Engine::Engine(Engine&&) noexcept = default;

Engine::CompiledExpr Engine::compileExpr(const Expr& e) const {
    CompiledExpr c{e.kind, e.op, e.value, -1, &e, {}, hasCellGuard(e)};
    if (!e.pred.empty()) c.predicate = predicateIndex_.at(&e.pred);
    if (!c.cellGuard)
        for (const Expr& k : e.kids) c.kids.push_back(compileExpr(k));
    return c;
}

bool Engine::addLinear(const CompiledExpr& e, std::int64_t sign, Conjunct& c) {
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
    default: return false;
    }
}

bool Engine::matches(const CellValue* cells, int placed) const {
    const Placed& p = placed_[placed];
    return test(tables_.shape(p.shape).lhs[0], combo_[p.cells[0]], cells[p.cells[0]]) && matchesAfterFirst(cells, placed);
}

bool Engine::guardHolds(const CellValue* cells, const Placed& p) const {
    return tables_.guard(tables_.shape(p.shape).guard, RegionCells{region_, cells, combo_.data()}, p.cells);
}

void Engine::apply(CellValue* cells, int placed, CellValue* saved) const {
    const Placed& p = placed_[placed];
    for (int k = 0; k < p.size; ++k) saved[k] = cells[p.cells[k]];
    for (int k = 0; k < p.size; ++k) cells[p.cells[k]] = rewritten(p, k, saved);
}

void Engine::undo(CellValue* cells, int placed, const CellValue* saved) const {
    const Placed& p = placed_[placed];
    for (int k = 0; k < p.size; ++k) cells[p.cells[k]] = saved[k];
}

const Engine::Mask& Engine::predicateMask(const CellPredicate& pred) const {
    auto it = predicateIndex_.find(&pred);
    if (it == predicateIndex_.end()) throw InternalError("an expression that is not part of the system was evaluated");
    return predicateMasks_[it->second];
}

// ---- Evaluator -----------------------------------------------------------------------------------

Engine::Evaluator::Evaluator(const Engine& engine)
    : engine_(&engine), cells_(engine.region().size(), 0), members_(engine.predicateMasks_.size(), 0),
      small_(engine.region().size() <= 64) {}

void Engine::Evaluator::load(const CellValue* cells) {
    std::copy(cells, cells + cells_.size(), cells_.begin());
    mass_ = 0;
    for (std::size_t i = 0; i < cells_.size(); ++i) mass_ += engine_->tables_.massUnitsOf(cells_[i]);
    if (!small_) return;
    std::fill(members_.begin(), members_.end(), 0);
    for (std::size_t i = 0; i < cells_.size(); ++i) updateMembers(static_cast<int>(i), cells_[i]);
}

void Engine::Evaluator::set(int cell, CellValue value) {
    const CellValue old = cells_[cell];
    if (old == value) return;
    mass_ += engine_->tables_.massUnitsOf(value) - engine_->tables_.massUnitsOf(old);
    cells_[cell] = value;
    updateMembers(cell, value);
}

void Engine::Evaluator::updateMembers(int cell, CellValue value) {
    if (!small_) return;
    const std::uint64_t bit = std::uint64_t{1} << cell;
    const int combo = engine_->combo_[cell];
    const std::size_t predicates = members_.size();
    if (predicates == 0) return;  // a system without constraints or properties: nothing to track (and no row to index)
    if (value < 64) {  // the common case, branch-free: one word of accepted states per predicate
        const std::uint64_t* accepted = &engine_->predicateStates_[combo * predicates];
        for (std::size_t k = 0; k < predicates; ++k) members_[k] = (members_[k] & ~bit) | (((accepted[k] >> value) & 1u) << cell);
        return;
    }
    for (std::size_t k = 0; k < predicates; ++k) {
        if (engine_->test(engine_->predicateMasks_[k], combo, value)) members_[k] |= bit;
        else members_[k] &= ~bit;
    }
}

void Engine::Evaluator::advance() {
    const int a = engine_->tables_.alphabet();
    for (std::size_t i = 0; i < cells_.size(); ++i) {
        const CellValue v = static_cast<CellValue>(cells_[i] + 1 == a ? 0 : cells_[i] + 1);
        set(static_cast<int>(i), v);
        if (v != 0) return;
    }
}

void Engine::Evaluator::apply(int placed, CellValue* saved) {
    const Placed& p = engine_->placed_[placed];
    for (int k = 0; k < p.size; ++k) saved[k] = cells_[p.cells[k]];
    for (int k = 0; k < p.size; ++k) set(p.cells[k], engine_->rewritten(p, k, saved));
}

void Engine::Evaluator::undo(int placed, const CellValue* saved) {
    const Placed& p = engine_->placed_[placed];
    for (int k = p.size - 1; k >= 0; --k) set(p.cells[k], saved[k]);
}

bool Engine::Evaluator::legal() const {
    if (!small_) return engine_->legal(cells_.data());
    for (const CompiledExpr& c : engine_->compiledConstraints_)
        if (!engine_->holdsOn(c, members_.data(), mass_, cells_.data())) return false;
    return true;
}

Rational Engine::numberOn(const CompiledExpr& e, const std::uint64_t* members, std::int64_t mass, const CellValue* cells) const {
    auto kid = [&](int k) -> const CompiledExpr& { return e.kids[k]; };
    if (e.cellGuard) return number(*e.source, cells);
    switch (e.kind) {
    case Expr::Kind::Number: return e.value;
    case Expr::Kind::Count: return std::popcount(members[e.predicate]);
    case Expr::Kind::Mass: return Rational(mass, tables_.massDenominator());
    case Expr::Kind::Add: return numberOn(kid(0), members, mass, cells) + numberOn(kid(1), members, mass, cells);
    case Expr::Kind::Sub: return numberOn(kid(0), members, mass, cells) - numberOn(kid(1), members, mass, cells);
    case Expr::Kind::Neg: return -numberOn(kid(0), members, mass, cells);
    default: return number(*e.source, cells);
    }
}

bool Engine::holdsOn(const CompiledExpr& e, const std::uint64_t* members, std::int64_t mass, const CellValue* cells) const {
    auto kid = [&](int k) -> const CompiledExpr& { return e.kids[k]; };
    if (e.cellGuard) return holds(*e.source, cells);
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
        const int n = region_->size();
        const std::uint64_t all = n == 64 ? ~std::uint64_t{0} : (std::uint64_t{1} << n) - 1;
        return members[e.predicate] == all;
    }
    case Expr::Kind::Connected: return connectedCells(members[e.predicate]);
    default: return holds(*e.source, cells);
    }
}

std::uint64_t Engine::cutCells(std::uint64_t set) const {
    if (!set) return 0;
    // Iterative depth-first search: a cell's low point is the earliest discovery time among its
    // neighbours (other than its parent) and its children's low points; a cell other than the
    // root is a cut cell when some child's low point is not earlier than its own discovery, the
    // root when it has two children.
    std::uint8_t discovered[64], low[64], parent[64], stack[64];
    std::uint64_t visited = 0, cut = 0;
    int top = 0, time = 0, rootChildren = 0;
    const int root = std::countr_zero(set);
    auto open = [&](int v, int from) {
        visited |= std::uint64_t{1} << v;
        discovered[v] = low[v] = static_cast<std::uint8_t>(time++);
        parent[v] = static_cast<std::uint8_t>(from);
        stack[top++] = static_cast<std::uint8_t>(v);
    };
    open(root, root);
    while (top) {
        const int v = stack[top - 1];
        if (const std::uint64_t next = neighbourBits_[v] & set & ~visited) {
            open(std::countr_zero(next), v);
            rootChildren += v == root;
            continue;
        }
        --top;
        const int p = parent[v];
        for (std::uint64_t n = neighbourBits_[v] & set & ~(std::uint64_t{1} << p); n; n &= n - 1)
            low[v] = std::min(low[v], discovered[std::countr_zero(n)]);
        if (v == root) break;
        low[p] = std::min(low[p], low[v]);
        if (p != root && low[v] >= discovered[p]) cut |= std::uint64_t{1} << p;
    }
    if (rootChildren >= 2) cut |= std::uint64_t{1} << root;
    return cut;
}

bool Engine::connectedCells(std::uint64_t m) const {
    // By shifts, a cell with no neighbour in m fails at once.
    if (!shifts_.empty() && (m & (m - 1)) && (m & ~neighboursOf(m))) return false;
    return connectedWord(m, [this](std::uint64_t r) { return around(r); });
}

int Engine::countCells(const Expr& e, const CellValue* cells, bool withCellGuard) const {
    const Mask& m = predicateMask(e.pred);
    const GuardNode* guard = withCellGuard && !e.kids.empty() ? &cellGuards_.at(&e) : nullptr;
    int n = 0;
    for (std::int32_t i = 0; i < region_->size(); ++i)
        n += test(m, combo_[i], cells[i]) && (!guard || tables_.guard(*guard, RegionCells{region_, cells, combo_.data()}, &i));
    return n;
}

std::vector<int> Engine::failureCells(const Expr& e, const CellValue* cells) const {
    std::vector<int> out;
    if (holds(e, cells)) return out;
    const int n = region_->size();
    auto where = [&](const Mask& m, auto&& also) {
        for (std::int32_t i = 0; i < n; ++i)
            if (test(m, combo_[i], cells[i]) && also(i)) out.push_back(i);
    };
    switch (e.kind) {
    case Expr::Kind::And:
    case Expr::Kind::Or:  // a false `or`: every disjunct is false
        for (const Expr& k : e.kids)
            for (int i : failureCells(k, cells)) out.push_back(i);
        break;
    case Expr::Kind::No:
        if (e.around == -1 && e.kids.empty()) where(predicateMask(e.pred), [](int) { return true; });
        break;
    case Expr::Kind::All:
        if (hasCellGuard(e)) {
            const GuardNode& guard = cellGuards_.at(&e);
            where(predicateMask(e.pred), [&](std::int32_t i) { return !tables_.guard(guard, RegionCells{region_, cells, combo_.data()}, &i); });
        }
        break;
    case Expr::Kind::Connected: {
        if (e.around != -1) break;
        // The parts of the T cells; every part but the largest is cut off.
        const Mask& m = predicateMask(e.pred);
        const auto member = [&](std::int64_t i) { return test(m, combo_[i], cells[i]); };
        std::vector<int> part(n, -1), sizes;
        Flood flood;
        components(flood, n, verticesWhere(n, member), regionEdges(*region_, member), [&](std::int64_t i, int k) {
            if (k == static_cast<int>(sizes.size())) sizes.push_back(0);
            part[i] = k, ++sizes[k];
        });
        const int largest = static_cast<int>(std::max_element(sizes.begin(), sizes.end()) - sizes.begin());
        where(m, [&](int i) { return part[i] != largest; });
        break;
    }
    default:
        break;
    }
    std::sort(out.begin(), out.end());
    out.erase(std::unique(out.begin(), out.end()), out.end());
    return out;
}

bool Engine::reachesAlongAdjacency(const Mask& from, const Mask& to, const CellValue* cells) const {
    // Marks `from` cells outward from the `to` cells, then looks for an unmarked one.
    thread_local Flood flood;
    const int n = region_->size();
    const auto edges = regionEdges(*region_, [&](std::int64_t j) { return test(from, combo_[j], cells[j]); });
    flood.begin(n);
    for (int i = 0; i < n; ++i)
        if (test(to, combo_[i], cells[i])) edges(i, [&](std::int64_t j) { flood.add(j); });
    flood.spread(edges);
    for (int i = 0; i < n; ++i)
        if (!flood.seen(i) && test(from, combo_[i], cells[i])) return false;
    return true;
}

bool Engine::connected(const Mask& m, const CellValue* cells) const {
    thread_local Flood flood;
    const auto member = [&](std::int64_t i) { return test(m, combo_[i], cells[i]); };
    return rules::connected(flood, region_->size(), verticesWhere(region_->size(), member), regionEdges(*region_, member));
}

bool Engine::legal(const CellValue* cells) const {
    for (const Constraint& c : model_->system().constraints)
        if (!holds(c.expr, cells)) return false;
    return true;
}

std::int64_t Engine::massUnits(const CellValue* cells) const {
    std::int64_t m = 0;
    for (int i = 0; i < region_->size(); ++i) m += tables_.massUnitsOf(cells[i]);
    return m;
}

Rational Engine::number(const Expr& e, const CellValue* cells) const {
    switch (e.kind) {
    case Expr::Kind::Number: return e.value;
    case Expr::Kind::Mass: return Rational(massUnits(cells), tables_.massDenominator());
    case Expr::Kind::Add: return number(e.kids[0], cells) + number(e.kids[1], cells);
    case Expr::Kind::Sub: return number(e.kids[0], cells) - number(e.kids[1], cells);
    case Expr::Kind::Neg: return -number(e.kids[0], cells);
    case Expr::Kind::Count: return countCells(e, cells, true);
    default: return 0;
    }
}

bool Engine::holds(const Expr& e, const CellValue* cells) const {
    switch (e.kind) {
    case Expr::Kind::Bool: return e.value.num() != 0;
    case Expr::Kind::And: return holds(e.kids[0], cells) && holds(e.kids[1], cells);
    case Expr::Kind::Or: return holds(e.kids[0], cells) || holds(e.kids[1], cells);
    case Expr::Kind::Implies: return !holds(e.kids[0], cells) || holds(e.kids[1], cells);
    case Expr::Kind::Not: return !holds(e.kids[0], cells);
    case Expr::Kind::Compare: return compare(e.op, number(e.kids[0], cells), number(e.kids[1], cells));
    case Expr::Kind::Some:
    case Expr::Kind::No:
    case Expr::Kind::All: {
        const int n = countCells(e, cells, true);
        if (e.kind == Expr::Kind::All) return n == (e.kids.empty() ? region_->size() : countCells(e, cells, false));
        return e.kind == Expr::Kind::Some ? n > 0 : n == 0;
    }
    case Expr::Kind::Connected: return connected(predicateMask(e.pred), cells);
    case Expr::Kind::Reaches: {
        if (e.field < 0) return reachesAlongAdjacency(predicateMask(e.pred), predicateMask(e.target), cells);
        // The same walk as Interpreter::reaches, written again on purpose: the engine is tested
        // against the interpreter, and a shared helper would hide a bug in both.
        const Mask& from = predicateMask(e.pred);
        const Mask& to = predicateMask(e.target);
        const int n = region_->size();
        thread_local std::vector<char> state;
        thread_local std::vector<int> walk;
        state.assign(n, 0);
        for (int start = 0; start < n; ++start) {
            if (state[start] || !test(from, combo_[start], cells[start])) continue;
            walk.clear();
            int i = start;
            char verdict = 3;
            while (true) {
                if (state[i] >= 2) {
                    verdict = state[i];
                    break;
                }
                if (state[i] == 1) break;
                state[i] = 1;
                walk.push_back(i);
                const int d = cells[i] == 0 ? kAbsent : model_->alphabet().fields(cells[i])[e.field];
                const int j = d == kAbsent ? -1 : region_->neighbour(i, d);
                if (j < 0) break;
                if (test(to, combo_[j], cells[j])) {
                    verdict = 2;
                    break;
                }
                if (!test(from, combo_[j], cells[j])) break;
                i = j;
            }
            for (int w : walk) state[w] = verdict;
            if (verdict == 3) return false;
        }
        return true;
    }
    default: return false;
    }
}

}  // namespace holon::rules
