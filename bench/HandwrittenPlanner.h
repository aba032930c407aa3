#pragma once
// A hand-written C++ copy of the U/P/F planner over intermediate (seed 000 §IV-A), kept only here
// as the yardstick for the compiled engine (issue: "at most 1.2x its time"). The six rules are
// written out as C++ conditions on a packed cell byte; the scheduler is the one the planner uses
// (synchronous rounds: enabled instances in random order, kept when they neither read what a kept
// one writes nor write what it reads; anchors within one step of a changed cell re-evaluated), so
// the comparison measures decision tables against hand-coded rules, nothing else. The memory layout
// and prefetching are the planner's too (enabled and listed bits side by side, read and write marks
// side by side, the memory of the visit 8 places ahead requested first).

#include "planner/Problem.h"
#include "planner/Random.h"

#include <cstdint>
#include <vector>

namespace holon::bench {

class HandwrittenPlanner {
public:
    /// Lays out the problem's start, target and seed (F) on its bounding box with its own padding;
    /// nothing of the problem's compiled rules is used.
    HandwrittenPlanner(const planner::Problem& problem, std::uint64_t randomSeed);
    /// Runs synchronous rounds until the goal (true) or until nothing is enabled (false).
    bool run();
    std::int64_t rounds() const { return rounds_; }
    std::int64_t steps() const { return steps_; }
    std::int64_t evaluations() const { return evaluations_; }
    std::int64_t occupied() const;

private:
    // Cell byte: kind in bits 0-1, parent direction in bits 2-4 (P only), target in bit 5.
    enum Kind : std::uint8_t { Empty = 0,
                               U = 1,
                               F = 2,
                               P = 3 };
    // Instance: anchor * 64 + rule * 8 + direction; the deletion uses direction 0.
    enum Rule { Finalize,
                PathFinalize,
                PathCreate,
                PathPropagate,
                Create,
                Delete,
                kRules };

    static Kind kind(std::uint8_t c) { return static_cast<Kind>(c & 3); }
    static bool inTarget(std::uint8_t c) { return (c >> 5) & 1; }
    static int parent(std::uint8_t c) { return (c >> 2) & 7; }
    bool enabled(std::int64_t a, int rule, int d) const;
    void recheck(std::int64_t a);
    bool take(std::int64_t a, int rule, int d);
    void fire(std::int64_t a, int rule, int d);
    bool atGoal(std::uint8_t c) const { return inTarget(c) ? kind(c) == F : kind(c) == Empty; }

    planner::Board board_;
    int degree_;
    std::vector<int> opposite_;
    std::vector<std::uint8_t> cells_;
    struct Bits {
        std::uint64_t enabled = 0, listed = 0;  // per anchor: bit rule * 8 + d
    };
    struct Marks {
        std::uint32_t read = 0, write = 0;
    };
    std::vector<Bits> bits_;
    std::vector<std::uint64_t> list_;
    std::vector<Marks> marks_;
    std::vector<std::uint32_t> stamp_;
    std::vector<std::int64_t> changed_, anchors_;
    std::uint32_t clock_ = 0;
    std::int64_t offGoal_ = 0, rounds_ = 0, steps_ = 0, evaluations_ = 0;
    planner::Random random_;
};

}  // namespace holon::bench
