#pragma once
// rules/library/hex_pivot.holon (seed 000 Fig. 1a: a disk rolls about an occupied neighbour, the
// cell on the other side of the move empty) compiled for one box of hex-lattice disk cells by the
// planner's engine. The disk back-end moves every disk by applying one of its instances, and the
// disk design's search asks the same engine which rolls are enabled, so neither re-codes the pivot.
// A roll is found by its geometry, read off the rule's two sides: the cell that empties, the one
// that fills, and the one that stays occupied (the pivot).

#include "planner/BoxEngine.h"
#include "rules/Model.h"

#include <memory>
#include <vector>

namespace holon::planner::hex {

class PivotRules {
public:
    using Value = BoxEngine::Value;
    /// hex_pivot on the box [lower, lower + extent) of hex2d (extent.z 1, as every 2D Board); every
    /// cell of the box can hold a disk.
    PivotRules(Vec lower, Vec extent);
    PivotRules(const PivotRules&) = delete;  // the model points into the system
    PivotRules& operator=(const PivotRules&) = delete;
    ~PivotRules();

    const Board& board() const { return *board_; }
    const BoxEngine& engine() const { return *engine_; }
    /// The state of a cell holding a disk (empty is 0).
    Value disk() const { return disk_; }
    /// An instance: a shape and the board index of its anchor; shape -1 for none.
    struct Instance {
        int shape = -1;
        std::int64_t anchor = 0;
    };
    /// The instance that rolls the disk at board cell `from` to its neighbour in direction d about
    /// the common neighbour in direction d + 1 (`side` 0) or d - 1 (`side` 1).
    Instance roll(std::int64_t from, int d, int side) const { return {roll_[d][side].shape, from + roll_[d][side].anchor}; }
    /// The instance that rolls the disk at `from` to `to` about `pivot`; shape -1 when these are
    /// no pivot move (not neighbours, or the pivot not next to both).
    Instance find(Vec from, Vec to, Vec pivot) const;

private:
    struct Compiled;
    std::unique_ptr<Compiled> compiled_;
    std::unique_ptr<Board> board_;
    std::unique_ptr<BoxEngine> engine_;
    Value disk_ = 0;
    Instance roll_[6][2];  // anchor: the index step from the moving disk to the shape's anchor
};

}  // namespace holon::planner::hex
