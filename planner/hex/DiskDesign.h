#pragma once
// A general_n metamodule design for hex-lattice disks (seed 000 §III-C, Fig. 4a): the disks each
// metamodule state holds, and the fixed module-level motion sequence behind every template, each
// found once by search and then replayed wherever the planner fires the template. Seed 000's
// description is the target: "metamodule creation sequences ... Each system's metamodule
// destruction sequence runs the creation sequence in reverse."
//
// Metamodule (x, y) is the s x s parallelogram of disk cells at axial (s·x + i, s·y + j). A state of
// k units of mass (B1 = 1 .. C = n + 1 on general_n) holds a ring of disks on the parallelogram's
// border (one unit: the skeleton, which touches the rings of all four neighbours, as seed 000 asks of
// partial metamodules) and k - 1 units of payload inside it. A template moves one unit from a slot
// A to the neighbouring slot B: a door opens in the double wall between them (a ring with a gap
// is still connected, so no move can cut the ensemble), the unit passes through, the door closes.
// Every pivot move (seed 000 Fig. 1a) has both of its common neighbours inside A and B, so a
// sequence is valid whatever the neighbouring slots hold; the rings of A and B outside the door
// never move while their slot stays non-empty, so every neighbour keeps its contact.
// The sequences are found for B east of A; the lattice's half turn about the pair's centre gives
// those where B gives to A, the mirror q <-> r those along y, and reversal the destructions.

#include "planner/Problem.h"

#include <cstdint>
#include <string>
#include <vector>

namespace holon::planner::hex {

/// One pivot move of one disk: it rolls from `from` to the neighbouring `to` about `pivot`, the
/// other cell next to both empty (axial coordinates).
struct PivotMove {
    Vec from, to, pivot;
};

class DiskDesign {
public:
    /// The design for general_n with `units` = n + 1 levels of mass (C = n + 1 units, B1 = 1).
    /// Chooses the smallest odd side for which every sequence is found. Throws InputError when
    /// none up to a limit is.
    explicit DiskDesign(int units);

    int side() const { return side_; }
    int units() const { return units_; }
    /// Disks per unit of mass (the ring's size).
    int disksPerUnit() const { return ringSize_; }
    /// The disk cells of a slot holding `level` units (0 .. units), slot-local (i, j).
    const std::vector<Vec>& layout(int level) const { return layouts_[level]; }
    /// The moves that take slots a (lower coordinate along the axis) and b (a + 1 along x, or
    /// along y when `alongY`) from levels (a0, b0) to (a1, b1), one unit changing hands; in global
    /// axial coordinates with slot a's origin at `origin`. Empty with ok = false if no sequence
    /// joins them: the levels are not one unit apart, or neither the giver before nor the receiver
    /// after holds the heaviest level (C), which every template of general_n has.
    std::vector<PivotMove> sequence(int a0, int b0, int a1, int b1, bool alongY, Vec origin, bool& ok) const;
    /// The base sequence with the receiver at `receiverLevel` (B east of A, A at the origin).
    const std::vector<PivotMove>& base(int receiverLevel) const { return base_[receiverLevel]; }

private:
    /// Lays out slots of the given side, payload kept `doorZone` hops from each door's middle,
    /// and searches every base sequence; false if one is not found.
    bool build(int side, int doorZone);

    int units_ = 0, side_ = 0, ringSize_ = 0;
    std::vector<std::vector<Vec>> layouts_;
    // base_[k]: A from `units` to `units - 1`, B from k to k + 1, for k = 0 .. units - 1.
    std::vector<std::vector<PivotMove>> base_;
};

}  // namespace holon::planner::hex
