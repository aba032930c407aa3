#pragma once
// The parts of `holon path` behind checker/Path.h: what a rule instance reads and writes, rule
// steps run backwards, a single-threaded search tree of packed states, and the two searches that
// use them (bidirectional breadth-first and A*). Path.cpp chooses among them.

#include "checker/Path.h"
#include "checker/StateStore.h"

#include <algorithm>
#include <string>
#include <vector>

namespace holon::checker {

/// Per placed instance of an engine: the region cells it may write (a pattern cell whose rewrite
/// is not the identity on some state its left side accepts) and the cells it reads (its pattern
/// cells, required-empty blocking cells included, and the neighbours of every pattern cell a guard
/// quantifies around). Each is worked out when asked: kept for every instance, they took 1.7 s
/// and a gigabyte on a 4-million-cell region, for the few instances of one path.
class Footprints {
public:
    /// The cells one instance may write (sorted) and reads (sorted, distinct).
    struct Footprint {
        std::vector<int> writes, reads;
    };
    /// One pass over the instances for maxWrites, reading the job's deadline and signals.
    explicit Footprints(const rules::Engine& engine);
    /// The most cells one instance writes: a step changes at most this many cells.
    int maxWrites() const { return maxWrites_; }
    Footprint of(int placed) const;
    /// a's reads meet b's writes or b's reads meet a's writes: the two cannot fire together.
    static bool interfere(const Footprint& a, const Footprint& b);

private:
    const rules::Engine* engine_;
    int maxWrites_ = 0;
};

/// Rule steps run backwards: the configurations s with an instance p that leads to a given s'
/// (p's left side and guard hold in s, and firing p in s gives s'). Every such s differs from s'
/// only in p's pattern cells, and each pattern cell's old state is constrained by its own new
/// state (or, for a cell whose old state moves to another cell, fixed by that cell's new state),
/// so the candidates are a product of per-cell sets; each is then checked forwards, which makes
/// the predecessors exact whatever the rule's guard and inputs. Like Engine::forEachMatch, this
/// leaves the system's constraints to the caller: s is a step of the search only when it is legal.
class Predecessors {
public:
    /// A rule whose firings may each come from more candidates than this is not run backwards.
    static constexpr std::uint64_t kMaxCandidates = 1024;
    explicit Predecessors(const rules::Engine& engine);
    /// Empty when every instance runs backwards; else why the search must go forwards only.
    const std::string& irreversible() const { return irreversible_; }
    /// f(placed, before) for every predecessor `before` of `after` (a region's cells), legal or
    /// not, and the instance leading from it; `before` is valid during the call only. Not
    /// thread-safe.
    template <class F>
    void forEach(const CellValue* after, F&& f) const;

private:
    const rules::Engine* engine_;
    int alphabet_;
    int combos_;
    /// Per rule shape (the same for all its instances), pattern cell k, input combination c and
    /// new state v: the old states of the cell that become v, a range of old_, at
    /// ranges_[first_[shape] + (k * combos + c) * alphabet + v]. A copy term's ranges are one list.
    struct Range {
        std::uint32_t begin = 0, end = 0;
    };
    std::vector<std::size_t> first_;  // per shape; unused shapes have none
    std::vector<Range> ranges_;
    std::vector<CellValue> old_;
    std::vector<std::vector<std::int8_t>> copiedFrom_;  // per shape and pattern cell k: the cell k takes its state from, or -1
    std::string irreversible_;
    mutable std::vector<CellValue> before_;  // scratch: `after` with one candidate written in
};

/// Single-threaded breadth-first or best-first search tree: packed states, each with the state
/// and instance it was reached from. Ids are handed out in insertion order.
class SearchTree {
public:
    explicit SearchTree(const rules::Engine& engine);
    /// The id of `cells`, and whether this call added it (with its parent and instance).
    std::pair<StateId, bool> add(const CellValue* cells, StateId parent, int via);
    StateId find(const CellValue* cells) const;
    /// find() for `cells` that differ from stored state `base` at most in the instance's cells:
    /// only those are packed anew.
    StateId findNear(StateId base, const rules::Engine::Placed& instance, const CellValue* cells) const;
    /// find() for the configuration the last find of `other` (of the same engine) looked for.
    StateId findAsIn(const SearchTree& other) const;
    /// Stores the configuration the last find() did not find (a search checks a configuration's
    /// legality only when it is new: every stored one is legal).
    StateId addMissing(StateId parent, int via);
    void cells(StateId id, CellValue* out) const { store_.layout().unpack(store_.state(id), out); }
    StateId parent(StateId id) const { return parent_[id]; }
    int via(StateId id) const { return via_[id]; }
    void relink(StateId id, StateId parent, int via) { parent_[id] = parent, via_[id] = via; }
    std::uint64_t size() const { return store_.size(); }
    std::size_t bytes() const { return store_.bytes() + parent_.capacity() * sizeof(StateId) + via_.capacity() * sizeof(int); }
    /// The tree's path from a root to `id`, roots first.
    std::vector<StateId> pathTo(StateId id) const;

private:
    int cells_;
    StateStore store_;
    std::uint64_t reserved_ = 0;
    mutable std::vector<std::uint64_t> packed_;  // the last configuration added or looked for
    mutable std::uint64_t hash_ = 0;             // its hash
    std::vector<StateId> parent_;
    std::vector<int> via_;
};

/// The limits of PathQuery for the searches that do not run on the explorer: states, time and
/// memory checked as states are stored, and progress reported about every half second.
class SearchMeter {
public:
    explicit SearchMeter(const PathQuery& query);
    /// Asked before a state is stored beside `stored` ones: StopReason::MaxStates when it would be
    /// one more than the cap allows (Limits::storable), else StopReason::Finished.
    StopReason admit(std::uint64_t stored) const;
    /// Asked after: StopReason::Finished while within the memory bound and the budget.
    StopReason check(std::uint64_t states, std::size_t bytes, int depth);
    /// Asked of every candidate step, stored or not: the deadline and the signals, read every 16th
    /// call, or every call on a region of more than 2^16 cells. One candidate's legality check can
    /// cost as much as the region is large (pixel's connectivity), so the clock read after every
    /// 1,024 stored states came minutes late, and every 16th call still 2 s late on 4 million cells.
    StopReason poll();
    ExploreStats finish(std::uint64_t states, std::size_t bytes, int depth, StopReason why) const;

private:
    const PathQuery* query_;
    Budget budget_;
    double lastReport_ = 0;
    std::uint32_t ticks_ = 0, polls_ = 0, pollEvery_;
};

class Evaluator;
/// Whether `next`, which differs from the configuration `evaluator` holds (`loaded`) at most in
/// the instance's cells, is legal; the evaluator is left as it was.
bool legalNear(Evaluator& evaluator, const rules::Engine::Placed& instance, const CellValue* loaded, const CellValue* next);

/// Bidirectional breadth-first search from query.from forwards and query.to backwards (needs
/// predecessors.irreversible() empty), one level at a time on the side with the smaller frontier,
/// until a state stored on one side is found on the other.
PathResult bidirectionalPath(const rules::Engine& engine, const Predecessors& predecessors, const PathQuery& query);
/// A* from query.from to query.to with the bound ceil(cells differing from the target /
/// footprints.maxWrites()).
PathResult aStarPath(const rules::Engine& engine, const Footprints& footprints, const PathQuery& query);

template <class F>
void Predecessors::forEach(const CellValue* after, F&& f) const {
    const auto& placed = engine_->instances();
    std::copy(after, after + engine_->region().size(), before_.begin());
    // Per pattern cell its candidates [lo, hi): a list of old_, or the one state `fixed` when
    // the cell's old state moves on to another cell.
    const CellValue *lo[rules::Engine::kMaxCells], *hi[rules::Engine::kMaxCells], *at[rules::Engine::kMaxCells];
    CellValue fixed[rules::Engine::kMaxCells], old[rules::Engine::kMaxCells];
    for (std::size_t p = 0; p < placed.size(); ++p) {
        const auto& inst = placed[p];
        const Range* ranges = &ranges_[first_[inst.shape]];
        const std::int8_t* copied = copiedFrom_[inst.shape].data();
        bool possible = true;
        for (int k = 0; k < inst.size && possible; ++k) {
            const int cell = inst.cells[k];
            const Range r = ranges[(static_cast<std::size_t>(k) * combos_ + engine_->comboOfCell(cell)) * alphabet_ + after[cell]];
            lo[k] = old_.data() + r.begin, hi[k] = old_.data() + r.end;
            possible = r.begin != r.end;
        }
        for (int k = 0; k < inst.size && possible; ++k) {
            const int j = copied[k];
            if (j < 0) continue;
            const CellValue v = after[inst.cells[k]];
            possible = std::find(lo[j], hi[j], v) != hi[j];
            fixed[j] = v, lo[j] = &fixed[j], hi[j] = lo[j] + 1;
        }
        if (!possible) continue;
        // Every combination of the cells' candidates, odometer-wise, cell 0 turning fastest.
        for (int k = 0; k < inst.size; ++k) at[k] = lo[k];
        for (;;) {
            for (int k = 0; k < inst.size; ++k) before_[inst.cells[k]] = old[k] = *at[k];
            bool exact = engine_->matches(before_.data(), static_cast<int>(p));
            for (int k = 0; k < inst.size && exact; ++k) exact = engine_->rewritten(inst, k, old) == after[inst.cells[k]];
            if (exact) f(static_cast<int>(p), before_.data());
            int k = 0;
            while (k < inst.size && ++at[k] == hi[k]) at[k] = lo[k], ++k;
            if (k == inst.size) break;
        }
        for (int k = 0; k < inst.size; ++k) before_[inst.cells[k]] = after[inst.cells[k]];
    }
}

}  // namespace holon::checker
