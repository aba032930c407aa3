// The search tree, legality near a stored state and the limits of the path searches that run
// beside the explorer (checker/PathSearch.h). Single-threaded on purpose: a bidirectional or A* search stores a few
// hundred thousand states where the forward one stores millions, so it gains less from threads
// than it would lose to the explorer's level barriers, and one thread keeps its ids in order.

#include "checker/Evaluator.h"
#include "checker/PathSearch.h"

#include <algorithm>

namespace holon::checker {

SearchTree::SearchTree(const rules::Engine& engine)
    : cells_(engine.region().size()), store_(StateLayout(engine.region().size(), engine.tables().alphabet())), packed_(store_.layout().words()) {}

std::pair<StateId, bool> SearchTree::add(const CellValue* cells, StateId parent, int via) {
    if (const StateId id = find(cells); id != kNoState) return {id, false};
    return {addMissing(parent, via), true};
}

StateId SearchTree::find(const CellValue* cells) const {
    store_.layout().pack(cells, packed_.data());
    hash_ = store_.layout().hash(packed_.data());
    return store_.find(packed_.data(), hash_);
}

StateId SearchTree::findNear(StateId base, const rules::Engine::Placed& instance, const CellValue* cells) const {
    const StateLayout& layout = store_.layout();
    std::copy(store_.state(base), store_.state(base) + layout.words(), packed_.begin());
    for (int k = 0; k < instance.size; ++k) layout.set(packed_.data(), instance.cells[k], cells[instance.cells[k]]);
    hash_ = layout.hash(packed_.data());
    return store_.find(packed_.data(), hash_);
}

StateId SearchTree::findAsIn(const SearchTree& other) const {
    std::copy(other.packed_.begin(), other.packed_.end(), packed_.begin());
    hash_ = other.hash_;
    return store_.find(packed_.data(), hash_);
}

StateId SearchTree::addMissing(StateId parent, int via) {
    if (store_.capacityUsed() + 1 > reserved_) {
        // Room doubles, so the table is rebuilt log(n) times.
        const std::uint64_t more = std::max<std::uint64_t>(reserved_, 1 << 12);
        store_.reserve(more);
        reserved_ = store_.capacityUsed() + more;
    }
    StateStore::IdBlock one{0, 0, 1};
    const StateId id = store_.insert(packed_.data(), hash_, one).first;
    parent_.push_back(parent), via_.push_back(via);
    return id;
}

std::vector<StateId> SearchTree::pathTo(StateId id) const {
    std::vector<StateId> path;
    for (StateId s = id; s != kNoState; s = parent_[s]) path.push_back(s);
    std::reverse(path.begin(), path.end());
    return path;
}

bool legalNear(Evaluator& evaluator, const rules::Engine::Placed& instance, const CellValue* loaded, const CellValue* next) {
    for (int k = 0; k < instance.size; ++k) evaluator.set(instance.cells[k], next[instance.cells[k]]);
    const bool legal = evaluator.legal();
    for (int k = 0; k < instance.size; ++k) evaluator.set(instance.cells[k], loaded[instance.cells[k]]);
    return legal;
}

SearchMeter::SearchMeter(const PathQuery& query) : query_(&query), budget_(query.limits.budget()), pollEvery_(query.from.cells.size() > (1u << 16) ? 1 : 16) {}

StopReason SearchMeter::admit(std::uint64_t stored) const { return query_->limits.storable(stored + 1) ? StopReason::Finished : StopReason::MaxStates; }

StopReason SearchMeter::check(std::uint64_t states, std::size_t bytes, int depth) {
    if (bytes >= query_->limits.memoryBytes) return StopReason::Memory;
    if (++ticks_ < 1024) return StopReason::Finished;
    ticks_ = 0;
    if (const auto why = budget_.reached()) return *why;  // the deadline, or a signal: interrupted
    if (query_->onProgress && budget_.elapsed() - lastReport_ >= 0.5) {
        lastReport_ = budget_.elapsed();
        query_->onProgress(finish(states, bytes, depth, StopReason::Finished));
    }
    return StopReason::Finished;
}

StopReason SearchMeter::poll() {
    if (++polls_ < pollEvery_) return StopReason::Finished;
    polls_ = 0;
    return budget_.reached().value_or(StopReason::Finished);
}

ExploreStats SearchMeter::finish(std::uint64_t states, std::size_t bytes, int depth, StopReason why) const {
    ExploreStats s;
    s.states = states, s.bytes = bytes, s.depth = depth, s.stopped = why, s.seconds = budget_.elapsed();
    return s;
}

}  // namespace holon::checker
