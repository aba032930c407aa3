// The gradient allocator: a distributed resource manager for general_n (seed 000 §IV-B asks for
// one that sends "the D to regions of anticipated deletion and the C to regions of anticipated
// creation"; §V blames the random one's slow diffusion for general_1's long deletion phase).
//
// Every metamodule learns, from its own cells only, whether it is a demand: a creation or deletion
// instance it takes part in would fire if its resource were heavier (it needs a C) or lighter (it
// needs a D). Demands seed two hop-count fields, relaxed by one message exchange between lattice
// neighbours per round (distance-vector routing, as in the hormone/gradient fields of the modular
// robotics literature). A transfer fires only when it moves the heavy resource down the "needs C"
// field or the light one down the "needs D" field, i.e. when it lowers their sum.
// Which resource is heavy or light, and which rules create or delete, is read off the compiled
// rule tables: nothing here names a rule of a particular system.

#include "planner/Allocator.h"
#include "planner/Execution.h"

#include <algorithm>
#include <cstring>

namespace holon::planner {

std::unique_ptr<Allocator> gradientAllocator(const Problem& problem, std::uint64_t seed);
std::unique_ptr<Allocator> randomAllocator(std::uint64_t seed);

namespace {

constexpr std::uint32_t kFar = 1u << 30;

class GradientAllocator final : public Allocator {
public:
    GradientAllocator(const Problem& problem, std::uint64_t seed) : problem_(&problem), fallback_(randomAllocator(seed)) {
        const rules::Alphabet& alphabet = problem.model->alphabet();
        const PlannerSchema& s = problem.schema;
        heavier_.assign(static_cast<std::size_t>(alphabet.size()), 0);
        lighter_.assign(static_cast<std::size_t>(alphabet.size()), 0);
        for (int v = 1; v < alphabet.size() && s.resource >= 0; ++v) {
            std::vector<int> f = alphabet.fields(static_cast<rules::CellValue>(v));
            f[s.resource] = s.creator;
            heavier_[v] = static_cast<BoxEngine::Value>(std::max(0, alphabet.find(f)));
            f[s.resource] = s.full;
            lighter_[v] = static_cast<BoxEngine::Value>(std::max(0, alphabet.find(f)));
        }
        const BoxEngine& engine = *problem.engine;
        for (int sh = 0; sh < engine.shapeCount(); ++sh)
            if (engine.kind(sh) == ShapeKind::Motion) motions_.push_back(sh);
        needC_.assign(problem.cells.size(), kFar), needD_.assign(problem.cells.size(), kFar);
        const rules::RuleTables& tables = *problem.tables;
        alphabet_ = static_cast<std::size_t>(tables.alphabet());
        accepting_.resize(static_cast<std::size_t>(tables.comboCount()) * alphabet_);
        for (int c = 0; c < tables.comboCount(); ++c)
            for (std::size_t v = 0; v < alphabet_; ++v)
                for (int sh : motions_)
                    for (std::size_t k = 0; k < engine.cellSteps(sh).size(); ++k)
                        if (tables.test(tables.shape(sh).lhs[k], c, static_cast<rules::CellValue>(v)))
                            accepting_[static_cast<std::size_t>(c) * alphabet_ + v].push_back({sh, engine.cellSteps(sh)[k]});
        // What a change at a cell can affect at once: the demand of every cell in a motion
        // instance that reads it, and the field values of its neighbours.
        const Board& board = *problem.board;
        for (int sh : motions_)
            for (std::int64_t step : engine.cellSteps(sh))
                for (std::int64_t r : engine.readSteps(sh)) around_.push_back(step - r);
        for (int d = 0; d < board.lattice().degree(); ++d) around_.push_back(board.step(d));
        around_.push_back(0);
        std::sort(around_.begin(), around_.end());
        around_.erase(std::unique(around_.begin(), around_.end()), around_.end());
        // The first round sees every cell change from empty.
        seen_.assign(problem.cells.size(), 0), mark_.assign(problem.cells.size(), 0), demand_.assign(problem.cells.size(), 0);
    }
    std::string name() const override { return "gradient"; }

    bool update(const Execution& ex) override {
        const auto& cells = ex.cells();
        const BoxEngine& engine = ex.engine();
        const Board& board = *problem_->board;
        const int degree = board.lattice().degree();
        // Only the metamodules whose inputs changed recompute: a cell whose own neighbourhood and
        // whose neighbours' values are as they were would compute the value it holds. So a round
        // costs what changed in it, not the board (a full pass per round made 10^6 metamodules
        // take hours), and the fields evolve as if every metamodule recomputed (up to the cap
        // below, which a cell sees anew only when it recomputes).
        const std::size_t n = cells.size();
        const auto* now = reinterpret_cast<const unsigned char*>(cells.data());
        for (std::size_t w = 0; w < n; w += 8) {
            const std::size_t len = std::min<std::size_t>(8, n - w);
            if (std::memcmp(now + w, seen_.data() + w, len) == 0) continue;
            for (std::size_t x = w; x < w + len; ++x) {
                if (cells[x] == seen_[x]) continue;
                occupied_ += (cells[x] != 0) - (seen_[x] != 0);
                seen_[x] = cells[x];
                for (std::int64_t d : around_) dirty(static_cast<std::int64_t>(x) + d, kDemand);
            }
        }
        // No path is longer than the ensemble: capping there stops a field cut off from every
        // demand from counting up to kFar one round at a time (distance-vector count-to-infinity).
        const std::uint32_t far = static_cast<std::uint32_t>(std::min<std::int64_t>(kFar, 2 * occupied_ + 2));
        updates_.clear();
        for (std::int64_t i : dirty_) {
            const BoxEngine::Value v = cells[i];
            if (mark_[i] & kDemand)
                demand_[i] = static_cast<char>((v && wouldEnable(ex, engine, i, heavier_[v]) ? kNeedsC : 0) | (v && wouldEnable(ex, engine, i, lighter_[v]) ? kNeedsD : 0));
            mark_[i] = 0;
            std::uint32_t c = kFar, dd = kFar;
            if (v) {
                std::uint32_t bestC = kFar, bestD = kFar;
                for (int d = 0; d < degree; ++d) {
                    const std::int64_t j = i + board.step(d);
                    if (!cells[j]) continue;
                    bestC = std::min(bestC, needC_[j]), bestD = std::min(bestD, needD_[j]);
                }
                c = demand_[i] & kNeedsC ? 0 : bestC + 1 >= far ? kFar : bestC + 1;
                dd = demand_[i] & kNeedsD ? 0 : bestD + 1 >= far ? kFar : bestD + 1;
            }
            if (c != needC_[i] || dd != needD_[i]) updates_.push_back({i, c, dd});
        }
        dirty_.clear();
        for (const Update& u : updates_) {
            needC_[u.cell] = u.c, needD_[u.cell] = u.d;
            for (int d = 0; d < degree; ++d) dirty(u.cell + board.step(d), kValue);
        }
        bool moved = !updates_.empty();
        // A round in which nothing fired although the fields had settled: the fields see no way
        // forward (a destroyer may need a D that only a detour brings), so the paper's randomizer
        // moves resources until the next creation or deletion.
        const RunStats& st = ex.stats();
        const std::int64_t motions = st.creations + st.deletions;
        if (motions != motionsAtUpdate_) anyTransfer_ = false;
        if (st.steps == stepsAtUpdate_ && !moved && !anyTransfer_) anyTransfer_ = moved = true;
        else if (anyTransfer_) moved = fallback_->update(ex) || moved;
        stepsAtUpdate_ = st.steps, motionsAtUpdate_ = motions;
        return moved;
    }

    bool wants(const Execution& ex, std::int64_t anchor, int shape) const override {
        if (anyTransfer_) return fallback_->wants(ex, anchor, shape);
        // The cell that loses mass gives its heavy resource to the one that gains it.
        const auto [from, to] = transferEnds(ex, anchor, shape);
        if (from < 0) return false;
        // The heavy resource goes down the creators' field. The light one goes down the
        // destroyers' field only where no creation is in reach: a transfer that brings a D also
        // takes a C away, and sending C's off from where creations wait cost a quarter more
        // transfers on the block experiments (1.62x against 1.32x of the bound at 2304).
        if (needC_[to] != needC_[from]) return needC_[to] < needC_[from];
        if (needC_[to] != kFar) return false;
        return needD_[from] < needD_[to];
    }

private:
    /// Whether a motion instance that cell i takes part in is disabled now but would be enabled
    /// with i in state `instead`.
    bool wouldEnable(const Execution& ex, const BoxEngine& engine, std::int64_t i, BoxEngine::Value instead) const {
        const BoxEngine::Value v = ex.cells()[i];
        if (!instead || instead == v) return false;
        const std::uint8_t combo = engine.combo(i);
        if (combo == BoxEngine::kOutside) return false;
        // Only the motion cells whose test the new state passes: most instances around a cell fail
        // there, and the fields ask this of every cell near a change.
        for (const auto& [sh, step] : accepting_[static_cast<std::size_t>(combo) * alphabet_ + instead]) {
            const std::int64_t anchor = i - step;
            if (engine.combo(anchor) == BoxEngine::kOutside || ex.enabled(anchor, sh)) continue;
            if (engine.matches(ex.cells().data(), anchor, sh, i, instead)) return true;
        }
        return false;
    }

    const Problem* problem_;
    std::vector<BoxEngine::Value> heavier_, lighter_;
    std::vector<int> motions_;
    // Per input combination and state: the motion shapes and steps to their anchor from a pattern
    // cell whose test that state passes.
    std::vector<std::vector<std::pair<int, std::int64_t>>> accepting_;
    std::size_t alphabet_ = 0;
    // mark_ bits: the cell is in dirty_ (its value is recomputed), its demand is recomputed too.
    static constexpr char kValue = 1, kDemand = 3;
    // demand_ bits: a creation or deletion waits for this cell to be heavier / lighter.
    static constexpr char kNeedsC = 1, kNeedsD = 2;
    void dirty(std::int64_t i, char how) {
        if (problem_->engine->combo(i) == BoxEngine::kOutside) return;
        if (!mark_[i]) dirty_.push_back(i);
        mark_[i] |= how;
    }
    struct Update {
        std::int64_t cell;
        std::uint32_t c, d;
    };
    std::vector<std::uint32_t> needC_, needD_;
    std::vector<BoxEngine::Value> seen_;  // the cells as of the previous update
    std::vector<char> mark_, demand_;
    std::vector<std::int64_t> dirty_, around_;
    std::vector<Update> updates_;
    std::int64_t occupied_ = 0;
    std::int64_t stepsAtUpdate_ = -1, motionsAtUpdate_ = 0;
    bool anyTransfer_ = false;
    std::unique_ptr<Allocator> fallback_;
};

}  // namespace

std::unique_ptr<Allocator> gradientAllocator(const Problem& problem, std::uint64_t seed) { return std::make_unique<GradientAllocator>(problem, seed); }

}  // namespace holon::planner
