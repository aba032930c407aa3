// Successors and legality on words for regions of at most 64 cells (see WordSuccessors.h).

#include "checker/WordSuccessors.h"

#include <bit>

namespace holon::checker {

bool WordSuccessors::fits(const rules::Engine& engine) {
    return engine.matchesOnWords() && engine.region().size() <= 64 && engine.model().alphabet().size() <= 64;
}

WordSuccessors::WordSuccessors(const rules::Engine& engine, const StateLayout& layout)
    : engine_(&engine), layout_(&layout), alphabet_(engine.model().alphabet().size()),
      planes_(layout.bitsPerCell()), words_(layout.words()), needCells_(engine.hasGuards()) {
    const int n = engine.region().size();
    placeValue_.assign(n, 1);
    for (int i = 1; i < n; ++i) placeValue_[i] = placeValue_[i - 1] * static_cast<std::uint64_t>(alphabet_);
    const auto& instances = engine.instances();
    fixed_.assign(instances.size(), 0);
    fixedDelta_.assign(instances.size() * words_, 0);
    fixedIndexDelta_.assign(instances.size(), 0);
    CellValue cells[64] = {};
    for (std::size_t p = 0; p < instances.size(); ++p) {
        // Fixed when every pattern cell's left side admits exactly one state for its inputs: then
        // a match says what every cell holds, and the delta follows.
        const rules::Engine::Placed& placed = instances[p];
        bool fixed = true;
        for (int k = 0; k < placed.size && fixed; ++k) {
            const int c = placed.cells[k], combo = engine.comboOfCell(c);
            int admitted = 0;
            for (int v = 0; v < alphabet_; ++v)
                if (engine.lhsAccepts(static_cast<int>(p), k, combo, static_cast<CellValue>(v)))
                    ++admitted, cells[c] = static_cast<CellValue>(v);
            fixed = admitted == 1;
        }
        if (!fixed) {
            needCells_ = true;
            continue;
        }
        fixed_[p] = 1;
        fixedIndexDelta_[p] = computeDelta(static_cast<int>(p), cells, &fixedDelta_[p * words_]);
    }
}

std::uint64_t WordSuccessors::computeDelta(int placed, const CellValue* cells, std::uint64_t* delta) const {
    const rules::Engine::Placed& p = engine_->instances()[placed];
    CellValue old[rules::Engine::kMaxCells];
    for (int k = 0; k < p.size; ++k) old[k] = cells[p.cells[k]];
    std::uint64_t planeDelta[kMaxPlanes] = {};
    std::uint64_t indexDelta = 0;
    for (int k = 0; k < p.size; ++k) {
        const int c = p.cells[k];
        const CellValue now = engine_->rewritten(p, k, old);
        for (unsigned change = static_cast<unsigned>(now ^ old[k]); change; change &= change - 1)
            planeDelta[std::countr_zero(change)] ^= std::uint64_t{1} << c;
        indexDelta +=
            (static_cast<std::uint64_t>(now) - old[k]) * placeValue_[c]; // wraps: unsigned arithmetic
    }
    for (int w = 0; w < words_; ++w) delta[w] = 0;
    for (int j = 0; j < planes_; ++j)
        if (planeDelta[j]) layout_->flip(delta, j, planeDelta[j]);
    return indexDelta;
}

void WordSuccessors::occupiedOf(const std::uint64_t* packed, std::uint64_t* occupied) const {
    // The cells in state v: the planes where v has a 1, and the complements where it has a 0.
    std::uint64_t planes[kMaxPlanes];
    for (int j = 0; j < planes_; ++j) planes[j] = layout_->plane(packed, j);
    const int n = engine_->region().size();
    const std::uint64_t all = n >= 64 ? ~std::uint64_t{0} : (std::uint64_t{1} << n) - 1;
    for (int v = 0; v < alphabet_; ++v) {
        std::uint64_t in = all;
        for (int j = 0; j < planes_; ++j) in &= (v >> j) & 1 ? planes[j] : ~planes[j];
        occupied[v] = in;
    }
}

void WordSuccessors::load(const std::uint64_t* packed, Loaded& out, bool withCells) const {
    occupiedOf(packed, out.occupied);
    if (withCells || needCells_) layout_->unpack(packed, out.cells);
}

bool WordSuccessors::legal(const std::uint64_t* packed, const Loaded* parent) const {
    if (!engine_->constraintsOnWords()) {
        CellValue cells[64];
        layout_->unpack(packed, cells);
        return engine_->legal(cells);
    }
    std::uint64_t occupied[64];
    occupiedOf(packed, occupied);
    return engine_->legalIn(occupied, parent ? parent->occupied : nullptr);
}

} // namespace holon::checker
