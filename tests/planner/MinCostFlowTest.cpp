// The min-cost flow behind the transport bound (planner/MinCostFlow.cpp) against an independent
// solver, LEMON's network simplex, on seeded random instances: grids with arcs of cost 0 to 3 in
// both directions, some capacitated, zero-cost shortcuts that close zero-cost cycles, and supplies
// that sometimes cannot be met.

#include "planner/MinCostFlow.h"
#include "planner/Random.h"

#include <doctest/doctest.h>
#include <lemon/network_simplex.h>
#include <lemon/smart_graph.h>

#include <vector>

namespace holon::test {

namespace {

struct Instance {
    int nodes = 0;
    struct Arc {
        int from, to;
        std::int64_t capacity, cost;
    };
    std::vector<Arc> arcs;
    std::vector<std::int64_t> supply;
};

Instance randomInstance(planner::Random& random) {
    Instance in;
    const int w = 2 + static_cast<int>(random.below(9)), h = 2 + static_cast<int>(random.below(9));
    in.nodes = w * h;
    auto capacity = [&]() -> std::int64_t { return random.below(3) == 0 ? 1 + static_cast<std::int64_t>(random.below(4)) : planner::MinCostFlow::kUnlimited; };
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x)
            for (const auto& [dx, dy] : {std::pair{1, 0}, std::pair{0, 1}}) {
                if (x + dx >= w || y + dy >= h || random.below(8) == 0) continue;
                const int a = y * w + x, b = (y + dy) * w + x + dx;
                in.arcs.push_back({a, b, capacity(), static_cast<std::int64_t>(random.below(4))});
                in.arcs.push_back({b, a, capacity(), static_cast<std::int64_t>(random.below(4))});
            }
    for (int k = 0; k < in.nodes / 4; ++k)
        in.arcs.push_back({static_cast<int>(random.below(static_cast<std::uint64_t>(in.nodes))), static_cast<int>(random.below(static_cast<std::uint64_t>(in.nodes))), capacity(), 0});
    in.supply.assign(static_cast<std::size_t>(in.nodes), 0);
    for (int k = 0; k < in.nodes / 2; ++k) {
        const auto amount = static_cast<std::int64_t>(1 + random.below(5));
        in.supply[random.below(static_cast<std::uint64_t>(in.nodes))] += amount;
        in.supply[random.below(static_cast<std::uint64_t>(in.nodes))] -= amount;
    }
    return in;
}

/// LEMON's answer: the least cost, or -1 when no flow meets the supplies.
std::int64_t lemonCost(const Instance& in) {
    lemon::SmartDigraph g;
    std::vector<lemon::SmartDigraph::Node> node;
    for (int v = 0; v < in.nodes; ++v) node.push_back(g.addNode());
    lemon::SmartDigraph::ArcMap<std::int64_t> cost(g), capacity(g);
    lemon::SmartDigraph::NodeMap<std::int64_t> supply(g);
    for (int v = 0; v < in.nodes; ++v) supply[node[static_cast<std::size_t>(v)]] = in.supply[static_cast<std::size_t>(v)];
    for (const auto& a : in.arcs) {
        const auto arc = g.addArc(node[static_cast<std::size_t>(a.from)], node[static_cast<std::size_t>(a.to)]);
        cost[arc] = a.cost, capacity[arc] = a.capacity;
    }
    lemon::NetworkSimplex<lemon::SmartDigraph, std::int64_t, std::int64_t> simplex(g);
    simplex.costMap(cost).upperMap(capacity).supplyMap(supply);  // the supplies sum to zero: its default (GEQ) is equality
    return simplex.run() == simplex.OPTIMAL ? simplex.totalCost() : -1;
}

}  // namespace

TEST_CASE("min-cost flow: the least cost LEMON's network simplex finds, with a flow that meets every supply") {
    planner::Random random(20261128);
    int solved = 0, infeasible = 0;
    for (int round = 0; round < 400; ++round) {
        const Instance in = randomInstance(random);
        planner::MinCostFlow flow;
        for (int v = 0; v < in.nodes; ++v) flow.addNode(), flow.addSupply(v, in.supply[static_cast<std::size_t>(v)]);
        for (const auto& a : in.arcs) flow.addArc(a.from, a.to, a.capacity, a.cost);
        const std::optional<std::int64_t> cost = flow.solve();
        const std::int64_t expected = lemonCost(in);
        CAPTURE(round);
        REQUIRE(cost.value_or(-1) == expected);
        if (!cost) {
            ++infeasible;
            continue;
        }
        ++solved;
        // The flow the cost comes from: within capacities, conserving, meeting the supplies.
        std::vector<std::int64_t> out(static_cast<std::size_t>(in.nodes), 0);
        std::int64_t paid = 0;
        for (std::size_t k = 0; k < in.arcs.size(); ++k) {
            const std::int64_t f = flow.flow(static_cast<int>(k));
            REQUIRE(f >= 0);
            REQUIRE(f <= in.arcs[k].capacity);
            out[static_cast<std::size_t>(in.arcs[k].from)] += f, out[static_cast<std::size_t>(in.arcs[k].to)] -= f;
            paid += f * in.arcs[k].cost;
        }
        CHECK(out == in.supply);
        CHECK(paid == *cost);
    }
    // Both outcomes are exercised.
    CHECK(solved > 100);
    CHECK(infeasible > 10);
}

}  // namespace holon::test
