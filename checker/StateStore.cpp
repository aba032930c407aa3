// Packed state storage in the manner of explicit-state model checkers (Storm, SPIN, LTSmin): a
// configuration is a bit vector of ceil(log2 |alphabet|) bits per cell; the arena holds them back to
// back and a linear-probing table of 32-bit slots (id and hash tag) finds them. Threads insert with
// one compare-and-swap on the table slot after writing the arena; when two threads race to add the
// same new state, the loser's reserved id becomes a hole that is skipped everywhere.

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
    growArena(need);
    // Keep the table at most three quarters full even if the arena fills up (in practice far
    // fewer states are inserted: most successors are already known). Ids then stay below the slot
    // count, so the tag width changes only when the table is rebuilt anyway.
    std::size_t want = 1024;
    while (want * 3 < 4 * capacity_) want <<= 1;
    if (want > slotCount_) rebuildTable(want);
}

void StateStore::growArena(std::size_t need) {
    if (need <= capacity_) return;
    capacity_ = std::max<std::size_t>(need, capacity_ + capacity_ / 2);
    arena_.resize(capacity_ * layout_.words());
    holeFlags_.resize(capacity_, 0);
}

StateId StateStore::append(const std::uint64_t* packed) {
    const StateId id = next_.load(std::memory_order_relaxed);
    if (id >= 0xFFFFFFF0u) throw InputError("more than 4 billion states; lower --max-states");
    growArena(static_cast<std::size_t>(id) + 1);
    std::memcpy(&arena_[static_cast<std::size_t>(id) * layout_.words()], packed, sizeof(std::uint64_t) * layout_.words());
    next_.store(id + 1, std::memory_order_relaxed);
    ++appended_;
    return id;
}

void StateStore::rebuildTable(std::size_t want) {
    std::unique_ptr<std::atomic<std::uint32_t>[]> old = std::move(slots_);
    const std::size_t oldCount = slotCount_;
    const std::uint32_t oldMask = tagMask_;
    slots_ = std::make_unique<std::atomic<std::uint32_t>[]>(want);
    slotCount_ = want;
    const int idBits = std::bit_width(want);
    tagMask_ = idBits >= 32 ? 0 : ~std::uint32_t{0} << idBits;
    for (std::size_t i = 0; i < want; ++i) slots_[i].store(0, std::memory_order_relaxed);
    for (std::size_t i = 0; i < oldCount; ++i) {
        const std::uint32_t s = old[i].load(std::memory_order_relaxed);
        if (!s) continue;
        const StateId id = (s & ~oldMask) - 1;
        const std::uint64_t h = layout_.hash(state(id));
        std::size_t pos = h & (want - 1);
        while (slots_[pos].load(std::memory_order_relaxed)) pos = (pos + 1) & (want - 1);
        slots_[pos].store(tagOf(h) | (id + 1), std::memory_order_relaxed);
    }
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
    while (want < 2 * (used - appended_)) want <<= 1;
    rebuildTable(want);
}

std::pair<StateId, bool> StateStore::insert(const std::uint64_t* packed, std::uint64_t hash) {
    const int words = layout_.words();
    const std::size_t mask = slotCount_ - 1;
    const std::uint32_t tag = tagOf(hash);
    std::size_t pos = hash & mask;
    StateId mine = kNoState;
    while (true) {
        std::uint32_t s = slots_[pos].load(std::memory_order_acquire);
        if (s == 0) {
            if (mine == kNoState) {
                mine = next_.fetch_add(1, std::memory_order_relaxed);
                std::memcpy(&arena_[static_cast<std::size_t>(mine) * words], packed, sizeof(std::uint64_t) * words);
            }
            if (slots_[pos].compare_exchange_strong(s, tag | (mine + 1), std::memory_order_acq_rel)) return {mine, true};
        }
        if ((s & tagMask_) == tag && sameWords(state(idIn(s)), packed, words)) {
            if (mine != kNoState) {
                holeFlags_[mine] = 1;
                holes_.fetch_add(1, std::memory_order_relaxed);
            }
            return {idIn(s), false};
        }
        pos = (pos + 1) & mask;
    }
}

StateId StateStore::find(const std::uint64_t* packed, std::uint64_t hash) const {
    const int words = layout_.words();
    const std::size_t mask = slotCount_ - 1;
    const std::uint32_t tag = tagOf(hash);
    for (std::size_t pos = hash & mask;; pos = (pos + 1) & mask) {
        const std::uint32_t s = slots_[pos].load(std::memory_order_acquire);
        if (s == 0) return kNoState;
        if ((s & tagMask_) == tag && sameWords(state(idIn(s)), packed, words)) return idIn(s);
    }
}

std::size_t StateStore::bytes() const {
    return arena_.size() * sizeof(std::uint64_t) + slotCount_ * sizeof(std::uint32_t) + holeFlags_.size();
}

double StateStore::bytesPerState() const {
    const double n = static_cast<double>(std::max<std::uint64_t>(1, size()));
    // What a stored state costs: its packed words, its table slots at the current load, its flag.
    return layout_.words() * 8.0 + static_cast<double>(slotCount_) * sizeof(StateId) / n + 1.0;
}

}  // namespace holon::checker
