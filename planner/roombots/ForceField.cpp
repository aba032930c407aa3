// The paper's decentralised strategies (seed 001 §IV-A c-f): a metamodule's status message (id, foot)
// is the only thing others know of it; before a step it looks up the step's collision cloud and refuses
// steps whose cloud meets the placed structure or a known foot within range; it follows the force of
// Eq. 1 with alpha of Eq. 2 and reaches for the connector most nearly in that direction (the nearer one
// on a tie); greedy pauses while a metamodule of higher priority (lower id) is within four cubes. The
// first metamodule to stand where it can fill an active seed claims it; a deadlock is K steps in which
// no metamodule comes closer to an active seed.
// choice: Eq. 1 as printed attracts away from the seeds; the text ("attracting sinks", "repelling
// sources") fixes the signs used here. Eq. 2 (b) as printed grows with distance; the text ("gradually
// decreases ... between four and eight cubes") reads alpha = (8 - d) / 4 clamped to [0, 1]. Range 8.

#include "planner/roombots/World.h"

namespace holon::planner::roombots::detail {
namespace {

constexpr double kRange = 8, kPauseRange = 4;

class ForceField : public World {
public:
    ForceField(const CloudTable& table, Coupling coupling, Strategy strategy, const Setting& setting, const AssemblyOptions& options)
        : World(table, coupling, setting), strategy_(strategy), options_(options), claimed_(setting.recipe.seeds.size()) {
        stopWhen(options.budget);
    }
    AssemblyResult run();

private:
    void decide(int i);
    std::vector<int> activeSeeds() const;
    /// The steps a metamodule standing so may take: onto a free floor connector, sweeping no known
    /// cell, and not onto an active seed it could not fill from the posture it would land in.
    std::vector<Move> steps(const Cell& foot, int yaw, const Joints& joints, const CellSet& known, const std::vector<int>& active) const;
    bool seatsOnArrival(const Move& m, const CellSet& known, const std::vector<int>& active) const;
    void wait(int i, double until);
    bool footprint(const Cell& floorCell) const;
    bool stalled() const;

    Strategy strategy_;
    AssemblyOptions options_;
    std::vector<bool> claimed_;
    CellSet structure_;
};

AssemblyResult ForceField::run() {
    for (int i = 0; i < static_cast<int>(bodies_.size()); ++i) events_.push({0.0, i});
    long decisions = 0;
    const long cap = 400L * static_cast<long>(bodies_.size());
    while (!events_.empty() && !done()) {
        const auto [t, i] = events_.top();
        events_.pop();
        now_ = t;
        stopIfAsked();
        decide(i);
        if (++decisions > cap) deadlock("no seed filled within " + std::to_string(cap) + " decisions");
        if (!result_.deadlocked && stalled()) deadlock("no metamodule came closer to an active seed for " + std::to_string(options_.stallSteps) + " steps");
    }
    return finish();
}

std::vector<int> ForceField::activeSeeds() const {
    int group = std::numeric_limits<int>::max();
    for (std::size_t s = 0; s < claimed_.size(); ++s)
        if (!claimed_[s]) group = std::min(group, setting_.recipe.seeds[s].group);
    std::vector<int> active;
    for (std::size_t s = 0; s < claimed_.size(); ++s)
        if (!claimed_[s] && setting_.recipe.seeds[s].group == group) active.push_back(static_cast<int>(s));
    return active;
}

void ForceField::decide(int i) {
    Body& b = bodies_[i];
    if (b.placed) return;
    if (b.seed >= 0) {  // the seating has ended
        placed(i);
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
        const double alpha = strategy_ == Strategy::Step ? 1.0 : strategy_ == Strategy::Slope ? std::clamp((8 - d) / 4, 0.0, 1.0)
                                                                                              : 0.0;
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
std::vector<Move> ForceField::steps(const Cell& foot, int yaw, const Joints& joints, const CellSet& known, const std::vector<int>& active) const {
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

bool ForceField::seatsOnArrival(const Move& m, const CellSet& known, const std::vector<int>& active) const {
    for (int s : active)
        if (seat(m.foot, m.yaw, m.joints, setting_.recipe.seeds[s], known)) return true;
    return false;
}

void ForceField::wait(int i, double until) {
    ++bodies_[i].stall;
    events_.push({until, i});
}

bool ForceField::footprint(const Cell& floorCell) const {
    for (int z = 0; z < 4; ++z)
        if (structure_.count({floorCell.x, floorCell.y, z})) return true;
    return false;
}

bool ForceField::stalled() const {
    bool walking = false;
    for (const Body& b : bodies_) {
        if (b.placed || b.seed >= 0) continue;
        if (b.stall < options_.stallSteps) return false;
        walking = true;
    }
    return walking;
}

}  // namespace

AssemblyResult assembleByForceField(const CloudTable& table, Coupling coupling, Strategy strategy, const Setting& setting,
                                    const AssemblyOptions& options) {
    return ForceField(table, coupling, strategy, setting, options).run();
}

}  // namespace holon::planner::roombots::detail
