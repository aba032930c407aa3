// The paper's baseline allocator (seed 000 §IV-B): "a randomizer which transports resources by
// randomly switching adjacent C and D labels". It approves every enabled transfer; the scheduler's
// random choice among them is the randomizer.

#include "planner/Allocator.h"

namespace holon::planner {

namespace {
class RandomAllocator final : public Allocator {
public:
    std::string name() const override { return "random"; }
    bool wants(const Execution&, std::int64_t, int) const override { return true; }
};
}  // namespace

std::unique_ptr<Allocator> randomAllocator() { return std::make_unique<RandomAllocator>(); }

}  // namespace holon::planner
