#pragma once
// The randomizer's turn for the field allocators (gradient, demand, eager): after a round in which
// nothing fired although the allocator's fields had settled, the fields see no way forward (a
// destroyer may need a D that only a detour brings), so seed 000 §IV-B's randomizer moves
// resources until the next creation or deletion. So does a run in which only transfers have fired
// for four rounds per metamodule, or a quarter of the no-progress window if that is shorter.

#include "planner/Allocator.h"

#include <cstdint>
#include <memory>

namespace holon::planner {

class StallFallback {
public:
    explicit StallFallback(std::uint64_t seed);
    /// Called from the allocator's update with whether its own fields moved; returns whether
    /// anything moved (the fields, or the randomizer taking or keeping its turn).
    bool update(const Execution& ex, bool fieldsMoved);
    /// Whether the randomizer has the turn; then it decides every transfer.
    bool active() const { return active_; }
    bool wants(const Execution& ex, std::int64_t anchor, int shape) const { return random_->wants(ex, anchor, shape); }

private:
    std::unique_ptr<Allocator> random_;
    std::int64_t stepsAtUpdate_ = -1, motionsAtUpdate_ = 0;
    bool active_ = false;
};

}  // namespace holon::planner
