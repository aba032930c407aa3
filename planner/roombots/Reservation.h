#pragma once
// holon's reservation strategy for Roombots assembly (rules/library/roombots_reserve.holon, run by
// the reference interpreter, coordinating walks on the kinematic model), and the walk planner it rests on,
// which the automatic seeding recipe also asks. Internal to planner/roombots.

#include "planner/roombots/CoordinationRule.h"
#include "planner/roombots/World.h"

#include <map>
#include <optional>

namespace holon::planner::roombots::detail {

class Reservation : public World {
public:
    Reservation(const CloudTable& table, Coupling coupling, const Setting& setting) : World(table, coupling, setting) {
        for (const Posture& p : postures_)  // an upper bound on a step's reach, for the A* heuristic
            if (p.stance()) maxStep_ = std::max(maxStep_, planar(p.cells[3], {}));
    }
    AssemblyResult run();
    /// The fewest actions from standing upright at `start` to filling seed `seed`, around `blocked`
    /// (-1: no walk).
    int walk(int seed, const Cell& start, const CellSet& blocked);
    /// How many postures a walk can stand in at the seed's foot (joint setting and yaw) change shape
    /// into the seed without sweeping `blocked`.
    int seatings(int seed, const CellSet& blocked) const;

private:
    void assignSeeds();
    /// A* over (foot, yaw, joint setting): the fewest actions to stand seated in the body's seed.
    std::vector<Move> plan(int i, const CellSet& blocked) const;
    /// In seeding order, each metamodule plans its walk and starts when the coordination rule
    /// fires its start; a metamodule never starts before one earlier in the order.
    void startWaiting();
    /// The body's previous action (if any) has ended: start the next, or sit when the walk is done.
    void advance(int i);
    /// Every floor column the walk's body and collision clouds cover, from standing at the start.
    std::vector<Cell> columns(int i, const std::vector<Move>& path) const;

    double maxStep_ = 1;
    std::vector<int> order_;
    std::optional<CoordinationRule> rule_;
    std::map<int, std::vector<Move>> paths_;
    std::pair<int, int> planned_{-1, -1};
    int version_ = 0;
};

}  // namespace holon::planner::roombots::detail
