#pragma once
// The compiled rule engine: a system on a region with fixed inputs, compiled into decision tables at
// load time. Every engine that needs speed (the explorer, the planner) runs rules through this one;
// tests hold it to the reference interpreter's semantics.

#include "rules/Interpreter.h"

#include <cstdint>
#include <unordered_map>
#include <vector>

namespace holon::rules {

class Engine {
public:
    static constexpr int kMaxCells = 8;  // pattern cells per rule

    /// One rule shape anchored in the region, with the region indices of its cells.
    struct Placed {
        int shape = 0, rule = 0;
        Vec anchor;
        std::uint8_t size = 0;
        std::int32_t cells[kMaxCells] = {};
    };

    /// `inputs`: per region cell, the input bits of the problem.
    Engine(const Model& model, const Region& region, const std::vector<std::uint32_t>& inputs);
    ~Engine();
    Engine(Engine&&) noexcept;
    const Model& model() const { return *model_; }
    const Region& region() const { return *region_; }
    const std::vector<Placed>& instances() const { return placed_; }
    /// Placed instances whose pattern includes region cell i (for incremental re-checking).
    const std::vector<std::int32_t>& instancesAt(int cell) const { return byCell_[cell]; }
    Instance instance(int placed) const { return {placed_[placed].shape, placed_[placed].anchor}; }

    /// Left side and guard hold.
    bool matches(const CellValue* cells, int placed) const;
    /// Rewrites the instance's cells in place; `saved` receives their old values for undo().
    void apply(CellValue* cells, int placed, CellValue* saved) const;
    void undo(CellValue* cells, int placed, const CellValue* saved) const;
    /// Every constraint holds.
    bool legal(const CellValue* cells) const;
    /// Mass of a configuration in units of 1/massDenominator().
    std::int64_t massUnits(const CellValue* cells) const;
    std::int64_t massDenominator() const { return massDen_; }

    const std::vector<std::uint32_t>& inputs() const { return inputs_; }

    /// Evaluate a non-local expression of this system (a constraint, the goal, a property) on a
    /// configuration. Thread-safe: every predicate is compiled in the constructor.
    bool holds(const Expr& e, const CellValue* cells) const;
    Rational number(const Expr& e, const CellValue* cells) const;

private:
    struct Mask {
        std::vector<std::uint64_t> bits;  // over (input combination, cell value)
    };
    bool test(const Mask& m, int combo, CellValue v) const {
        const std::size_t i = static_cast<std::size_t>(combo) * alphabet_ + v;
        return (m.bits[i >> 6] >> (i & 63)) & 1u;
    }
    Mask compileTerm(const CellTerm& term, const std::vector<Vec>* pattern, Vec position, const CellTerm* alsoInputs) const;
    Mask compilePredicate(const CellPredicate& pred, const std::vector<Vec>* pattern, Vec position) const;
    struct GuardNode;
    struct ShapeTables;
    int comboOf(int cell) const { return cell < 0 ? emptyCombo_ : combo_[cell]; }
    bool guard(const GuardNode& g, const CellValue* cells, const Placed& p) const;
    int guardCount(const GuardNode& g, const CellValue* cells, const Placed& p) const;
    Rational guardNumber(const GuardNode& g, const CellValue* cells, const Placed& p) const;
    const Mask& predicateMask(const CellPredicate& pred) const;
    bool connected(const Mask& m, const CellValue* cells) const;

    const Model* model_;
    const Region* region_;
    std::vector<std::uint32_t> inputs_;
    int alphabet_ = 0;
    std::vector<int> combo_;             // per cell: index of its input combination
    std::vector<std::uint32_t> combos_;  // the distinct input combinations present (plus 0)
    int emptyCombo_ = 0;
    std::vector<ShapeTables> shapes_;
    std::vector<Placed> placed_;
    std::vector<std::vector<std::int32_t>> byCell_;
    std::vector<std::int64_t> mass_;
    std::int64_t massDen_ = 1;
    std::unordered_map<const CellPredicate*, Mask> predicates_;
};

}  // namespace holon::rules
