#pragma once
// Token transport for general_n plans: how many resource transfers at least remain from a
// configuration to the target, and along which lattice arcs (see Transport.cpp).

#include "planner/Problem.h"

#include <optional>
#include <unordered_map>

namespace holon::planner {

struct TransportPlan {
    std::int64_t cost = 0;  // the least number of transfers still needed
    /// Tokens to move out of board cell i towards direction d, keyed i * degree + d; zero flows omitted.
    std::unordered_map<std::int64_t, std::int32_t> flow;
};

/// Solves the transport from `cells` (a configuration on the problem's board) to the target;
/// nullopt when the system has no transfers or the instance has no solution. Without `withFlow`
/// only the cost (at 10^6 metamodules the flow has millions of arcs).
std::optional<TransportPlan> planTransport(const Problem& problem, const std::vector<BoxEngine::Value>& cells, bool withFlow = true);

}  // namespace holon::planner
