#pragma once
// The planner's compiled rule engine: the system's RuleTables placed on a Board by index
// arithmetic, so an ensemble of millions of cells costs one byte of state and one byte of input
// combination per cell and no per-instance tables. Instances are (anchor, rule shape) pairs, the
// anchor being the board index of the shape's first pattern cell.

#include "planner/Board.h"
#include "rules/RuleTables.h"

#include <cstdint>
#include <vector>

namespace holon::planner {

/// What applying a rule shape does, read off its tables.
enum class ShapeKind {
    Relabel,   // occupancy and every cell's mass unchanged (the planner's labels, trees)
    Transfer,  // occupancy unchanged, mass moves between cells (a resource allocator's move)
    Motion,    // a cell becomes occupied or empty (creation, deletion) or a module moves
};

class BoxEngine {
public:
    static constexpr std::uint8_t kOutside = 255;  // combination of padding cells: no rule reaches them
    using Value = std::uint8_t;

    /// How far (in coordinates) any rule shape reaches from its anchor, guards included: the
    /// padding a Board needs.
    static int reach(const rules::RuleTables& tables);

    /// `combo`: per board cell, its input combination's index in `tables`, or kOutside.
    BoxEngine(const rules::RuleTables& tables, const Board& board, std::vector<std::uint8_t> combo);

    const rules::RuleTables& tables() const { return *tables_; }
    const Board& board() const { return *board_; }
    int shapeCount() const { return tables_->shapeCount(); }
    int ruleOf(int shape) const { return ruleOf_[shape]; }
    ShapeKind kind(int shape) const { return kinds_[shape]; }
    std::uint8_t combo(std::int64_t cell) const { return combo_[cell]; }
    /// Index steps of a shape's pattern cells from its anchor.
    const std::vector<std::int64_t>& cellSteps(int shape) const { return cellSteps_[shape]; }
    /// Index steps of the pattern cells an instance of the shape may change.
    const std::vector<std::int64_t>& writeSteps(int shape) const { return writeSteps_[shape]; }
    /// Index steps of every cell a shape's instance reads (pattern and guard neighbourhoods).
    const std::vector<std::int64_t>& readSteps(int shape) const { return readSteps_[shape]; }
    /// Union over shapes of readSteps: a change at cell c can only affect anchors c - r.
    const std::vector<std::int64_t>& influence() const { return influence_; }

    /// Left side and guard of the instance hold. With `cell` >= 0, as if that cell held `value`
    /// (an allocator asking "would this rule fire if the resource here were different?").
    bool matches(const Value* cells, std::int64_t anchor, int shape, std::int64_t cell = -1, Value value = 0) const;
    /// Calls f(shape) for each shape enabled at the anchor (only shapes whose first cell accepts
    /// the anchor's state are evaluated); returns the number of evaluations.
    template <class F>
    int forEachMatchAt(const Value* cells, std::int64_t anchor, F&& f) const {
        if (combo_[anchor] == kOutside) return 0;
        const auto& candidates = tables_->shapesByFirst(combo_[anchor], cells[anchor]);
        for (std::int32_t s : candidates)
            if (matches(cells, anchor, s)) f(s);
        return static_cast<int>(candidates.size());
    }
    /// Rewrites the instance in place; `old` (kMaxCells entries) receives the previous values.
    void apply(Value* cells, std::int64_t anchor, int shape, Value* old) const;

private:
    const rules::RuleTables* tables_;
    const Board* board_;
    std::vector<std::uint8_t> combo_;
    std::vector<int> ruleOf_;
    std::vector<ShapeKind> kinds_;
    std::vector<std::vector<std::int64_t>> cellSteps_, writeSteps_, readSteps_;
    std::vector<std::int64_t> influence_;
};

}  // namespace holon::planner
