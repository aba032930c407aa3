// The transport lower bound on resource transfers for general_n plans (seed 000 §IV-B; the
// issue's `transfer_lower_bound`). Resources move in tokens of the creator's extra mass (1/n):
// a transfer C D <=> D C moves one token one lattice step; a creation consumes n tokens that
// arrive from a neighbour of the new cell (that last step is free: the creation rule takes it); a
// deletion frees n tokens onto a neighbour (free as well); every token left over rests in a target
// cell, at most one per cell (a C). Tokens never leave start ∪ target, the only cells that are
// ever occupied. So every plan's transfers pay at least the minimum cost of a flow from the
// supplies (initial creators, deleted cells) to the demands (created cells, leftover places) on
// the lattice graph of start ∪ target — a min-cost flow solved exactly with LEMON's network
// simplex. The bound ignores timing (a token may pass a cell before it exists), so it can be lower
// than what any real plan achieves, never higher.

#include "planner/Allocator.h"
#include "planner/Problem.h"

#include "rules/Error.h"

#include <lemon/network_simplex.h>
#include <lemon/smart_graph.h>

#include <unordered_map>

namespace holon::planner {

namespace {
constexpr std::int64_t kUnlimited = std::int64_t{1} << 40;
}  // namespace

std::int64_t transferLowerBound(const Problem& problem) {
    const PlannerSchema& schema = problem.schema;
    const BoxEngine& engine = *problem.engine;
    bool hasTransfers = false;
    for (int s = 0; s < engine.shapeCount(); ++s) hasTransfers = hasTransfers || engine.kind(s) == ShapeKind::Transfer;
    if (schema.resource < 0 || !hasTransfers) return -1;

    // Tokens per metamodule: 1 / (mass(C) - 1).
    const rules::Rational extra = schema.extra;
    if (!(rules::Rational(0) < extra) || extra.num() != 1) return -1;
    const std::int64_t n = extra.den();

    const Board& board = *problem.board;
    const int degree = board.lattice().degree();
    lemon::SmartDigraph g;
    using Node = lemon::SmartDigraph::Node;
    std::unordered_map<std::int64_t, Node> node;
    std::vector<char> inStart(static_cast<std::size_t>(board.size()), 0), inTarget(static_cast<std::size_t>(board.size()), 0);
    for (Vec v : problem.start.cells) inStart[board.index(v)] = 1;
    for (Vec v : problem.target.cells) inTarget[board.index(v)] = 1;
    auto nodeOf = [&](std::int64_t i) {
        auto it = node.find(i);
        if (it == node.end()) it = node.emplace(i, g.addNode()).first;
        return it->second;
    };
    for (const Shape* s : {&problem.start, &problem.target})
        for (Vec v : s->cells) nodeOf(board.index(v));
    lemon::SmartDigraph::ArcMap<std::int64_t> cost(g);
    lemon::SmartDigraph::NodeMap<std::int64_t> supply(g, 0);
    lemon::SmartDigraph::ArcMap<std::int64_t> capacity(g);  // entries of arcs added later start at 0: set on each
    auto arc = [&](Node from, Node to, std::int64_t c, std::int64_t cap = kUnlimited) {
        const auto a = g.addArc(from, to);
        cost[a] = c, capacity[a] = cap;
    };
    const Node sink = g.addNode();
    std::int64_t leftover = 0;
    for (const auto& [i, x] : std::vector<std::pair<std::int64_t, Node>>(node.begin(), node.end())) {
        for (int d = 0; d < degree; ++d) {
            const std::int64_t j = i + board.step(d);
            if (inStart[j] || inTarget[j]) arc(x, node.at(j), 1);
        }
        const BoxEngine::Value v = problem.cells[i];
        if (v && problem.model->alphabet().fields(v)[schema.resource] == schema.creator) supply[x] += 1, leftover += 1;
        if (inStart[i] && !inTarget[i]) {  // deleted: n tokens freed onto a neighbour
            const Node freed = g.addNode();
            supply[freed] = n, leftover += n;
            for (int d = 0; d < degree; ++d)
                if (const std::int64_t j = i + board.step(d); inStart[j] || inTarget[j]) arc(freed, node.at(j), 0);
        }
        if (inTarget[i] && !inStart[i]) {  // created: n tokens taken from a neighbour
            const Node needed = g.addNode();
            supply[needed] = -n, leftover -= n;
            for (int d = 0; d < degree; ++d)
                if (const std::int64_t j = i + board.step(d); inStart[j] || inTarget[j]) arc(node.at(j), needed, 0);
        }
        if (inTarget[i]) arc(x, sink, 0, 1);
    }
    supply[sink] = -leftover;
    lemon::NetworkSimplex<lemon::SmartDigraph, std::int64_t, std::int64_t> simplex(g);
    simplex.costMap(cost).upperMap(capacity).supplyMap(supply);
    if (simplex.run() != decltype(simplex)::OPTIMAL) throw InputError("internal: the transport problem has no solution; the mass check should have refused this problem");
    return simplex.totalCost();
}

}  // namespace holon::planner
