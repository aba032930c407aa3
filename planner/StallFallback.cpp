// When a field allocator hands its transfers to the randomizer, and when it takes them back
// (see StallFallback.h).

#include "planner/StallFallback.h"
#include "planner/Execution.h"

#include <algorithm>

namespace holon::planner {

std::unique_ptr<Allocator> randomAllocator(std::uint64_t seed);

StallFallback::StallFallback(std::uint64_t seed) : random_(randomAllocator(seed)) {}

bool StallFallback::update(const Execution& ex, bool fieldsMoved) {
    const RunStats& st = ex.stats();
    const std::int64_t motions = st.creations + st.deletions;
    bool moved = fieldsMoved;
    if (motions != motionsAtUpdate_) active_ = false;
    // The randomizer takes the turn after a round in which nothing fired and the fields did not
    // move, or when only transfers have fired for longer than any resource needs to cross the
    // ensemble, with room to spare: four rounds per metamodule (on the shape bench's general_n
    // runs the longest such stretch was under two rounds per metamodule), or a quarter of the
    // no-progress window if that is shorter. Then the fields move resources back and forth and
    // never settle, where the randomizer completes (a lock planner under `demand` whose locked
    // pair waits for a D the fields send elsewhere: audit 12).
    const bool livelock = ex.idleRounds() > std::min(4 * ex.metamodules(), ex.idleWindow() / 4);
    if ((livelock || (st.steps == stepsAtUpdate_ && !moved)) && !active_) active_ = moved = true;
    else if (active_) moved = random_->update(ex) || moved;
    stepsAtUpdate_ = st.steps, motionsAtUpdate_ = motions;
    return moved;
}

}  // namespace holon::planner
