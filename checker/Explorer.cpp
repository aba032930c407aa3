// Breadth-first exploration of the reconfiguration graph (seed 000 §II-B: vertices are legal
// configurations, edges single rule instances). Successors come from the compiled engine, which the
// tests hold to the reference interpreter. The frontier is expanded in chunks; within a chunk both
// cores expand disjoint slices and insert into the lock-free store; between chunks the store grows
// and the limits are checked, so a limit stops the search between two chunks with everything found
// so far intact. Parent links give shortest paths for counterexample traces.

#include "checker/Explorer.h"

#include "rules/Error.h"

#include <algorithm>
#include <cmath>
#include <thread>

namespace holon::checker {

std::string stopReasonName(StopReason r) {
    switch (r) {
    case StopReason::Finished: return "finished";
    case StopReason::MaxStates: return "max-states";
    case StopReason::Timeout: return "timeout";
    case StopReason::Memory: return "memory";
    case StopReason::Decided: return "decided";
    }
    return "";
}

Explorer::Explorer(const rules::Engine& engine, Options options)
    : engine_(&engine), options_(std::move(options)),
      store_(StateLayout(engine.region().size(), engine.model().alphabet().size())) {}

std::vector<CellValue> Explorer::cells(StateId id) const {
    std::vector<CellValue> c(engine_->region().size());
    unpack(id, c.data());
    return c;
}

StateId Explorer::addInitial(const CellValue* cells) {
    std::vector<std::uint64_t> packed(store_.layout().words());
    store_.layout().pack(cells, packed.data());
    store_.reserve(1);
    parent_.resize(store_.capacityUsed() + 1, kNoState);
    via_.resize(store_.capacityUsed() + 1, -1);
    auto [id, inserted] = store_.insert(packed.data());
    if (inserted) {
        frontier_.push_back(id);
        if (options_.onState) options_.onState(id, cells);
    }
    return id;
}

void Explorer::addAllLegal() {
    const int n = engine_->region().size();
    const int a = engine_->model().alphabet().size();
    const double candidates = std::pow(static_cast<double>(a), n);
    const double budget = std::min(4.0e9, static_cast<double>(options_.limits.maxStates) * 64.0);
    if (candidates > budget)
        throw InputError("--all on region " + engine_->region().spec() + " means " + std::to_string(a) + "^" + std::to_string(n) +
                         " candidate configurations, too many to enumerate; choose a smaller region, raise --max-states, "
                         "or explore from a configuration with --from");
    const std::uint64_t total = static_cast<std::uint64_t>(std::llround(candidates));
    const int threads = std::max(1, options_.limits.threads);
    const std::uint64_t batch = 1u << 20;
    // Enumerate in batches: threads test legality of disjoint index ranges into local lists (in
    // index order), then the lists are inserted in a fixed order so ids are deterministic.
    for (std::uint64_t base = 0; base < total; base += batch * threads) {
        std::vector<std::vector<std::uint64_t>> found(threads);
        auto work = [&](int t) {
            const std::uint64_t lo = base + batch * t, hi = std::min(total, lo + batch);
            if (lo >= hi) return;
            std::vector<CellValue> cells(n);
            std::uint64_t x = lo;
            for (int i = 0; i < n; ++i) cells[i] = static_cast<CellValue>(x % a), x /= a;
            std::vector<std::uint64_t> packed(store_.layout().words());
            rules::Engine::Evaluator ev(*engine_);
            ev.load(cells.data());
            for (std::uint64_t idx = lo; idx < hi; ++idx) {
                if (ev.legal()) {
                    store_.layout().pack(ev.cells(), packed.data());
                    found[t].insert(found[t].end(), packed.begin(), packed.end());
                }
                // Odometer step; the evaluator follows the few cells that change.
                for (int i = 0; i < n; ++i) {
                    const CellValue v = static_cast<CellValue>(ev.cells()[i] + 1 == a ? 0 : ev.cells()[i] + 1);
                    ev.set(i, v);
                    if (v != 0) break;
                }
            }
        };
        std::vector<std::thread> pool;
        for (int t = 1; t < threads; ++t) pool.emplace_back(work, t);
        work(0);
        for (auto& th : pool) th.join();
        std::vector<CellValue> cells(n);
        for (const auto& list : found) {
            const std::size_t count = list.size() / store_.layout().words();
            if (store_.size() + count > options_.limits.maxStates)
                throw InputError("region " + engine_->region().spec() + " has more than --max-states=" +
                                 std::to_string(options_.limits.maxStates) + " legal configurations; raise the limit or choose a smaller region");
            store_.reserve(count);
            parent_.resize(store_.capacityUsed() + count, kNoState);
            via_.resize(store_.capacityUsed() + count, -1);
            for (std::size_t k = 0; k < count; ++k) {
                auto [id, inserted] = store_.insert(&list[k * store_.layout().words()]);
                if (!inserted) continue;
                frontier_.push_back(id);
                if (options_.onState) {
                    unpack(id, cells.data());
                    options_.onState(id, cells.data());
                }
            }
        }
    }
}

void Explorer::expand(StateId id, rules::Engine::Evaluator& ev, std::vector<CellValue>& cells,
                      std::vector<StateId>& next, std::vector<std::pair<StateId, std::pair<StateId, std::int32_t>>>& edges,
                      std::vector<StateId>& terminal, std::uint64_t& edgeCount) {
    // First collect the successors, packed by patching the parent's words and with their table
    // slots prefetched; then insert them, so the cache misses of the hash table overlap.
    const StateLayout& layout = store_.layout();
    const int words = layout.words();
    unpack(id, cells.data());
    ev.load(cells.data());
    const std::uint64_t* base = store_.state(id);
    CellValue saved[rules::Engine::kMaxCells];
    thread_local std::vector<std::uint64_t> batch, hashes;
    thread_local std::vector<std::int32_t> batchVia;
    batch.clear(), hashes.clear(), batchVia.clear();
    engine_->forEachMatch(ev.cells(), [&](int p) {
        ev.apply(p, saved);
        if (ev.legal()) {
            const std::size_t at = batch.size();
            batch.insert(batch.end(), base, base + words);
            const rules::Engine::Placed& placed = engine_->instances()[p];
            for (int k = 0; k < placed.size; ++k) layout.set(&batch[at], placed.cells[k], ev.cells()[placed.cells[k]]);
            batchVia.push_back(p);
        }
        ev.undo(p, saved);
    });
    for (std::size_t k = 0; k < batchVia.size(); ++k) hashes.push_back(store_.prefetch(&batch[k * words]));
    thread_local std::vector<StateId> seen;
    seen.clear();
    for (std::size_t k = 0; k < batchVia.size(); ++k) {
        auto [sid, inserted] = store_.insert(&batch[k * words], hashes[k]);
        if (inserted) {
            parent_[sid] = id;
            via_[sid] = batchVia[k];
            next.push_back(sid);
            if (options_.onState) {
                layout.unpack(&batch[k * words], cells.data());
                options_.onState(sid, cells.data());
            }
        }
        // Two instances with the same effect are one edge of the graph.
        if (std::find(seen.begin(), seen.end(), sid) != seen.end()) continue;
        seen.push_back(sid);
        if (options_.recordEdges) edges.push_back({id, {sid, batchVia[k]}});
    }
    if (seen.empty()) terminal.push_back(id);
    edgeCount += seen.size();
}

const ExploreStats& Explorer::explore() {
    using Clock = std::chrono::steady_clock;
    const auto start = Clock::now();
    auto last = start;
    const int threads = std::max(1, options_.limits.threads);
    const std::uint64_t branching = std::max<std::size_t>(1, engine_->instances().size());
    // A chunk reserves room for chunk * branching new states; keep that headroom near a million.
    const std::uint64_t chunk = std::max<std::uint64_t>(64, std::min<std::uint64_t>(1u << 14, (1u << 20) / branching));
    std::vector<std::vector<std::pair<StateId, std::pair<StateId, std::int32_t>>>> edges(threads);
    const std::size_t edgeBytes = options_.recordEdges ? 12 : 0;
    stats_ = {};
    while (!frontier_.empty() && stats_.stopped == StopReason::Finished) {
        std::vector<StateId> nextLevel;
        for (std::size_t pos = 0; pos < frontier_.size(); pos += chunk) {
            const double elapsed = std::chrono::duration<double>(Clock::now() - start).count();
            std::size_t edgesHeld = 0;
            for (const auto& e : edges) edgesHeld += e.size();
            const std::size_t bytes = store_.bytes() + parent_.size() * 8 + edgesHeld * edgeBytes;
            if (store_.size() >= options_.limits.maxStates) stats_.stopped = StopReason::MaxStates;
            else if (options_.limits.timeoutSeconds > 0 && elapsed >= options_.limits.timeoutSeconds) stats_.stopped = StopReason::Timeout;
            else if (bytes >= options_.limits.memoryBytes) stats_.stopped = StopReason::Memory;
            if (stats_.stopped != StopReason::Finished) {
                stats_.frontier = frontier_.size() - pos + nextLevel.size();
                break;
            }
            const std::size_t end = std::min(frontier_.size(), pos + chunk);
            store_.reserve((end - pos) * branching);
            parent_.resize(store_.capacityUsed() + (end - pos) * branching, kNoState);
            via_.resize(parent_.size(), -1);
            std::vector<std::vector<StateId>> next(threads), terminal(threads);
            std::vector<std::uint64_t> edgeCounts(threads, 0);
            auto work = [&](int t) {
                std::vector<CellValue> cells(engine_->region().size());
                rules::Engine::Evaluator ev(*engine_);
                const std::size_t per = (end - pos + threads - 1) / threads;
                const std::size_t lo = pos + per * t, hi = std::min(end, lo + per);
                for (std::size_t k = lo; k < hi; ++k) expand(frontier_[k], ev, cells, next[t], edges[t], terminal[t], edgeCounts[t]);
            };
            std::vector<std::thread> pool;
            for (int t = 1; t < threads; ++t) pool.emplace_back(work, t);
            work(0);
            for (auto& th : pool) th.join();
            for (int t = 0; t < threads; ++t) {
                nextLevel.insert(nextLevel.end(), next[t].begin(), next[t].end());
                terminal_.insert(terminal_.end(), terminal[t].begin(), terminal[t].end());
                stats_.edges += edgeCounts[t];
            }
            stats_.states = store_.size();
            if (options_.onProgress && std::chrono::duration<double>(Clock::now() - last).count() > 0.5) {
                last = Clock::now();
                stats_.seconds = std::chrono::duration<double>(last - start).count();
                stats_.frontier = frontier_.size() - end + nextLevel.size();
                options_.onProgress(stats_);
            }
        }
        if (stats_.stopped != StopReason::Finished) break;
        frontier_ = std::move(nextLevel);
        if (!frontier_.empty()) ++stats_.depth;
        if (!frontier_.empty() && options_.decided && options_.decided()) {
            stats_.stopped = StopReason::Decided;
            stats_.frontier = frontier_.size();
        }
    }
    std::sort(terminal_.begin(), terminal_.end());
    stats_.states = store_.size();
    store_.shrinkToFit();
    parent_.resize(store_.capacityUsed());
    parent_.shrink_to_fit();
    via_.resize(store_.capacityUsed());
    via_.shrink_to_fit();
    if (options_.recordEdges) buildRows(edges);
    stats_.seconds = std::chrono::duration<double>(Clock::now() - start).count();
    stats_.bytes = store_.bytes() + parent_.size() * 8 + succ_.size() * 8 + rowStart_.size() * 8;
    return stats_;
}

void Explorer::buildRows(std::vector<std::vector<std::pair<StateId, std::pair<StateId, std::int32_t>>>>& perThread) {
    const std::size_t n = store_.capacityUsed();
    rowStart_.assign(n + 1, 0);
    for (const auto& list : perThread)
        for (const auto& e : list) ++rowStart_[e.first + 1];
    for (std::size_t i = 0; i < n; ++i) rowStart_[i + 1] += rowStart_[i];
    succ_.resize(rowStart_[n]);
    succVia_.resize(rowStart_[n]);
    std::vector<std::uint64_t> fill(rowStart_.begin(), rowStart_.end() - 1);
    for (auto& list : perThread) {
        for (const auto& e : list) {
            succ_[fill[e.first]] = e.second.first;
            succVia_[fill[e.first]++] = e.second.second;
        }
        list.clear();
        list.shrink_to_fit();
    }
}

std::vector<StateId> Explorer::ids() const {
    std::vector<StateId> out;
    for (StateId id = 0; id < store_.capacityUsed(); ++id)
        if (!store_.isHole(id)) out.push_back(id);
    return out;
}

std::vector<std::pair<StateId, std::int32_t>> Explorer::pathTo(StateId id) const {
    std::vector<std::pair<StateId, std::int32_t>> path;
    for (StateId s = id; s != kNoState; s = parent_[s]) path.push_back({s, via_[s]});
    std::reverse(path.begin(), path.end());
    return path;
}

std::size_t Explorer::bytesPerState() const {
    return static_cast<std::size_t>(std::ceil(store_.bytesPerState())) + sizeof(StateId) + sizeof(std::int32_t);
}

}  // namespace holon::checker
