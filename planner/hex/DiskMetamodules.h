#pragma once
// Seed 000's general_n metamodules realised on hex-lattice disk modules (§III-C, Fig. 4a): a plan of
// the U/P/F planner on the square metamodule lattice becomes module-level pivot moves. Metamodule
// (x, y) is a slot of disks laid out by DiskDesign; every fired template that moves a unit of mass
// between two slots replays the design's motion sequence for that template, turned and mirrored
// into place, each move one applied instance of hex_pivot.holon (PivotRules), and templates that
// only relabel move no disk.

#include "planner/Problem.h"
#include "planner/hex/DiskDesign.h"
#include "planner/hex/PivotRules.h"

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

namespace holon::planner::hex {

struct DiskMove {
    std::int64_t instance = 0;  // the fired instance of the plan this move belongs to (0-based)
    std::string rule;
    Vec from, to, pivot;  // axial disk coordinates
};

class DiskMetamodules {
public:
    /// Lays the problem's start configuration out as disks. Throws InputError for a 3D problem or a
    /// system whose templates do not conserve mass (disks are neither made nor destroyed).
    explicit DiskMetamodules(const Problem& problem);

    const DiskDesign& design() const { return design_; }
    int side() const { return design_.side(); }
    int disksPerUnit() const { return design_.disksPerUnit(); }
    /// Moves the disks for one fired instance (`old`: its cells' previous values, `now`: the board).
    /// Returns false, with failure() saying why, for a template the design has no sequence for or
    /// a move hex_pivot does not enable there. Throws InternalError for a move of the design that
    /// is no pivot move at all.
    bool fired(std::int64_t anchor, int shape, const BoxEngine::Value* old, const std::vector<BoxEngine::Value>& now);
    const std::vector<DiskMove>& moves() const { return moves_; }
    const std::string& failure() const { return failure_; }
    const std::vector<Vec>& startDisks() const { return start_; }
    std::vector<Vec> disks() const;
    /// Whether every metamodule slot holds exactly the design's layout for the board's value.
    bool slotsMatch(const std::vector<BoxEngine::Value>& now, std::string& why) const;

private:
    bool occupied(Vec disk) const { return cells_[pivots_->board().index(disk)] != 0; }
    Vec slotOrigin(Vec metamodule) const { return {side() * metamodule.x, side() * metamodule.y, 0}; }

    const Problem* problem_;
    DiskDesign design_;
    std::unique_ptr<PivotRules> pivots_;   // on the slots of the board and one slot of margin
    std::vector<BoxEngine::Value> cells_;  // the disks, on pivots_'s board
    std::int64_t instances_ = 0;
    std::vector<Vec> start_;
    std::vector<DiskMove> moves_;
    std::string failure_;
};

/// Replays `moves` from `start` and checks each one independently of how it was found and of the
/// engine that applied it (hex_pivot's left side and its constraint `connected`): it moves a
/// disk to an empty neighbouring cell, rolling about an occupied common neighbour with the other
/// common neighbour empty, and all disks are connected afterwards. Returns "" or the first fault.
std::string replayDiskMoves(const std::vector<Vec>& start, const std::vector<DiskMove>& moves);

/// SVG of disk configurations side by side (e.g. start and end), each with a caption.
std::string disksSvg(const std::vector<std::pair<std::string, std::vector<Vec>>>& panels);

/// seed 000 Fig. 4a: a creation sequence (the design's base sequence with the receiver at level
/// `receiverLevel`) drawn as `frames` snapshots of the two slots, the moving disks highlighted.
std::string sequenceSvg(const DiskDesign& design, int receiverLevel, int frames);

}  // namespace holon::planner::hex
