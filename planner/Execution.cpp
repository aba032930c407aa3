// Execution of seed 000's U/P/F planner (§IV-A) and a resource allocator (§IV-B) from compiled
// rules. The enabled set is exact: an instance's status can only change when a cell it reads
// changes, so after every firing the anchors within the rules' read stencil of each changed cell
// are re-evaluated, and nothing else.
//
// Synchronous rounds: instances are taken in random order and one is kept when the cells it
// changes are read by no instance kept before and the cells it reads are changed by none. Kept
// instances therefore neither disable nor alter each other, so firing them together gives the
// same configuration as firing them one after another in any order: a round is an interleaving,
// and everything proved about the asynchronous semantics holds for it. Each round is maximal: an
// enabled instance left out conflicts with one that was kept. Then transfers are pipelined: a cell
// that handed its resource on takes the next one from behind (pipeline), so a queue of resources
// moves one hop per round as a whole; these are fired one after another, each enabled when it
// fires, so the round is still an interleaving.

#include "planner/Execution.h"

#include "rules/Error.h"
#include "rules/Limits.h"

#include <algorithm>
#include <bit>
#include <optional>

namespace holon::planner {

namespace {
constexpr int kShapeBits = 7;  // instance key = anchor << 7 | shape
constexpr int kMaxShapes = 1 << kShapeBits;
std::int64_t anchorOf(std::uint64_t key) { return static_cast<std::int64_t>(key >> kShapeBits); }
int shapeOf(std::uint64_t key) { return static_cast<int>(key & ((1u << kShapeBits) - 1)); }
std::uint64_t keyOf(std::int64_t anchor, int shape) { return (static_cast<std::uint64_t>(anchor) << kShapeBits) | static_cast<std::uint64_t>(shape); }
// The scheduler visits cells in random order, so nearly every visit misses the cache; loops over
// such visits ask for the memory of the visit kAhead places later first.
constexpr std::size_t kAhead = 8;
// Boards from which a round's work is shared between two threads, and the least number of anchors
// to re-evaluate that is split between them. Chosen, not tuned: the smallest board measured, the
// block at K = 12 (about 140,000 cells, `eager`), already gains a quarter (5.64 -> 4.15 s, medians
// of 3 alternated); smaller boards were not measured and stay on one thread.
constexpr std::int64_t kParallelCells = std::int64_t{1} << 17;
constexpr std::size_t kParallelAnchors = 4096;
/// RunOptions::maxIdleRounds, or 1000 + 20 D^2 on a board of extents summing to D, times the
/// message delay; saturated, since a board a billion cells long, or --delay 10^6, would overflow.
std::int64_t noProgressWindow(const Board& board, const RunOptions& options) {
    const Vec extent = board.extent();
    const auto d = static_cast<std::uint64_t>(std::int64_t{extent.x} + extent.y + extent.z);
    const std::uint64_t rounds = options.maxIdleRounds > 0 ? static_cast<std::uint64_t>(options.maxIdleRounds) : std::min<std::uint64_t>(rules::checkedProduct({20, d, d}), UINT64_MAX - 1000) + 1000;
    const auto delay = static_cast<std::uint64_t>(std::max<std::int64_t>(1, options.messageDelay));
    return static_cast<std::int64_t>(std::min<std::uint64_t>(rules::checkedProduct({rounds, delay}), INT64_MAX));
}
}  // namespace

void Execution::prefetchAnchor(std::int64_t anchor) const {
    __builtin_prefetch(&bits_[bitOf(anchor, 0).first]);
    __builtin_prefetch(&cells_[anchor]);
    engine().prefetchCombo(anchor);
}

Execution::Execution(const Problem& problem, Allocator& allocator, RunOptions options)
    : problem_(&problem), allocator_(&allocator), options_(options), random_(options.seed), shapes_(problem.engine->shapeCount()), words_((shapes_ + 63) / 64),
      cells_(problem.cells) {
    if (shapes_ > kMaxShapes)
        throw InputError("system '" + problem.model->system().name + "' has " + std::to_string(shapes_) + " rule orientations; the planner handles at most " +
                         std::to_string(kMaxShapes) + ": split rules that never fire together into separate systems");
    const std::size_t n = cells_.size();
    bits_.assign(2 * n * static_cast<std::size_t>(words_), 0);
    stamp_.assign(n, 0), marks_.assign(n, {});
    const BoxEngine& engine = *problem.engine;
    // Transfers between two cells that read nothing else can be chained within a round (pipeline).
    for (int sh = 0; sh < shapes_; ++sh)
        if (engine.kind(sh) == ShapeKind::Transfer && engine.cellSteps(sh).size() == 2 && engine.readSteps(sh).size() == 2)
            for (std::int64_t step : engine.cellSteps(sh)) pipelined_.push_back({sh, step});
    for (std::int64_t a = 0; a < static_cast<std::int64_t>(n); ++a) {
        offGoal_ += !atGoal(a, cells_[a]);
        if (engine.combo(a) == BoxEngine::kOutside || cells_[a] == 0) continue;
        ++occupied_;
        stats_.evaluations += recheck(a, plannerList_, transferList_);
    }
    maxIdle_ = noProgressWindow(*problem.board, options_);
    // A thread's wake-up costs some microseconds: only boards whose rounds take milliseconds get one.
    if (options_.threads > 1 && static_cast<std::int64_t>(n) >= kParallelCells) {
        workers_ = std::make_unique<rules::WorkerPool>(2);
        if (workers_->threads() < 2) workers_.reset();  // the system would not start one
    }
}

std::int64_t Execution::recheck(std::int64_t anchor, std::vector<std::uint64_t>& planners, std::vector<std::uint64_t>& transfers) {
    std::uint64_t now[kMaxShapes / 64] = {};
    const std::int64_t evaluations = engine().forEachMatchAt(cells_.data(), anchor, [&](int s) { now[s >> 6] |= std::uint64_t{1} << (s & 63); });
    std::uint64_t* bits = bits_.data() + 2 * static_cast<std::size_t>(anchor) * static_cast<std::size_t>(words_);
    for (int w = 0; w < words_; ++w) {
        bits[2 * w] = now[w];
        std::uint64_t fresh = now[w] & ~bits[2 * w + 1];
        bits[2 * w + 1] |= fresh;
        while (fresh) {
            const int s = w * 64 + std::countr_zero(fresh);
            fresh &= fresh - 1;
            (engine().kind(s) == ShapeKind::Transfer ? transfers : planners).push_back(keyOf(anchor, s));
        }
    }
    return evaluations;
}

void Execution::together(const std::function<void(int)>& job) const {
    if (workers_) return workers_->run(job);
    job(0);
    job(1);
}

void Execution::recheckAround(const std::vector<std::int64_t>& changed) {
    if (++clock_ == 0) std::fill(stamp_.begin(), stamp_.end(), 0), clock_ = 1;
    anchors_.clear();
    const BoxEngine& engine = this->engine();
    for (std::int64_t c : changed)
        for (std::int64_t r : engine.influence()) {
            const std::int64_t a = c - r;
            if (stamp_[a] != clock_) stamp_[a] = clock_, anchors_.push_back(a);  // recheck skips padding
        }
    // Anchors are distinct, so the halves write disjoint bits; the second half lists its newly
    // enabled instances apart and they are appended after the first half's, in anchor order.
    const std::size_t n = anchors_.size(), half = workers_ && n >= kParallelAnchors ? n / 2 : n;
    std::int64_t evaluations[2] = {0, 0};
    auto recheckRange = [&](std::size_t from, std::size_t to, std::vector<std::uint64_t>& planners, std::vector<std::uint64_t>& transfers) -> std::int64_t {
        std::int64_t e = 0;
        for (std::size_t k = from; k < to; ++k) {
            if (k + kAhead < to) prefetchAnchor(anchors_[k + kAhead]);
            e += recheck(anchors_[k], planners, transfers);
        }
        return e;
    };
    if (half == n) {
        evaluations[0] = recheckRange(0, n, plannerList_, transferList_);
    } else {
        laterPlanners_.clear(), laterTransfers_.clear();
        together([&](int t) {
            evaluations[t] = t == 0 ? recheckRange(0, half, plannerList_, transferList_) : recheckRange(half, n, laterPlanners_, laterTransfers_);
        });
        plannerList_.insert(plannerList_.end(), laterPlanners_.begin(), laterPlanners_.end());
        transferList_.insert(transferList_.end(), laterTransfers_.begin(), laterTransfers_.end());
    }
    stats_.evaluations += evaluations[0] + evaluations[1];
}

void Execution::compact(std::vector<std::uint64_t>& list) {
    std::size_t out = 0;
    for (std::size_t k = 0; k < list.size(); ++k) {
        if (k + kAhead < list.size()) __builtin_prefetch(&bits_[bitOf(anchorOf(list[k + kAhead]), 0).first]);
        const std::uint64_t key = list[k];
        const auto [word, bit] = bitOf(anchorOf(key), shapeOf(key));
        if (bits_[word] & bit) list[out++] = key;
        else bits_[word + 1] &= ~bit;
    }
    list.resize(out);
}

bool Execution::takeIfFree(std::int64_t anchor, int shape) {
    const std::uint32_t round = static_cast<std::uint32_t>(stats_.rounds);
    const BoxEngine& engine = this->engine();
    for (std::int64_t r : engine.readSteps(shape))
        if (marks_[anchor + r].write == round) return false;
    for (std::int64_t w : engine.writeSteps(shape))
        if (marks_[anchor + w].read == round) return false;
    for (std::int64_t r : engine.readSteps(shape)) marks_[anchor + r].read = round;
    for (std::int64_t w : engine.writeSteps(shape)) marks_[anchor + w].write = round;
    return true;
}

bool Execution::admitted(std::int64_t anchor, int shape) {
    if (!options_.admit || options_.admit(anchor, shape)) return true;
    deferred_ = true;
    plannerDeferred_ = plannerDeferred_ || engine().kind(shape) != ShapeKind::Transfer;
    return false;
}

BoxEngine::Value Execution::lose(std::int64_t cell) {
    const BoxEngine::Value old = cells_[cell];
    cells_[cell] = 0;
    occupied_ -= old != 0;
    offGoal_ += static_cast<int>(atGoal(cell, old)) - static_cast<int>(atGoal(cell, 0));
    recheckAround({cell});
    return old;
}

void Execution::fire(std::int64_t anchor, int shape, const RunObserver& observer, std::vector<std::int64_t>& changed) {
    BoxEngine::Value old[rules::RuleTables::kMaxCells];
    const BoxEngine& engine = this->engine();
    if (engine.kind(shape) == ShapeKind::Transfer) allocator_->firing(*this, anchor, shape);
    engine.apply(cells_.data(), anchor, shape, old);
    const std::span<const std::int64_t> steps = engine.cellSteps(shape);
    for (std::size_t k = 0; k < steps.size(); ++k) {
        const std::int64_t i = anchor + steps[k];
        if (old[k] == cells_[i]) continue;
        changed.push_back(i);
        offGoal_ += static_cast<int>(atGoal(i, old[k])) - static_cast<int>(atGoal(i, cells_[i]));
        stats_.creations += old[k] == 0;
        stats_.deletions += cells_[i] == 0;
        occupied_ += (old[k] == 0) - (cells_[i] == 0);
    }
    const ShapeKind kind = engine.kind(shape);
    stats_.transfers += kind == ShapeKind::Transfer;
    stats_.relabels += kind == ShapeKind::Relabel;
    ++stats_.steps;
    if (observer.fired) observer.fired(anchor, shape, old);
}

bool Execution::asyncStep(const RunObserver& observer, std::vector<std::int64_t>& changed) {
    // Uniform over the enabled planner instances and the transfers the allocator wants, by
    // rejection from the two lists; after many rejections the candidates are listed explicitly.
    for (int attempt = 0; attempt < 64; ++attempt) {
        const std::size_t total = plannerList_.size() + transferList_.size();
        if (total == 0) return false;
        const std::size_t i = random_.below(total);
        const bool planner = i < plannerList_.size();
        std::vector<std::uint64_t>& list = planner ? plannerList_ : transferList_;
        const std::size_t at = planner ? i : i - plannerList_.size();
        const std::uint64_t key = list[at];
        if (!enabled(anchorOf(key), shapeOf(key))) {
            const auto [word, bit] = bitOf(anchorOf(key), shapeOf(key));
            bits_[word + 1] &= ~bit;
            list[at] = list.back();
            list.pop_back();
            continue;
        }
        if (!(planner ? allocator_->releases(*this, anchorOf(key), shapeOf(key)) : allocator_->wants(*this, anchorOf(key), shapeOf(key)))) continue;
        if (!admitted(anchorOf(key), shapeOf(key))) continue;
        fire(anchorOf(key), shapeOf(key), observer, changed);
        return true;
    }
    compact(plannerList_);
    compact(transferList_);
    std::vector<std::uint64_t> candidates;
    for (std::uint64_t key : plannerList_)
        if (allocator_->releases(*this, anchorOf(key), shapeOf(key)) && admitted(anchorOf(key), shapeOf(key))) candidates.push_back(key);
    for (std::uint64_t key : transferList_)
        if (allocator_->wants(*this, anchorOf(key), shapeOf(key)) && admitted(anchorOf(key), shapeOf(key))) candidates.push_back(key);
    if (candidates.empty()) return false;
    const std::uint64_t key = candidates[random_.below(candidates.size())];
    fire(anchorOf(key), shapeOf(key), observer, changed);
    return true;
}

bool Execution::adversarialStep(const RunObserver& observer, std::vector<std::int64_t>& changed) {
    // Deterministic and unfair to the planner: the latest-declared rule first, then the highest
    // anchor. Transfers stay the allocator's choice (uniform among those it wants) and fire only
    // when no planner rule is enabled: an adversary that also picked the transfers could swap one
    // pair back and forth forever, the "purposely malicious resource allocator" of §IV-B.
    compact(plannerList_);
    auto rank = [&](std::uint64_t k) { return std::pair(engine().ruleOf(shapeOf(k)), k); };
    std::optional<std::uint64_t> worst;
    for (std::uint64_t key : plannerList_)
        if ((!worst || rank(*worst) < rank(key)) && allocator_->releases(*this, anchorOf(key), shapeOf(key)) && admitted(anchorOf(key), shapeOf(key))) worst = key;
    if (worst) {
        fire(anchorOf(*worst), shapeOf(*worst), observer, changed);
        return true;
    }
    return asyncStep(observer, changed);
}

bool Execution::syncRound(const RunObserver& observer, std::vector<std::int64_t>& changed) {
    std::vector<std::uint64_t> chosen;
    compact(plannerList_);
    random_.shuffle(plannerList_);
    for (std::size_t k = 0; k < plannerList_.size(); ++k) {
        if (k + kAhead < plannerList_.size()) __builtin_prefetch(&marks_[anchorOf(plannerList_[k + kAhead])]);
        const std::uint64_t key = plannerList_[k];
        if (allocator_->releases(*this, anchorOf(key), shapeOf(key)) && admitted(anchorOf(key), shapeOf(key)) && takeIfFree(anchorOf(key), shapeOf(key)))
            chosen.push_back(key);
    }
    compact(transferList_);
    random_.shuffle(transferList_);
    for (std::uint64_t key : transferList_)
        if (allocator_->wants(*this, anchorOf(key), shapeOf(key)) && admitted(anchorOf(key), shapeOf(key)) && takeIfFree(anchorOf(key), shapeOf(key)))
            chosen.push_back(key);
    std::vector<std::int64_t> givers;
    for (std::size_t k = 0; k < chosen.size(); ++k) {
        if (k + kAhead < chosen.size()) prefetchAnchor(anchorOf(chosen[k + kAhead]));
        const int shape = shapeOf(chosen[k]);
        if (engine().kind(shape) == ShapeKind::Transfer) givers.push_back(transferEnds(*this, anchorOf(chosen[k]), shape).first);
        fire(anchorOf(chosen[k]), shape, observer, changed);
    }
    if (options_.pipeline) pipeline(observer, changed, givers);
    return !chosen.empty();
}

void Execution::pipeline(const RunObserver& observer, std::vector<std::int64_t>& changed, std::vector<std::int64_t>& givers) {
    // A cell that handed its resource on this round takes the next one from a neighbour that has
    // not acted yet, which then takes from its own neighbour, and so on: a queue of resources
    // advances as a whole, one hop each, like a bucket brigade, instead of one resource every
    // other round. Each transfer is tested against the cells as they are when it fires, so the
    // round stays an interleaving; a cell takes part in at most one transfer as giver and one as
    // taker, so no resource moves twice in a round.
    if (pipelined_.empty()) return;
    const std::uint32_t round = static_cast<std::uint32_t>(stats_.rounds);
    const BoxEngine& engine = this->engine();
    for (std::size_t k = 0; k < givers.size(); ++k) {
        const std::int64_t taker = givers[k];
        if (taker < 0) continue;
        const int first = static_cast<int>(random_.below(pipelined_.size()));
        for (std::size_t t = 0; t < pipelined_.size(); ++t) {
            const auto [shape, step] = pipelined_[(t + static_cast<std::size_t>(first)) % pipelined_.size()];
            const std::int64_t anchor = taker - step;
            if (!engine.matches(cells_.data(), anchor, shape)) continue;
            const auto [from, to] = transferEnds(*this, anchor, shape);
            if (to != taker || marks_[from].read == round || marks_[from].write == round) continue;
            if (!allocator_->wants(*this, anchor, shape)) continue;
            marks_[from].read = marks_[from].write = round;
            fire(anchor, shape, observer, changed);
            givers.push_back(from);
            break;
        }
    }
}

Execution::Waiting Execution::waiting() const {
    Waiting w;
    for (std::uint64_t key : plannerList_)  // may hold stale keys; an enabled instance is listed once
        if (enabled(anchorOf(key), shapeOf(key))) ++w.enabled, w.held += !allocator_->releases(*this, anchorOf(key), shapeOf(key));
    return w;
}

bool Execution::atGoal(std::int64_t cell, BoxEngine::Value v) const {
    const std::uint8_t combo = engine().combo(cell);
    return combo == BoxEngine::kOutside || problem_->tables->test(problem_->goal, combo, v);
}

RunStats Execution::run(const RunObserver& observer) {
    const auto begin = std::chrono::steady_clock::now();
    auto elapsed = [&] { return std::chrono::duration<double>(std::chrono::steady_clock::now() - begin).count(); };
    std::vector<std::int64_t> changed;
    std::int64_t sinceUpdate = 0, updateEvery = 1;
    std::int64_t plannerSteps = 0;
    for (std::uint64_t iteration = 0;; ++iteration) {
        // Reaching the goal ends the run even while transfers are still enabled.
        if (offGoal_ == 0) {
            stats_.stopped = StopReason::Goal;
            break;
        }
        // A signal first, then a halt, the caps, no progress and the deadline. A sync round is long
        // enough to read the clock each time; async steps are short.
        if (options_.budget.interrupted()) {
            stats_.stopped = StopReason::Interrupted;
            break;
        }
        if (halt_) {
            stats_.stopped = *halt_;
            break;
        }
        const bool clock = options_.scheduler == Scheduler::Sync || (iteration & 255) == 0;
        const Progress done{0, static_cast<std::uint64_t>(stats_.steps), static_cast<std::uint64_t>(stats_.rounds)};
        if (const auto why = options_.budget.reached(done, false)) {
            stats_.stopped = *why;
            break;
        }
        if (stats_.steps - stats_.transfers != plannerSteps) plannerSteps = stats_.steps - stats_.transfers, idleSince_ = stats_.rounds;
        if (idleRounds() > maxIdle_) {
            stats_.stopped = StopReason::NoProgress;
            break;
        }
        if (clock && options_.budget.expired()) {
            stats_.stopped = StopReason::Timeout;
            break;
        }
        changed.clear();
        deferred_ = plannerDeferred_ = false;
        bool allocatorMoved = false;
        bool fired;
        if (options_.scheduler == Scheduler::Sync) {
            ++stats_.rounds;
            allocatorMoved = allocator_->update(*this);
            fired = syncRound(observer, changed);
        } else {
            // An asynchronous round: as many steps as there were candidates when it began.
            if (++sinceUpdate >= updateEvery) {
                allocatorMoved = allocator_->update(*this);
                sinceUpdate = 0;
                updateEvery = std::max<std::int64_t>(1, static_cast<std::int64_t>(plannerList_.size() + transferList_.size()));
                ++stats_.rounds;
            }
            fired = options_.scheduler == Scheduler::Async ? asyncStep(observer, changed) : adversarialStep(observer, changed);
        }
        // Nothing fired: let the allocator look again before calling the run stuck.
        if (!fired && !allocatorMoved) {
            sinceUpdate = 0;
            allocatorMoved = allocator_->update(*this);
        }
        // The fault model held back what could fire: time passes (async: the next step starts a
        // new round, so delays expire).
        if (!fired && deferred_ && options_.scheduler != Scheduler::Sync) sinceUpdate = updateEvery;
        // Nor is a round in which the fault model held back a planner instance idle: the run
        // waits for the delays and drops the user asked for, and no-progress would call a plan
        // that completes (--delay 20000) stuck. Held-back transfers are not progress: counting
        // them let a livelock of transfers under --delay run for ever (the window is longer
        // instead, RunOptions::messageDelay).
        if (plannerDeferred_) idleSince_ = stats_.rounds;
        if (!fired && !allocatorMoved && !deferred_) {
            stats_.stopped = StopReason::Stuck;
            break;
        }
        recheckAround(changed);
        if (observer.roundEnd && !observer.roundEnd(stats_)) {
            stats_.stopped = StopReason::Monitor;
            break;
        }
    }
    stats_.complete = stats_.stopped == StopReason::Goal;
    stats_.metamodules = occupied_;
    stats_.seconds = elapsed();
    return stats_;
}

}  // namespace holon::planner
