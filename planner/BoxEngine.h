#pragma once
// The planner's compiled rule engine: the system's RuleTables placed on a Board by index
// arithmetic, so an ensemble of millions of cells costs one byte of state and one byte of input
// combination per cell and no per-instance tables. Instances are (anchor, rule shape) pairs, the
// anchor being the board index of the shape's first pattern cell.

#include "planner/Board.h"
#include "rules/RuleTables.h"

#include <cstdint>
#include <span>
#include <vector>

namespace holon::planner {

/// What applying a rule shape does, read off its tables.
enum class ShapeKind {
    Relabel,   // occupancy and every cell's mass unchanged (the planner's labels, trees)
    Transfer,  // occupancy unchanged, cells exchange their masses (a resource allocator's move)
    Motion,    // a cell becomes occupied or empty (creation, deletion), a module moves, or mass
               // moves otherwise (a stage of a general_n creation or deletion through a partial)
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
    /// Asks for the cache line of a cell's combination ahead of forEachMatchAt.
    void prefetchCombo(std::int64_t cell) const { __builtin_prefetch(&combo_[cell]); }
    /// Index steps of a shape's pattern cells from its anchor.
    std::span<const std::int64_t> cellSteps(int shape) const { return {steps_.data() + programs_[shape].at, static_cast<std::size_t>(programs_[shape].cells)}; }
    /// Index steps of the pattern cells an instance of the shape may change (RuleTables::mayWrite).
    std::span<const std::int64_t> writeSteps(int shape) const { return {writePool_.data() + programs_[shape].writeAt, programs_[shape].writes}; }
    /// Index steps of every cell a shape's instance reads (RuleTables::readSites: its pattern cells
    /// and the neighbours its guard reads).
    std::span<const std::int64_t> readSteps(int shape) const { return {readPool_.data() + programs_[shape].readAt, programs_[shape].reads}; }
    /// Union over shapes of readSteps: a change at cell c can only affect anchors c - r.
    const std::vector<std::int64_t>& influence() const { return influence_; }

    /// Left side and guard of the instance hold. With `cell` >= 0, as if that cell held `value`, and
    /// `cell2` >= 0 held `value2` (an allocator asking "would this rule fire if the resources here
    /// were different?").
    bool matches(const Value* cells, std::int64_t anchor, int shape, std::int64_t cell = -1, Value value = 0, std::int64_t cell2 = -1, Value value2 = 0) const;
    /// Calls f(shape) for each shape enabled at the anchor (only shapes whose first cell accepts
    /// the anchor's state are evaluated); returns the number of evaluations.
    template <class F>
    int forEachMatchAt(const Value* cells, std::int64_t anchor, F&& f) const {
        if (cells[anchor] == 0 && !emptyAnchors_) return 0;  // padding and empty cells, without loading the combination
        const std::uint8_t combo = combo_[anchor];
        if (combo == kOutside) return 0;
        const auto& candidates = tables_->shapesByFirst(combo, cells[anchor]);
        for (std::int32_t s : candidates) {
            const Hot h = hot_[s];
            if (othersMatch(cells, anchor, tests_.data() + h.first, h.count) && (!h.guard || guardHolds(cells, anchor, s))) f(s);
        }
        return static_cast<int>(candidates.size());
    }
    /// Rewrites the instance in place; `old` (kMaxCells entries) receives the previous values.
    void apply(Value* cells, std::int64_t anchor, int shape, Value* old) const;

private:
    /// A shape flattened: its index steps and right-side tables from `at` in steps_, rhs_ and
    /// copyFrom_, and the cells an instance reads and writes (the synchronous scheduler's conflict
    /// test) in readPool_ and writePool_. Variable length, so that a large rule (a hex hole move
    /// reads 19 cells) does not spread every small one over more cache lines.
    struct Program {
        int cells = 0;
        std::uint32_t at = 0, readAt = 0, writeAt = 0;
        std::size_t reads = 0, writes = 0;
    };
    /// The test of one pattern cell after the first, packed so that the tests of every shape
    /// share a few cache lines (the enabled-set updates run them millions of times).
    struct Test {
        std::int64_t step;
        const std::uint64_t* lhs;
        // Whether the cell's input combination is needed: not when its left side ignores the
        // inputs and rejects the empty state (padding is empty, so it cannot match either).
        bool needsCombo;
        // The states (below 64) some combination accepts: tested first, so that a cell whose state
        // no combination accepts (most cells) costs no load of its combination.
        std::uint64_t anyCombo;
    };
    struct Hot {
        std::uint32_t first = 0, count = 0;  // the shape's tests in tests_
        bool guard = false;
    };
    /// Pattern cells 1.. accept their states (shapesByFirst already tested cell 0).
    bool othersMatch(const Value* cells, std::int64_t anchor, const Test* t, std::uint32_t count) const {
        for (std::uint32_t k = 0; k < count; ++k) {
            const std::int64_t i = anchor + t[k].step;
            std::size_t bit = cells[i];
            if (t[k].needsCombo) {
                if (bit < 64 && !((t[k].anyCombo >> bit) & 1u)) return false;
                const std::uint8_t c = combo_[i];
                if (c == kOutside) return false;
                bit += static_cast<std::size_t>(c) * alphabet_;
            }
            if (!((t[k].lhs[bit >> 6] >> (bit & 63)) & 1u)) return false;
        }
        return true;
    }
    bool guardHolds(const Value* cells, std::int64_t anchor, int shape) const;

    const rules::RuleTables* tables_;
    const Board* board_;
    std::vector<std::uint8_t> combo_;
    std::vector<int> ruleOf_;
    std::vector<ShapeKind> kinds_;
    std::vector<std::int64_t> influence_;
    std::vector<Program> programs_;
    std::vector<std::int64_t> steps_, readPool_, writePool_;
    std::vector<const rules::CellValue*> rhs_;  // null for a copy term
    std::vector<int> copyFrom_;
    std::vector<Hot> hot_;
    std::vector<Test> tests_;
    std::size_t alphabet_;
    bool emptyAnchors_ = false;  // some shape's first pattern cell accepts the empty state
};

}  // namespace holon::planner
