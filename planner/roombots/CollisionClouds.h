#pragma once
// The collision-cloud look-up table of seed 001 §IV-A f: for every metamodule configuration and every
// shape transition a metamodule makes from a posture it can stand in, the grid cells the motion
// touches. Computed once from the kinematics (`holon roombots --make-clouds FILE`), shipped as JSON and
// only read at run time, as the paper's external table.

#include "planner/roombots/Kinematics.h"
#include "rules/Budget.h"

#include <array>
#include <map>
#include <string>
#include <vector>

namespace holon::planner::roombots {

struct Transition {
    enum class Kind : std::uint8_t { Step,
                                     Seat };
    Kind kind;  // Step: the head lands facing down on the floor; Seat: any other posture
    Joints to;
    double seconds;           // the slowest joint's travel (outer joints 2 s, swivel 3 s per turn, §III)
    std::vector<Cell> cloud;  // relative to the foot at yaw 0, sorted
};

class CloudTable {
public:
    static constexpr int kSamples = 48;
    static constexpr double kRadius = 0.45;
    /// Every transition from the start posture (all joints 0, the upright I) and from every posture a
    /// walk reaches, to one representative per reachable target (fewest cells swept, then fastest).
    /// `budget` is read between postures (Budget::check: a signal or the deadline ends it).
    static CloudTable compute(const Budget& budget = {});
    static CloudTable load(const std::string& path);  // throws InputError naming the file
    /// The default table that ships with holon.
    static std::string defaultPath();
    std::string json() const;

    /// Transitions from joint setting `from` (empty when the table has none).
    const std::vector<Transition>& from(Coupling c, const Joints& from) const;
    std::size_t size() const;

private:
    std::array<std::map<int, std::vector<Transition>>, 4> table_;
};

}  // namespace holon::planner::roombots
