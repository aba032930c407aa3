#pragma once
// Explicit-state exploration of a reconfiguration graph: breadth-first from initial configurations,
// or over every legal configuration of a region, on all cores, with limits that stop the search
// cleanly and say what was left.

#include "checker/Evaluator.h"
#include "checker/StateStore.h"
#include "checker/WordConstraints.h"
#include "checker/WordSuccessors.h"
#include "rules/Budget.h"
#include "rules/Engine.h"
#include "rules/Limits.h"

#include <atomic>
#include <bit>
#include <chrono>
#include <cstdint>
#include <functional>
#include <memory>
#include <string>
#include <vector>

namespace holon::checker {

/// When to give up. A budget is a value passed to every long-running call (OMPL's termination
/// condition): it never throws, it only says "stop". memoryBytes bounds what the explorer holds
/// (the store, the BFS links, the frontier, the edges and the rows built from them, the workers'
/// buffers, --all's lists and bitmaps), counted before each allocation.
struct Limits {
    /// At most this many states are stored: a search that needs no more completes, one that needs
    /// one more stops (StopReason::MaxStates). storable and stateRoom are that rule, for every search.
    std::uint64_t maxStates = 50'000'000;
    double timeoutSeconds = 0;  // 0: none
    std::uint64_t memoryBytes = rules::kDefaultMemoryBytes;
    int threads = 2;
    /// Set by a signal handler (rules::StopSignals): the search stops as interrupted; null: never.
    const volatile std::sig_atomic_t* stopFlag = nullptr;
    /// The deadline (from now, and no later than the job's: its --timeout counts setup too) and
    /// the stop flag as one budget. From now alone, path --timeout 2 on a 4-million-cell region
    /// searched for 2 s after a second of setup.
    Budget budget() const { return Budget(timeoutSeconds) || Budget::job() || Budget::stopFlag(stopFlag); }
    /// Whether `states` states may be stored.
    bool storable(std::uint64_t states) const { return states <= maxStates; }
    /// How many more states may be stored beside `stored` ones.
    std::uint64_t stateRoom(std::uint64_t stored) const { return storable(stored) ? maxStates - stored : 0; }
};

struct ExploreStats {
    std::uint64_t states = 0, edges = 0, frontier = 0;
    int depth = 0;
    double seconds = 0;
    StopReason stopped = StopReason::Finished;
    bool enumerating = false;  // stopped while --all listed the legal configurations (frontier: those found)
    std::size_t bytes = 0;
};

class Explorer {
public:
    struct Options {
        Limits limits;
        bool recordEdges = true;  // keep the successor lists (for components, holonomy, --dot)
        /// addAllLegal indexes the legal configurations by rank when the candidates are few
        /// enough; false keeps the hash table (the tests compare both).
        bool rankAllLegal = true;
        /// On regions of at most 64 cells, successors and legality on words (WordSuccessors);
        /// false keeps the cell-by-cell path of larger regions (the tests compare both).
        bool onWords = true;
        /// Called from worker threads for every newly stored state (id, unpacked cells); must be
        /// thread-safe. Used for per-state property checks.
        std::function<void(StateId, const CellValue*)> onState;
        /// Asked after each breadth-first level: true ends the search early, every question the
        /// caller asks being answered (each checked invariant already has a shortest violation).
        std::function<bool()> decided;
        /// Progress reports, about every half second, from the thread that runs explore().
        std::function<void(const ExploreStats&)> onProgress;
        /// The job's budget, when it started before the explorer (the check's setup counts), with
        /// its stop flag; limits.timeoutSeconds also runs, from the explorer's construction.
        Budget budget;
    };

    Explorer(const rules::Engine& engine, Options options);
    /// Adds an initial configuration (it must be legal; the caller checks).
    StateId addInitial(const CellValue* cells);
    /// Adds every legal configuration of the region (the `--all` graph); throws InputError when the
    /// region has more candidate configurations than the limits allow. A limit hit while listing
    /// them leaves the explorer empty, and explore() reports the limit.
    void addAllLegal();
    /// Runs the breadth-first search until done or a limit is hit.
    const ExploreStats& explore();

    const rules::Engine& engine() const { return *engine_; }
    const StateStore& store() const { return store_; }
    const ExploreStats& stats() const { return stats_; }
    void unpack(StateId id, CellValue* cells) const { store_.layout().unpack(store_.state(id), cells); }
    /// The id of a stored configuration, or kNoState.
    StateId find(const CellValue* cells) const;
    std::vector<CellValue> cells(StateId id) const;
    /// BFS tree: the state a state was first reached from (kNoState for initial ones), and the placed
    /// instance that led to it.
    StateId parent(StateId id) const { return parent_[id] - 1; }  // 0 - 1 wraps to kNoState
    std::int32_t via(StateId id) const { return via_[id] - 1; }
    bool isInitial(StateId id) const { return parent(id) == kNoState && !store_.isHole(id); }
    /// Ids of states stored so far, holes excluded, in id order.
    std::vector<StateId> ids() const;
    /// States with no enabled instance at all.
    const std::vector<StateId>& terminal() const { return terminal_; }
    /// Successor lists as compressed rows (edges recorded only while exploring with recordEdges).
    const std::vector<std::uint64_t>& rowStart() const { return rowStart_; }
    const std::vector<StateId>& successors() const { return succ_; }
    const std::vector<std::int32_t>& successorVia() const { return succVia_; }
    /// The instances that make edge `edge`'s step: successorVia()'s first, then each one that adds
    /// a rule the step is a step of (rules::RuleShape::rules). Two instances with the same effect
    /// are one edge, but a property may judge a step by its rules: a ranking's `except`.
    std::vector<std::int32_t> viasOf(std::uint64_t edge) const;
    bool hasEdges() const { return !rowStart_.empty(); }
    /// The path of (state, instance that led to it) from an initial state to `id`.
    std::vector<std::pair<StateId, std::int32_t>> pathTo(StateId id) const;
    std::size_t bytesPerState() const;

private:
    /// The successors of one state, packed (unless ranked), with their hashes and the instances
    /// that lead to them.
    struct Successors {
        StateId from = kNoState;
        std::vector<CellValue> cells;   // of `from`, unpacked (the cell-by-cell path)
        WordSuccessors::Loaded loaded;  // of `from` (the word path)
        // The first `count` entries are the successors; there is room for one per instance of
        // the region, so listing one is a store. keys: hash in the store, or the candidate index
        // when ranked.
        std::vector<std::uint64_t> packed, keys;
        std::vector<std::uint64_t> probe;  // where the look-up resumes (StateStore::prefetchStored)
        std::vector<std::int32_t> via;
        std::size_t count = 0;
    };
    /// Per worker thread: its tools, kept from chunk to chunk, and what it found in the chunk.
    /// Its buffers grow with one state's successors (a word per instance), never with the region
    /// times the instances: on the cell-by-cell path a successor's words are rebuilt from its
    /// instance where they are needed instead of being kept for every successor.
    struct Worker {
        Worker(const WordConstraints& constraints, int words, bool onWords);
        /// The bytes of the successor buffers the constructor sizes for `instances` instances.
        static std::uint64_t bufferBytes(std::uint64_t instances, int words, bool onWords);
        Evaluator ev;
        Successors ring[3];  // expandRange's pipeline
        StateStore::IdBlock ids;
        std::vector<StateId> next, terminal;
        std::vector<StateId> deferred;       // states of the round left for a later one (no room, or a limit)
        std::vector<StateId> found;          // resolve's first pass: per successor its id, kNoState or kFresh
        std::vector<std::uint64_t> scratch;  // one successor's words
        std::uint32_t ticks = 0;             // work since the clock was last read
        std::uint64_t room = 0;              // room for new states taken from the round's, not used yet
        struct Edge {
            StateId from, to;
            std::int32_t via;
        };
        PageArray<Edge> edges;         // grows by remapping: 39 M edges for pixel on 5x5
        std::vector<Edge> otherRules;  // an edge's step again, by an instance of another rule
        std::uint64_t edgeCount = 0;
    };
    /// addAllLegal's first phase: found(thread, job, index) for every legal candidate, from
    /// every index in turn, or from the connected sets when a conjunct requires connectivity.
    /// stop() is asked between pieces of work; true ends the enumeration.
    template <class Sink, class Stop>
    void legalByIndex(std::uint64_t total, std::uint64_t batch, Sink& found, Stop& stop);
    template <class Sink, class Stop>
    void legalByConnectedSets(const rules::CellPredicate& connected, Sink& found, Stop& stop);
    bool legalCells(const CellValue* cells, std::uint64_t* occupied) const;
    /// The cells of the candidate with this index (its digits in base alphabet size).
    void digits(std::uint64_t index, CellValue* cells) const;
    /// Lists a state's successors; false when a limit stopped it first.
    bool gather(StateId id, Successors& out, Worker& worker);
    /// The cell-by-cell path's successor by instance `placed` of the state gather loaded into `s`.
    void packSuccessor(const Successors& s, int placed, std::uint64_t* out) const;
    /// Stores a state's new successors and records its edges; false when the round must stop
    /// first (a limit, or no room left), with nothing of the state done.
    bool resolve(const Successors& s, Worker& worker);
    /// Expands states[lo, hi); those a stop left undone go to worker.deferred.
    void expandRange(const StateId* states, std::size_t lo, std::size_t hi, Worker& worker);
    void buildRows(std::vector<Worker>& workers);

    // Stopping a round. A worker reads the clock every few thousand units of work (a state, a
    // successor); a limit, a worker's failure or the store's room running out makes every worker
    // put back the rest of its states. halt_ holds the limit (StopReason::Finished: none).
    bool stopping(Worker& w, std::uint32_t work) {
        if ((w.ticks += work) >= 4096) {
            w.ticks = 0;
            if (const auto why = budget_.reached()) halt(*why);
        }
        return abandon_.load(std::memory_order_relaxed);
    }
    void halt(StopReason why) {
        int none = static_cast<int>(StopReason::Finished);
        halt_.compare_exchange_strong(none, static_cast<int>(why));
        abandon_.store(true, std::memory_order_relaxed);
    }
    StopReason halted() const { return static_cast<StopReason>(halt_.load()); }
    /// Takes room for n new states from the round's reservation; false when it is spent, and
    /// then, if `mayRefuse`, the round stops to grow.
    bool claimRoom(Worker& worker, std::uint64_t n, bool mayRefuse);
    /// What the explorer holds now, and what one more stored state costs at most.
    std::size_t bytesHeld(const std::vector<Worker>& workers, std::size_t listed) const;
    std::size_t bytesPerNewState() const;

    const rules::Engine* engine_;
    WordConstraints constraints_;
    Options options_;
    Budget budget_;
    std::atomic<int> halt_{static_cast<int>(StopReason::Finished)};
    std::atomic<bool> abandon_{false};
    std::atomic<std::int64_t> room_{0};           // new states the round may still add
    std::atomic<std::uint64_t> refusedClaim_{0};  // the largest claim the round refused
    std::uint64_t enumerated_ = 0;                // legal configurations --all found before a limit
    StateStore store_;
    std::unique_ptr<WordSuccessors> words_;  // regions of at most 64 cells
    // One more than the parent's id and the instance's index, so that the zero pages a PageArray
    // grows into read as "none" without being written.
    PageArray<StateId> parent_;
    PageArray<std::int32_t> via_;
    /// Room for links up to id n (they only grow until the search ends: shrinking and growing
    /// again would clear the headroom's pages for nothing).
    void growLinks(std::size_t n) {
        if (n > parent_.size()) parent_.resize(n), via_.resize(n);
    }
    std::vector<StateId> frontier_;
    std::vector<StateId> terminal_;
    bool complete_ = false;  // the store holds every legal configuration (after addAllLegal)
    // After addAllLegal, when the candidates are few enough: a perfect hash. Candidate
    // configuration c has index sum_i c[i] * a^i (a the alphabet size); a bit per candidate says
    // whether it is legal, and a legal one's id is its rank among the legal ones.
    std::vector<std::uint64_t> legalBits_;
    std::vector<StateId> rankBefore_;        // per word of legalBits_: legal candidates before it
    std::vector<std::uint64_t> placeValue_;  // a^i
    bool ranked() const { return !legalBits_.empty(); }
    std::size_t rankingBytes() const { return legalBits_.size() * 8 + rankBefore_.size() * sizeof(StateId) + placeValue_.size() * 8; }
    std::uint64_t indexOf(const CellValue* cells) const;
    StateId rankOf(std::uint64_t index) const {
        const std::uint64_t word = legalBits_[index >> 6], bit = std::uint64_t{1} << (index & 63);
        return word & bit ? rankBefore_[index >> 6] + static_cast<StateId>(std::popcount(word & (bit - 1))) : kNoState;
    }
    void prefetchRank(std::uint64_t index) const {
        __builtin_prefetch(&legalBits_[index >> 6]);
        __builtin_prefetch(&rankBefore_[index >> 6]);
    }
    std::vector<std::uint64_t> rowStart_;
    std::vector<StateId> succ_;
    std::vector<std::int32_t> succVia_;
    std::vector<std::pair<std::uint64_t, std::int32_t>> otherVia_;  // (edge, instance of another rule), by edge
    ExploreStats stats_;
};

}  // namespace holon::checker
