#pragma once
// Whether a change to the hex ensemble keeps it one connected mass, answered from a spanning
// structure kept alongside the ensemble rather than by searching the whole mass each time. The
// structure is the one the U/P/F planner grows (seed 000 §IV-A: every metamodule has a parent on a
// path to the root, and only a cell nothing hangs on may go); here it is a hop potential d over the
// filled cells (modules and hole cells) with one invariant: every filled cell but the root has a
// filled neighbour whose d is one less. Following those parents reaches the root, so the invariant
// is connectivity. A distributed ensemble keeps such a potential by neighbour messages.

#include "planner/hex/HexArray.h"

#include <cstdint>
#include <functional>
#include <vector>

namespace holon::planner::hex {

class MassTree {
public:
    /// `filled(i)`: whether board cell i holds a module or a hole cell, read at every call.
    MassTree(const HexArray& array, std::function<bool(std::int64_t)> filled);

    /// Hop distances from `root` by breadth-first search over the filled cells. Throws
    /// std::logic_error if some filled cell is not connected to the root.
    void rebuild(std::int64_t root);
    std::int64_t root() const { return root_; }

    /// Whether emptying `emptied` and filling `filledNow` (given against the ensemble as it is now)
    /// keeps every filled cell connected to the root. Exact when no more than `kReseatLimit` cells
    /// lose every parent; beyond that it answers no. On yes the potential is updated as though the
    /// change were made, and the caller must make it.
    bool change(const std::int64_t* emptied, int emptiedCount, const std::int64_t* filledNow, int filledCount);
    bool change(const std::vector<std::int64_t>& emptied, const std::vector<std::int64_t>& filledNow) {
        return change(emptied.data(), static_cast<int>(emptied.size()), filledNow.data(), static_cast<int>(filledNow.size()));
    }

    /// The potential of a filled cell (-1 for an empty one).
    std::int32_t distance(std::int64_t i) const { return d_[i]; }

    static constexpr int kReseatLimit = 4096;

private:
    bool filledAfter(std::int64_t i) const;

    const HexArray* array_;
    std::function<bool(std::int64_t)> filled_;
    std::int64_t root_ = -1;
    std::vector<std::int32_t> d_;
    // Scratch for one change: 1 emptied, 2 filled now, 3 lost its parents (being re-seated).
    std::vector<std::uint8_t> mark_;
    std::vector<std::int64_t> touched_;
};

}  // namespace holon::planner::hex
