// The planner's run-time monitor (issue: --check). Seed 000's Theorem 1 promises that the
// ensemble stays connected (Lemma 1, Safety) and, for general_n, the transfer and motion rules
// conserve mass (§III); the monitor checks both on the actual run.
//
// A round is checked from the cells it wrote (issue 28: from scratch it cost 50x the run at 10^6
// metamodules). Mass and the alphabet change only at written cells. Connectivity: if the
// configuration before the round was connected, the one after is connected exactly when (a) around
// every face-connected cluster of emptied cells the occupied cells lie in one component, and (b)
// every cluster of filled cells touches a cell that was and stays occupied (or, with no such cell
// left, the filled cells are one cluster). Why (a) suffices: on an old path between two surviving
// cells, each run of emptied cells lies in one cluster and the cells just before and after it are
// around that cluster. Around a lone emptied cell its neighbours usually meet again within two
// steps (linkedNearby); otherwise one breadth-first search per neighbour runs, the smallest
// advancing first, and searches that meet merge (union-find), so a piece that was cut off is found
// after visiting that piece only. The whole configuration is re-checked from scratch at rounds 1,
// 4, 16, 64, ... and at the end: O(log rounds) scans, which also catch a write the engine did not
// report.

#include "planner/Monitor.h"

#include "rules/ConfigIo.h"
#include "rules/ItfWriter.h"

#include <algorithm>
#include <queue>

namespace holon::planner {

Monitor::Monitor(const Problem& problem, const Execution& execution) : problem_(&problem), execution_(&execution) {
    conservesMass_ = problem.model->system().conservesMass();
    for (BoxEngine::Value v : execution.cells()) initialMass_ += problem.tables->massUnitsOf(v);
    mass_ = initialMass_;
    stamp_.assign(execution.cells().size(), 0);
    // The window around a cell: its neighbours and theirs, with which of them are neighbours.
    const Board& board = *problem.board;
    const int degree = board.lattice().degree();
    for (int d = 0; d < degree; ++d)
        for (int e = -1; e < degree; ++e) {
            const std::int64_t o = board.step(d) + (e < 0 ? 0 : board.step(e));
            if (o != 0 && std::find(window_.begin(), window_.end(), o) == window_.end()) window_.push_back(o);
        }
    if (window_.size() > 64) window_.clear();  // no lattice holon knows has such a window; use the searches
    windowLinks_.assign(window_.size(), 0);
    for (std::int64_t o : window_) {
        bool neighbour = false;
        for (int d = 0; d < degree; ++d) neighbour |= board.step(d) == o;
        windowNeighbour_.push_back(neighbour);
    }
    for (std::size_t a = 0; a < window_.size(); ++a)
        for (std::size_t b = 0; b < window_.size(); ++b)
            for (int d = 0; d < degree; ++d)
                if (window_[a] + board.step(d) == window_[b]) windowLinks_[a] |= std::uint64_t{1} << b;
    label_.assign(execution.cells().size(), 0);
    if (!connected()) violation_ = "the start is not connected";
}

void Monitor::fired(std::int64_t anchor, int shape, const BoxEngine::Value* old) {
    lastFired_.push_back({anchor, shape});
    const auto& steps = problem_->engine->cellSteps(shape);
    for (std::size_t k = 0; k < steps.size(); ++k) before_.push_back(old[k]);
}

void Monitor::lost(std::int64_t, BoxEngine::Value old) {
    initialMass_ -= problem_->tables->massUnitsOf(old);
    mass_ -= problem_->tables->massUnitsOf(old);
    --occupied_;
}

bool Monitor::connected() const {
    const Board& board = *problem_->board;
    const auto& cells = execution_->cells();
    const auto occupied = [&](std::int64_t j) { return cells[j] != 0; };
    rules::Flood flood;
    return rules::connected(flood, cells.size(), rules::verticesWhere(static_cast<std::int64_t>(cells.size()), occupied),
                            rules::offsetEdges(
                                board.lattice().degree(), [&](int d) { return board.step(d); }, occupied));
}

void Monitor::checkFromScratch() {
    ++fullChecks_;
    std::int64_t mass = 0;
    for (BoxEngine::Value v : execution_->cells()) {
        if (v >= problem_->tables->alphabet()) violation_ = "a cell holds state " + std::to_string(v) + ", outside the alphabet";
        mass += problem_->tables->massUnitsOf(v < problem_->tables->alphabet() ? v : 0);
    }
    mass_ = mass;
    occupied_ = 0;
    for (BoxEngine::Value v : execution_->cells()) occupied_ += v != 0;
    if (violation_.empty() && conservesMass_ && mass != initialMass_)
        violation_ = "mass changed from " + rules::Rational(initialMass_, problem_->tables->massDenominator()).str() + " to " +
                     rules::Rational(mass, problem_->tables->massDenominator()).str();
    if (violation_.empty() && !connected()) violation_ = "the ensemble is disconnected";
}

std::uint32_t Monitor::freshEpoch() {
    if (++epoch_ == 0) std::fill(stamp_.begin(), stamp_.end(), 0), epoch_ = 1;
    return epoch_;
}

bool Monitor::oneComponent(const std::vector<std::int64_t>& sources) {
    const Board& board = *problem_->board;
    const auto& cells = execution_->cells();
    const int degree = board.lattice().degree();
    const std::uint32_t reached = freshEpoch();
    parent_.clear(), visited_.clear();
    for (std::int64_t s : sources)
        if (stamp_[s] != reached) {
            const auto g = static_cast<std::int32_t>(parent_.size());
            stamp_[s] = reached, label_[s] = g, parent_.push_back(g), visited_.push_back(0);
            if (frontier_.size() <= static_cast<std::size_t>(g)) frontier_.emplace_back(), head_.push_back(0);
            frontier_[g].assign(1, s), head_[g] = 0;
        }
    auto find = [&](std::int32_t a) {
        while (parent_[a] != a) a = parent_[a] = parent_[parent_[a]];
        return a;
    };
    std::int64_t groups = static_cast<std::int64_t>(parent_.size());
    using Entry = std::pair<std::int64_t, std::int32_t>;  // (cells visited, search)
    std::priority_queue<Entry, std::vector<Entry>, std::greater<>> next;
    for (std::int32_t g = 0; g < static_cast<std::int32_t>(parent_.size()); ++g) next.push({0, g});
    while (groups > 1) {
        const auto [count, g0] = next.top();
        next.pop();
        if (find(g0) != g0 || count != visited_[g0]) continue;  // merged away, or a stale entry
        // The smallest search advances a few cells breadth first, then the smallest is chosen again.
        std::int32_t at = g0;  // the search these cells belong to, after any merge
        for (int burst = 0; burst < 16 && groups > 1; ++burst) {
            std::vector<std::int64_t>& queue = frontier_[at];
            if (head_[at] == queue.size()) return false;  // a closed piece while others remain
            const std::int64_t i = queue[head_[at]++];
            ++visited_[at];
            for (int d = 0; d < degree && groups > 1; ++d) {
                const std::int64_t j = i + board.step(d);
                if (!cells[j]) continue;
                if (stamp_[j] != reached) {
                    stamp_[j] = reached, label_[j] = at, frontier_[at].push_back(j);
                    continue;
                }
                const std::int32_t h = find(label_[j]);
                if (h == at) continue;
                const std::size_t atLeft = frontier_[at].size() - head_[at], hLeft = frontier_[h].size() - head_[h];
                const std::int32_t keep = atLeft >= hLeft ? at : h, drop = atLeft >= hLeft ? h : at;
                frontier_[keep].insert(frontier_[keep].end(), frontier_[drop].begin() + static_cast<std::ptrdiff_t>(head_[drop]), frontier_[drop].end());
                frontier_[drop].clear(), head_[drop] = 0;
                parent_[drop] = keep, visited_[keep] += visited_[drop], --groups;
                at = keep;
            }
        }
        next.push({visited_[at], at});
    }
    return true;
}

bool Monitor::linkedNearby(std::int64_t cell) const {
    const auto& cells = execution_->cells();
    std::uint64_t occupied = 0, neighbours = 0;  // bit k: window cell k
    const auto size = static_cast<std::int64_t>(cells.size());
    for (std::size_t k = 0; k < window_.size(); ++k) {
        // Two steps can leave the board's padding (one cell): beyond it is empty.
        const std::int64_t j = cell + window_[k];
        if (j >= 0 && j < size && cells[j]) occupied |= std::uint64_t{1} << k;
    }
    for (std::size_t k = 0; k < window_.size(); ++k)
        if (windowNeighbour_[k]) neighbours |= std::uint64_t{1} << k;
    const std::uint64_t ends = occupied & neighbours;
    if (!ends) return true;
    return !(ends & ~rules::reachedWithin(ends & (~ends + 1), occupied, rules::aroundByTable(windowLinks_.data())));
}

bool Monitor::changesKeepConnected() {
    const Board& board = *problem_->board;
    const auto& cells = execution_->cells();
    const int degree = board.lattice().degree();
    // The stamps below must survive until the searches: start a fresh cycle when few epochs remain.
    if (epoch_ > UINT32_MAX - 8) std::fill(stamp_.begin(), stamp_.end(), 0), epoch_ = 0;
    const std::uint32_t written = freshEpoch();
    // The cells written this round, each with its value before the round (its first write's).
    std::vector<std::pair<std::int64_t, BoxEngine::Value>> changed;
    std::size_t at = 0;
    for (const auto& [anchor, shape] : lastFired_)
        for (std::int64_t step : problem_->engine->cellSteps(shape)) {
            const std::int64_t c = anchor + step;
            if (stamp_[c] != written) stamp_[c] = written, changed.push_back({c, before_[at]});
            ++at;
        }
    std::vector<std::int64_t> emptied, filled;
    for (const auto& [c, old] : changed) {
        const BoxEngine::Value now = cells[c];
        if (now >= problem_->tables->alphabet()) {
            violation_ = "a cell holds state " + std::to_string(now) + ", outside the alphabet";
            return true;
        }
        mass_ += problem_->tables->massUnitsOf(now) - problem_->tables->massUnitsOf(old);
        if (old && !now) emptied.push_back(c);
        if (!old && now) filled.push_back(c);
    }
    const std::int64_t survivors = occupied_ - static_cast<std::int64_t>(emptied.size());
    occupied_ += static_cast<std::int64_t>(filled.size()) - static_cast<std::int64_t>(emptied.size());
    if (emptied.empty() && filled.empty()) return true;

    // Face-connected clusters of emptied cells and of filled cells, each with the occupied cells
    // around it: any occupied cell around an emptied cluster; around a filled one, those not filled
    // this round. Both are gathered before any search, which reuses the stamps.
    const std::uint32_t mark = freshEpoch();
    for (std::int64_t c : emptied) stamp_[c] = mark;
    for (std::int64_t c : filled) stamp_[c] = mark;
    auto arounds = [&](const std::vector<std::int64_t>& set, bool filledSet) {
        std::vector<std::pair<std::int64_t, std::vector<std::int64_t>>> out;  // (the cell of a one-cell cluster or -1, around)
        const auto edges = [&](std::int64_t i, auto&& step) {
            for (int d = 0; d < degree; ++d) {
                const std::int64_t j = i + board.step(d);
                if (stamp_[j] == mark && (cells[j] != 0) == filledSet) step(j);
                else if (cells[j] && !(filledSet && stamp_[j] == mark)) out.back().second.push_back(j);
            }
        };
        rules::components(
            flood_, cells.size(),
            [&](auto&& f) {
                for (std::int64_t c : set) f(c);
            },
            edges,
            [&](std::int64_t c, int k) {
                if (k == static_cast<int>(out.size())) out.push_back({c, {}});
                else out.back().first = -1;
            });
        return out;
    };
    const auto aroundEmptied = arounds(emptied, false);
    const auto aroundFilled = arounds(filled, true);
    // Around an emptied cluster, the occupied cells must stay linked: most often through the cells
    // next to a lone emptied cell, else by the searches.
    for (const auto& [single, around] : aroundEmptied)
        if (around.size() > 1 && !(single >= 0 && linkedNearby(single)) && !oneComponent(around)) return false;
    // A filled cluster must touch a cell that was and stays occupied, if any survives; with none,
    // the filled cells are the whole ensemble and must be one cluster.
    for (const auto& [single, around] : aroundFilled)
        if (around.empty() && (survivors > 0 || aroundFilled.size() > 1)) return false;
    return true;
}

bool Monitor::report(const RunStats& stats, const char* how) {
    if (violation_.empty()) return true;
    violation_ += " after step " + std::to_string(stats.steps) + " (round " + std::to_string(stats.rounds) + ")" + how;
    return false;
}

bool Monitor::roundEnd(const RunStats& stats) {
    if (!violation_.empty()) return false;
    ++checks_;
    if (checks_ == nextFullCheck_) {
        nextFullCheck_ *= 4;
        checkFromScratch();
    } else {
        if (!changesKeepConnected() && violation_.empty()) violation_ = "the ensemble is disconnected";
        if (violation_.empty() && conservesMass_ && mass_ != initialMass_)
            violation_ = "mass changed from " + rules::Rational(initialMass_, problem_->tables->massDenominator()).str() + " to " +
                         rules::Rational(mass_, problem_->tables->massDenominator()).str();
    }
    if (!report(stats, "")) return false;
    lastFired_.clear(), before_.clear();
    return true;
}

bool Monitor::finish(const RunStats& stats) {
    if (!violation_.empty()) return false;
    checkFromScratch();
    return report(stats, ", found by the check of the final configuration from scratch");
}

std::string Monitor::summary() const {
    if (!violation_.empty()) return "VIOLATED: " + violation_;
    return "connectivity" + std::string(conservesMass_ ? ", mass" : "") + " held at all " + std::to_string(checks_) + " checks (" +
           std::to_string(fullChecks_) + " of the whole configuration, the others of what each step or round changed)";
}

void Monitor::writeTrace(const rules::OutputFile& file) const {
    const rules::Model& model = *problem_->model;
    const Board& board = *problem_->board;
    const rules::Lattice& lattice = board.lattice();
    std::vector<BoxEngine::Value> earlier = execution_->cells();
    std::size_t at = before_.size();
    for (std::size_t f = lastFired_.size(); f-- > 0;) {  // undo the last round, latest first
        const auto& steps = problem_->engine->cellSteps(lastFired_[f].second);
        at -= steps.size();
        for (std::size_t k = 0; k < steps.size(); ++k) earlier[lastFired_[f].first + steps[k]] = before_[at + k];
    }
    rules::ItfWriter itf(model, {model.system().sourceName, model.system().name, "", "monitor", violation_}, false);
    auto state = [&](const std::vector<BoxEngine::Value>& cells, nlohmann::json meta) {
        itf.state(std::move(meta), [&](auto&& f) {
            for (std::size_t i = 0; i < cells.size(); ++i)
                if (cells[i]) f(board.point(static_cast<std::int64_t>(i)), cells[i]);
        });
    };
    nlohmann::json fired = nlohmann::json::array();
    for (const auto& [anchor, shape] : lastFired_) {
        nlohmann::json cells = nlohmann::json::array();
        for (std::int64_t s : problem_->engine->cellSteps(shape)) cells.push_back(rules::pointJson(lattice, board.point(anchor + s)));
        fired.push_back({{"rule", model.rules()[problem_->engine->ruleOf(shape)].name}, {"cells", cells}});
    }
    state(earlier, {{"index", 0}});
    state(execution_->cells(), {{"index", 1}, {"fired", fired}});
    file.write(itf.json().dump(1) + '\n');
}

}  // namespace holon::planner
