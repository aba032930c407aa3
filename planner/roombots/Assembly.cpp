// Reconfiguration by locomotion (seed 001 §IV-A, §V): metamodules stand on a structured floor by their
// foot, walk inch-worm fashion (the head swings to a floor connector, latches, the foot lets go and the
// roles swap) and finally change shape into their seed. Time is continuous: an action lasts its slowest
// joint's travel plus a latch, so metamodules that start together drift apart, as the paper observes.
//
// Paper strategies (§IV-A c-f): a metamodule's status message (id, foot) is the only thing others know
// of it; before a step it looks up the step's collision cloud and refuses steps whose cloud meets the
// placed structure or a known foot within range; it follows the force of Eq. 1 with alpha of Eq. 2 and
// reaches for the connector most nearly in that direction (the nearer one on a tie); greedy pauses while
// a metamodule of higher priority (lower id) is within four cubes.
// choice: Eq. 1 as printed attracts away from the seeds; the text ("attracting sinks", "repelling
// sources") fixes the signs used here. Eq. 2 (b) as printed grows with distance; the text ("gradually
// decreases ... between four and eight cubes") reads alpha = (8 - d) / 4 clamped to [0, 1]. Range 8.
//
// Reserve (holon): seeds are assigned in seeding order to the nearest free metamodule; in that order
// each metamodule plans a shortest walk to its seed (A* over foot, yaw and joint setting, around
// placed and standing metamodules and the seeds of metamodules already under way) and starts only once
// it can reserve every cell its whole walk sweeps; cells are released as it passes. A started walk
// never waits, so every reservation is released and no metamodule waits forever (no deadlock), and a
// body only ever occupies cells its owner has reserved (no collision). Collisions are still detected by
// the same geometric test as for the paper's strategies, so the claim is measured, not assumed.

#include "planner/roombots/Assembly.h"

#include "rules/Error.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <optional>
#include <queue>
#include <set>
#include <unordered_map>
#include <unordered_set>

namespace holon::planner::roombots {
namespace {

struct CellHash {
    std::size_t operator()(const Cell& c) const {
        return static_cast<std::size_t>(c.x) * 73856093u ^ static_cast<std::size_t>(c.y) * 19349663u ^ static_cast<std::size_t>(c.z) * 83492791u;
    }
};
using CellSet = std::unordered_set<Cell, CellHash>;

constexpr double kLatchSeconds = 1.0;  // choice: head latches, foot unlatches (§III gives no figure)
constexpr double kRange = 8, kPauseRange = 4;
constexpr double kInf = std::numeric_limits<double>::infinity();

Cell turn(Cell c, int yaw) {
    for (int k = 0; k < yaw; ++k) c = {-c.y, c.x, c.z};
    return c;
}

double planar(const Cell& a, const Cell& b) { return std::hypot(a.x - b.x, a.y - b.y); }

bool meets(const std::vector<Cell>& cloud, const CellSet& cells) {
    return std::any_of(cloud.begin(), cloud.end(), [&](const Cell& c) { return cells.count(c) != 0; });
}
template <class Cells>
bool meets(const std::vector<Cell>& a, const Cells& b) {
    for (const Cell& c : a)
        if (std::find(b.begin(), b.end(), c) != b.end()) return true;
    return false;
}

struct Body {
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

class Assembly {
public:
    Assembly(const CloudTable& table, Coupling coupling, Strategy strategy, const Setting& setting, const AssemblyOptions& options)
        : table_(table), coupling_(coupling), strategy_(strategy), setting_(setting), options_(options), claimed_(setting.recipe.seeds.size()) {
        const Metamodule metamodule(coupling);
        for (int i = 0; i < kJointSettings; ++i) postures_.push_back(metamodule.posture(Joints::fromIndex(i), 0));
        floor_ = {kInfInt, -kInfInt, kInfInt, -kInfInt};
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
            extend(b.foot);
        }
        for (const Posture& p : postures_)  // an upper bound on a step's reach, for the A* heuristic
            if (p.headFace == Cell{0, 0, -1} && p.cells[3].z == 0) maxStep_ = std::max(maxStep_, planar(p.cells[3], {}));
    }

    AssemblyResult run() {
        if (strategy_ == Strategy::Reserve) assignSeeds();
        for (int i = 0; i < static_cast<int>(bodies_.size()); ++i) events_.push({0.0, i});
        if (strategy_ == Strategy::Reserve) {
            for (const Body& b : bodies_)
                for (const Cell& c : b.cells) reserved_[c] = &b - bodies_.data();
            startWaiting();
        }
        long decisions = 0;
        const long cap = 400L * static_cast<long>(bodies_.size());
        while (!events_.empty() && !done()) {
            const auto [t, i] = events_.top();
            events_.pop();
            now_ = t;
            if (strategy_ == Strategy::Reserve) {
                advanceReserved(i);
                startWaiting();
            } else {
                decidePaper(i);
                if (++decisions > cap) deadlock("no seed filled within " + std::to_string(cap) + " decisions");
                if (!result_.deadlocked && stalled()) deadlock("no metamodule came closer to an active seed for " + std::to_string(options_.stallSteps) + " steps");
            }
        }
        if (!done() && !result_.deadlocked) deadlock("no metamodule can move");
        result_.completed = done();
        result_.seconds = now_;
        for (const Body& b : bodies_) result_.moves.push_back(b.moves), result_.cells.push_back(b.cells);
        double sum = 0;
        for (int m : result_.moves) sum += m;
        result_.meanMoves = result_.moves.empty() ? 0 : sum / result_.moves.size();
        return std::move(result_);
    }

    /// The fewest actions from standing upright at `start` to filling seed `seed`, around `blocked`
    /// (-1: no walk).
    int walk(int seed, const Cell& start, const CellSet& blocked) {
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
    int seatings(int seed, const CellSet& blocked) const {
        const Seed& s = setting_.recipe.seeds[seed];
        int count = 0;
        for (int j = 0; j < kJointSettings; ++j)
            for (int yaw = 0; yaw < 4; ++yaw)
                if (!table_.from(coupling_, Joints::fromIndex(j)).empty() && seat(s.cells[0], yaw, Joints::fromIndex(j), s, blocked)) ++count;
        return count;
    }

private:
    static constexpr int kInfInt = std::numeric_limits<int>::max() / 2;

    std::array<Cell, 4> place(const std::array<Cell, 4>& local, const Cell& foot, int yaw) const {
        std::array<Cell, 4> cells;
        for (int k = 0; k < 4; ++k) cells[k] = foot + turn(local[k], yaw);
        return cells;
    }

    Move realise(const Transition& t, const Cell& foot, int yaw) const {
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
    std::optional<Move> seat(const Cell& foot, int yaw, const Joints& joints, const Seed& s, const CellSet& blocked) const {
        if (foot != s.cells[0]) return std::nullopt;
        for (const Transition& t : table_.from(coupling_, joints)) {
            if (t.kind != Transition::Kind::Seat) continue;
            Move m = realise(t, foot, yaw);
            if (m.cells == s.cells && !meets(m.cloud, blocked)) return m;
        }
        return std::nullopt;
    }

    bool done() const {
        return std::all_of(bodies_.begin(), bodies_.end(), [](const Body& b) { return b.placed; });
    }

    std::vector<int> activeSeeds() const {
        int group = std::numeric_limits<int>::max();
        for (std::size_t s = 0; s < claimed_.size(); ++s)
            if (!claimed_[s]) group = std::min(group, setting_.recipe.seeds[s].group);
        std::vector<int> active;
        for (std::size_t s = 0; s < claimed_.size(); ++s)
            if (!claimed_[s] && setting_.recipe.seeds[s].group == group) active.push_back(static_cast<int>(s));
        return active;
    }

    /// Starts an action: the body takes its new state at once, and sweeps `cloud` until the end.
    void start(int i, const Move& m, bool seatAction, double fx, double fy) {
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
        result_.actions.push_back({i, now_, end, b.foot, m.foot, fx, fy, seatAction});
        b.foot = m.foot, b.yaw = m.yaw, b.joints = m.joints, b.cells = m.cells, b.cloud = m.cloud;
        b.moving = end, b.action = id;
        ++b.moves;
        events_.push({end, i});
    }

    // ---- the paper's strategies

    void decidePaper(int i) {
        Body& b = bodies_[i];
        if (b.placed) return;
        if (b.seed >= 0) {  // the seating has ended
            b.placed = true;
            result_.placed.push_back(setting_.recipe.seeds[b.seed]);
            for (const Cell& c : b.cells) structure_.insert(c);
            return;
        }
        b.knownFoot = b.foot;  // status message
        const std::vector<int> active = activeSeeds();
        if (active.empty()) return;
        CellSet known = structure_;
        for (const Body& o : bodies_)
            if (&o != &b && !o.placed && planar(o.knownFoot, b.foot) <= kRange) known.insert(o.knownFoot);
        for (int s : active)
            if (auto m = seat(b.foot, b.yaw, b.joints, setting_.recipe.seeds[s], known)) {
                claimed_[s] = true, b.seed = s;
                for (Body& o : bodies_) o.best = kInf, o.stall = 0;
                start(i, *m, true, 0, 0);
                return;
            }
        if (strategy_ == Strategy::Greedy)
            for (int n = 0; n < i; ++n) {
                const Body& o = bodies_[n];
                if (!o.placed && o.seed < 0 && planar(o.knownFoot, b.foot) <= kPauseRange) {
                    wait(i, std::max(o.moving, now_ + 0.5));  // until its next status message
                    return;
                }
            }
        double fx = 0, fy = 0;
        for (int s : active) {
            const Cell& f = setting_.recipe.seeds[s].cells[0];
            const double d = planar(f, b.foot);
            if (d > 0) fx += (f.x - b.foot.x) / d, fy += (f.y - b.foot.y) / d;
        }
        for (const Body& o : bodies_) {
            const double d = planar(o.knownFoot, b.foot);
            if (&o == &b || o.placed || d <= 0 || d > kRange) continue;
            const double alpha = strategy_ == Strategy::Step ? 1.0 : strategy_ == Strategy::Slope ? std::clamp((8 - d) / 4, 0.0, 1.0) : 0.0;
            fx += alpha * (b.foot.x - o.knownFoot.x) / d, fy += alpha * (b.foot.y - o.knownFoot.y) / d;
        }
        const double norm = std::hypot(fx, fy);
        // choice: the connector "in the direction of Vf" is judged one step further on — by the farthest
        // a step and the step after it get along Vf — because a metamodule's foot yaw limits where its
        // head can reach, and a one-step rule walks PAR metamodules back and forth on the spot.
        const double ux = norm > 0 ? fx / norm : 0, uy = norm > 0 ? fy / norm : 0;
        auto along = [&](const Cell& p) { return (p.x - b.foot.x) * ux + (p.y - b.foot.y) * uy; };
        std::optional<Move> best;
        double bestScore = -kInf, bestLength = kInf;
        for (bool allowBack : {false, true}) {
            for (Move& m : steps(b.foot, b.yaw, b.joints, known, active)) {
                if (!allowBack && m.foot == b.previousFoot) continue;
                double score;
                if (seatsOnArrival(m, known, active)) {
                    score = 1000;
                } else {
                    score = along(m.foot);
                    for (const Move& next : steps(m.foot, m.yaw, m.joints, known, active))
                        score = std::max(score, seatsOnArrival(next, known, active) ? 100.0 : along(next.foot));
                }
                const double length = planar(m.foot, b.foot);
                const bool better = score > bestScore + 1e-9 ||
                                    (score > bestScore - 1e-9 && (length < bestLength - 1e-9 ||
                                                                  (length < bestLength + 1e-9 && m.cloud.size() < best->cloud.size())));
                if (better) best = std::move(m), bestScore = score, bestLength = length;
            }
            if (best) break;
        }
        if (!best) {
            wait(i, now_ + 1.0);
            return;
        }
        double nearest = kInf;
        for (int s : active) nearest = std::min(nearest, planar(setting_.recipe.seeds[s].cells[0], best->foot));
        if (nearest < b.best - 1e-9) b.best = nearest, b.stall = 0;
        else ++b.stall;
        b.previousFoot = b.foot;
        start(i, *best, false, fx, fy);
    }

    /// The steps a metamodule standing so may take: onto a free floor connector, sweeping no known
    /// cell, and not onto an active seed it could not fill from the posture it would land in.
    std::vector<Move> steps(const Cell& foot, int yaw, const Joints& joints, const CellSet& known, const std::vector<int>& active) const {
        std::vector<Move> moves;
        for (const Transition& t : table_.from(coupling_, joints)) {
            if (t.kind != Transition::Kind::Step) continue;
            Move m = realise(t, foot, yaw);
            if (!floor_.contains(m.foot) || known.count(m.foot) || footprint(m.foot) || meets(m.cloud, known)) continue;
            bool blocksSeed = false;
            for (int s : active)
                if (m.foot == setting_.recipe.seeds[s].cells[0] && !seat(m.foot, m.yaw, m.joints, setting_.recipe.seeds[s], known)) blocksSeed = true;
            if (!blocksSeed) moves.push_back(std::move(m));
        }
        return moves;
    }

    bool seatsOnArrival(const Move& m, const CellSet& known, const std::vector<int>& active) const {
        for (int s : active)
            if (seat(m.foot, m.yaw, m.joints, setting_.recipe.seeds[s], known)) return true;
        return false;
    }

    void wait(int i, double until) {
        ++bodies_[i].stall;
        events_.push({until, i});
    }

    bool footprint(const Cell& floorCell) const {
        for (int z = 0; z < 4; ++z)
            if (structure_.count({floorCell.x, floorCell.y, z})) return true;
        return false;
    }

    bool stalled() const {
        bool walking = false;
        for (const Body& b : bodies_) {
            if (b.placed || b.seed >= 0) continue;
            if (b.stall < options_.stallSteps) return false;
            walking = true;
        }
        return walking;
    }

    void deadlock(const std::string& reason) {
        result_.deadlocked = true;
        result_.reason = reason;
        while (!events_.empty()) events_.pop();
    }

    // ---- holon's reservation strategy

    void assignSeeds() {
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
    std::vector<Move> plan(int i, const CellSet& blocked) const {
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

    /// In seeding order, metamodules start whenever their whole walk can be reserved; a metamodule
    /// never starts before one earlier in the order.
    void startWaiting() {
        for (int i : order_) {
            Body& b = bodies_[i];
            if (b.started) continue;
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
            if (planned_ != std::make_pair(i, version_)) {  // replan only when a metamodule started or was placed
                waitingPath_ = plan(i, blocked);
                planned_ = {i, version_};
            }
            std::vector<Move>& path = waitingPath_;
            if (path.empty()) {
                if (!othersMoving) deadlock("metamodule " + std::to_string(i) + " has no walk to seed " + std::to_string(b.seed));
                return;
            }
            for (const Move& m : path)
                for (const Cell& c : m.cloud) {
                    const auto it = reserved_.find(c);
                    if (it != reserved_.end() && it->second != i) return;  // wait for a release
                }
            for (const Move& m : path)
                for (const Cell& c : m.cloud) reserved_[c] = i;
            b.started = true;
            ++version_;
            paths_[i] = std::move(path);
            advanceReserved(i);
        }
    }

    /// The body's previous action (if any) has ended: release what the rest of the walk does not need
    /// and start the next action.
    void advanceReserved(int i) {
        Body& b = bodies_[i];
        auto& path = paths_[i];
        if (!b.started || b.placed) return;
        if (b.moving >= 0 && b.moving > now_) return;  // the start of a walk already scheduled this body
        CellSet keep(b.cells.begin(), b.cells.end());
        for (const Move& m : path) keep.insert(m.cloud.begin(), m.cloud.end());
        for (const Cell& c : b.cloud)
            if (!keep.count(c) && reserved_.count(c) && reserved_[c] == i) reserved_.erase(c);
        if (path.empty()) {
            b.placed = true;
            ++version_;
            result_.placed.push_back(setting_.recipe.seeds[b.seed]);
            return;
        }
        const Move m = path.front();
        path.erase(path.begin());
        start(i, m, m.transition->kind == Transition::Kind::Seat, 0, 0);
    }

    const CloudTable& table_;
    Coupling coupling_;
    Strategy strategy_;
    const Setting& setting_;
    AssemblyOptions options_;
    std::vector<Posture> postures_;
    Floor floor_{};
    double maxStep_ = 1;
    std::vector<Body> bodies_;
    std::vector<bool> claimed_;
    CellSet structure_;
    std::set<std::pair<int, int>> collided_;  // (action, module) pairs already counted
    using Event = std::pair<double, int>;
    std::priority_queue<Event, std::vector<Event>, std::greater<>> events_;
    double now_ = 0;
    AssemblyResult result_;
    // reserve
    std::vector<int> order_;
    std::unordered_map<Cell, int, CellHash> reserved_;
    std::map<int, std::vector<Move>> paths_;
    std::vector<Move> waitingPath_;  // the plan of the next metamodule to start
    std::pair<int, int> planned_{-1, -1};
    int version_ = 0;
};

}  // namespace

const char* strategyName(Strategy s) {
    static constexpr const char* kNames[] = {"greedy", "slope", "step", "reserve"};
    return kNames[static_cast<int>(s)];
}

Strategy parseStrategy(const std::string& name) {
    for (Strategy s : {Strategy::Greedy, Strategy::Slope, Strategy::Step, Strategy::Reserve})
        if (name == strategyName(s)) return s;
    throw InputError("--strategy: unknown strategy '" + name + "'; use greedy, slope, step or reserve");
}

AssemblyResult assemble(const CloudTable& table, Coupling coupling, Strategy strategy, const Setting& setting, const AssemblyOptions& options) {
    return Assembly(table, coupling, strategy, setting, options).run();
}

// choice: the structures here stand on the floor, so "attached to something already built" always
// holds; what decides a good order is that no seed walls in a later one. Greedily, the next seed is
// one a metamodule can walk to and fill now and after which the hardest later seed keeps the most
// postures it can be filled from (seatings); ties go to the seed farthest from the starts. If no
// seed leaves every later one fillable, the given order is kept.
Recipe automaticRecipe(const CloudTable& table, Coupling coupling, const Setting& setting) {
    Assembly probe(table, coupling, Strategy::Reserve, setting, {});
    const auto& seeds = setting.recipe.seeds;
    double cx = 0, cy = 0;
    for (const Cell& s : setting.starts) cx += s.x, cy += s.y;
    cx /= setting.starts.size(), cy /= setting.starts.size();
    std::vector<bool> done(seeds.size());
    CellSet built;
    Recipe recipe{"auto", {}};
    for (std::size_t round = 0; round < seeds.size(); ++round) {
        int pick = -1;
        std::pair<int, double> best{0, 0};  // (seatings of the hardest later seed, distance from the starts)
        for (std::size_t s = 0; s < seeds.size(); ++s) {
            if (done[s]) continue;
            CellSet after = built;
            after.insert(seeds[s].cells.begin(), seeds[s].cells.end());
            int hardest = std::numeric_limits<int>::max();
            for (std::size_t r = 0; r < seeds.size() && hardest > 0; ++r)
                if (!done[r] && r != s) hardest = std::min(hardest, probe.seatings(static_cast<int>(r), after));
            const std::pair<int, double> score{hardest, std::hypot(seeds[s].cells[0].x - cx, seeds[s].cells[0].y - cy)};
            if (hardest == 0 || (pick >= 0 && score <= best)) continue;
            bool reachable = false;
            for (const Cell& start : setting.starts)
                if (probe.walk(static_cast<int>(s), start, built) >= 0) {
                    reachable = true;
                    break;
                }
            if (reachable) pick = static_cast<int>(s), best = score;
        }
        if (pick < 0) return setting.recipe;
        done[pick] = true;
        built.insert(seeds[pick].cells.begin(), seeds[pick].cells.end());
        Seed seed = seeds[pick];
        seed.group = static_cast<int>(round);
        recipe.seeds.push_back(seed);
    }
    return recipe;
}

}  // namespace holon::planner::roombots
