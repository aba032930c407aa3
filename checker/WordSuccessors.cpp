// Successors and legality on words for regions of at most 64 cells (see WordSuccessors.h).

#include "checker/WordSuccessors.h"

#include <algorithm>
#include <bit>

namespace holon::checker {

bool WordSuccessors::fits(const rules::Engine& engine) { return WordMatcher::fits(engine.region().size(), engine.model().alphabet().size()); }

WordSuccessors::WordSuccessors(const WordConstraints& constraints, const StateLayout& layout)
    : engine_(&constraints.engine()), constraints_(&constraints), layout_(&layout), alphabet_(engine_->model().alphabet().size()),
      planes_(layout.bitsPerCell()), words_(layout.words()), needCells_(false) {
    const rules::Engine& engine = *engine_;
    for (int s = 0; s < engine.tables().shapeCount(); ++s) needCells_ = needCells_ || engine.tables().shape(s).hasGuard;
    const int n = engine.region().size();
    placeValue_.assign(n, 1);
    for (int i = 1; i < n; ++i) placeValue_[i] = placeValue_[i - 1] * static_cast<std::uint64_t>(alphabet_);
    const auto& instances = engine.instances();
    fixed_.assign(instances.size(), 0);
    fixedDelta_.assign(instances.size() * words_, 0);
    fixedIndexDelta_.assign(instances.size(), 0);
    fixedChange_.resize(instances.size());
    firstCheck_.assign(instances.size() + 1, 0);
    CellValue cells[64] = {};
    std::vector<CellValue> pinned(instances.size() * rules::Engine::kMaxCells);  // fixed instances' left sides
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
        for (int k = 0; k < placed.size; ++k) pinned[p * rules::Engine::kMaxCells + k] = cells[placed.cells[k]];
        fixedIndexDelta_[p] = computeDelta(static_cast<int>(p), cells, &fixedDelta_[p * words_]);
        if (!constraints.onWords()) continue;
        CellValue old[rules::Engine::kMaxCells];
        for (int k = 0; k < placed.size; ++k) old[k] = cells[placed.cells[k]];
        for (int k = 0; k < placed.size; ++k) constraints.addChange(placed.cells[k], old[k], engine.rewritten(placed, k, old), fixedChange_[p]);
        const auto checks = constraints.compileChange(fixedChange_[p]);
        firstCheck_[p] = static_cast<std::uint32_t>(checks_.size());
        checks_.insert(checks_.end(), checks.begin(), checks.end());
        firstCheck_[p + 1] = static_cast<std::uint32_t>(checks_.size());
    }
    findUnique(pinned);
    matcher_ = std::make_unique<WordMatcher>(engine);
    if (constraints.onWords()) addFilters();
    matcher_->finish();
}

void WordSuccessors::addFilters() {
    // Per shape, the (word, pattern cell) removals every instance of it makes; the instances'
    // cut-cell checks on them become the matcher's filter.
    using Kind = WordConstraints::Check::Kind;
    const auto& instances = engine_->instances();
    std::vector<std::vector<std::pair<int, int>>> common(engine_->model().shapes().size());
    std::vector<char> seen(common.size(), 0);
    for (std::size_t p = 0; p < instances.size(); ++p) {
        const int shape = instances[p].shape;
        std::vector<std::pair<int, int>> removals;
        if (fixed_[p])
            for (std::uint32_t i = firstCheck_[p]; i < firstCheck_[p + 1]; ++i)
                if (checks_[i].kind == Kind::Removed) {
                    const int cell = std::countr_zero(checks_[i].bits);
                    for (int k = 0; k < instances[p].size; ++k)
                        if (instances[p].cells[k] == cell) removals.push_back({checks_[i].index, k});
                }
        if (!seen[shape]) common[shape] = removals, seen[shape] = 1;
        else std::erase_if(common[shape], [&](const auto& r) { return std::find(removals.begin(), removals.end(), r) == removals.end(); });
    }
    for (std::size_t shape = 0; shape < common.size(); ++shape)
        for (const auto& [word, k] : common[shape]) {
            auto it = std::find(filteredWord_.begin(), filteredWord_.end(), word);
            if (it == filteredWord_.end()) {
                if (static_cast<int>(filteredWord_.size()) == kMaxFilters) continue;
                filteredWord_.push_back(word);
                matcher_->addWordTest();
                it = filteredWord_.end() - 1;
            }
            matcher_->require(static_cast<int>(shape), k, static_cast<int>(it - filteredWord_.begin()));
        }
    // The filtered instances' cut-cell checks are now the matcher's: drop them.
    std::vector<WordConstraints::Check> kept;
    std::vector<std::uint32_t> first(firstCheck_.size(), 0);
    for (std::size_t p = 0; p < instances.size(); ++p) {
        first[p] = static_cast<std::uint32_t>(kept.size());
        const auto& filtered = common[instances[p].shape];
        for (std::uint32_t i = firstCheck_[p]; i < firstCheck_[p + 1]; ++i) {
            const WordConstraints::Check& c = checks_[i];
            const bool dropped = c.kind == Kind::Removed && std::find(filteredWord_.begin(), filteredWord_.end(), c.index) != filteredWord_.end() &&
                                 std::any_of(filtered.begin(), filtered.end(), [&](const auto& r) {
                                     return r.first == c.index && instances[p].cells[r.second] == std::countr_zero(c.bits);
                                 });
            if (!dropped) kept.push_back(c);
        }
    }
    first[instances.size()] = static_cast<std::uint32_t>(kept.size());
    checks_ = std::move(kept);
    firstCheck_ = std::move(first);
}

void WordSuccessors::findUnique(const std::vector<CellValue>& pinned) {
    // Instance q can have p's effect only if it rewrites every cell p changes, so the candidates
    // are the instances that read p's first changed cell. A fixed q has it only with the same
    // delta and a left side that agrees with p's on the cells they share; an instance whose delta
    // depends on the states might have it.
    const auto& instances = engine_->instances();
    constexpr int kCells = rules::Engine::kMaxCells;
    unique_.assign(instances.size(), 0);
    for (std::size_t p = 0; p < instances.size(); ++p) {
        if (!fixed_[p]) continue;
        const std::uint64_t* delta = &fixedDelta_[p * words_];
        int first = -1;
        for (int k = 0; k < instances[p].size && first < 0; ++k)
            for (int j = 0; j < planes_; ++j)
                if ((layout_->plane(delta, j) >> instances[p].cells[k]) & 1u) first = instances[p].cells[k];
        // An instance that changes nothing (`A => *`) has the effect of every other such instance
        // anywhere in the region: its self-loop is one edge with theirs (each was counted).
        bool unique = first >= 0;
        for (const std::int32_t q : engine_->instancesAt(first < 0 ? instances[p].cells[0] : first)) {
            if (!unique) break;
            if (q == static_cast<std::int32_t>(p)) continue;
            if (!fixed_[q]) {
                unique = false;
                break;
            }
            if (!std::equal(delta, delta + words_, &fixedDelta_[static_cast<std::size_t>(q) * words_])) continue;
            bool agree = true;
            for (int a = 0; a < instances[p].size; ++a)
                for (int b = 0; b < instances[q].size; ++b)
                    if (instances[p].cells[a] == instances[q].cells[b] && pinned[p * kCells + a] != pinned[q * kCells + b]) agree = false;
            if (agree) {
                unique = false;
                break;
            }
        }
        unique_[p] = unique;
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
            (static_cast<std::uint64_t>(now) - old[k]) * placeValue_[c];  // wraps: unsigned arithmetic
    }
    for (int w = 0; w < words_; ++w) delta[w] = 0;
    for (int j = 0; j < planes_; ++j)
        if (planeDelta[j]) layout_->flip(delta, j, planeDelta[j]);
    return indexDelta;
}

void WordSuccessors::occupiedOf(const std::uint64_t* packed, std::uint64_t* occupied) const {
    // The cells in state v, by doubling: after plane j, occupied[v] for v < 2^(j+1) holds the
    // cells whose low j + 1 bits are v's.
    const int n = engine_->region().size();
    occupied[0] = n >= 64 ? ~std::uint64_t{0} : (std::uint64_t{1} << n) - 1;
    for (int j = 0, half = 1; j < planes_; ++j, half <<= 1) {
        const std::uint64_t plane = layout_->plane(packed, j);
        for (int v = 0; v < half; ++v) occupied[v + half] = occupied[v] & plane, occupied[v] &= ~plane;
    }
}

void WordSuccessors::load(const std::uint64_t* packed, Loaded& out, bool withCells, bool prune) const {
    occupiedOf(packed, out.occupied);
    if (withCells || needCells_) layout_->unpack(packed, out.cells);
    if (constraints_->onWords()) constraints_->wordsOf(out.occupied, out.legal.words), constraints_->prepare(out.legal);
    for (std::size_t f = 0; f < filteredWord_.size(); ++f) out.allowed[f] = prune ? ~constraints_->cutsOf(out.legal, filteredWord_[f]) : ~std::uint64_t{0};
}

bool WordSuccessors::legal(const std::uint64_t* packed, const Loaded& parent, int placed) const {
    if (!constraints_->onWords()) {
        CellValue cells[64];
        layout_->unpack(packed, cells);
        return engine_->legal(cells);
    }
    if (fixed_[placed])
        return constraints_->legalAfter(parent.legal, checks_.data() + firstCheck_[placed], firstCheck_[placed + 1] - firstCheck_[placed], fixedChange_[placed]);
    WordConstraints::Words now;
    std::uint64_t occupied[64];
    occupiedOf(packed, occupied);
    constraints_->wordsOf(occupied, now);
    return constraints_->legalOn(now, &parent.legal);
}
}  // namespace holon::checker
