#pragma once
// Visited-state storage for explicit-state search: configurations packed into bit vectors, kept in an
// arena and indexed by an open-addressing hash table. Insertion is lock-free so several threads can
// expand states at once; growing happens between phases.

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

/// How a configuration of n cells over an alphabet packs into 64-bit words (no cell straddles a word).
class StateLayout {
public:
    StateLayout(int cells, int alphabetSize);
    int words() const { return words_; }
    int bitsPerCell() const { return bits_; }
    void pack(const CellValue* cells, std::uint64_t* out) const;
    void unpack(const std::uint64_t* in, CellValue* cells) const;
    std::uint64_t hash(const std::uint64_t* packed) const;
    /// Overwrites one cell of a packed state.
    void set(std::uint64_t* packed, int cell, CellValue v) const {
        const int w = cell / perWord_, shift = (cell % perWord_) * bits_;
        packed[w] = (packed[w] & ~(mask_ << shift)) | (static_cast<std::uint64_t>(v) << shift);
    }

private:
    int cells_, bits_, perWord_, words_;
    std::uint64_t mask_;
};

class StateStore {
public:
    explicit StateStore(const StateLayout& layout);
    const StateLayout& layout() const { return layout_; }
    /// Ids handed out so far (including the rare ids lost to a race, see isHole()).
    StateId capacityUsed() const { return next_.load(std::memory_order_relaxed); }
    std::uint64_t size() const { return capacityUsed() - holes_.load(std::memory_order_relaxed); }
    /// Makes room for `more` new states without reallocating; call only while no thread inserts.
    void reserve(std::uint64_t more);
    /// Releases the headroom reserve() kept: the table is rebuilt at most half full and the arena cut
    /// to the states stored. Call only while no thread inserts.
    void shrinkToFit();
    /// Thread-safe: the id of the state, and whether this call added it.
    std::pair<StateId, bool> insert(const std::uint64_t* packed) { return insert(packed, layout_.hash(packed)); }
    std::pair<StateId, bool> insert(const std::uint64_t* packed, std::uint64_t hash);
    /// Hints the cache about the table slot a state hashes to; returns the hash for insert().
    std::uint64_t prefetch(const std::uint64_t* packed) const {
        const std::uint64_t h = layout_.hash(packed);
        __builtin_prefetch(&slots_[h & (slotCount_ - 1)]);
        return h;
    }
    StateId find(const std::uint64_t* packed) const;
    const std::uint64_t* state(StateId id) const { return &arena_[static_cast<std::size_t>(id) * layout_.words()]; }
    /// An id reserved by a thread that then found its state already inserted by another thread.
    bool isHole(StateId id) const { return holeFlags_[id] != 0; }
    /// Memory held per stored state, table and arena together.
    double bytesPerState() const;
    std::size_t bytes() const;

private:
    StateLayout layout_;
    std::vector<std::uint64_t> arena_;
    std::unique_ptr<std::atomic<StateId>[]> slots_;  // 0 empty, id + 1 otherwise
    std::size_t slotCount_ = 0;
    std::vector<std::uint8_t> holeFlags_;
    std::atomic<StateId> next_{0};
    std::atomic<StateId> holes_{0};
    std::size_t capacity_ = 0;  // states the arena holds without growing
};

}  // namespace holon::checker
