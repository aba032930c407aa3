// A* towards a given configuration (checker/PathSearch.h). The bound: a step fires one instance,
// which changes at most W cells (Footprints::maxWrites: the most pattern cells any instance may
// rewrite), so a configuration that differs from the target in d cells is at least ceil(d / W)
// steps from it. It never overestimates (admissible) and changes by at most one per step
// (consistent), so the first time a configuration is taken from the queue its distance is known,
// and the target's is the length of a shortest path. It holds for every system; it is tight for
// systems whose steps each change W cells towards the target (pixel's add and remove: W = 1), and
// weak where modules must first move away.

#include "checker/Evaluator.h"
#include "checker/PathSearch.h"

#include <algorithm>

namespace holon::checker {

PathResult aStarPath(const rules::Engine& engine, const Footprints& footprints, const PathQuery& query) {
    const int n = engine.region().size();
    const CellValue* target = query.to->cells.data();
    const int perStep = std::max(1, footprints.maxWrites());
    const auto bound = [&](const CellValue* cells) {
        int differ = 0;
        for (int i = 0; i < n; ++i) differ += cells[i] != target[i];
        return static_cast<std::uint32_t>((differ + perStep - 1) / perStep);
    };
    SearchMeter meter(query);
    SearchTree tree(engine);
    std::vector<std::uint32_t> g, h;  // per state: the best distance found so far, and the bound
    std::vector<char> closed;
    std::vector<std::vector<StateId>> open;  // by g + h; a state is pushed again when g improves
    const auto push = [&](StateId id) {
        const std::size_t f = g[id] + h[id];
        if (f >= open.size()) open.resize(f + 1);
        open[f].push_back(id);
    };
    tree.add(query.from.cells.data(), kNoState, -1);
    g.push_back(0), h.push_back(bound(query.from.cells.data())), closed.push_back(0);
    push(0);
    PathResult result;
    result.search = PathSearch::AStar;
    result.bound = static_cast<int>(h[0]);
    const auto bytes = [&] { return tree.bytes() + (g.capacity() + h.capacity()) * sizeof(std::uint32_t) + closed.capacity(); };

    std::vector<CellValue> cells(n), after(n);
    CellValue saved[rules::Engine::kMaxCells];
    const WordConstraints constraints(engine);
    Evaluator evaluator(constraints);  // holds the state being expanded
    StopReason stop = StopReason::Finished;
    int deepest = 0;
    std::size_t f = 0;  // the queue's lowest g + h: no path is shorter
    for (; f < open.size() && stop == StopReason::Finished; ++f) {
        while (!open[f].empty() && stop == StopReason::Finished) {
            const StateId id = open[f].back();
            open[f].pop_back();
            if (closed[id] || g[id] + h[id] != f) continue;  // expanded already, or pushed before a shorter way was found
            closed[id] = 1;
            deepest = std::max(deepest, static_cast<int>(g[id]));
            if (h[id] == 0) {  // no cell differs: the target
                result.outcome = PathOutcome::Found;
                result.trace.description = "a shortest path to the given configuration";
                for (StateId s : tree.pathTo(id)) {
                    tree.cells(s, cells.data());
                    result.trace.steps.push_back({cells, tree.via(s)});
                }
                result.stats = meter.finish(tree.size(), bytes(), static_cast<int>(g[id]), StopReason::Decided);
                return result;
            }
            tree.cells(id, cells.data());
            evaluator.load(cells.data());
            std::copy(cells.begin(), cells.end(), after.begin());
            engine.forEachMatch(cells.data(), [&](int placed) {
                engine.apply(after.data(), placed, saved);
                if (stop == StopReason::Finished) stop = meter.poll();
                if (stop == StopReason::Finished) {
                    const rules::Engine::Placed& instance = engine.instances()[placed];
                    StateId next = tree.findNear(id, instance, after.data());
                    const bool fresh = next == kNoState && legalNear(evaluator, instance, cells.data(), after.data());
                    if (fresh) stop = meter.admit(tree.size());
                    if (fresh && stop == StopReason::Finished) {
                        next = tree.addMissing(id, placed);
                        g.push_back(g[id] + 1), h.push_back(bound(after.data())), closed.push_back(0);
                        push(next);
                        stop = meter.check(tree.size(), bytes(), deepest);
                    } else if (next != kNoState && !closed[next] && g[id] + 1 < g[next]) {
                        g[next] = g[id] + 1, tree.relink(next, id, placed);
                        push(next);
                    }
                }
                engine.undo(after.data(), placed, saved);
            });
            if (stop == StopReason::Finished) stop = meter.check(tree.size(), bytes(), deepest);
        }
    }
    result.outcome = stop == StopReason::Finished ? PathOutcome::Unreachable : PathOutcome::Undecided;
    result.closed = tree.size();  // when unreachable: every configuration reachable from the start
    // Stopped: no path within f - 1 steps (the loop's ++f ran once more unless the queue ran dry).
    result.stats = meter.finish(tree.size(), bytes(), stop == StopReason::Finished ? deepest : std::max(0, static_cast<int>(f) - 2), stop);
    return result;
}

}  // namespace holon::checker
