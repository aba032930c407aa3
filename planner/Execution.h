#pragma once
// Running a planning problem: the set of enabled rule instances kept exactly up to date as cells
// change, and the schedulers that choose from it — asynchronous (one instance at a time, uniformly
// at random: the semantics the proofs speak about), synchronous rounds (a maximal set of
// non-interfering instances fires together, then transfers pipelined behind them) and an
// adversarial one for tests.

#include "planner/Allocator.h"
#include "planner/Problem.h"
#include "planner/Random.h"
#include "rules/Budget.h"
#include "rules/WorkerPool.h"

#include <chrono>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <utility>

namespace holon::planner {

enum class Scheduler { Async,
                       Sync,
                       Adversarial };

struct RunOptions {
    Scheduler scheduler = Scheduler::Sync;
    std::uint64_t seed = 1;
    /// When to stop short of the goal: its step cap (every fired instance is a step), round cap,
    /// deadline and stop flag. The flag is set asynchronously, by a signal handler: the run stops
    /// as interrupted at the next round (sync) or step (async) boundary, where every output is
    /// consistent. Default: no limit.
    Budget budget;
    /// Rounds in a row in which only transfers fire before the run stops as "no-progress"
    /// (an allocator shuffling resources forever); 0: 1000 + 20 D^2 for a board of extents
    /// summing to D, far above the diffusion time of the random allocator across the board.
    std::int64_t maxIdleRounds = 0;
    /// The most rounds a state change may take to reach a neighbour (a fault model's delay; 0 or
    /// 1: the next round). Every hop of a resource may wait that long, so the no-progress window
    /// is that many times longer.
    std::int64_t messageDelay = 0;
    /// Sync rounds pipeline transfers (Execution.cpp); false: each resource moves at most one hop
    /// every other round along a queue, as before pipelining (the yardstick PipelineTest holds
    /// pipelined runs to).
    bool pipeline = true;
    /// A fault model's veto (planner/Faults.h): an instance it refuses waits for a later step or
    /// round. A step or round in which refusals alone kept everything from firing is not stuck:
    /// time passes. Empty: every instance is admitted.
    std::function<bool(std::int64_t anchor, int shape)> admit;
    /// Threads for the independent work of a round on a large board (re-evaluating the instances
    /// around the changed cells, the allocator's searches): at most 2 are used. The plan is the
    /// same for any value; 1: no thread is started.
    int threads = 2;
};

struct RunStats {
    std::int64_t metamodules = 0;  // occupied cells at the end
    std::int64_t creations = 0, deletions = 0, transfers = 0, relabels = 0;
    std::int64_t rounds = 0, steps = 0;
    std::int64_t evaluations = 0;  // rule instances tested against the decision tables
    double seconds = 0;
    bool complete = false;                  // the system's goal was reached
    StopReason stopped = StopReason::Goal;  // why the run ended
};

/// Hooks for output while a plan runs; every hook is optional.
struct RunObserver {
    /// An instance fired in the current step or round; `old` holds its cells' previous values.
    std::function<void(std::int64_t anchor, int shape, const BoxEngine::Value* old)> fired;
    /// A step (async) or round (sync) ended; returning false stops the run (the monitor's veto).
    std::function<bool(const RunStats&)> roundEnd;
};

class Execution {
public:
    Execution(const Problem& problem, Allocator& allocator, RunOptions options);
    RunStats run(const RunObserver& observer = {});

    const BoxEngine& engine() const { return *problem_->engine; }
    const std::vector<BoxEngine::Value>& cells() const { return cells_; }
    const RunStats& stats() const { return stats_; }
    /// The run's deadline and stop flag: what work between rounds (Faults) polls too.
    const Budget& budget() const { return options_.budget; }
    /// The planner instances (not transfers) enabled now, and how many of them the allocator holds
    /// back (Allocator::releases): where a slow plan waits (completion.csv). A pass over the
    /// enabled instances; nothing changes.
    struct Waiting {
        std::int64_t enabled = 0, held = 0;
    };
    Waiting waiting() const;
    bool enabled(std::int64_t anchor, int shape) const {
        const auto [word, bit] = bitOf(anchor, shape);
        return (bits_[word] & bit) != 0;
    }
    /// Rounds since a planner instance last fired (or the fault model held one back), and how many
    /// such rounds in a row stop the run as no-progress (RunOptions::maxIdleRounds).
    std::int64_t idleRounds() const { return stats_.rounds - idleSince_; }
    std::int64_t idleWindow() const { return maxIdle_; }
    /// The occupied cells now.
    std::int64_t metamodules() const { return occupied_; }
    /// Whether a cell in state v satisfies the system's goal predicate (padding always does).
    bool atGoal(std::int64_t cell, BoxEngine::Value v) const;
    /// A metamodule lost to a fault (planner/Faults.h), between steps or rounds: the cell becomes
    /// empty and the enabled set follows. Returns the state it held.
    BoxEngine::Value lose(std::int64_t cell);
    /// Ends the run before the next step or round, with `why` as RunStats::stopped.
    void halt(StopReason why) { halt_ = why; }
    /// Runs job(0) and job(1), on two threads when the board is large enough for a round's work
    /// to outweigh a thread's wake-up (RunOptions::threads), else one after the other on this
    /// one. The jobs must not write the same memory; the first exception one throws is rethrown
    /// once both have finished.
    void together(const std::function<void(int)>& job) const;
    /// Threads a round's work runs on: 2 on a large board with RunOptions::threads > 1, else 1.
    int threads() const { return workers_ ? 2 : 1; }

private:
    /// Where the enabled bit of an instance lives in bits_ (its listed bit is in the next word):
    /// word index and mask.
    std::pair<std::size_t, std::uint64_t> bitOf(std::int64_t anchor, int shape) const {
        return {2 * (static_cast<std::size_t>(anchor) * static_cast<std::size_t>(words_) + static_cast<std::size_t>(shape >> 6)), std::uint64_t{1} << (shape & 63)};
    }
    /// Re-evaluates the instances anchored at `anchor`; lists the ones newly enabled in `planners`
    /// and `transfers`. Returns the number of evaluations. Writes only the anchor's bits.
    std::int64_t recheck(std::int64_t anchor, std::vector<std::uint64_t>& planners, std::vector<std::uint64_t>& transfers);
    void prefetchAnchor(std::int64_t anchor) const;
    void recheckAround(const std::vector<std::int64_t>& changed);
    bool takeIfFree(std::int64_t anchor, int shape);
    bool admitted(std::int64_t anchor, int shape);
    void fire(std::int64_t anchor, int shape, const RunObserver& observer, std::vector<std::int64_t>& changed);
    void compact(std::vector<std::uint64_t>& list);
    bool asyncStep(const RunObserver& observer, std::vector<std::int64_t>& changed);
    bool adversarialStep(const RunObserver& observer, std::vector<std::int64_t>& changed);
    bool syncRound(const RunObserver& observer, std::vector<std::int64_t>& changed);
    void pipeline(const RunObserver& observer, std::vector<std::int64_t>& changed, std::vector<std::int64_t>& givers);
    const Problem* problem_;
    Allocator* allocator_;
    RunOptions options_;
    Random random_;
    int shapes_;
    int words_;  // 64-bit words of instance bits per cell: one up to 64 rule orientations
    std::vector<BoxEngine::Value> cells_;
    // Per cell, words_ pairs of words (enabled, listed): bit s for the instance of shape s anchored
    // there is enabled / is in a list. Interleaved, like the marks below, because the scheduler
    // visits cells in random order and each visit then costs one cache miss, not two.
    std::vector<std::uint64_t> bits_;
    std::vector<std::uint64_t> plannerList_, transferList_;  // instance keys anchor * 128 + shape; may hold stale keys
    struct Marks {
        std::uint32_t read = 0, write = 0;  // the last round whose kept instances read / write the cell
    };
    std::vector<Marks> marks_;
    std::vector<std::uint32_t> stamp_;
    std::uint32_t clock_ = 0;
    std::vector<std::int64_t> anchors_;
    // The second half's newly enabled instances while the two halves of recheckAround run on two
    // threads; appended after the first half's, so the lists are as one thread would leave them.
    std::vector<std::uint64_t> laterPlanners_, laterTransfers_;
    mutable std::unique_ptr<rules::WorkerPool> workers_;   // two threads on a large board, else none
    std::vector<std::pair<int, std::int64_t>> pipelined_;  // transfer shapes that may chain, and the step of each of their cells
    std::int64_t offGoal_ = 0;                             // cells not as the goal wants them
    std::int64_t maxIdle_ = 0, idleSince_ = 0;             // idleWindow(), and the round idleRounds() counts from
    std::int64_t occupied_ = 0;                            // metamodules()
    bool deferred_ = false;                                // options_.admit refused an instance in the current step or round
    bool plannerDeferred_ = false;                         // ... and one of them was a planner instance, not a transfer
    std::optional<StopReason> halt_;
    RunStats stats_;
};

}  // namespace holon::planner
