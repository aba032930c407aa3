// Bidirectional breadth-first search (checker/PathSearch.h): forwards from the start with the
// engine's enabled instances, backwards from the target with Predecessors, a whole level at a
// time on whichever side has the smaller frontier. Why the first meeting is a shortest path: let
// the sides have finished levels 0..a and 0..b without meeting, so every path is longer than
// a + b (its state a steps from the start would be on both sides). A state x found while
// expanding level a of the forward side gives a path of a + 1 + (x's distance to the target) <=
// a + 1 + b steps, and no path is shorter than a + b + 1: x's path is a shortest one. The same
// holds the other way round. Each side stores about the states within half the distance of its
// end, which on a space that grows with the distance is a small part of what the forward search
// stores.

#include "checker/Evaluator.h"
#include "checker/PathSearch.h"

#include <algorithm>

namespace holon::checker {

PathResult bidirectionalPath(const rules::Engine& engine, const Predecessors& predecessors, const PathQuery& query) {
    const int n = engine.region().size();
    const rules::Configuration& to = *query.to;
    SearchMeter meter(query);
    SearchTree trees[2] = {SearchTree(engine), SearchTree(engine)};  // 0: from the start, 1: to the target
    StateId begin[2] = {0, 0};                                       // each side's current level: ids [begin, size)
    int depth[2] = {0, 0};
    PathResult result;
    result.search = PathSearch::Bidirectional;
    const auto states = [&] { return trees[0].size() + trees[1].size(); };
    const auto bytes = [&] { return trees[0].bytes() + trees[1].bytes(); };
    trees[0].add(query.from.cells.data(), kNoState, -1);
    if (!engine.legal(to.cells.data())) {  // no step leads to it
        result.outcome = PathOutcome::Unreachable, result.closed = 0, result.closedFromStart = false;
        result.stats = meter.finish(states(), bytes(), 0, StopReason::Finished);
        return result;
    }
    trees[1].add(to.cells.data(), kNoState, -1);

    StateId meet[2] = {kNoState, kNoState};
    if (query.from.cells == to.cells) meet[0] = meet[1] = 0;
    StopReason stop = StopReason::Finished;
    std::vector<CellValue> cells(n), after(n);
    CellValue saved[rules::Engine::kMaxCells];
    const WordConstraints constraints(engine);
    Evaluator evaluator(constraints);  // holds the state being expanded
    while (meet[0] == kNoState && stop == StopReason::Finished) {
        const std::uint64_t frontier[2] = {trees[0].size() - begin[0], trees[1].size() - begin[1]};
        if (!frontier[0] || !frontier[1]) {
            const int dry = frontier[0] ? 1 : 0;
            result.outcome = PathOutcome::Unreachable, result.closed = trees[dry].size(), result.closedFromStart = dry == 0;
            result.stats = meter.finish(states(), bytes(), depth[0] + depth[1], StopReason::Finished);
            return result;
        }
        const int side = frontier[0] <= frontier[1] ? 0 : 1;
        SearchTree& tree = trees[side];
        const StateId end = static_cast<StateId>(tree.size());
        for (StateId id = begin[side]; id < end && meet[0] == kNoState && stop == StopReason::Finished; ++id) {
            tree.cells(id, cells.data());
            evaluator.load(cells.data());
            const auto visit = [&](int placed, const CellValue* next) {
                const rules::Engine::Placed& instance = engine.instances()[placed];
                if (meet[0] != kNoState || stop != StopReason::Finished || (stop = meter.poll()) != StopReason::Finished) return;
                if (tree.findNear(id, instance, next) != kNoState || !legalNear(evaluator, instance, cells.data(), next)) return;
                if ((stop = meter.admit(states())) != StopReason::Finished) return;
                const StateId found = tree.addMissing(id, placed);
                if (const StateId other = trees[1 - side].findAsIn(tree); other != kNoState) meet[side] = found, meet[1 - side] = other;
                stop = meter.check(states(), bytes(), depth[0] + depth[1]);
            };
            if (side == 0) {
                std::copy(cells.begin(), cells.end(), after.begin());
                engine.forEachMatch(cells.data(), [&](int placed) {
                    engine.apply(after.data(), placed, saved);
                    visit(placed, after.data());
                    engine.undo(after.data(), placed, saved);
                });
            } else {
                predecessors.forEach(cells.data(), visit);
            }
            if (stop == StopReason::Finished) stop = meter.check(states(), bytes(), depth[0] + depth[1]);
        }
        if (stop != StopReason::Finished) break;  // a level cut short is not finished: no bound from it
        begin[side] = end, ++depth[side];
    }
    if (meet[0] == kNoState) {
        result.outcome = PathOutcome::Undecided;
        result.stats = meter.finish(states(), bytes(), depth[0] + depth[1], stop);
        return result;
    }
    // The start's tree down to the meeting state, then the target's tree up from it: there each
    // state's instance leads from it to its parent.
    result.outcome = PathOutcome::Found;
    result.trace.description = "a shortest path to the given configuration";
    for (StateId s : trees[0].pathTo(meet[0])) {
        trees[0].cells(s, cells.data());
        result.trace.steps.push_back({cells, trees[0].via(s)});
    }
    for (StateId s = meet[1]; trees[1].parent(s) != kNoState; s = trees[1].parent(s)) {
        trees[1].cells(trees[1].parent(s), cells.data());
        result.trace.steps.push_back({cells, trees[1].via(s)});
    }
    result.stats = meter.finish(states(), bytes(), static_cast<int>(result.trace.steps.size()) - 1, StopReason::Decided);
    return result;
}

}  // namespace holon::checker
