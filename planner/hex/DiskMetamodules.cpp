// general_n metamodules on hex-lattice disks (seed 000 §III-C, Fig. 4a): a planner run expanded into
// disk moves. A fired template changes the mass of two neighbouring metamodules by one unit each way
// (create_i, delete_i, transfer; seed 000 §III-C); the disks behind it are DiskDesign's motion
// sequence for those two levels, turned and mirrored onto the two slots, each move applied as the
// hex_pivot instance that rolls that disk about that pivot. The design guarantees the sequence
// whatever the neighbouring slots hold (and that every move is a pivot move: one that is not is a
// bug, reported as such); the engine refuses a move hex_pivot does not enable there. The compiled
// engine does not evaluate the system's constraint `connected`: replayDiskMoves re-checks every
// move on its own, knowing nothing of the design or the engine (a roll about an occupied common
// neighbour with the other one empty, onto an empty cell, all disks connected after it).

#include "planner/hex/DiskMetamodules.h"

#include "rules/Components.h"
#include "rules/Error.h"
#include "rules/Parameter.h"
#include "rules/Svg.h"

#include <algorithm>
#include <map>
#include <sstream>

namespace holon::planner::hex {

namespace {

/// The levels of mass the problem's system uses (C = the heaviest), after checking that disks can
/// realise it: a plane, and templates that conserve mass.
int levelsOf(const Problem& problem) {
    const std::string hexDisks = rules::parameterName(rules::Parameter::HexDisks);
    if (problem.model->lattice().dimension() != 2) throw InputError(hexDisks + ": disks lie in the plane; give a 2D start and target", rules::Parameter::HexDisks);
    const bool conserves = problem.model->system().conservesMass();
    std::int64_t heaviest = 0;
    for (int v = 0; v < problem.tables->alphabet(); ++v) heaviest = std::max(heaviest, problem.tables->massUnitsOf(static_cast<rules::CellValue>(v)));
    if (!conserves || heaviest <= 1)
        throw InputError(hexDisks + ": " + problem.model->system().name + " does not conserve mass; disks are neither made nor destroyed, use a general_n planner (e.g. " +
                             rules::parameterName(rules::Parameter::Rules) + " planner_general2)",
                         rules::Parameter::HexDisks);
    return static_cast<int>(heaviest);
}

}  // namespace

DiskMetamodules::DiskMetamodules(const Problem& problem) : problem_(&problem), design_(levelsOf(problem)) {
    const Board& board = *problem.board;
    // One empty slot of margin around the board.
    pivots_ = std::make_unique<PivotRules>(slotOrigin(Vec{board.lower().x - 1, board.lower().y - 1, 0}),
                                           Vec{side() * (board.extent().x + 2), side() * (board.extent().y + 2), 1});
    cells_.assign(static_cast<std::size_t>(pivots_->board().size()), 0);
    board.forEachInside([&](std::int64_t i, Vec p) {
        for (Vec c : design_.layout(static_cast<int>(problem.tables->massUnitsOf(problem.cells[i])))) {
            cells_[pivots_->board().index(slotOrigin(p) + c)] = pivots_->disk();
            start_.push_back(slotOrigin(p) + c);
        }
    });
}

bool DiskMetamodules::fired(std::int64_t anchor, int shape, const BoxEngine::Value* old, const std::vector<BoxEngine::Value>& now) {
    const BoxEngine& engine = *problem_->engine;
    const std::string& rule = problem_->model->rules()[engine.ruleOf(shape)].name;
    const auto steps = engine.cellSteps(shape);
    struct Change {
        Vec slot;
        int before, after;
    };
    std::vector<Change> changes;
    for (std::size_t k = 0; k < steps.size(); ++k) {
        const std::int64_t i = anchor + steps[k];
        const int before = static_cast<int>(problem_->tables->massUnitsOf(old[k])), after = static_cast<int>(problem_->tables->massUnitsOf(now[i]));
        if (before != after) changes.push_back({problem_->board->point(i), before, after});
    }
    const std::int64_t instance = instances_++;
    if (changes.empty()) return true;  // a relabelling: no disk moves
    const auto fail = [&](const std::string& why) {
        failure_ = rule + ": " + why;
        return false;
    };
    if (changes.size() != 2) return fail("changes the mass of " + std::to_string(changes.size()) + " metamodules; the disk design moves one unit between two");
    Change a = changes[0], b = changes[1];
    const bool alongY = a.slot.x == b.slot.x;
    if (alongY ? b.slot.y < a.slot.y : b.slot.x < a.slot.x) std::swap(a, b);
    if (alongY ? b.slot.y - a.slot.y != 1 : (b.slot.x - a.slot.x != 1 || a.slot.y != b.slot.y)) return fail("moves mass between metamodules that are not neighbours");
    bool ok = false;
    const std::vector<PivotMove> sequence = design_.sequence(a.before, b.before, a.after, b.after, alongY, slotOrigin(a.slot), ok);
    if (!ok) return fail("moves more than one unit of mass between two metamodules");
    const BoxEngine& pivot = pivots_->engine();
    BoxEngine::Value was[rules::RuleTables::kMaxCells];
    for (const PivotMove& m : sequence) {
        const PivotRules::Instance roll = pivots_->find(m.from, m.to, m.pivot);
        const auto cell = [](Vec v) { return "(" + std::to_string(v.x) + "," + std::to_string(v.y) + ")"; };
        if (roll.shape < 0)
            throw InternalError("hex disks: the design moves a disk from " + cell(m.from) + " to " + cell(m.to) + " about " + cell(m.pivot) +
                                ", which is no instance of hex_pivot");
        if (!pivot.matches(cells_.data(), roll.anchor, roll.shape))
            return fail("the design's sequence does not fit the disks there (a slot was not in its layout)");
        pivot.apply(cells_.data(), roll.anchor, roll.shape, was);
        moves_.push_back({instance, rule, m.from, m.to, m.pivot});
    }
    return true;
}

std::vector<Vec> DiskMetamodules::disks() const {
    std::vector<Vec> out;
    pivots_->board().forEachInside([&](std::int64_t i, Vec p) {
        if (cells_[i]) out.push_back(p);
    });
    return out;
}

bool DiskMetamodules::slotsMatch(const std::vector<BoxEngine::Value>& now, std::string& why) const {
    std::int64_t placed = 0;
    bool ok = true;
    problem_->board->forEachInside([&](std::int64_t i, Vec p) {
        if (!ok) return;
        const std::vector<Vec>& layout = design_.layout(static_cast<int>(problem_->tables->massUnitsOf(now[i])));
        std::int64_t held = 0;
        for (int j = 0; j < side(); ++j)
            for (int k = 0; k < side(); ++k) held += occupied(slotOrigin(p) + Vec{k, j, 0});
        bool inLayout = true;
        for (Vec c : layout) inLayout &= occupied(slotOrigin(p) + c);
        placed += held;
        if (held != static_cast<std::int64_t>(layout.size()) || !inLayout)
            why = "slot (" + std::to_string(p.x) + "," + std::to_string(p.y) + ") does not hold its state's layout", ok = false;
    });
    if (ok && placed != static_cast<std::int64_t>(start_.size())) why = std::to_string(start_.size() - placed) + " disks lie outside every slot", ok = false;
    return ok;
}

std::string replayDiskMoves(const std::vector<Vec>& start, const std::vector<DiskMove>& moves) {
    // A grid one cell wider than every cell named, so that every neighbour of a disk is on it.
    int lowX = 0, lowY = 0, highX = 0, highY = 0;
    bool first = true;
    const auto cover = [&](Vec v) {
        if (first) lowX = highX = v.x, lowY = highY = v.y, first = false;
        lowX = std::min(lowX, v.x), highX = std::max(highX, v.x), lowY = std::min(lowY, v.y), highY = std::max(highY, v.y);
    };
    for (Vec v : start) cover(v);
    for (const DiskMove& m : moves) cover(m.from), cover(m.to), cover(m.pivot);
    const int width = highX - lowX + 3, height = highY - lowY + 3;
    std::vector<std::uint8_t> grid(static_cast<std::size_t>(width) * height, 0);
    const auto index = [&](Vec v) { return static_cast<std::size_t>(v.y - lowY + 1) * width + (v.x - lowX + 1); };
    const auto has = [&](Vec v) { return grid[index(v)] != 0; };
    for (Vec v : start) grid[index(v)] = 1;
    // Whether the disks next to `gone` (just emptied) still reach each other. If they are one arc
    // around it they touch in turn; otherwise a breadth-first search from one of them, which stops
    // once it has met them all (in a connected ensemble the others are near).
    const std::vector<Vec>& neighbours = rules::Lattice::get(rules::LatticeKind::Hex2D).directions();  // counterclockwise
    std::vector<std::int64_t> offsets;
    for (Vec d : neighbours) offsets.push_back(static_cast<std::int64_t>(d.y) * width + d.x);
    const auto edges = rules::offsetEdges(
        6, [&](int d) { return offsets[d]; }, [&](std::int64_t i) { return grid[i] != 0; });
    rules::Flood flood;
    const auto rejoined = [&](Vec gone) {
        std::vector<std::int64_t> ends;
        int arcs = 0;
        for (int d = 0; d < 6; ++d) {
            const bool here = has(gone + neighbours[d]), before = has(gone + neighbours[(d + 5) % 6]);
            if (here) ends.push_back(static_cast<std::int64_t>(index(gone + neighbours[d])));
            arcs += here && !before;
        }
        if (arcs <= 1) return true;
        flood.begin(grid.size());
        flood.add(ends[0]);
        std::size_t found = 0;
        flood.spread(edges, [&](std::int64_t c) {
            found += std::find(ends.begin(), ends.end(), c) != ends.end();
            return found < ends.size();
        });
        return found == ends.size();
    };
    // The start is one connected set; then each move keeps it so if the disks next to the one
    // that leaves still reach each other (any path through it can go round).
    const bool joined = rules::connected(
        flood, grid.size(),
        [&](auto&& f) {
            for (Vec v : start) f(static_cast<std::int64_t>(index(v)));
        },
        edges);
    if (!joined) return "the start's disks are not connected";
    for (std::size_t k = 0; k < moves.size(); ++k) {
        const DiskMove& m = moves[k];
        const std::string where = "move " + std::to_string(k + 1) + " (" + m.rule + "): ";
        int direction = -1;
        for (int d = 0; d < 6; ++d)
            if (m.from + neighbours[d] == m.to) direction = d;
        if (!has(m.from)) return where + "no disk at the start cell";
        if (has(m.to)) return where + "the end cell is occupied";
        if (direction < 0) return where + "start and end cells are not neighbours";
        const Vec c1 = m.from + neighbours[(direction + 1) % 6], c2 = m.from + neighbours[(direction + 5) % 6];
        if (!((m.pivot == c1 && has(c1) && !has(c2)) || (m.pivot == c2 && has(c2) && !has(c1))))
            return where + "not a pivot: the disk must roll about an occupied common neighbour with the other one empty";
        grid[index(m.from)] = 0;
        if (!rejoined(m.from)) return where + "the disks are no longer connected";
        grid[index(m.to)] = 1;  // it rests on its pivot, so it is joined to the rest
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
    rules::Svg svg;
    for (std::size_t p = 0; p < panels.size(); ++p) {
        const double left = panelWidth * p;
        svg.text(left + 6, 16, panels[p].first, {{"font-family", "sans-serif"}, {"font-size", 13}});
        for (Vec v : panels[p].second) {
            const double x = left + (v.x + 0.5 * v.y - minX + 1.5) * kScale, y = height - (kRow * v.y - minY + 1.5) * kScale;
            svg.circle(x, y, 0.48 * kScale, {{"fill", "#7a9"}, {"stroke", "#354"}});
        }
    }
    return svg.document(panelWidth * panels.size(), height);
}

std::string sequenceSvg(const DiskDesign& design, int receiverLevel, int frames) {
    constexpr double kScale = 11, kRow = 0.8660254037844386;
    constexpr int kColumns = 3;
    const int s = design.side();
    const std::vector<PivotMove>& moves = design.base(receiverLevel);
    // Every disk keeps its colour as it moves: A's ring, A's payload, B's disks.
    std::map<std::pair<int, int>, const char*> colour;
    const std::vector<Vec>& ring = design.layout(1);
    for (Vec c : design.layout(design.units())) colour[{c.x, c.y}] = std::find(ring.begin(), ring.end(), c) != ring.end() ? "#888" : "#3a8";
    for (Vec c : design.layout(receiverLevel)) colour[{c.x + s, c.y}] = "#7ab";
    const double panelWidth = (2.5 * s + 2) * kScale, panelHeight = (kRow * s + 2) * kScale + 24;
    frames = std::max(2, frames);
    const int rows = (frames + kColumns - 1) / kColumns;
    rules::Svg svg;
    std::size_t done = 0;
    for (int f = 0; f < frames; ++f) {
        const std::size_t until = moves.size() * f / (frames - 1);
        for (; done < until; ++done) {
            auto node = colour.extract({moves[done].from.x, moves[done].from.y});
            node.key() = {moves[done].to.x, moves[done].to.y};
            colour.insert(std::move(node));
        }
        const double left = panelWidth * (f % kColumns), top = panelHeight * (f / kColumns);
        svg.text(left + 6, top + 16, "move " + std::to_string(done) + " of " + std::to_string(moves.size()));
        for (const auto& [cell, fill] : colour) {
            const double x = left + (cell.first + 0.5 * cell.second + 1) * kScale, y = top + panelHeight - (kRow * cell.second + 1) * kScale;
            svg.circle(x, y, 0.47 * kScale, {{"fill", fill}});
        }
    }
    return svg.document(panelWidth * std::min(frames, kColumns), panelHeight * rows, {{"font-family", "sans-serif"}, {"font-size", 13}});
}

}  // namespace holon::planner::hex
