// The compiled rule engine. Each rule shape is compiled, once per load, into decision tables
// (rules/RuleTables): for every pattern cell a bit mask over (input combination, cell state) for its
// left side, and a state -> state table for its right side; guards become per-direction masks over
// the neighbours. The engine places every shape at every anchor of the region where it fits, so
// testing an instance is a handful of table look-ups with no allocation. Non-local expressions
// (constraints, goals, properties) are evaluated over the same masks, cell by cell: this is the
// one evaluator of the compiled semantics, exactly the reference interpreter's
// (tests/rules/EngineTest.cpp runs both side by side); checker/WordConstraints decides the
// constraints faster on words for the explorer and is tested against this one.

#include "rules/Engine.h"

#include "rules/Components.h"

#include "rules/Error.h"
#include "rules/Limits.h"
#include "rules/Printer.h"

#include <algorithm>

namespace holon::rules {

bool hasCellGuard(const Expr& e) {
    const bool quantifier = e.kind == Expr::Kind::Count || e.kind == Expr::Kind::All || e.kind == Expr::Kind::Some || e.kind == Expr::Kind::No;
    return quantifier && e.around < 0 && !e.kids.empty();
}

namespace {

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

Engine::Engine(const Model& model, const Region& region, const std::vector<std::uint32_t>& inputs, bool everyInputCombination, const std::vector<int>& onlyShapes,
               const std::function<void()>& checkpoint)
    : model_(&model), region_(&region), inputs_(inputs.size() == static_cast<std::size_t>(region.size()) ? inputs : std::vector<std::uint32_t>(region.size(), 0)),
      tables_(model, combosFor(model, inputs_, everyInputCombination), onlyShapes) {
    combo_.resize(region.size());
    for (int i = 0; i < region.size(); ++i) combo_[i] = tables_.comboIndex(inputs_[i]);
    byCell_.resize(region.size());
    // Room for every shape placed at every cell, so that the pools never double (bytesFor counts
    // this); only the compiled ones: a drawing's engine of one shape among 3,480 reserved them all.
    std::size_t shapes = 0, poolCells = 0;
    for (int s = 0; s < tables_.shapeCount(); ++s)
        if (!tables_.shape(s).lhs.empty()) ++shapes, poolCells += model.shapes()[s].offsets.size();
    placed_.reserve(shapes * region.cells().size());
    cellPool_.reserve(poolCells * region.cells().size());
    std::uint64_t tried = 0;
    for (int s = 0; s < static_cast<int>(model.shapes().size()); ++s) {
        if (tables_.shape(s).lhs.empty()) continue;  // not among onlyShapes
        const RuleShape& shape = model.shapes()[s];
        for (std::size_t i = 0; i < region.cells().size(); ++i) {
            // Every 2^16 placements in all: a small region's build (microseconds) is never cut.
            if (checkpoint && (++tried & 0xffff) == 0) checkpoint();
            const Vec cell = region.cells()[i];
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
}

std::uint64_t Engine::bytesFor(const Model& model, const Region& region) {
    // Per cell and shape: the instance, its slot in placedIndex_, its cells in the pool (reserved)
    // and in the lists of the cells it covers (8 bytes a cell: a list doubles as it grows). Per cell: its list
    // (with the allocator's header), its input combination and inputs.
    std::uint64_t perCell = sizeof(std::vector<std::int32_t>) + 16 + sizeof(int) + sizeof(std::uint32_t);
    for (const RuleShape& shape : model.shapes()) perCell += sizeof(Placed) + sizeof(std::int32_t) + 12 * shape.offsets.size();
    return checkedProduct({perCell, static_cast<std::uint64_t>(region.size())});
}

std::uint64_t Engine::regionBytes() const {
    std::uint64_t bytes = placed_.capacity() * sizeof(Placed) + (cellPool_.capacity() + placedIndex_.capacity()) * sizeof(std::int32_t) +
                          combo_.capacity() * sizeof(int) + inputs_.capacity() * sizeof(std::uint32_t);
    for (const auto& list : byCell_) bytes += sizeof(list) + 16 + list.capacity() * sizeof(std::int32_t);
    return bytes;
}

bool Engine::matches(const CellValue* cells, int placed) const {
    const Placed& p = placed_[placed];
    return test(tables_.shape(p.shape).lhs[0], combo_[p.cells[0]], cells[p.cells[0]]) && matchesAfterFirst(cells, placed);
}

bool Engine::guardHolds(const CellValue* cells, int placed) const {
    const Placed& p = placed_[placed];
    const RuleTables::Shape& t = tables_.shape(p.shape);
    return !t.hasGuard || tables_.guard(t.guard, RegionCells{region_, cells, combo_.data()}, p.cells);
}

bool Engine::cellGuardHolds(const Expr& quantifier, const CellValue* cells, std::int32_t cell) const {
    return tables_.guard(cellGuards_.at(&quantifier), RegionCells{region_, cells, combo_.data()}, &cell);
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

bool Engine::lhsAccepts(int placed, int k, int combo, CellValue v) const { return test(tables_.shape(placed_[placed].shape).lhs[k], combo, v); }
int Engine::rhsCopyFrom(int placed, int k) const { return tables_.shape(placed_[placed].shape).copyFrom[k]; }
CellValue Engine::rhsValue(int placed, int k, CellValue v) const { return tables_.shape(placed_[placed].shape).rhs[k][v]; }
const Engine::GuardNode* Engine::guardOf(int placed) const {
    const RuleTables::Shape& t = tables_.shape(placed_[placed].shape);
    return t.hasGuard ? &t.guard : nullptr;
}
bool Engine::guardAccepts(const GuardNode& node, int site, int combo, CellValue v) const { return tables_.guardAccepts(node, site, combo, v); }

int Engine::countCells(const Expr& e, const CellValue* cells, bool withCellGuard) const {
    const Mask& m = predicateMask(e.pred);
    const GuardNode* guard = withCellGuard && !e.kids.empty() ? &cellGuards_.at(&e) : nullptr;
    int n = 0;
    for (std::int32_t i = 0; i < region_->size(); ++i)
        n += test(m, combo_[i], cells[i]) && (!guard || tables_.guard(*guard, RegionCells{region_, cells, combo_.data()}, &i));
    return n;
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

bool Engine::reachesAlongField(const Expr& e, const CellValue* cells) const {
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
        break;  // conditions: the parser types every expression, so none is read as a number
    }
    return 0;
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
    case Expr::Kind::Reaches:
        return e.field < 0 ? reachesAlongAdjacency(predicateMask(e.pred), predicateMask(e.target), cells) : reachesAlongField(e, cells);
    case Expr::Kind::Number:
    case Expr::Kind::Mass:
    case Expr::Kind::Add:
    case Expr::Kind::Sub:
    case Expr::Kind::Neg:
    case Expr::Kind::Count:
        break;  // numbers: the parser types every expression, so none is read as a condition
    }
    return false;
}

}  // namespace holon::rules
