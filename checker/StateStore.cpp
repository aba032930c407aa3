// Packed state storage in the manner of explicit-state model checkers (Storm, SPIN, LTSmin): a
// configuration is a bit vector of ceil(log2 |alphabet|) bits per cell; the arena holds them back to
// back and a linear-probing table of 32-bit ids finds them. Threads insert with one compare-and-swap
// on the table slot after writing the arena; when two threads race to add the same new state, the
// loser's reserved id becomes a hole that is skipped everywhere.

#include "checker/StateStore.h"

#include "rules/Error.h"

#include <bit>
#include <cstring>

namespace holon::checker {

StateLayout::StateLayout(int cells, int alphabetSize) : cells_(cells) {
    bits_ = std::max(1, static_cast<int>(std::bit_width(static_cast<unsigned>(alphabetSize - 1))));
    perWord_ = 64 / bits_;
    words_ = (cells + perWord_ - 1) / perWord_;
    mask_ = bits_ == 64 ? ~std::uint64_t{0} : (std::uint64_t{1} << bits_) - 1;
}

void StateLayout::pack(const CellValue* cells, std::uint64_t* out) const {
    for (int w = 0; w < words_; ++w) out[w] = 0;
    for (int i = 0; i < cells_; ++i) out[i / perWord_] |= static_cast<std::uint64_t>(cells[i]) << ((i % perWord_) * bits_);
}

void StateLayout::unpack(const std::uint64_t* in, CellValue* cells) const {
    for (int i = 0; i < cells_; ++i) cells[i] = static_cast<CellValue>((in[i / perWord_] >> ((i % perWord_) * bits_)) & mask_);
}

std::uint64_t StateLayout::hash(const std::uint64_t* packed) const {
    std::uint64_t h = 0x9E3779B97F4A7C15ull;
    for (int w = 0; w < words_; ++w) {
        std::uint64_t x = packed[w] + h;
        x = (x ^ (x >> 30)) * 0xBF58476D1CE4E5B9ull;
        x = (x ^ (x >> 27)) * 0x94D049BB133111EBull;
        h = x ^ (x >> 31);
    }
    return h;
}

StateStore::StateStore(const StateLayout& layout) : layout_(layout) { reserve(1024); }

void StateStore::reserve(std::uint64_t more) {
    const std::uint64_t need = static_cast<std::uint64_t>(capacityUsed()) + more;
    if (need >= 0xFFFFFFF0ull) throw InputError("more than 4 billion states; lower --max-states");
    if (need > capacity_) {
        capacity_ = std::max<std::size_t>(need, capacity_ + capacity_ / 2);
        arena_.resize(capacity_ * layout_.words());
        holeFlags_.resize(capacity_, 0);
    }
    // Keep the table at most three quarters full even if every reserved id is inserted (in practice
    // far fewer are: most successors are already known).
    std::size_t want = 1024;
    while (want * 3 < 4 * need) want <<= 1;
    if (want <= slotCount_) return;
    auto slots = std::make_unique<std::atomic<StateId>[]>(want);
    for (std::size_t i = 0; i < want; ++i) slots[i].store(0, std::memory_order_relaxed);
    const std::size_t mask = want - 1;
    for (std::size_t i = 0; i < slotCount_; ++i) {
        const StateId s = slots_[i].load(std::memory_order_relaxed);
        if (!s) continue;
        std::size_t pos = layout_.hash(state(s - 1)) & mask;
        while (slots[pos].load(std::memory_order_relaxed)) pos = (pos + 1) & mask;
        slots[pos].store(s, std::memory_order_relaxed);
    }
    slots_ = std::move(slots);
    slotCount_ = want;
}

namespace {
bool sameWords(const std::uint64_t* a, const std::uint64_t* b, int words) {
    for (int w = 0; w < words; ++w)
        if (a[w] != b[w]) return false;
    return true;
}
}  // namespace

void StateStore::shrinkToFit() {
    const std::size_t used = capacityUsed();
    capacity_ = std::max<std::size_t>(used, 1);
    arena_.resize(capacity_ * layout_.words());
    arena_.shrink_to_fit();
    holeFlags_.resize(capacity_);
    holeFlags_.shrink_to_fit();
    std::size_t want = 1024;
    while (want < 2 * used) want <<= 1;
    auto slots = std::make_unique<std::atomic<StateId>[]>(want);
    for (std::size_t i = 0; i < want; ++i) slots[i].store(0, std::memory_order_relaxed);
    for (std::size_t i = 0; i < slotCount_; ++i) {
        const StateId s = slots_[i].load(std::memory_order_relaxed);
        if (!s) continue;
        std::size_t pos = layout_.hash(state(s - 1)) & (want - 1);
        while (slots[pos].load(std::memory_order_relaxed)) pos = (pos + 1) & (want - 1);
        slots[pos].store(s, std::memory_order_relaxed);
    }
    slots_ = std::move(slots);
    slotCount_ = want;
}

std::pair<StateId, bool> StateStore::insert(const std::uint64_t* packed, std::uint64_t hash) {
    const int words = layout_.words();
    const std::size_t mask = slotCount_ - 1;
    std::size_t pos = hash & mask;
    StateId mine = kNoState;
    while (true) {
        StateId s = slots_[pos].load(std::memory_order_acquire);
        if (s == 0) {
            if (mine == kNoState) {
                mine = next_.fetch_add(1, std::memory_order_relaxed);
                std::memcpy(&arena_[static_cast<std::size_t>(mine) * words], packed, sizeof(std::uint64_t) * words);
            }
            if (slots_[pos].compare_exchange_strong(s, mine + 1, std::memory_order_acq_rel)) return {mine, true};
        }
        if (sameWords(state(s - 1), packed, words)) {
            if (mine != kNoState) {
                holeFlags_[mine] = 1;
                holes_.fetch_add(1, std::memory_order_relaxed);
            }
            return {s - 1, false};
        }
        pos = (pos + 1) & mask;
    }
}

StateId StateStore::find(const std::uint64_t* packed) const {
    const int words = layout_.words();
    const std::size_t mask = slotCount_ - 1;
    for (std::size_t pos = layout_.hash(packed) & mask;; pos = (pos + 1) & mask) {
        const StateId s = slots_[pos].load(std::memory_order_acquire);
        if (s == 0) return kNoState;
        if (sameWords(state(s - 1), packed, words)) return s - 1;
    }
}

std::size_t StateStore::bytes() const {
    return arena_.size() * sizeof(std::uint64_t) + slotCount_ * sizeof(StateId) + holeFlags_.size();
}

double StateStore::bytesPerState() const {
    const double n = static_cast<double>(std::max<std::uint64_t>(1, size()));
    // What a stored state costs: its packed words, its table slots at the current load, its flag.
    return layout_.words() * 8.0 + static_cast<double>(slotCount_) * sizeof(StateId) / n + 1.0;
}

}  // namespace holon::checker
