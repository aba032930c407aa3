// When a field allocator hands its transfers to the randomizer, and when it takes them back
// (see StallFallback.h).

#include "planner/StallFallback.h"
#include "planner/Execution.h"

namespace holon::planner {

std::unique_ptr<Allocator> randomAllocator(std::uint64_t seed);

StallFallback::StallFallback(std::uint64_t seed) : random_(randomAllocator(seed)) {}

bool StallFallback::update(const Execution& ex, bool fieldsMoved) {
    const RunStats& st = ex.stats();
    const std::int64_t motions = st.creations + st.deletions;
    bool moved = fieldsMoved;
    if (motions != motionsAtUpdate_) active_ = false;
    if (st.steps == stepsAtUpdate_ && !moved && !active_) active_ = moved = true;
    else if (active_) moved = random_->update(ex) || moved;
    stepsAtUpdate_ = st.steps, motionsAtUpdate_ = motions;
    return moved;
}

}  // namespace holon::planner
