// The simulated floor of seed 001 §IV-A shared by every assembly strategy: bodies, transitions from
// the collision-cloud table made concrete at a foot and yaw, actions in continuous time (an action
// lasts its slowest joint's travel plus a latch, so metamodules that start together drift apart, as
// the paper observes), and collision counting.

#include "planner/roombots/World.h"

namespace holon::planner::roombots::detail {

World::World(const CloudTable& table, Coupling coupling, const Setting& setting)
    : table_(table), coupling_(coupling), setting_(setting) {
    const Metamodule metamodule(coupling);
    for (int i = 0; i < kJointSettings; ++i) postures_.push_back(metamodule.posture(Joints::fromIndex(i), 0));
    constexpr int kFar = std::numeric_limits<int>::max() / 2;
    floor_ = {kFar, -kFar, kFar, -kFar};
    auto extend = [&](const Cell& c) {
        floor_.x0 = std::min(floor_.x0, c.x - 6), floor_.x1 = std::max(floor_.x1, c.x + 6);
        floor_.y0 = std::min(floor_.y0, c.y - 6), floor_.y1 = std::max(floor_.y1, c.y + 6);
    };
    for (const Seed& s : setting.recipe.seeds) extend(s.cells[0]);
    for (std::size_t i = 0; i < setting.starts.size(); ++i) {
        Body b;
        b.foot = b.knownFoot = setting.starts[i];
        b.joints = Joints{};
        b.cells = place(postures_[0].cells, b.foot, 0);
        bodies_.push_back(b);
        result_.start.push_back(b.cells);
        extend(b.foot);
    }
}

std::array<Cell, 4> World::place(const std::array<Cell, 4>& local, const Cell& foot, int yaw) const {
    std::array<Cell, 4> cells;
    for (int k = 0; k < 4; ++k) cells[k] = foot + turn(local[k], yaw);
    return cells;
}

Move World::realise(const Transition& t, const Cell& foot, int yaw) const {
    Move m;
    m.transition = &t;
    const Posture& p = postures_[t.to.index()];
    const auto cells = place(p.cells, foot, yaw);
    for (const Cell& c : t.cloud) m.cloud.push_back(foot + turn(c, yaw));
    if (t.kind == Transition::Kind::Step) {
        m.foot = cells[3];
        m.yaw = (p.headYaw + yaw) % 4;
        m.joints = reversed(t.to);
        for (int k = 0; k < 4; ++k) m.cells[k] = cells[3 - k];
    } else {
        m.foot = foot, m.yaw = yaw, m.joints = t.to, m.cells = cells;
    }
    return m;
}

/// The seating transition from a standing state into seed s whose cloud avoids `blocked`.
std::optional<Move> World::seat(const Cell& foot, int yaw, const Joints& joints, const Seed& s, const CellSet& blocked) const {
    if (foot != s.cells[0]) return std::nullopt;
    for (const Transition& t : table_.from(coupling_, joints)) {
        if (t.kind != Transition::Kind::Seat) continue;
        Move m = realise(t, foot, yaw);
        if (m.cells == s.cells && !meets(m.cloud, blocked)) return m;
    }
    return std::nullopt;
}

bool World::done() const {
    return std::all_of(bodies_.begin(), bodies_.end(), [](const Body& b) { return b.placed; });
}

/// Starts an action: the body takes its new state at once, and sweeps `cloud` until the end.
void World::start(int i, const Move& m, bool seatAction, double fx, double fy) {
    Body& b = bodies_[i];
    const double end = now_ + m.transition->seconds + kLatchSeconds;
    const int id = static_cast<int>(result_.actions.size());
    for (int n = 0; n < static_cast<int>(bodies_.size()); ++n) {
        if (n == i) continue;
        const Body& o = bodies_[n];
        if (o.moving > now_) {
            if (meets(m.cloud, o.cloud) && !collided_.count({o.action, i})) ++result_.collisions, collided_.insert({id, n});
        } else if (meets(m.cloud, o.cells)) {
            ++result_.collisions, collided_.insert({id, n});
        }
    }
    result_.actions.push_back({i, now_, end, b.foot, m.foot, fx, fy, seatAction, m.cells});
    b.foot = m.foot, b.yaw = m.yaw, b.joints = m.joints, b.cells = m.cells, b.cloud = m.cloud;
    b.moving = end, b.action = id;
    ++b.moves;
    events_.push({end, i});
}

void World::deadlock(const std::string& reason) {
    result_.deadlocked = true;
    result_.reason = reason;
    while (!events_.empty()) events_.pop();
}

void World::placed(int i) {
    Body& b = bodies_[i];
    b.placed = true;
    result_.placed.push_back(setting_.recipe.seeds[b.seed]);
    std::vector<std::array<Cell, 4>> cells;
    for (const Body& o : bodies_) cells.push_back(o.cells);
    result_.snapshots.push_back(std::move(cells));
}

AssemblyResult World::finish() {
    if (!done() && !result_.deadlocked) deadlock("no metamodule can move");
    result_.completed = done();
    result_.seconds = now_;
    for (const Body& b : bodies_) result_.moves.push_back(b.moves), result_.cells.push_back(b.cells);
    double sum = 0;
    for (int m : result_.moves) sum += m;
    result_.meanMoves = result_.moves.empty() ? 0 : sum / result_.moves.size();
    return std::move(result_);
}

}  // namespace holon::planner::roombots::detail
