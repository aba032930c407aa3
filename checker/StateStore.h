#pragma once
// Visited-state storage for explicit-state search: configurations packed into bit vectors, kept in an
// arena and indexed by an open-addressing hash table. Insertion is lock-free so several threads can
// expand states at once; growing happens between phases.

#include "checker/PageArray.h"
#include "rules/Model.h"

#include <atomic>
#include <cstdint>
#include <memory>
#include <utility>
#include <vector>

namespace holon::checker {

using rules::CellValue;
using StateId = std::uint32_t;
constexpr StateId kNoState = 0xFFFFFFFFu;

/// How a configuration of n cells over an alphabet packs into 64-bit words. Cell-major: a cell's
/// bits side by side, no cell straddling a word. Plane-major (regions of at most 64 cells): plane j
/// holds bit j of every cell's state, planes back to back (a plane may straddle two words), so
/// the word-parallel successor generator reads a plane with a shift.
class StateLayout {
public:
    StateLayout(int cells, int alphabetSize, bool planeMajor = false);
    int words() const { return words_; }
    int bitsPerCell() const { return bits_; }
    bool planeMajor() const { return planeMajor_; }
    void pack(const CellValue* cells, std::uint64_t* out) const;
    void unpack(const std::uint64_t* in, CellValue* cells) const;
    std::uint64_t hash(const std::uint64_t* packed) const {
        std::uint64_t h = 0x9E3779B97F4A7C15ull;
        for (int w = 0; w < words_; ++w) {
            std::uint64_t x = packed[w] + h;
            x = (x ^ (x >> 30)) * 0xBF58476D1CE4E5B9ull;
            x = (x ^ (x >> 27)) * 0x94D049BB133111EBull;
            h = x ^ (x >> 31);
        }
        return h;
    }
    /// Overwrites one cell of a packed state.
    void set(std::uint64_t* packed, int cell, CellValue v) const;
    /// Plane-major only: plane j of a packed state (bit c is bit j of cell c's state).
    std::uint64_t plane(const std::uint64_t* packed, int j) const {
        const int at = j * cells_, w = at >> 6, shift = at & 63;
        std::uint64_t p = packed[w] >> shift;
        if (shift && w + 1 < words_) p |= packed[w + 1] << (64 - shift);
        return p & cellMask_;
    }
    /// Plane-major only: XORs `bits` (a word over cells) into plane j of a packed state.
    void flip(std::uint64_t* packed, int j, std::uint64_t bits) const {
        const int at = j * cells_, w = at >> 6, shift = at & 63;
        packed[w] ^= bits << shift;
        if (shift && w + 1 < words_) packed[w + 1] ^= bits >> (64 - shift);
    }

private:
    int cells_, bits_, perWord_, words_;
    bool planeMajor_;
    std::uint64_t mask_, cellMask_;
};

class StateStore {
public:
    explicit StateStore(const StateLayout& layout);
    const StateLayout& layout() const { return layout_; }
    /// Ids handed out so far (including those of blocks their threads did not use, see isHole()).
    StateId capacityUsed() const { return next_.load(std::memory_order_relaxed); }
    std::uint64_t size() const { return capacityUsed() - holes_.load(std::memory_order_relaxed); }
    /// Makes room for `more` new states without reallocating; call only while no thread inserts.
    void reserve(std::uint64_t more);
    /// Releases the headroom reserve() kept: the table is rebuilt at most half full and the arena cut
    /// to the states stored. Call only while no thread inserts.
    void shrinkToFit();
    /// Adds a state to the arena without indexing it: the caller knows it is new and finds it by
    /// other means (the explorer ranks a complete enumeration). A store used this way is never
    /// searched. Call only while no thread inserts.
    StateId append(const std::uint64_t* packed);
    /// The ids one thread gives the states it adds, taken from the store a block at a time, so
    /// that two threads' new states do not share cache lines of the arena and of the caller's
    /// per-state arrays (measured: two threads were slower than one without this).
    struct IdBlock {
        static constexpr StateId kSize = 16;
        StateId next = 0, end = 0, size = kSize;
    };
    /// Thread-safe: the id of the state, and whether this call added it.
    std::pair<StateId, bool> insert(const std::uint64_t* packed) {
        IdBlock one{0, 0, 1};
        return insert(packed, layout_.hash(packed), one);
    }
    std::pair<StateId, bool> insert(const std::uint64_t* packed, std::uint64_t hash, IdBlock& ids);
    /// The ids left in a block become holes; call only while no thread inserts. reserve()'s room
    /// must cover IdBlock::kSize ids per thread beyond the states added.
    void release(IdBlock& ids);
    /// Hints the cache about the table slot a state hashes to; returns the hash for insert().
    std::uint64_t prefetch(const std::uint64_t* packed) const {
        const std::uint64_t h = layout_.hash(packed);
        __builtin_prefetch(&slots_[h & (slots_.size() - 1)]);
        return h;
    }
    /// The second stage of a look-up pipeline: once prefetch()'s slot is in cache, hints the cache
    /// about the first stored state whose tag matches, the one find() compares against. Returns
    /// where that walk stopped (at that state's slot or at an empty one): find() may resume there,
    /// since a slot once filled never empties.
    std::size_t prefetchStored(std::uint64_t hash) const {
        const std::uint32_t tag = tagOf(hash);
        const std::size_t mask = slots_.size() - 1;
        for (std::size_t pos = hash & mask;; pos = (pos + 1) & mask) {
            const std::uint32_t s = slot(pos).load(std::memory_order_relaxed);
            if (!s) return pos;
            if ((s & tagMask_) == tag) {
                __builtin_prefetch(state(idIn(s)));
                return pos;
            }
        }
    }
    StateId find(const std::uint64_t* packed) const { return find(packed, layout_.hash(packed)); }
    StateId find(const std::uint64_t* packed, std::uint64_t hash) const { return find(packed, hash, hash & (slots_.size() - 1)); }
    /// find() from a position prefetchStored returned for this hash.
    StateId find(const std::uint64_t* packed, std::uint64_t hash, std::size_t from) const;
    const std::uint64_t* state(StateId id) const { return &arena_[static_cast<std::size_t>(id) * layout_.words()]; }
    /// An id of a block that its thread did not use (IdBlock).
    bool isHole(StateId id) const { return holeFlags_[id] != 0; }
    /// Memory held per stored state, table and arena together.
    double bytesPerState() const;
    std::size_t bytes() const;
    /// bytes() without the arena's room beyond the states stored (untouched pages).
    std::size_t bytesUsed() const;

private:
    // A slot is 0 (empty) or id + 1 in its low bits (as many as the slot count needs) and, above
    // them, a tag: the same bits of the state's hash. Most probes that meet another state are then
    // rejected without reading it.
    std::uint32_t tagOf(std::uint64_t hash) const { return static_cast<std::uint32_t>(hash >> 32) & tagMask_; }
    StateId idIn(std::uint32_t slot) const { return (slot & ~tagMask_) - 1; }
    std::atomic_ref<std::uint32_t> slot(std::size_t pos) const { return std::atomic_ref<std::uint32_t>(slots_[pos]); }
    void rebuildTable(std::size_t slots);

    StateLayout layout_;
    PageArray<std::uint64_t> arena_;
    mutable PageArray<std::uint32_t> slots_;  // read and written through atomic_ref
    std::uint32_t tagMask_ = 0;
    PageArray<std::uint8_t> holeFlags_;
    std::atomic<StateId> next_{0};
    std::atomic<StateId> holes_{0};
    std::size_t capacity_ = 0;  // states the arena holds without growing
    std::size_t appended_ = 0;  // states added by append(), not in the table
    void growArena(std::size_t need);
};

}  // namespace holon::checker
