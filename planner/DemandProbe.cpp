// A metamodule's view of the resource demand around it (see DemandProbe.h): the state it would
// be in one resource heavier or lighter, and the motion instances that change would enable.

#include "planner/DemandProbe.h"
#include "planner/Execution.h"

#include <algorithm>

namespace holon::planner {

DemandProbe::DemandProbe(const Problem& problem) {
    const rules::Alphabet& alphabet = problem.model->alphabet();
    const PlannerSchema& s = problem.schema;
    const auto size = static_cast<std::size_t>(alphabet.size());
    heavier_.assign(size, 0), lighter_.assign(size, 0), heavy_.assign(size, 0), light_.assign(size, 0), final_.assign(size, 0);
    for (int v = 1; v < alphabet.size() && s.resource >= 0; ++v) {
        std::vector<int> f = alphabet.fields(static_cast<rules::CellValue>(v));
        heavy_[v] = f[s.resource] == s.creator, light_[v] = f[s.resource] == s.full, final_[v] = f[s.label] == s.final;
        f[s.resource] = s.creator;
        heavier_[v] = static_cast<BoxEngine::Value>(std::max(0, alphabet.find(f)));
        f[s.resource] = s.full;
        lighter_[v] = static_cast<BoxEngine::Value>(std::max(0, alphabet.find(f)));
    }
    const BoxEngine& engine = *problem.engine;
    const rules::RuleTables& tables = *problem.tables;
    alphabet_ = static_cast<std::size_t>(tables.alphabet());
    accepting_.resize(static_cast<std::size_t>(tables.comboCount()) * alphabet_);
    carrier_.assign(accepting_.size(), 0);
    for (int sh = 0; sh < engine.shapeCount(); ++sh)
        for (int c = 0; c < tables.comboCount(); ++c)
            for (std::size_t v = 0; v < alphabet_; ++v)
                for (std::size_t k = 0; k < engine.cellSteps(sh).size(); ++k) {
                    if (!tables.test(tables.shape(sh).lhs[k], c, static_cast<rules::CellValue>(v))) continue;
                    const std::size_t at = static_cast<std::size_t>(c) * alphabet_ + v;
                    if (engine.kind(sh) == ShapeKind::Motion) accepting_[at].push_back({sh, engine.cellSteps(sh)[k]});
                    if (engine.kind(sh) == ShapeKind::Transfer) carrier_[at] = 1;
                }
}

bool DemandProbe::needsHeavier(const Execution& ex, std::int64_t i) const { return wouldEnable(ex, i, heavier_[ex.cells()[i]]); }
bool DemandProbe::needsLighter(const Execution& ex, std::int64_t i) const { return wouldEnable(ex, i, lighter_[ex.cells()[i]]); }

bool DemandProbe::carrier(const Execution& ex, std::int64_t i) const {
    const std::uint8_t combo = ex.engine().combo(i);
    return combo != BoxEngine::kOutside && carrier_[static_cast<std::size_t>(combo) * alphabet_ + ex.cells()[i]];
}

bool DemandProbe::wouldEnable(const Execution& ex, std::int64_t i, BoxEngine::Value instead) const {
    const BoxEngine::Value v = ex.cells()[i];
    if (!instead || instead == v) return false;
    const BoxEngine& engine = ex.engine();
    const std::uint8_t combo = engine.combo(i);
    if (combo == BoxEngine::kOutside) return false;
    for (const auto& [sh, step] : accepting_[static_cast<std::size_t>(combo) * alphabet_ + instead]) {
        const std::int64_t anchor = i - step;
        if (engine.combo(anchor) == BoxEngine::kOutside || ex.enabled(anchor, sh)) continue;
        if (engine.matches(ex.cells().data(), anchor, sh, i, instead)) return true;
        // Or, for the instance's own metamodule (its anchor: the leaf a deletion removes, the
        // creator of a creation), enabled once one more of its cells had the other resource too.
        // A P leaf holding a C next to a partner holding a C waits for two D's (D&P D => ...);
        // asked one change at a time neither cell is a demand, no field reaches them, and the run
        // waited for the randomizer (general3, a spiral start: its last two deletions took 51,567
        // of 54,357 rounds).
        // Only the anchor: marking the partners too drew D's to every C beside a leaf and cost the
        // optimal allocator's gradient fallback up to 40% more transfers on the shape bench.
        if (i != anchor) continue;
        for (const std::int64_t s : engine.cellSteps(sh)) {
            const std::int64_t j = anchor + s;
            const BoxEngine::Value w = ex.cells()[j];
            if (j == i || !w) continue;
            for (const BoxEngine::Value other : {heavier_[w], lighter_[w]})
                if (other != w && other && engine.matches(ex.cells().data(), anchor, sh, i, instead, j, other)) return true;
        }
    }
    return false;
}

DemandStencil::DemandStencil(const Problem& problem, const DemandProbe& probe)
    : problem_(&problem), probe_(&probe), alphabet_(static_cast<std::size_t>(problem.tables->alphabet())), index_(alphabet_ * alphabet_, -1) {}

std::int32_t DemandStencil::build(BoxEngine::Value was, BoxEngine::Value now) const {
    // A cell's demand reads the motion instances it is a pattern cell of: from the changed cell at
    // read site r of such an instance, the cell at its pattern step is step - r away.
    const BoxEngine& engine = *problem_->engine;
    const rules::RuleTables& tables = *problem_->tables;
    const Board& board = *problem_->board;
    std::vector<std::int64_t> steps{0};
    for (int sh = 0; sh < engine.shapeCount(); ++sh) {
        if (engine.kind(sh) != ShapeKind::Motion) continue;
        const auto cells = engine.cellSteps(sh);
        for (const rules::RuleTables::Site site : tables.readSites(sh)) {
            // Asked of a partner, the demand questions also try it one resource heavier or lighter.
            if (!tables.distinguishes(sh, site, was, now) && !tables.distinguishes(sh, site, probe_->heavierOf(was), probe_->heavierOf(now)) &&
                !tables.distinguishes(sh, site, probe_->lighterOf(was), probe_->lighterOf(now)))
                continue;
            const std::int64_t r = cells[static_cast<std::size_t>(site.cell)] + (site.direction < 0 ? 0 : board.step(site.direction));
            for (std::int64_t step : cells) steps.push_back(step - r);
        }
    }
    std::sort(steps.begin(), steps.end());
    steps.erase(std::unique(steps.begin(), steps.end()), steps.end());
    lists_.push_back(std::move(steps));
    return static_cast<std::int32_t>(lists_.size() - 1);
}

}  // namespace holon::planner
