#pragma once
// The compiled rule engine: a system's RuleTables placed on a region with fixed inputs, and the
// system's non-local expressions (constraints, the goal, properties) evaluated over the same
// tables, cell by cell. Every engine that needs speed runs rules through these tables; tests hold
// this one to the reference interpreter's semantics. The explorer's word-level successors and
// incremental legality are checker/'s (WordMatcher, WordConstraints).

#include "rules/Interpreter.h"
#include "rules/RuleTables.h"

#include <cstdint>
#include <functional>
#include <unordered_map>
#include <vector>

namespace holon::rules {

/// A region quantifier with a cell guard (`all(H: no nbr _)`): its guard is compiled as a one-cell
/// pattern's, not as predicates over the region.
bool hasCellGuard(const Expr& e);

class Engine {
public:
    static constexpr int kMaxCells = RuleTables::kMaxCells;
    using GuardNode = RuleTables::GuardNode;
    using Mask = RuleTables::Mask;

    /// One rule shape anchored in the region, with the region indices of its cells.
    struct Placed {
        int shape = 0, rule = 0;
        Vec anchor;
        std::uint8_t size = 0;
        const std::int32_t* cells = nullptr;  // region indices of the pattern cells (in the engine's pool)
    };

    /// `inputs`: per region cell, the input bits of the problem. With `everyInputCombination`, the
    /// tables cover all 2^k combinations of the k inputs, for encodings where inputs are unknown.
    /// `onlyShapes`, when not empty: the only shapes compiled and placed (a drawing of one rule).
    /// `checkpoint`, when given, is called every few thousand placements and may throw to stop the
    /// build (a deadline or a signal: placing every shape on 4 million cells takes a minute).
    Engine(const Model& model, const Region& region, const std::vector<std::uint32_t>& inputs, bool everyInputCombination = false,
           const std::vector<int>& onlyShapes = {}, const std::function<void()>& checkpoint = {});
    /// An upper estimate of the bytes an engine on `region` holds, known before it is built: every
    /// shape placed at every cell, its cells in the pool and in each cell's list (with a vector's
    /// doubling), and the arrays per cell: 0.5 KB a cell for intermediate, 200 KB for hex_delete.
    static std::uint64_t bytesFor(const Model& model, const Region& region);
    /// The bytes this engine holds for its region (its arrays' capacities), not its tables.
    std::uint64_t regionBytes() const;
    const Model& model() const { return *model_; }
    const Region& region() const { return *region_; }
    const std::vector<Placed>& instances() const { return placed_; }
    /// Placed instances whose pattern includes region cell i (for incremental re-checking).
    const std::vector<std::int32_t>& instancesAt(int cell) const { return byCell_[cell]; }
    /// The instance of `shape` whose first pattern cell is region cell `first`, or -1.
    std::int32_t instanceAt(int first, int shape) const { return placedIndex_[static_cast<std::size_t>(first) * tables_.shapeCount() + shape]; }
    Instance instance(int placed) const { return {placed_[placed].shape, placed_[placed].anchor}; }

    /// Left side and guard hold.
    bool matches(const CellValue* cells, int placed) const;
    /// The guard of an instance whose left side holds (true without one).
    bool guardHolds(const CellValue* cells, int placed) const;
    /// Calls f(placed) once for every instance whose left side and guard hold, cell by cell,
    /// trying only the shapes whose first cell accepts that cell's state.
    template <class F>
    void forEachMatch(const CellValue* cells, F&& f) const {
        const int shapes = tables_.shapeCount();
        for (int c = 0; c < region_->size(); ++c) {
            for (std::int32_t s : tables_.shapesByFirst(combo_[c], cells[c])) {
                const std::int32_t p = placedIndex_[static_cast<std::size_t>(c) * shapes + s];
                if (p >= 0 && matchesAfterFirst(cells, p)) f(p);
            }
        }
    }
    /// The state pattern cell k of an instance takes when the instance fires; `old[j]` is the
    /// state of its pattern cell j before.
    CellValue rewritten(const Placed& p, int k, const CellValue* old) const {
        const RuleTables::Shape& t = tables_.shape(p.shape);
        return t.copyFrom[k] >= 0 ? old[t.copyFrom[k]] : t.rhs[k][old[k]];
    }
    /// Rewrites the instance's cells in place; `saved` receives their old values for undo().
    void apply(CellValue* cells, int placed, CellValue* saved) const;
    void undo(CellValue* cells, int placed, const CellValue* saved) const;
    /// Every constraint holds.
    bool legal(const CellValue* cells) const;
    /// Mass of a configuration in units of 1/massDenominator().
    std::int64_t massUnits(const CellValue* cells) const;
    std::int64_t massDenominator() const { return tables_.massDenominator(); }
    const RuleTables& tables() const { return tables_; }

    const std::vector<std::uint32_t>& inputs() const { return inputs_; }

    // ---- read access to the compiled tables, per (input combination, state), for encoders ----
    int comboCount() const { return tables_.comboCount(); }
    std::uint32_t comboInputs(int combo) const { return tables_.comboInputs(combo); }
    int comboOfCell(int cell) const { return combo_[cell]; }
    bool lhsAccepts(int placed, int k, int combo, CellValue v) const;
    /// The pattern cell whose old state cell k takes (a move), or -1.
    int rhsCopyFrom(int placed, int k) const;
    CellValue rhsValue(int placed, int k, CellValue v) const;
    const GuardNode* guardOf(int placed) const;
    /// The compiled cell guard of a region quantifier of this system (`all(H: no nbr _)`).
    const GuardNode& cellGuardOf(const Expr& quantifier) const { return cellGuards_.at(&quantifier); }
    /// Whether a region quantifier's cell guard holds at region cell `cell`.
    bool cellGuardHolds(const Expr& quantifier, const CellValue* cells, std::int32_t cell) const;
    bool guardAccepts(const GuardNode& node, int site, int combo, CellValue v) const;
    /// The compiled mask of a predicate of this system's expressions; predicates of equal text
    /// share one (the same object).
    const Mask& predicateMask(const CellPredicate& pred) const;
    bool predicateAccepts(const CellPredicate& pred, int combo, CellValue v) const { return tables_.test(predicateMask(pred), combo, v); }
    std::int64_t massUnitsOf(CellValue v) const { return tables_.massUnitsOf(v); }

    /// Evaluate a non-local expression of this system (a constraint, the goal, a property) on a
    /// configuration. Thread-safe: every predicate is compiled in the constructor.
    bool holds(const Expr& e, const CellValue* cells) const;
    /// Whether one cell in state v satisfies a predicate of this system's expressions.
    bool cellMatches(const CellPredicate& pred, int cell, CellValue v) const { return predicateAccepts(pred, combo_[cell], v); }
    Rational number(const Expr& e, const CellValue* cells) const;

private:
    /// Left side and guard hold, the first pattern cell known to match. Most cells are decided by
    /// the states their pattern cell accepts under some and under every input combination.
    bool matchesAfterFirst(const CellValue* cells, int placed) const {
        const Placed& p = placed_[placed];
        const RuleTables::Shape& t = tables_.shape(p.shape);
        const CellTest* tests = &cellTests_[firstCellTest_[p.shape]];
        for (int k = 1; k < p.size; ++k) {
            const CellValue v = cells[p.cells[k]];
            if (v < 64) {
                if (!((tests[k].any >> v) & 1u)) return false;
                if ((tests[k].all >> v) & 1u) continue;
            }
            if (!test(t.lhs[k], combo_[p.cells[k]], v)) return false;
        }
        return !t.hasGuard || guardHolds(cells, placed);
    }
    struct CellTest {
        std::uint64_t any, all;  // states below 64 accepted under some / every input combination
    };
    std::vector<CellTest> cellTests_;  // per shape, per pattern cell
    std::vector<int> firstCellTest_;   // per shape: its first entry in cellTests_
    bool test(const Mask& m, int combo, CellValue v) const { return tables_.test(m, combo, v); }
    bool connected(const Mask& m, const CellValue* cells) const;
    /// reaches(from, nbr, to): every `from` cell has a path through `from` cells to a `to` cell.
    bool reachesAlongAdjacency(const Mask& from, const Mask& to, const CellValue* cells) const;
    /// reaches(from, field, to): every `from` cell follows its field to a `to` cell, acyclically.
    bool reachesAlongField(const Expr& e, const CellValue* cells) const;
    /// Cells satisfying a region quantifier's predicate (and, if asked, its cell guard).
    int countCells(const Expr& e, const CellValue* cells, bool withCellGuard) const;

    const Model* model_;
    const Region* region_;
    std::vector<std::uint32_t> inputs_;
    RuleTables tables_;
    std::vector<int> combo_;  // per cell: index of its input combination in tables_
    std::vector<Placed> placed_;
    std::vector<std::int32_t> cellPool_;     // Placed::cells point here
    std::vector<std::int32_t> placedIndex_;  // [cell * shapes + shape]: the instance anchored there, or -1
    std::vector<std::vector<std::int32_t>> byCell_;
    std::unordered_map<const CellPredicate*, int> predicateIndex_;
    std::vector<Mask> predicateMasks_;                       // distinct predicates only: equal text, one mask
    std::unordered_map<const Expr*, GuardNode> cellGuards_;  // per quantifier with a cell guard
};

}  // namespace holon::rules
