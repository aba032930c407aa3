// The transport bound on resource transfers for general_n plans (seed 000 §IV-B; the issue's
// `transfer_lower_bound`) and the flow the optimal allocator follows. Resources move in tokens of
// the creator's extra mass (1/n of a metamodule, the rules' mass unit): a transfer C D <=> D C
// moves one token one lattice step. From any configuration, every cell of the target must end
// with n tokens (a D) or n + 1 (a C): a missing or partial one takes what it lacks from a
// neighbour (that last step is free: the creation rule takes it); every cell outside the target
// is deleted, its n tokens (or what a partial has left) going onto a neighbour for free, while
// a creator's extra token must be transferred away first; tokens left over rest in target cells,
// at most one per cell. Tokens never leave the occupied cells and the target. So every plan's
// transfers pay at least the minimum cost of a flow from the supplies to the demands on that
// lattice graph — a min-cost flow, solved exactly (MinCostFlow.cpp). The bound ignores
// timing (a token may pass a cell before it exists), so it can be lower than what any real plan
// achieves, never higher.

#include "planner/Transport.h"

#include "planner/Allocator.h"
#include "planner/MinCostFlow.h"
#include "rules/Error.h"

namespace holon::planner {

bool movesResources(const Problem& problem) {
    const BoxEngine& engine = *problem.engine;
    bool transfers = false;
    for (int s = 0; s < engine.shapeCount(); ++s) transfers = transfers || engine.kind(s) == ShapeKind::Transfer;
    return problem.schema.resource >= 0 && transfers;
}

std::optional<TransportPlan> planTransport(const Problem& problem, const std::vector<BoxEngine::Value>& cells, bool withFlow) {
    if (!movesResources(problem)) return std::nullopt;
    const rules::RuleTables& tables = *problem.tables;
    const std::int64_t n = tables.massDenominator();  // tokens in a full metamodule

    const Board& board = *problem.board;
    const int degree = board.lattice().degree();
    std::vector<char> inTarget(static_cast<std::size_t>(board.size()), 0);
    for (Vec v : problem.target.cells) inTarget[board.index(v)] = 1;
    auto used = [&](std::int64_t i) { return cells[i] != 0 || inTarget[i]; };

    MinCostFlow g;
    std::vector<int> node(static_cast<std::size_t>(board.size()), -1);
    std::vector<std::int64_t> cellOf;
    board.forEachInside([&](std::int64_t i, Vec) {
        if (!used(i)) return;
        node[static_cast<std::size_t>(i)] = g.addNode();
        cellOf.push_back(i);
    });
    auto nodeAt = [&](std::int64_t i) {
        const int x = node[static_cast<std::size_t>(i)];
        if (x < 0) throw InternalError("the transport graph: a used cell outside the board's interior");
        return x;
    };
    std::vector<std::pair<int, std::int64_t>> lattice;  // transfer arcs and their key i * degree + d
    const int sink = g.addNode();
    std::int64_t leftover = 0;
    // A node for tokens that neighbours hand over for free, or take for free.
    auto freeNode = [&](std::int64_t i, std::int64_t tokens) {
        const int x = g.addNode();
        g.addSupply(x, tokens), leftover += tokens;
        for (int d = 0; d < degree; ++d)
            if (const std::int64_t j = i + board.step(d); used(j)) tokens > 0 ? g.addArc(x, nodeAt(j), MinCostFlow::kUnlimited, 0) : g.addArc(nodeAt(j), x, MinCostFlow::kUnlimited, 0);
    };
    for (std::int64_t i : cellOf) {
        const int x = nodeAt(i);
        for (int d = 0; d < degree; ++d)
            if (const std::int64_t j = i + board.step(d); used(j)) {
                const int a = g.addArc(x, nodeAt(j), MinCostFlow::kUnlimited, 1);
                if (withFlow) lattice.push_back({a, i * degree + d});
            }
        const std::int64_t m = cells[i] ? tables.massUnitsOf(cells[i]) : 0;
        const std::int64_t extra = std::max<std::int64_t>(0, m - n);
        g.addSupply(x, extra), leftover += extra;
        if (inTarget[i]) {
            if (m < n) freeNode(i, -(n - m));
            g.addArc(x, sink, 1, 0);
        } else if (m > 0) {
            freeNode(i, std::min(m, n));
        }
    }
    g.addSupply(sink, -leftover);
    const std::optional<std::int64_t> cost = g.solve();
    if (!cost) return std::nullopt;
    TransportPlan plan;
    plan.cost = *cost;
    for (const auto& [a, key] : lattice)
        if (const std::int64_t f = g.flow(a); f > 0) plan.flow[key] = static_cast<std::int32_t>(f);
    return plan;
}

std::int64_t transferLowerBound(const Problem& problem) {
    if (!movesResources(problem)) return -1;
    const std::optional<TransportPlan> plan = planTransport(problem, problem.cells, false);
    if (!plan) throw InternalError("the transport problem has no solution; the mass check should have refused this problem");
    return plan->cost;
}

}  // namespace holon::planner
