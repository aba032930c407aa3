#pragma once
// A region of at most 64 cells as words: a set of cells is one 64-bit word, and the neighbours of
// a set are a few shifts of it (one per lattice direction in a box region). The explorer decides
// connectivity with it: flood fills a layer at a time, and the cut cells of a connected set.

#include "rules/Region.h"

#include <bit>
#include <cstdint>
#include <vector>

namespace holon::checker {

class WordAdjacency {
public:
    /// Usable when the region has at most 64 cells.
    static bool fits(const rules::Region& region) { return region.size() <= 64; }
    explicit WordAdjacency(const rules::Region& region);
    /// The cells adjacent to each cell.
    const std::vector<std::uint64_t>& neighbours() const { return neighbourBits_; }
    /// The cells adjacent to some cell of r (r's own cells included where they neighbour one).
    std::uint64_t around(std::uint64_t r) const {
        if (!shifts_.empty()) return neighboursOf(r);
        std::uint64_t out = 0;
        for (; r; r &= r - 1) out |= neighbourBits_[std::countr_zero(r)];
        return out;
    }
    /// Whether a set of cells is connected (the empty set is).
    bool connected(std::uint64_t set) const;
    /// The cut cells of a connected, non-empty set: those whose removal disconnects it.
    std::uint64_t cutCells(std::uint64_t set) const;
    /// Whether `set` is connected, given targets such that every component of `set` holds one:
    /// exactly when one target reaches all the others.
    [[gnu::noinline]] bool targetsJoined(std::uint64_t set, std::uint64_t targets) const;

private:
    std::vector<std::uint64_t> neighbourBits_;  // per cell, its neighbours as a mask
    /// The neighbours of a set of cells as a few word shifts. Cells whose neighbour sits `delta`
    /// indices away form one mask (in a box, one per direction), so the neighbours of every cell
    /// in r are the union over steps of (r & from) shifted by delta. Empty on an irregular region.
    struct Shift {
        std::uint64_t from;
        std::uint8_t left, right;  // delta = left - right; one of them is 0 (branch-free)
    };
    std::vector<Shift> shifts_;
    template <std::size_t N>
    std::uint64_t neighboursBy(std::uint64_t r) const {  // unrolled for boxes: 4 shifts on square2d, 6 on cubic3d
        std::uint64_t out = 0;
        for (std::size_t i = 0; i < N; ++i) out |= ((r & shifts_[i].from) << shifts_[i].left) >> shifts_[i].right;
        return out;
    }
    std::uint64_t neighboursOf(std::uint64_t r) const {
        switch (shifts_.size()) {
        case 4: return neighboursBy<4>(r);
        case 6: return neighboursBy<6>(r);
        }
        std::uint64_t out = 0;
        for (const Shift& s : shifts_) out |= ((r & s.from) << s.left) >> s.right;
        return out;
    }
};

}  // namespace holon::checker
