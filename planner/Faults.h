#pragma once
// Faults injected into a plan run (`holon plan --lose, --lose-random, --delay, --drop`):
// metamodules lost between rounds, and a message layer between neighbours in which a state change
// reaches them late and relabel messages are lost. Delays and drops only choose which interleaving
// runs, so seed 000's lemmas cover them; a loss makes a configuration no rule leads to, so after
// each one the reference interpreter judges the lemmas' hypotheses (the system's invariants and its
// progress assumption): the run goes on only from a configuration they cover, and otherwise stops
// naming what the loss broke. docs/faults.md says what that does and does not promise.

#include "planner/Execution.h"

#include <nlohmann/json.hpp>

#include <functional>
#include <optional>
#include <string>
#include <vector>

namespace holon::planner {

/// A metamodule lost after a round: the one at `cell`, or a random one (no cell).
struct Loss {
    std::int64_t round = 1;
    std::optional<Vec> cell;
};

struct FaultOptions {
    std::vector<Loss> losses;
    std::int64_t delay = 0;  // a state change reaches the neighbours 1 to `delay` rounds later; 0: no message layer
    double drop = 0;         // the chance that a relabel's message is lost when it would fire (it is sent again later)
    std::uint64_t seed = 1;
    bool any() const { return !losses.empty() || delay > 0 || drop > 0; }
};

/// `--lose ROUND:x,y[,z]` (with `cell`) or `--lose-random ROUND`; throws InputError naming the
/// option and the fix.
Loss parseLoss(const std::string& option, const std::string& text, int dimension, bool cell);

class Faults {
public:
    /// Throws InputError (naming --lose) for a lost cell outside the board.
    Faults(const Problem& problem, FaultOptions options);
    /// RunOptions::admit: whether the messages the instance needs have arrived and, for a relabel,
    /// whether its message gets through this time.
    bool admit(const Execution& execution, std::int64_t anchor, int shape);
    /// An instance fired: the cells it changed reach their neighbours 1 to `delay` rounds later.
    void fired(const Execution& execution, std::int64_t anchor, int shape, const BoxEngine::Value* old);
    /// At the end of a step or round, the losses that are due. `lost` hears each lost cell (the
    /// monitor and the report); a loss that breaks the lemmas' hypotheses halts the run ("fault").
    void roundEnd(Execution& execution, const std::function<void(std::int64_t cell, BoxEngine::Value old)>& lost);
    /// What a loss broke, or empty.
    const std::string& broken() const { return broken_; }
    /// One line on what was injected: losses made and still pending, messages dropped and delayed.
    std::string summary() const;
    nlohmann::json json() const;

private:
    std::string judge(const Execution& execution, std::int64_t cell, BoxEngine::Value old, std::int64_t round) const;
    std::string describe(std::int64_t cell, BoxEngine::Value value) const;
    const Problem* problem_;
    FaultOptions options_;
    Random random_;
    std::vector<bool> done_;           // per loss
    std::vector<std::string> events_;  // what each loss did
    std::int64_t roundsSeen_ = 0;      // the last round roundEnd was called after
    /// What loss k did, or why it was not made.
    std::string event(std::size_t k) const;
    std::vector<std::int64_t> arrives_;  // per board cell with --delay: the round its latest state reaches the neighbours (64 bits: --delay 10^6 allows runs past 2^32 rounds)
    std::int64_t dropped_ = 0, delayed_ = 0;
    std::string broken_;
};

}  // namespace holon::planner
