// The incremental evaluator (see Evaluator.h): a changed cell updates its bit in each predicate
// word with one look-up of the states its input combination accepts, and the mass by its
// states' masses, so a configuration one rule step away is judged without reading the others.

#include "checker/Evaluator.h"

#include <algorithm>

namespace holon::checker {

Evaluator::Evaluator(const WordConstraints& constraints)
    : constraints_(&constraints), engine_(&constraints.engine()), cells_(engine_->region().size(), 0), members_(constraints.predicates(), 0),
      small_(engine_->region().size() <= 64) {}

void Evaluator::load(const CellValue* cells) {
    std::copy(cells, cells + cells_.size(), cells_.begin());
    mass_ = 0;
    for (std::size_t i = 0; i < cells_.size(); ++i) mass_ += engine_->massUnitsOf(cells_[i]);
    if (!small_) return;
    std::fill(members_.begin(), members_.end(), 0);
    for (std::size_t i = 0; i < cells_.size(); ++i) updateMembers(static_cast<int>(i), cells_[i]);
}

void Evaluator::set(int cell, CellValue value) {
    const CellValue old = cells_[cell];
    if (old == value) return;
    mass_ += engine_->massUnitsOf(value) - engine_->massUnitsOf(old);
    cells_[cell] = value;
    updateMembers(cell, value);
}

void Evaluator::updateMembers(int cell, CellValue value) {
    if (!small_) return;
    const std::uint64_t bit = std::uint64_t{1} << cell;
    const int combo = engine_->comboOfCell(cell);
    const std::size_t predicates = members_.size();
    if (predicates == 0) return;  // a system without constraints: nothing to track (and no row to index)
    if (value < 64) {             // the common case, branch-free: one word of accepted states per predicate
        const std::uint64_t* accepted = constraints_->acceptedStates(combo);
        for (std::size_t k = 0; k < predicates; ++k) members_[k] = (members_[k] & ~bit) | (((accepted[k] >> value) & 1u) << cell);
        return;
    }
    for (std::size_t k = 0; k < predicates; ++k) {
        if (constraints_->accepts(static_cast<int>(k), combo, value)) members_[k] |= bit;
        else members_[k] &= ~bit;
    }
}

void Evaluator::advance() {
    const int a = engine_->tables().alphabet();
    for (std::size_t i = 0; i < cells_.size(); ++i) {
        const CellValue v = static_cast<CellValue>(cells_[i] + 1 == a ? 0 : cells_[i] + 1);
        set(static_cast<int>(i), v);
        if (v != 0) return;
    }
}

void Evaluator::apply(int placed, CellValue* saved) {
    const rules::Engine::Placed& p = engine_->instances()[placed];
    for (int k = 0; k < p.size; ++k) saved[k] = cells_[p.cells[k]];
    for (int k = 0; k < p.size; ++k) set(p.cells[k], engine_->rewritten(p, k, saved));
}

void Evaluator::undo(int placed, const CellValue* saved) {
    const rules::Engine::Placed& p = engine_->instances()[placed];
    for (int k = p.size - 1; k >= 0; --k) set(p.cells[k], saved[k]);
}

bool Evaluator::legal() const {
    if (!small_) return engine_->legal(cells_.data());
    return constraints_->holdsOn(members_.data(), mass_, cells_.data());
}

}  // namespace holon::checker
