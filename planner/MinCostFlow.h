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
    /// The largest arc cost. Dial's buckets hold one list per distance under reduced costs, and
    /// those grow with the costs: the solver is for small ones (the transport bound's are 0 and 1).
    static constexpr std::int64_t kMaxCost = std::int64_t{1} << 16;

    int addNode();
    /// Returns the arc's index, for flow(); 0 <= `cost` <= kMaxCost.
    int addArc(int from, int to, std::int64_t capacity, std::int64_t cost);
    /// Positive: the node sends this much; negative: it takes this much. Supplies must sum to zero.
    void addSupply(int node, std::int64_t amount);

    /// The least total cost of a flow that meets every supply, or nullopt when none exists. Once
    /// only: the arcs as given are released (the transport bound at 10^6 metamodules has tens of
    /// millions), and flow() reads the solution.
    std::optional<std::int64_t> solve();
    /// The flow on an arc in the solution (after solve() only): what its reverse half may carry back.
    std::int64_t flow(int arc) const { return residual_[partner_[slot_[static_cast<std::size_t>(arc)]]]; }

private:
    void buildResidual();
    std::int64_t reduced(std::uint32_t place, int from) const { return placeCost_[place] + potential_[from] - potential_[to_[place]]; }
    bool shortestPaths(int s, int t);
    bool levels(int s, int t);
    std::int64_t augment(int s, int t);

    bool solved_ = false;
    std::vector<std::int64_t> supply_;
    // The arcs as given, until solve() builds the residual graph from them.
    std::vector<int> tail_, head_, cost_;
    std::vector<std::int64_t> capacity_;
    // The residual graph in adjacency order: places first_[v] .. first_[v + 1] are v's half-arcs
    // (an arc forwards, or an arc's reverse: from head to tail, cost negated, with the arc's flow
    // as capacity); slot_[k] is arc k's forward place, partner_ a place's reverse. 44 bytes per
    // arc.
    std::vector<std::uint32_t> first_, slot_, partner_, current_, path_;
    std::vector<int> to_, placeCost_;
    std::vector<std::int64_t> residual_, potential_, distance_;
    std::vector<int> level_, queue_;
    std::vector<std::vector<int>> buckets_;
};

}  // namespace holon::planner
