#pragma once
// The simulated floor every assembly strategy runs on (seed 001 §IV-A): metamodules standing by their
// foot on a structured floor, their actions in continuous time, and the one geometric collision test
// for all strategies — two collision clouds, or a cloud and a standing body, meeting in overlapping
// time. Internal to planner/roombots.

#include "planner/roombots/Assembly.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>
#include <queue>
#include <set>
#include <unordered_set>

namespace holon::planner::roombots::detail {

struct CellHash {
    std::size_t operator()(const Cell& c) const {
        return static_cast<std::size_t>(c.x) * 73856093u ^ static_cast<std::size_t>(c.y) * 19349663u ^ static_cast<std::size_t>(c.z) * 83492791u;
    }
};
using CellSet = std::unordered_set<Cell, CellHash>;

constexpr double kInf = std::numeric_limits<double>::infinity();

inline Cell turn(Cell c, int yaw) {
    for (int k = 0; k < yaw; ++k) c = {-c.y, c.x, c.z};
    return c;
}

inline double planar(const Cell& a, const Cell& b) { return std::hypot(a.x - b.x, a.y - b.y); }

inline bool meets(const std::vector<Cell>& cloud, const CellSet& cells) {
    return std::any_of(cloud.begin(), cloud.end(), [&](const Cell& c) { return cells.count(c) != 0; });
}
template <class Cells>
bool meets(const std::vector<Cell>& a, const Cells& b) {
    for (const Cell& c : a)
        if (std::find(b.begin(), b.end(), c) != b.end()) return true;
    return false;
}

struct Body {  // one metamodule: its stance, its current action, and each strategy's bookkeeping
    Cell foot;
    int yaw = 0;
    Joints joints;
    std::array<Cell, 4> cells;
    bool placed = false, started = false;
    int moves = 0, stall = 0, seed = -1, action = -1;
    double best = kInf, moving = -1;  // moving: end of the current action
    std::vector<Cell> cloud;
    Cell knownFoot, previousFoot{1 << 20, 0, 0};
};

/// A transition made concrete for a body: where it ends up and what it sweeps.
struct Move {
    const Transition* transition = nullptr;
    Cell foot;
    int yaw = 0;
    Joints joints;
    std::array<Cell, 4> cells;
    std::vector<Cell> cloud;
};

struct Floor {
    int x0, x1, y0, y1;
    bool contains(const Cell& c) const { return c.z == 0 && c.x >= x0 && c.x <= x1 && c.y >= y0 && c.y <= y1; }
};

class World {
public:
    World(const CloudTable& table, Coupling coupling, const Setting& setting);
    /// The budget asked before every action (AssemblyOptions::budget).
    void stopWhen(const Budget& budget) { budget_ = budget; }

protected:
    static constexpr double kLatchSeconds = 1.0;  // choice: head latches, foot unlatches (§III gives no figure)

    std::array<Cell, 4> place(const std::array<Cell, 4>& local, const Cell& foot, int yaw) const;
    Move realise(const Transition& t, const Cell& foot, int yaw) const;
    /// The seating transition from a standing state into seed s whose cloud avoids `blocked`.
    std::optional<Move> seat(const Cell& foot, int yaw, const Joints& joints, const Seed& s, const CellSet& blocked) const;
    bool done() const;
    /// Throws AssemblyStopped once the run's budget is spent; called before every action.
    void stopIfAsked() const {
        if (budget_.reached()) throw AssemblyStopped{};
    }
    /// Starts an action: the body takes its new state at once, and sweeps `cloud` until the end.
    void start(int i, const Move& m, bool seatAction, double fx, double fy);
    void deadlock(const std::string& reason);
    /// Body i has filled its seed: it joins the structure, and every metamodule's cells are recorded.
    void placed(int i);
    /// The result, once the event loop has stopped.
    AssemblyResult finish();

    const CloudTable& table_;
    Coupling coupling_;
    const Setting& setting_;
    std::vector<Posture> postures_;
    Floor floor_{};
    std::vector<Body> bodies_;
    std::set<std::pair<int, int>> collided_;  // (action, module) pairs already counted
    using Event = std::pair<double, int>;
    std::priority_queue<Event, std::vector<Event>, std::greater<>> events_;
    double now_ = 0;
    AssemblyResult result_;
    Budget budget_;
};

AssemblyResult assembleByForceField(const CloudTable& table, Coupling coupling, Strategy strategy, const Setting& setting,
                                    const AssemblyOptions& options);
AssemblyResult assembleByReservation(const CloudTable& table, Coupling coupling, const Setting& setting, const AssemblyOptions& options);

}  // namespace holon::planner::roombots::detail
