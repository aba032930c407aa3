#pragma once
// Hole-motion shape sculpting, seed 003 §IV: holes (a missing module and its six neighbours,
// guarded by a 12-module shepherd group) wander through a hex-lattice ensemble; growth nodes on
// the surface create holes, deletion nodes consume them, and gravity-driven column collapse
// smooths the surface. One object holds the ensemble and advances it one timestep at a time.

#include "planner/Random.h"
#include "planner/hex/HexArray.h"
#include "planner/hex/HoleRules.h"
#include "planner/hex/MassTree.h"
#include "planner/hex/TriRegions.h"

#include <cstdint>
#include <limits>
#include <memory>
#include <vector>

namespace holon::planner::hex {

struct SculptOptions {
    double decay = 25;            // c_decay of the temperature test (§IV-E), in timesteps per diameter
    double holeDensity = 0.01;    // initial holes per lattice point of the source
    int startWindow = 100;        // initial holes start moving at a uniformly random timestep below this
    bool keepConnected = false;   // holon's improvement: refuse every change that would cut the mass apart (MassTree)
    bool dropOverhangs = false;   // holon's improvement: a column head with a gap below it falls into the gap
    bool roll = false;            // holon's improvement: outside the target, surface modules roll down one-hop slopes
    bool deleteOverflow = false;  // holon's improvement: modules outside the target delete holes in growth regions too
    bool growInside = false;      // holon's improvement: growth only where the new shepherd group lies inside the target
    bool flexibleGrowth = false;  // holon's improvement: growth with one module more or fewer than a shepherd group
    bool migrate = false;         // holon's improvement: modules outside the target move along the surface to empty target points
    bool balance = false;         // holon's improvement: keep the holes to the number that makes the volume the target's area
    std::uint64_t seed = 1;
};

/// Where the wrong lattice points are (compliance counts them): modules outside the target, target
/// points empty (of those, how many no empty path joins to the empty points outside the target:
/// voids walled in by the mass), and hole cells outside the target.
struct SculptResidue {
    std::int64_t outside = 0, emptyInside = 0, walledIn = 0, holeCellsOutside = 0;
};

struct SculptCounts {
    std::int64_t created = 0, deleted = 0, steered = 0, collapsed = 0, holeMoves = 0, refusedSplits = 0, migrated = 0, surplusDeleted = 0;
};

class HoleSculptor {
public:
    HoleSculptor(const HexArray& array, const std::vector<std::uint8_t>& source, const std::vector<std::uint8_t>& target,
                 const TriPlan& plan, const SculptOptions& options);

    /// One timestep of §IV-C: holes move, creation/deletion regions activate, smoothing.
    void step();

    int time() const { return time_; }
    std::int64_t modules() const { return modules_; }
    std::int64_t holes() const { return liveHoles_; }
    /// (target area - modules) / 7: the live holes with which the volume equals the target's area.
    std::int64_t holeBudget() const { return holeBudget_; }
    const SculptCounts& counts() const { return counts_; }
    /// §V-A's metrics; a lattice point counts as filled when it holds a module or belongs to a hole.
    double completeness() const;
    double stability() const;
    double compliance() const;
    /// Modules outside the largest connected mass (modules and hole cells, 6-adjacency).
    std::int64_t islands() const;
    SculptResidue residue() const;
    bool module(std::int64_t i) const { return cells_[i] == rules_->module(); }
    /// Centres of the holes alive now.
    std::vector<std::int64_t> holeCentres() const;
    bool holeCell(std::int64_t i) const { return cells_[i] == rules_->rim() || cells_[i] == rules_->centre(); }
    const HexArray& array() const { return *array_; }
    /// A board cell's state (hex_holes's M, H, C; 0 empty) and the rules that write it.
    BoxEngine::Value cell(std::int64_t i) const { return cells_[i]; }
    const HoleRules& rules() const { return *rules_; }
    const std::vector<std::uint8_t>& target() const { return *target_; }

private:
    struct Hole {
        std::int64_t centre = 0;
        int direction = 0, start = 0;
        bool alive = false;
    };
    using Value = HoleRules::Value;
    /// Writes a cell of the start configuration (the source and its initial holes); every later
    /// change applies a rule instance (apply).
    void place(std::int64_t i, Value v);
    /// Bookkeeping (module count, metrics) after cell i changed from `old`.
    void changed(std::int64_t i, Value old);
    /// Applies a rule instance of `engine` to the ensemble, with the bookkeeping of every changed cell.
    void apply(const BoxEngine& engine, std::int64_t anchor, int shape);
    bool filled(std::int64_t i) const { return cells_[i] != 0; }
    /// The hole a cell belongs to, or -1.
    std::int32_t holeOf(std::int64_t i) const;
    bool onSurface(std::int64_t k) const;
    void placeInitialHoles();
    bool canMove(int id, int d) const;
    void move(int id, int d);
    void activate(std::int64_t k);
    void tryCreate(std::int64_t k);
    void tryDelete(std::int64_t k, int gravity);
    void smooth(std::int64_t k, int gravity);
    void migrate();  // SurfaceMigration.cpp
    void deleteSurplus();
    /// The hex_delete shape that empties exactly `emptied` around hole `id` (it must match).
    int deletion(int id, const std::vector<std::int64_t>& emptied) const;
    void remove(int id, int shape);
    int towardSurface(std::int64_t centre, std::int64_t node, int up) const;
    std::vector<std::int64_t> nearestTheSurface(int id, int toward) const;
    bool shepherdsAnother(std::int64_t i, int id) const;

    const HexArray* array_;
    const std::vector<std::uint8_t>* target_;
    const TriPlan* plan_;
    SculptOptions options_;
    Random random_;
    int time_ = 0;
    std::unique_ptr<const HoleRules> rules_;
    std::unique_ptr<MassTree> tree_;         // with keepConnected or migrate: the connectivity test
    std::vector<std::int32_t> towardEmpty_;  // with migrate: moves along the surface to an empty target point
    struct Arrival {
        std::int32_t value = std::numeric_limits<std::int32_t>::max();  // the field value a migrant arrived with
        int time = 0;
    };
    std::vector<Arrival> arrival_;             // with migrate: per cell, how its migrant arrived there
    static constexpr int kArrivalMemory = 16;  // timesteps an arrival value binds the migrant
    std::vector<Value> cells_;                 // the ensemble, as hex_holes.holon's cell states
    std::vector<std::uint8_t> class_;          // class: 0 stays filled, 1 stays empty, 2 to fill, 3 to empty
    std::vector<std::int32_t> holeAt_;         // per hole centre: its hole's id; -1 elsewhere
    std::vector<Hole> holesById_;
    std::vector<std::int64_t> activePoints_;  // lattice points inside active tri-regions, shuffled once
    std::vector<double> nearPerimeter_;       // d_near: hops to the target's perimeter
    double maxDistance_ = 1;                  // d_max
    std::int64_t classSize_[4] = {}, classCorrect_[4] = {};
    std::int64_t modules_ = 0, liveHoles_ = 0;
    std::int64_t holeBudget_ = 0;        // (target area - modules) / 7: the holes that fill the target exactly
    std::int64_t growthDemand_ = 0;      // --balance: growth nodes this timestep that the budget held back
    std::int64_t deletionLicences_ = 0;  // --balance: deletions below the budget still allowed this timestep
    SculptCounts counts_;
    // Offsets (index steps): ring 1, disk of radius 1 and 2, ring 2 and 3, radius-3 disk, and per
    // direction the shepherds ordered by how far they lie toward the direction.
    std::vector<std::int64_t> ring1_, disk1_, ring2_, ring3_, disk2_, disk3_;
    std::vector<int> distance3_;  // hops of each disk3_ cell from the centre
    std::vector<std::int64_t> uppermost_[6];
};

}  // namespace holon::planner::hex
