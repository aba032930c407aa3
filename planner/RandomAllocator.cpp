// The paper's baseline allocator (seed 000 §IV-B): "a randomizer which transports resources by
// randomly switching adjacent C and D labels". Each enabled transfer is approved on a fair coin.
// Approving every one would not be random under synchronous rounds: a maximal set of swaps moves
// every resource every round, and on a line two D's then keep the parity of their distance and
// may never meet where a deletion needs them (box:8x1 -> box:4x1 under general1 ran forever).

#include "planner/Allocator.h"
#include "planner/Random.h"

#include <utility>

namespace holon::planner {

namespace {
class RandomAllocator final : public Allocator {
public:
    explicit RandomAllocator(std::uint64_t seed) : random_(seed ^ 0x72616e646f6dull) {}
    std::string name() const override { return "random"; }
    bool wants(const Execution&, std::int64_t, int) const override {
        const bool yes = random_.below(2) == 0;
        declined_ = declined_ || !yes;
        return yes;
    }
    /// A round whose coins all came up tails is not stuck: the next round flips again.
    bool update(const Execution&) override { return std::exchange(declined_, false); }

private:
    mutable Random random_;
    mutable bool declined_ = false;
};
}  // namespace

std::unique_ptr<Allocator> randomAllocator(std::uint64_t seed) { return std::make_unique<RandomAllocator>(seed); }

}  // namespace holon::planner
