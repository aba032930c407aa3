#pragma once
// Incremental evaluation of the constraints while one thread walks through configurations that
// differ in a few cells: the explorer's cell-by-cell successors, and --all's walk over every
// candidate. On regions of at most 64 cells every predicate the constraints read is kept as a word
// (WordConstraints), updated per changed cell; larger regions fall back to rules::Engine::legal.

#include "checker/WordConstraints.h"

#include <cstdint>
#include <vector>

namespace holon::checker {

class Evaluator {
public:
    explicit Evaluator(const WordConstraints& constraints);
    void load(const CellValue* cells);
    const CellValue* cells() const { return cells_.data(); }
    void apply(int placed, CellValue* saved);
    void undo(int placed, const CellValue* saved);
    void set(int cell, CellValue value);
    /// The next configuration in candidate order (cell 0 the fastest digit), wrapping to all
    /// zeros after the last; the few cells that change are followed incrementally.
    void advance();
    bool legal() const;

private:
    /// Cell `cell` now holds `value`: its bit in every predicate word follows.
    void updateMembers(int cell, CellValue value);
    const WordConstraints* constraints_;
    const rules::Engine* engine_;
    std::vector<CellValue> cells_;
    std::vector<std::uint64_t> members_;  // per predicate word
    std::int64_t mass_ = 0;
    bool small_;
};

}  // namespace holon::checker
