// general_n metamodules on hex-lattice disks (seed 000 §III-C, Fig. 4a, whose picture the text
// lacks): the module-level motion behind each metamodule template. A template changes the mass of
// its cells; the disks of a slot that loses mass roll one at a time into the slot that gains it,
// each by a shortest sequence of pivot moves (seed 000 §II, Fig. 1a; hex_pivot.holon) found by
// breadth-first search around the two slots, and only a disk whose removal keeps the others
// connected may go, so the ensemble stays connected after every move.
// The design is holon's (the paper gives none in its text): a skeleton cross that reaches all four
// neighbouring slots, the rest of the mass in rings around its centre, and a free channel two cells
// wide between neighbouring slots. The crosses wall in a plaza at every corner of the metamodule
// grid, so mass that must cross an arm goes by relay: a disk of the wall rolls on and a disk behind
// it takes its place (relay(), below).

#include "planner/hex/DiskMetamodules.h"

#include "rules/Error.h"

#include <algorithm>
#include <cmath>
#include <deque>
#include <functional>
#include <sstream>
#include <unordered_map>
#include <unordered_set>
#include <tuple>

namespace holon::planner::hex {

namespace {

constexpr Vec kNeighbour[6] = {{1, 0, 0}, {1, -1, 0}, {0, -1, 0}, {-1, 0, 0}, {-1, 1, 0}, {0, 1, 0}};  // counterclockwise

int hexDistance(Vec a, Vec b) {
    const int dq = a.x - b.x, dr = a.y - b.y;
    return (std::abs(dq) + std::abs(dr) + std::abs(dq + dr)) / 2;
}

/// The two cells next to both a and its neighbour in direction d.
std::pair<Vec, Vec> commonNeighbours(Vec a, int d) { return {a + kNeighbour[(d + 1) % 6], a + kNeighbour[(d + 5) % 6]}; }

}  // namespace

DiskMetamodules::DiskMetamodules(const Problem& problem) : problem_(&problem) {
    if (problem.model->lattice().dimension() != 2) throw InputError("--hex-disks: disks lie in the plane; give a 2D start and target");
    bool conserves = false;
    for (const rules::Property& p : problem.model->system().properties)
        conserves |= p.kind == rules::Property::Kind::Conserves && p.quantity == rules::Property::Quantity::Mass;
    std::int64_t heaviest = 0;
    for (int v = 0; v < problem.tables->alphabet(); ++v) heaviest = std::max(heaviest, problem.tables->massUnitsOf(static_cast<rules::CellValue>(v)));
    if (!conserves || heaviest <= 0)
        throw InputError("--hex-disks: " + problem.model->system().name + " does not conserve mass; disks are neither made nor destroyed, use a general_n planner (e.g. --rules planner_general2)");
    // The design (see slotCells): a state of one mass unit is the skeleton alone, 2s - 1 disks, and
    // the heaviest state must leave the slot's inner cells at most 60% full. Measured on four plans
    // of general_2: with 74% full (s = 11) three of them jam, with 60% (s = 13) one does.
    for (side_ = 5;; side_ += 2) {
        perUnit_ = 2 * side_ - 1;
        if (10 * heaviest * perUnit_ <= 6 * ((side_ - 2) * (side_ - 2) + 4)) break;
    }

    const Board& board = *problem.board;
    origin_ = Vec{side_ * (board.lower().x - 1), side_ * (board.lower().y - 1), 0};  // one empty slot of margin around the board
    width_ = side_ * (board.extent().x + 2), height_ = side_ * (board.extent().y + 2);
    occupied_.assign(static_cast<std::size_t>(width_) * height_, 0);
    board.forEachInside([&](std::int64_t i, Vec p) {
        const std::int64_t count = problem.tables->massUnitsOf(problem.cells[i]) * perUnit_;
        const std::vector<std::int64_t> cells = slotCells(p);
        for (std::int64_t c = 0; c < count; ++c) occupied_[cells[c]] = 1, start_.push_back(diskOf(cells[c])), ++disks_;
    });
    if (!connectedWithout(-1)) throw InputError("--hex-disks: the start's disks are not connected in " + std::to_string(side_) + "x" + std::to_string(side_) + " slots");
}

// A slot's cells in the order a slot fills. First its skeleton, the row and the column through its
// centre: they touch the skeletons of all four neighbouring slots, so slots that hold their
// skeleton keep the ensemble connected (seed 000 §III-C: a partial metamodule must connect to every
// neighbouring position). Then the rest in rings around the centre, the outermost ring left out:
// between the disks of two neighbouring slots runs a channel two cells wide, in which a disk can
// roll (a one-wide gap would pinch it). A slot gives up its disks in the reverse order.
std::vector<std::int64_t> DiskMetamodules::slotCells(Vec m) const {
    const int middle = (side_ - 1) / 2;
    const Vec centre{side_ * m.x + middle, side_ * m.y + middle, 0};
    std::vector<std::pair<std::tuple<bool, int, int>, Vec>> cells;  // ((off the skeleton, ring, distance to the centre), cell)
    for (int j = 0; j < side_; ++j)
        for (int i = 0; i < side_; ++i) {
            const Vec c{side_ * m.x + i, side_ * m.y + j, 0};
            const bool skeleton = i == middle || j == middle;
            const int ring = std::max(std::abs(i - middle), std::abs(j - middle));
            if (!skeleton && ring == middle) continue;
            cells.push_back({{!skeleton, ring, hexDistance(c, centre)}, c});
        }
    std::stable_sort(cells.begin(), cells.end(), [](const auto& a, const auto& b) { return a.first < b.first; });
    std::vector<std::int64_t> out;
    for (const auto& [rank, c] : cells) out.push_back(at(c));
    return out;
}

bool DiskMetamodules::connectedWithout(std::int64_t skip) const {
    std::vector<std::uint8_t> seen(occupied_.size(), 0);
    std::vector<std::int64_t> stack;
    for (std::size_t i = 0; i < occupied_.size() && stack.empty(); ++i)
        if (occupied_[i] && static_cast<std::int64_t>(i) != skip) stack.push_back(static_cast<std::int64_t>(i)), seen[i] = 1;
    std::int64_t reached = 0;
    while (!stack.empty()) {
        const Vec c = diskOf(stack.back());
        stack.pop_back(), ++reached;
        for (Vec d : kNeighbour) {
            const Vec n = c + d;
            if (n.x < origin_.x || n.y < origin_.y || n.x >= origin_.x + width_ || n.y >= origin_.y + height_) continue;
            const std::int64_t k = at(n);
            if (k != skip && occupied_[k] && !seen[k]) seen[k] = 1, stack.push_back(k);
        }
    }
    return reached == disks_ - (skip >= 0 ? 1 : 0);
}

bool DiskMetamodules::fired(std::int64_t anchor, int shape, const BoxEngine::Value* old, const std::vector<BoxEngine::Value>& now) {
    const BoxEngine& engine = *problem_->engine;
    const std::string& rule = problem_->model->rules()[engine.ruleOf(shape)].name;
    const auto steps = engine.cellSteps(shape);
    std::vector<std::pair<Vec, std::int64_t>> gains, losses;  // slot, disks
    for (std::size_t k = 0; k < steps.size(); ++k) {
        const std::int64_t i = anchor + steps[k];
        const std::int64_t delta = (problem_->tables->massUnitsOf(now[i]) - problem_->tables->massUnitsOf(old[k])) * perUnit_;
        const Vec slot = problem_->board->point(i);
        if (delta > 0) gains.emplace_back(slot, delta);
        if (delta < 0) losses.emplace_back(slot, -delta);
    }
    const std::int64_t instance = instances_;
    for (auto& [to, need] : gains)
        for (auto& [from, have] : losses)
            for (; need > 0 && have > 0; --need, --have)
                if (!moveOne(from, to, instance, rule)) return false;
    for (const auto& [to, need] : gains)
        if (need > 0) {
            failure_ = rule + ": slot (" + std::to_string(to.x) + "," + std::to_string(to.y) + ") gains mass that no cell of the template gives up";
            return false;
        }
    ++instances_;
    return true;
}

// One disk from slot `source` to slot `destination`: the source's disk last in its fill order whose
// removal keeps the others connected and that has a pivot path (searched within the two slots and
// the ring of slots around them) into the destination, to the empty cell first in the destination's
// fill order that it can reach.
// The disks of slot `source` that may leave, in the order they try: while the slot holds more than
// its skeleton only the others (the skeleton keeps the ensemble connected), last filled first; a
// skeleton that dissolves goes from its far end first, so that the arm towards the destination is
// the bridge the last disks cross.
std::vector<std::int64_t> DiskMetamodules::movers(Vec source, Vec destination) const {
    const std::vector<std::int64_t> from = slotCells(source);
    const std::size_t skeleton = 2 * side_ - 1;
    std::size_t held = 0;
    for (std::int64_t c : from) held += occupied_[c];
    std::vector<std::int64_t> out;
    for (std::size_t r = from.size(); r-- > 0;)
        if (occupied_[from[r]] && (r >= skeleton || held <= skeleton)) out.push_back(from[r]);
    const int middle = (side_ - 1) / 2;
    const Vec centre{side_ * destination.x + middle, side_ * destination.y + middle, 0};
    const std::unordered_set<std::int64_t> inSkeleton(from.begin(), from.begin() + skeleton);
    std::stable_sort(out.begin(), out.end(), [&](std::int64_t a, std::int64_t b) {
        const bool sa = inSkeleton.count(a) != 0, sb = inSkeleton.count(b) != 0;
        if (sa != sb) return sb;
        return sa && hexDistance(diskOf(a), centre) > hexDistance(diskOf(b), centre);
    });
    return out;
}

// A shortest sequence of pivots for the disk at `start` (already lifted) to the reachable cell of
// least rankOf(c) (kNotGoal: not a goal), within the window; found is -1 when there is none.
DiskMetamodules::Path DiskMetamodules::rollPath(std::int64_t start, const std::function<std::size_t(std::int64_t)>& rankOf, const Window& window) const {
    std::vector<std::int64_t> parent(occupied_.size(), -2), pivotOf(occupied_.size(), -1);
    std::deque<std::int64_t> queue{start};
    parent[start] = -1;
    Path out;
    std::size_t best = kNotGoal;
    while (!queue.empty()) {
        const std::int64_t c = queue.front();
        queue.pop_front();
        if (const std::size_t r = rankOf(c); r != kNotGoal && r < best) best = r, out.found = c;
        const Vec a = diskOf(c);
        for (int d = 0; d < 6; ++d) {
            const Vec b = a + kNeighbour[d];
            if (!window.contains(b) || occupied_[at(b)] || parent[at(b)] != -2) continue;
            const auto [c1, c2] = commonNeighbours(a, d);
            const bool o1 = window.contains(c1) && occupied_[at(c1)], o2 = window.contains(c2) && occupied_[at(c2)];
            if (o1 == o2) continue;  // no pivot, or both sides blocked
            parent[at(b)] = c, pivotOf[at(b)] = at(o1 ? c1 : c2);
            queue.push_back(at(b));
        }
    }
    for (std::int64_t c = out.found; out.found >= 0 && parent[c] >= 0; c = parent[c]) out.steps.push_back({diskOf(parent[c]), diskOf(c), diskOf(pivotOf[c])});
    std::reverse(out.steps.begin(), out.steps.end());
    return out;
}

void DiskMetamodules::commit(const Path& path, std::int64_t instance, const std::string& rule) {
    for (const PivotStep& s : path.steps) moves_.push_back({instance, rule, s.from, s.to, s.pivot});
    occupied_[path.found] = 1;
}

// One disk from slot `source` to slot `destination`: a mover of the source with a pivot path, within
// the two slots and the ring of slots around them, to the empty cell of the destination first in
// its fill order that it can reach; failing that, a relay.
bool DiskMetamodules::moveOne(Vec source, Vec destination, std::int64_t instance, const std::string& rule) {
    const std::vector<std::int64_t> candidates = movers(source, destination), to = slotCells(destination);
    std::unordered_map<std::int64_t, std::size_t> rank;  // a destination cell's place in the fill order
    for (std::size_t r = 0; r < to.size(); ++r) rank[to[r]] = r;
    const Window window{std::max(side_ * (std::min(source.x, destination.x) - 1), origin_.x), std::min(side_ * (std::max(source.x, destination.x) + 2), origin_.x + width_),
                        std::max(side_ * (std::min(source.y, destination.y) - 1), origin_.y), std::min(side_ * (std::max(source.y, destination.y) + 2), origin_.y + height_)};
    const auto destinationRank = [&](std::int64_t c) { const auto r = rank.find(c); return r == rank.end() ? kNotGoal : r->second; };
    for (std::int64_t mover : candidates) {
        if (!connectedWithout(mover)) continue;
        occupied_[mover] = 0;
        if (const Path path = rollPath(mover, destinationRank, window); path.found >= 0) {
            commit(path, instance, rule);
            return true;
        }
        occupied_[mover] = 1;
    }
    if (relay(candidates, to, window, instance, rule)) return true;
    failure_ = rule + ": no disk of slot (" + std::to_string(source.x) + "," + std::to_string(source.y) + ") can roll into slot (" + std::to_string(destination.x) +
               "," + std::to_string(destination.y) + ") while the others stay connected";
    return false;
}

// A relay across the walls a mover cannot get round: the arms of the skeletons enclose a plaza at
// every corner of the metamodule grid, and a disk in one plaza reaches no other by rolling. A chain
// of disks x1..xn, found by breadth-first search back from the destination's empty cells: x1 rolls
// into the destination, each x(i+1) into the cell x(i) left, and a mover into the cell xn left, so
// the walls are whole again afterwards. A disk whose removal disconnects the ensemble (a bridge)
// cannot be a relay. Every roll is searched again as the chain runs; a chain that breaks is undone.
bool DiskMetamodules::relay(const std::vector<std::int64_t>& candidates, const std::vector<std::int64_t>& to, const Window& window, std::int64_t instance,
                            const std::string& rule) {
    constexpr int kMaxRelays = 3;
    const std::unordered_set<std::int64_t> isMover(candidates.begin(), candidates.end());
    std::unordered_map<std::int64_t, std::int64_t> next;  // disk -> the cell it rolls into
    std::vector<std::int64_t> frontier;
    for (std::int64_t c : to)
        if (!occupied_[c] && window.contains(diskOf(c))) frontier.push_back(c), next[c] = -1;
    for (int level = 0; level <= kMaxRelays && !frontier.empty(); ++level) {
        std::vector<std::int64_t> following;
        for (std::int64_t t : frontier) {
            const std::uint8_t held = occupied_[t];
            occupied_[t] = 0;
            std::vector<std::int64_t> region;  // where a disk at t can roll: a disk next to it can roll to t
            rollPath(t, [&](std::int64_t c) { region.push_back(c); return kNotGoal; }, window);
            occupied_[t] = held;
            for (std::int64_t c : region)
                for (Vec d : kNeighbour) {
                    const Vec v = diskOf(c) + d;
                    if (!window.contains(v)) continue;
                    const std::int64_t w = at(v);
                    if (!occupied_[w] || next.count(w) || (!isMover.count(w) && !connectedWithout(w))) continue;
                    next[w] = t;
                    if (!isMover.count(w)) {
                        following.push_back(w);
                        continue;
                    }
                    std::vector<std::int64_t> chain;  // x1 .. xn, mover
                    for (std::int64_t x = w; next[x] >= 0; x = next[x]) chain.push_back(x);
                    std::reverse(chain.begin(), chain.end());
                    if (runChain(chain, next, window, instance, rule)) return true;
                    next.erase(w);  // another relay may still bring this mover
                }
        }
        frontier = std::move(following);
    }
    return false;
}

bool DiskMetamodules::runChain(const std::vector<std::int64_t>& chain, const std::unordered_map<std::int64_t, std::int64_t>& next, const Window& window,
                               std::int64_t instance, const std::string& rule) {
    const std::size_t movesBefore = moves_.size();
    std::vector<std::pair<std::int64_t, std::int64_t>> done;  // (from, to)
    for (std::int64_t x : chain) {
        const std::int64_t cell = next.at(x);
        Path path;
        if (connectedWithout(x)) {
            occupied_[x] = 0;
            path = rollPath(x, [&](std::int64_t c) { return c == cell ? std::size_t{0} : kNotGoal; }, window);
            if (path.found < 0) occupied_[x] = 1;
        }
        if (path.found < 0) {
            for (auto it = done.rbegin(); it != done.rend(); ++it) occupied_[it->second] = 0, occupied_[it->first] = 1;
            moves_.resize(movesBefore);
            return false;
        }
        commit(path, instance, rule);
        done.emplace_back(x, cell);
    }
    return true;
}

std::vector<Vec> DiskMetamodules::disks() const {
    std::vector<Vec> out;
    for (std::size_t i = 0; i < occupied_.size(); ++i)
        if (occupied_[i]) out.push_back(diskOf(static_cast<std::int64_t>(i)));
    return out;
}

bool DiskMetamodules::slotsMatch(const std::vector<BoxEngine::Value>& now, std::string& why) const {
    bool ok = true;
    std::int64_t placed = 0;
    problem_->board->forEachInside([&](std::int64_t i, Vec p) {
        const std::vector<std::int64_t> cells = slotCells(p);
        std::int64_t count = 0, skeleton = 0;
        for (std::size_t r = 0; r < cells.size(); ++r) count += occupied_[cells[r]], skeleton += r < std::size_t(2 * side_ - 1) && occupied_[cells[r]];
        placed += count;
        const std::int64_t want = problem_->tables->massUnitsOf(now[i]) * perUnit_;
        const std::string slot = "slot (" + std::to_string(p.x) + "," + std::to_string(p.y) + ") ";
        if (ok && count != want) why = slot + "holds " + std::to_string(count) + " disks, its state needs " + std::to_string(want), ok = false;
        if (ok && want > 0 && skeleton != 2 * side_ - 1) why = slot + "has lost part of its skeleton", ok = false;
    });
    if (ok && placed != disks_) why = std::to_string(disks_ - placed) + " disks lie outside every slot", ok = false;
    return ok;
}

std::string replayDiskMoves(const std::vector<Vec>& start, const std::vector<DiskMove>& moves) {
    auto key = [](Vec v) { return (static_cast<std::int64_t>(v.x) << 32) ^ static_cast<std::uint32_t>(v.y); };
    std::unordered_set<std::int64_t> disks;
    for (Vec v : start) disks.insert(key(v));
    auto has = [&](Vec v) { return disks.count(key(v)) != 0; };
    auto connected = [&] {
        if (disks.empty()) return true;
        std::unordered_set<std::int64_t> seen;
        std::vector<Vec> stack;
        for (Vec v : start)  // any disk to begin from: find one present
            if (has(v)) {
                stack.push_back(v), seen.insert(key(v));
                break;
            }
        if (stack.empty())
            for (const DiskMove& m : moves)
                if (has(m.to)) {
                    stack.push_back(m.to), seen.insert(key(m.to));
                    break;
                }
        while (!stack.empty()) {
            const Vec c = stack.back();
            stack.pop_back();
            for (Vec d : kNeighbour)
                if (has(c + d) && seen.insert(key(c + d)).second) stack.push_back(c + d);
        }
        return seen.size() == disks.size();
    };
    for (std::size_t k = 0; k < moves.size(); ++k) {
        const DiskMove& m = moves[k];
        const std::string where = "move " + std::to_string(k + 1) + " (" + m.rule + "): ";
        int direction = -1;
        for (int d = 0; d < 6; ++d)
            if (m.from + kNeighbour[d] == m.to) direction = d;
        if (!has(m.from)) return where + "no disk at the start cell";
        if (has(m.to)) return where + "the end cell is occupied";
        if (direction < 0) return where + "start and end cells are not neighbours";
        const auto [c1, c2] = commonNeighbours(m.from, direction);
        if (!((m.pivot == c1 && has(c1) && !has(c2)) || (m.pivot == c2 && has(c2) && !has(c1))))
            return where + "not a pivot: the disk must roll about an occupied common neighbour with the other one empty";
        disks.erase(key(m.from)), disks.insert(key(m.to));
        if (!connected()) return where + "the disks are no longer connected";
    }
    return "";
}

std::string disksSvg(const std::vector<std::pair<std::string, std::vector<Vec>>>& panels) {
    constexpr double kScale = 14, kRow = 0.8660254037844386;
    double minX = 1e9, maxX = -1e9, minY = 1e9, maxY = -1e9;
    for (const auto& [caption, disks] : panels)
        for (Vec v : disks) {
            const double x = v.x + 0.5 * v.y, y = kRow * v.y;
            minX = std::min(minX, x), maxX = std::max(maxX, x), minY = std::min(minY, y), maxY = std::max(maxY, y);
        }
    if (minX > maxX) minX = maxX = minY = maxY = 0;
    const double panelWidth = (maxX - minX + 3) * kScale, height = (maxY - minY + 3) * kScale + 20;
    std::ostringstream svg;
    svg << "<svg xmlns='http://www.w3.org/2000/svg' width='" << panelWidth * panels.size() << "' height='" << height << "'>\n"
        << "<rect width='100%' height='100%' fill='white'/>\n";
    for (std::size_t p = 0; p < panels.size(); ++p) {
        const double left = panelWidth * p;
        svg << "<text x='" << left + 6 << "' y='16' font-family='sans-serif' font-size='13'>" << panels[p].first << "</text>\n";
        for (Vec v : panels[p].second) {
            const double x = left + (v.x + 0.5 * v.y - minX + 1.5) * kScale, y = height - (kRow * v.y - minY + 1.5) * kScale;
            svg << "<circle cx='" << x << "' cy='" << y << "' r='" << 0.48 * kScale << "' fill='#7a9' stroke='#354'/>\n";
        }
    }
    svg << "</svg>\n";
    return svg.str();
}

}  // namespace holon::planner::hex
