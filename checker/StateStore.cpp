// Packed state storage in the manner of explicit-state model checkers (Storm, SPIN, LTSmin): a
// configuration is a bit vector of ceil(log2 |alphabet|) bits per cell; the arena holds them back to
// back and a linear-probing table of 32-bit slots (id and hash tag) finds them. Threads insert with
// one compare-and-swap on the table slot after writing the arena; each takes its ids from blocks of
// its own, and the ids a block did not use become holes that are skipped everywhere.

#include "checker/StateStore.h"

#include "rules/Error.h"
#include "rules/Parameter.h"

#include <bit>
#include <cstring>

namespace holon::checker {

StateLayout::StateLayout(int cells, int alphabetSize, bool planeMajor) : cells_(cells), planeMajor_(planeMajor && cells <= 64) {
    bits_ = std::max(1, static_cast<int>(std::bit_width(static_cast<unsigned>(alphabetSize - 1))));
    perWord_ = 64 / bits_;
    words_ = planeMajor_ ? (cells * bits_ + 63) / 64 : (cells + perWord_ - 1) / perWord_;
    mask_ = bits_ == 64 ? ~std::uint64_t{0} : (std::uint64_t{1} << bits_) - 1;
    cellMask_ = cells >= 64 ? ~std::uint64_t{0} : (std::uint64_t{1} << cells) - 1;
}

void StateLayout::pack(const CellValue* cells, std::uint64_t* out) const {
    for (int w = 0; w < words_; ++w) out[w] = 0;
    if (planeMajor_) {
        for (int j = 0; j < bits_; ++j) {
            std::uint64_t p = 0;
            for (int i = 0; i < cells_; ++i) p |= static_cast<std::uint64_t>((cells[i] >> j) & 1u) << i;
            flip(out, j, p);
        }
        return;
    }
    for (int i = 0; i < cells_; ++i) out[i / perWord_] |= static_cast<std::uint64_t>(cells[i]) << ((i % perWord_) * bits_);
}

void StateLayout::unpack(const std::uint64_t* in, CellValue* cells) const {
    if (planeMajor_) {
        for (int i = 0; i < cells_; ++i) cells[i] = 0;
        for (int j = 0; j < bits_; ++j)
            for (std::uint64_t p = plane(in, j); p; p &= p - 1) cells[std::countr_zero(p)] |= static_cast<CellValue>(1u << j);
        return;
    }
    for (int i = 0; i < cells_; ++i) cells[i] = static_cast<CellValue>((in[i / perWord_] >> ((i % perWord_) * bits_)) & mask_);
}

void StateLayout::set(std::uint64_t* packed, int cell, CellValue v) const {
    if (planeMajor_) {
        for (int j = 0; j < bits_; ++j)
            if (((plane(packed, j) >> cell) & 1u) != ((v >> j) & 1u)) flip(packed, j, std::uint64_t{1} << cell);
        return;
    }
    const int w = cell / perWord_, shift = (cell % perWord_) * bits_;
    packed[w] = (packed[w] & ~(mask_ << shift)) | (static_cast<std::uint64_t>(v) << shift);
}

StateStore::StateStore(const StateLayout& layout) : layout_(layout) { reserve(1024); }

void StateStore::reserve(std::uint64_t more) {
    const std::uint64_t need = static_cast<std::uint64_t>(capacityUsed()) + more;
    if (need >= 0xFFFFFFF0ull) throw InputError("more than 4 billion states; lower " + rules::parameterName(rules::Parameter::MaxStates), rules::Parameter::MaxStates);
    growArena(need);
    // The table stays at most 7/8 full even if all the room asked for is used, which it almost
    // never is (most successors are already known), so it is rebuilt rarely. Ids stay below the
    // slot count, so the tag width changes only when the table is rebuilt anyway.
    std::size_t want = 1024;
    while (want * 7 < 8 * need) want <<= 1;
    if (want > slots_.size()) rebuildTable(want);
}

void StateStore::growArena(std::size_t need) {
    if (need <= capacity_) return;
    capacity_ = need;  // the pages grow by remapping: no copy, so no reason to grow ahead
    arena_.resize(capacity_ * layout_.words());
    holeFlags_.resize(capacity_);
}

StateId StateStore::append(const std::uint64_t* packed) {
    const StateId id = next_.load(std::memory_order_relaxed);
    if (id >= 0xFFFFFFF0u) throw InputError("more than 4 billion states; lower " + rules::parameterName(rules::Parameter::MaxStates), rules::Parameter::MaxStates);
    growArena(static_cast<std::size_t>(id) + 1);
    std::memcpy(&arena_[static_cast<std::size_t>(id) * layout_.words()], packed, sizeof(std::uint64_t) * layout_.words());
    next_.store(id + 1, std::memory_order_relaxed);
    ++appended_;
    return id;
}

void StateStore::rebuildTable(std::size_t want) {
    // Only called while no thread inserts: plain reads and writes.
    PageArray<std::uint32_t> old = std::move(slots_);
    const std::uint32_t oldMask = tagMask_;
    slots_.resize(want);  // fresh pages: every slot empty
    const int idBits = std::bit_width(want);
    tagMask_ = idBits >= 32 ? 0 : ~std::uint32_t{0} << idBits;
    for (const std::uint32_t s : old) {
        if (!s) continue;
        const StateId id = (s & ~oldMask) - 1;
        const std::uint64_t h = layout_.hash(state(id));
        std::size_t pos = h & (want - 1);
        while (slots_[pos]) pos = (pos + 1) & (want - 1);
        slots_[pos] = tagOf(h) | (id + 1);
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
    arena_.shrinkToFit();
    holeFlags_.resize(capacity_);
    holeFlags_.shrinkToFit();
    std::size_t want = 1024;
    while (want < 2 * (used - appended_)) want <<= 1;
    if (want != slots_.size()) rebuildTable(want);
}

void StateStore::release(IdBlock& ids) {
    for (; ids.next < ids.end; ++ids.next) holeFlags_[ids.next] = 1, holes_.fetch_add(1, std::memory_order_relaxed);
}

std::pair<StateId, bool> StateStore::insert(const std::uint64_t* packed, std::uint64_t hash, IdBlock& ids) {
    const int words = layout_.words();
    const std::size_t mask = slots_.size() - 1;
    const std::uint32_t tag = tagOf(hash);
    std::size_t pos = hash & mask;
    StateId mine = kNoState;
    while (true) {
        std::uint32_t s = slot(pos).load(std::memory_order_acquire);
        if (s == 0) {
            if (mine == kNoState) {
                if (ids.next == ids.end) ids.next = next_.fetch_add(ids.size, std::memory_order_relaxed), ids.end = ids.next + ids.size;
                mine = ids.next++;
                std::memcpy(&arena_[static_cast<std::size_t>(mine) * words], packed, sizeof(std::uint64_t) * words);
            }
            if (slot(pos).compare_exchange_strong(s, tag | (mine + 1), std::memory_order_acq_rel)) return {mine, true};
        }
        if ((s & tagMask_) == tag && sameWords(state(idIn(s)), packed, words)) {
            if (mine != kNoState) --ids.next;  // another thread added it first: the id goes back to the block
            return {idIn(s), false};
        }
        pos = (pos + 1) & mask;
    }
}

StateId StateStore::find(const std::uint64_t* packed, std::uint64_t hash, std::size_t from) const {
    const int words = layout_.words();
    const std::size_t mask = slots_.size() - 1;
    const std::uint32_t tag = tagOf(hash);
    for (std::size_t pos = from;; pos = (pos + 1) & mask) {
        const std::uint32_t s = slot(pos).load(std::memory_order_acquire);
        if (s == 0) return kNoState;
        if ((s & tagMask_) == tag && sameWords(state(idIn(s)), packed, words)) return idIn(s);
    }
}

std::size_t StateStore::bytes() const {
    return arena_.size() * sizeof(std::uint64_t) + slots_.size() * sizeof(std::uint32_t) + holeFlags_.size();
}

std::size_t StateStore::bytesUsed() const {
    return static_cast<std::size_t>(capacityUsed()) * (layout_.words() * sizeof(std::uint64_t) + 1) + slots_.size() * sizeof(std::uint32_t);
}

double StateStore::bytesPerState() const {
    const double n = static_cast<double>(std::max<std::uint64_t>(1, size()));
    // What a stored state costs: its packed words, its table slots at the current load, its flag.
    return layout_.words() * 8.0 + static_cast<double>(slots_.size()) * sizeof(StateId) / n + 1.0;
}

}  // namespace holon::checker
