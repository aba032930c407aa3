// holon's reservation strategy (seed 001 §VI asks for consensus on priorities; this is one): seeds are
// assigned in seeding order to the nearest free metamodule; in that order each metamodule plans a
// shortest walk to its seed (A* over foot, yaw and joint setting, around placed and standing
// metamodules and the seeds of metamodules already under way) and asks the coordination rule
// (roombots_reserve.holon, CoordinationRule.cpp) to start it: the rule fires only when no walk under
// way shares a floor column with this one. A started walk never waits, so it ends and the next
// metamodule can start (no deadlock), and walks under way cover disjoint columns (no collision). The
// collision test of World.cpp still runs, so the claim is measured, not assumed.

#include "planner/roombots/Reservation.h"

#include <unordered_map>

namespace holon::planner::roombots::detail {

AssemblyResult Reservation::run() {
    assignSeeds();
    int reach = 0;  // how far from its foot a metamodule's body or clouds reach across the floor
    for (int j = 0; j < kJointSettings; ++j) {
        for (const Cell& c : postures_[j].cells) reach = std::max({reach, std::abs(c.x), std::abs(c.y)});
        for (const Transition& t : table_.from(coupling_, Joints::fromIndex(j)))
            for (const Cell& c : t.cloud) reach = std::max({reach, std::abs(c.x), std::abs(c.y)});
    }
    std::vector<Cell> feet;
    for (int i : order_) feet.push_back(bodies_[i].foot);
    rule_.emplace(floor_, reach, feet);
    for (int i = 0; i < static_cast<int>(bodies_.size()); ++i) events_.push({0.0, i});
    startWaiting();
    while (!events_.empty() && !done()) {
        const auto [t, i] = events_.top();
        events_.pop();
        now_ = t;
        stopIfAsked();
        advance(i);
        startWaiting();
    }
    result_.coordination = rule_->configurationJson();
    return finish();
}

/// The fewest actions from standing upright at `start` to filling seed `seed`, around `blocked`
/// (-1: no walk).
int Reservation::walk(int seed, const Cell& start, const CellSet& blocked) {
    Body b;
    b.foot = b.knownFoot = start;
    b.cells = place(postures_[0].cells, start, 0);
    b.seed = seed;
    bodies_.push_back(b);
    const std::size_t actions = plan(static_cast<int>(bodies_.size()) - 1, blocked).size();
    bodies_.pop_back();
    return actions == 0 ? -1 : static_cast<int>(actions);
}

/// How many postures a walk can stand in at the seed's foot (joint setting and yaw) change shape
/// into the seed without sweeping `blocked`.
int Reservation::seatings(int seed, const CellSet& blocked) const {
    const Seed& s = setting_.recipe.seeds[seed];
    int count = 0;
    for (int j = 0; j < kJointSettings; ++j)
        for (int yaw = 0; yaw < 4; ++yaw)
            if (!table_.from(coupling_, Joints::fromIndex(j)).empty() && seat(s.cells[0], yaw, Joints::fromIndex(j), s, blocked)) ++count;
    return count;
}

void Reservation::assignSeeds() {
    std::vector<bool> taken(bodies_.size());
    for (std::size_t s = 0; s < setting_.recipe.seeds.size(); ++s) {
        int pick = -1;
        for (std::size_t i = 0; i < bodies_.size(); ++i)
            if (!taken[i] && (pick < 0 || planar(bodies_[i].foot, setting_.recipe.seeds[s].cells[0]) <
                                              planar(bodies_[pick].foot, setting_.recipe.seeds[s].cells[0]) - 1e-9))
                pick = static_cast<int>(i);
        taken[pick] = true;
        bodies_[pick].seed = static_cast<int>(s);
        order_.push_back(pick);
    }
}

/// A* over (foot, yaw, joint setting): the fewest actions to stand seated in the body's seed.
std::vector<Move> Reservation::plan(int i, const CellSet& blocked) const {
    const Body& b = bodies_[i];
    const Seed& goal = setting_.recipe.seeds[b.seed];
    // The blocked cells as a bit map over the floor (nothing is blocked off the floor).
    const int width = floor_.x1 - floor_.x0 + 1, depth = floor_.y1 - floor_.y0 + 1, height = 8;
    std::vector<bool> wall(static_cast<std::size_t>(width) * depth * height);
    auto at = [&](const Cell& c) {
        return (static_cast<std::size_t>(c.z) * depth + (c.y - floor_.y0)) * width + (c.x - floor_.x0);
    };
    auto inBox = [&](const Cell& c) {
        return c.x >= floor_.x0 && c.x <= floor_.x1 && c.y >= floor_.y0 && c.y <= floor_.y1 && c.z >= 0 && c.z < height;
    };
    for (const Cell& c : blocked)
        if (inBox(c)) wall[at(c)] = true;
    struct Node {
        Cell foot;
        int yaw;
        Joints joints;
        int parent;
        const Transition* step;
    };
    std::vector<Node> nodes{{b.foot, b.yaw, b.joints, -1, nullptr}};
    std::unordered_map<std::int64_t, int> cost;
    auto key = [&](const Cell& f, int yaw, const Joints& j) {
        return ((static_cast<std::int64_t>(f.x - floor_.x0) * 4096 + (f.y - floor_.y0)) * 4 + yaw) * kJointSettings + j.index();
    };
    auto heuristic = [&](const Cell& f) { return std::ceil(planar(f, goal.cells[0]) / maxStep_ - 1e-9); };
    using Entry = std::tuple<double, int, int>;  // f, g, node
    std::priority_queue<Entry, std::vector<Entry>, std::greater<>> open;
    open.push({heuristic(b.foot), 0, 0});
    cost[key(b.foot, b.yaw, b.joints)] = 0;
    constexpr int kMaxNodes = 400000;
    while (!open.empty() && static_cast<int>(nodes.size()) < kMaxNodes) {
        const auto [f, g, index] = open.top();
        open.pop();
        const Node node = nodes[index];
        if (cost[key(node.foot, node.yaw, node.joints)] < g) continue;
        if (auto m = seat(node.foot, node.yaw, node.joints, goal, blocked)) {
            std::vector<Move> path{*m};
            for (int k = index; nodes[k].parent >= 0; k = nodes[k].parent) {
                const Node& from = nodes[nodes[k].parent];
                path.push_back(realise(*nodes[k].step, from.foot, from.yaw));
            }
            std::reverse(path.begin(), path.end());
            return path;
        }
        for (const Transition& t : table_.from(coupling_, node.joints)) {
            if (t.kind != Transition::Kind::Step) continue;
            const Posture& p = postures_[t.to.index()];
            const Cell landing = node.foot + turn(p.cells[3], node.yaw);
            if (!floor_.contains(landing)) continue;
            const int yaw = (p.headYaw + node.yaw) % 4;
            const Joints joints = reversed(t.to);
            const std::int64_t k = key(landing, yaw, joints);
            const auto it = cost.find(k);
            if (it != cost.end() && it->second <= g + 1) continue;
            const bool hits = std::any_of(t.cloud.begin(), t.cloud.end(), [&](const Cell& c) {
                const Cell w = node.foot + turn(c, node.yaw);
                return inBox(w) && wall[at(w)];
            });
            if (hits) continue;
            cost[k] = g + 1;
            nodes.push_back({landing, yaw, joints, index, &t});
            open.push({g + 1 + heuristic(landing), g + 1, static_cast<int>(nodes.size()) - 1});
        }
    }
    return {};
}

/// In seeding order, each metamodule plans its walk and starts when the coordination rule fires its
/// start; a metamodule never starts before one earlier in the order.
void Reservation::startWaiting() {
    for (int i : order_) {
        Body& b = bodies_[i];
        if (b.started) continue;
        // Only a new plan (a metamodule started or sat since) can change the rule's answer.
        if (planned_ == std::make_pair(i, version_)) return;
        planned_ = {i, version_};
        CellSet blocked;
        bool othersMoving = false;
        for (std::size_t n = 0; n < bodies_.size(); ++n) {
            const Body& o = bodies_[n];
            if (static_cast<int>(n) == i) continue;
            if (o.placed || !o.started) blocked.insert(o.cells.begin(), o.cells.end());
            else {
                othersMoving = true;
                blocked.insert(setting_.recipe.seeds[o.seed].cells.begin(), setting_.recipe.seeds[o.seed].cells.end());
            }
        }
        std::vector<Move> path = plan(i, blocked);
        if (path.empty()) {
            if (!othersMoving) deadlock("metamodule " + std::to_string(i) + " has no walk to seed " + std::to_string(b.seed));
            return;
        }
        if (!rule_->start(b.seed, columns(i, path))) return;  // a walk under way shares a column
        b.started = true;
        ++version_;
        paths_[i] = std::move(path);
        advance(i);
    }
}

std::vector<Cell> Reservation::columns(int i, const std::vector<Move>& path) const {
    CellSet seen;
    std::vector<Cell> out;
    auto add = [&](const Cell& c) {
        const Cell column{c.x, c.y, 0};
        if (seen.insert(column).second) out.push_back(column);
    };
    for (const Cell& c : bodies_[i].cells) add(c);
    for (const Move& m : path) {
        for (const Cell& c : m.cloud) add(c);
        for (const Cell& c : m.cells) add(c);
    }
    return out;
}

/// The body's previous action (if any) has ended: start the next, or sit when the walk is done.
void Reservation::advance(int i) {
    Body& b = bodies_[i];
    auto& path = paths_[i];
    if (!b.started || b.placed) return;
    if (b.moving >= 0 && b.moving > now_) return;  // the start of a walk already scheduled this body
    if (path.empty()) {
        rule_->sit(b.seed);
        placed(i);
        ++version_;
        return;
    }
    const Move m = path.front();
    path.erase(path.begin());
    start(i, m, m.transition->kind == Transition::Kind::Seat, 0, 0);
}

AssemblyResult assembleByReservation(const CloudTable& table, Coupling coupling, const Setting& setting, const AssemblyOptions& options) {
    Reservation r(table, coupling, setting);
    r.stopWhen(options.budget);
    return r.run();
}

}  // namespace holon::planner::roombots::detail
