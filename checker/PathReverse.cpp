// What rule instances read and write, and rule steps run backwards (checker/PathSearch.h): the
// two facts about a system that a search towards a given configuration needs beyond its forward
// steps. Both are computed once per engine from the compiled tables (left-side masks, rewrites,
// copy terms, guard sites), so they follow inputs exactly as the forward engine does.

#include "checker/PathSearch.h"

#include "rules/StopSignals.h"

#include <algorithm>

namespace holon::checker {

Footprints::Footprints(const rules::Engine& engine) : engine_(&engine) {
    const rules::RuleTables& tables = engine.tables();
    const auto& placed = engine.instances();
    for (std::size_t p = 0; p < placed.size(); ++p) {
        if (p % (1u << 16) == 0) rules::StopSignals::checkJob("preparing the search");
        int writes = 0;  // an instance's pattern cells are distinct
        for (int k = 0; k < placed[p].size; ++k) writes += tables.mayWrite(placed[p].shape, k, engine.comboOfCell(placed[p].cells[k]));
        maxWrites_ = std::max(maxWrites_, writes);
    }
}

Footprints::Footprint Footprints::of(int placed) const {
    const auto& inst = engine_->instances()[placed];
    Footprint f;
    for (int k = 0; k < inst.size; ++k)
        if (engine_->tables().mayWrite(inst.shape, k, engine_->comboOfCell(inst.cells[k]))) f.writes.push_back(inst.cells[k]);
    for (const rules::RuleTables::Site site : engine_->tables().readSites(inst.shape)) {
        const int cell = inst.cells[site.cell];
        if (const int n = site.direction < 0 ? cell : engine_->region().neighbour(cell, site.direction); n >= 0) f.reads.push_back(n);
    }
    std::sort(f.writes.begin(), f.writes.end());
    std::sort(f.reads.begin(), f.reads.end());
    f.reads.erase(std::unique(f.reads.begin(), f.reads.end()), f.reads.end());
    return f;
}

bool Footprints::interfere(const Footprint& a, const Footprint& b) {
    const auto meet = [](const std::vector<int>& x, const std::vector<int>& y) {
        for (std::size_t i = 0, j = 0; i < x.size() && j < y.size();)
            if (x[i] == y[j]) return true;
            else if (x[i] < y[j]) ++i;
            else ++j;
        return false;
    };
    return meet(a.reads, b.writes) || meet(b.reads, a.writes);
}

Predecessors::Predecessors(const rules::Engine& engine)
    : engine_(&engine), alphabet_(engine.tables().alphabet()), combos_(engine.comboCount()), before_(engine.region().size()) {
    const auto& placed = engine.instances();
    const int shapes = engine.tables().shapeCount();
    first_.assign(shapes, 0), copiedFrom_.assign(shapes, {});
    std::vector<char> built(shapes, 0);
    for (std::size_t p = 0; p < placed.size(); ++p) {
        const auto& inst = placed[p];
        if (built[inst.shape]) continue;
        built[inst.shape] = 1;
        const int pi = static_cast<int>(p);  // the shape's tables, read through one of its instances
        first_[inst.shape] = ranges_.size();
        ranges_.resize(ranges_.size() + static_cast<std::size_t>(inst.size) * combos_ * alphabet_);
        std::uint64_t worst = 1;  // the most candidates one firing can have
        for (int k = 0; k < inst.size; ++k) {
            const int from = engine.rhsCopyFrom(pi, k);
            copiedFrom_[inst.shape].push_back(static_cast<std::int8_t>(from));
            for (int combo = 0; combo < combos_; ++combo) {
                Range* ranges = &ranges_[first_[inst.shape] + (static_cast<std::size_t>(k) * combos_ + combo) * alphabet_];
                std::vector<std::vector<CellValue>> becomes(from >= 0 ? 1 : alphabet_);  // per new state (a copy term: one for all)
                for (int u = 0; u < alphabet_; ++u) {
                    const auto state = static_cast<CellValue>(u);
                    // A copy term takes any old state its left side accepts (the state it moves
                    // on to constrains another cell); a rewrite, those it maps to the new state.
                    if (engine.lhsAccepts(pi, k, combo, state)) becomes[from >= 0 ? 0 : engine.rhsValue(pi, k, state)].push_back(state);
                }
                for (std::size_t v = 0; v < becomes.size(); ++v) {
                    const Range r{static_cast<std::uint32_t>(old_.size()), static_cast<std::uint32_t>(old_.size() + becomes[v].size())};
                    old_.insert(old_.end(), becomes[v].begin(), becomes[v].end());
                    if (from >= 0) std::fill(ranges, ranges + alphabet_, r);
                    else ranges[v] = r;
                }
            }
            std::size_t most = 1;
            for (std::size_t e = 0; e < static_cast<std::size_t>(combos_) * alphabet_; ++e) {
                const Range r = ranges_[first_[inst.shape] + static_cast<std::size_t>(k) * combos_ * alphabet_ + e];
                most = std::max<std::size_t>(most, r.end - r.begin);
            }
            worst = std::min<std::uint64_t>(worst * most, kMaxCandidates + 1);
        }
        if (worst > kMaxCandidates && irreversible_.empty())
            irreversible_ = "rule '" + engine.model().rules()[inst.rule].name + "' is not run backwards: one of its steps may come from more than " +
                            std::to_string(kMaxCandidates) + " candidate configurations";
    }
}

}  // namespace holon::checker
