#pragma once
// An exact min-cost flow for graphs whose arc costs are small non-negative integers: the primal-
// dual method (see MinCostFlow.cpp). The transport bound's lattice graphs (Transport.cpp) have
// millions of arcs of cost 0 or 1, where a general network simplex pivots for minutes.

#include <cstdint>
#include <optional>
#include <vector>

namespace holon::planner {

class MinCostFlow {
public:
    /// An arc's capacity when it has none worth stating.
    static constexpr std::int64_t kUnlimited = std::int64_t{1} << 40;

    int addNode();
    /// Returns the arc's index, for flow(); `cost` >= 0.
    int addArc(int from, int to, std::int64_t capacity, std::int64_t cost);
    /// Positive: the node sends this much; negative: it takes this much. Supplies must sum to zero.
    void addSupply(int node, std::int64_t amount);

    /// The least total cost of a flow that meets every supply, or nullopt when none exists.
    std::optional<std::int64_t> solve();
    /// The flow on an arc in the last solution.
    std::int64_t flow(int arc) const { return capacity_[static_cast<std::size_t>(arc)] - residual_[slot_[static_cast<std::size_t>(arc)]]; }

private:
    void buildResidual();
    std::int64_t reduced(std::size_t place, int from) const { return placeCost_[place] + potential_[from] - potential_[to_[place]]; }
    bool shortestPaths(int s, int t);
    bool levels(int s, int t);
    std::int64_t augment(int s, int t);

    std::vector<std::int64_t> supply_;
    std::vector<int> tail_, head_;
    std::vector<std::int64_t> capacity_, cost_;
    // The residual graph in adjacency order: places first_[v] .. first_[v + 1] are v's half-arcs
    // (an arc forwards, or an arc's reverse: from head to tail, cost negated, with the arc's flow
    // as capacity); slot_[k] is arc k's forward place, partner_ a place's reverse.
    std::vector<std::size_t> first_, slot_, partner_, current_;
    std::vector<int> to_;
    std::vector<std::int64_t> residual_, placeCost_, potential_, distance_;
    std::vector<int> level_, queue_;
    std::vector<std::vector<int>> buckets_;
    std::vector<std::size_t> path_;
};

}  // namespace holon::planner
