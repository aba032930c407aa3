#pragma once
// Seed 000's general_n metamodules realised on hex-lattice disk modules (§III-C, Fig. 4a): a plan of
// the U/P/F planner on the square metamodule lattice becomes a sequence of module-level pivot moves.
// Metamodule (x, y) is the s x s parallelogram of disks at axial (s·x + i, s·y + j); a state of m mass
// units holds m·(2s - 1) disks: the lightest state is the skeleton cross alone (it touches all four
// neighbours, as seed 000 asks of partial metamodules) and s is the smallest odd side whose inner
// cells the heaviest state fills to at most 60% (general_2: s = 13, B1 = 25 disks, D = 50, C = 75).
// Every template moves disks one at a time from the slots that lose mass to those that gain it, each
// rolling about a neighbour (seed 000 Fig. 1a: the cell on the other side of the move must be empty)
// while the rest stays connected.

#include "planner/Problem.h"

#include <cstdint>
#include <functional>
#include <unordered_map>
#include <string>
#include <vector>

namespace holon::planner::hex {

struct DiskMove {
    std::int64_t instance = 0;  // the fired instance of the plan this move belongs to (0-based)
    std::string rule;
    Vec from, to, pivot;        // axial disk coordinates
};

class DiskMetamodules {
public:
    /// Lays the problem's start configuration out as disks. Throws InputError for a 3D problem or a
    /// system whose templates do not conserve mass (disks are neither made nor destroyed).
    explicit DiskMetamodules(const Problem& problem);

    int side() const { return side_; }
    int disksPerUnit() const { return perUnit_; }
    /// Moves the disks for one fired instance (`old`: its cells' previous values, `now`: the board).
    /// Returns false, with failure() saying why, when no pivot path exists.
    bool fired(std::int64_t anchor, int shape, const BoxEngine::Value* old, const std::vector<BoxEngine::Value>& now);
    const std::vector<DiskMove>& moves() const { return moves_; }
    const std::string& failure() const { return failure_; }
    std::vector<Vec> startDisks() const { return start_; }
    std::vector<Vec> disks() const;
    /// Disks each metamodule slot should hold for the board's values, and whether every slot does.
    bool slotsMatch(const std::vector<BoxEngine::Value>& now, std::string& why) const;

private:
    std::int64_t at(Vec disk) const { return (disk.x - origin_.x) + std::int64_t(width_) * (disk.y - origin_.y); }
    Vec diskOf(std::int64_t i) const { return {static_cast<int>(i % width_) + origin_.x, static_cast<int>(i / width_) + origin_.y, 0}; }
    std::vector<std::int64_t> slotCells(Vec metamodule) const;
    bool connectedWithout(std::int64_t skip) const;
    struct Window {
        int lowX, highX, lowY, highY;
        bool contains(Vec v) const { return v.x >= lowX && v.x < highX && v.y >= lowY && v.y < highY; }
    };
    struct PivotStep {
        Vec from, to, pivot;
    };
    struct Path {
        std::int64_t found = -1;  // the cell reached
        std::vector<PivotStep> steps;
    };
    static constexpr std::size_t kNotGoal = static_cast<std::size_t>(-1);
    std::vector<std::int64_t> movers(Vec source, Vec destination) const;
    Path rollPath(std::int64_t start, const std::function<std::size_t(std::int64_t)>& rankOf, const Window& window) const;
    void commit(const Path& path, std::int64_t instance, const std::string& rule);
    bool moveOne(Vec source, Vec destination, std::int64_t instance, const std::string& rule);
    bool relay(const std::vector<std::int64_t>& candidates, const std::vector<std::int64_t>& to, const Window& window, std::int64_t instance, const std::string& rule);
    bool runChain(const std::vector<std::int64_t>& chain, const std::unordered_map<std::int64_t, std::int64_t>& next, const Window& window, std::int64_t instance,
                  const std::string& rule);

    const Problem* problem_;
    int side_ = 1, perUnit_ = 1, width_ = 0, height_ = 0;
    Vec origin_;                          // the disk at grid index 0
    std::vector<std::uint8_t> occupied_;  // per disk cell of the grid
    std::int64_t disks_ = 0, instances_ = 0;
    std::vector<Vec> start_;
    std::vector<DiskMove> moves_;
    std::string failure_;
};

/// Replays `moves` from `start` and checks each one independently of how it was found: it moves a
/// disk to an empty neighbouring cell, rolling about an occupied common neighbour with the other
/// common neighbour empty, and all disks are connected afterwards. Returns "" or the first fault.
std::string replayDiskMoves(const std::vector<Vec>& start, const std::vector<DiskMove>& moves);

/// SVG of disk configurations side by side (e.g. start and end), each with a caption.
std::string disksSvg(const std::vector<std::pair<std::string, std::vector<Vec>>>& panels);

}  // namespace holon::planner::hex
