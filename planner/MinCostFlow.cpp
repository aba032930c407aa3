// Exact min-cost flow by the primal-dual method (Ahuja, Magnanti and Orlin, "Network Flows",
// §9.8): node potentials keep every residual arc's reduced cost non-negative; each phase finds the
// shortest distances from the supplies under reduced costs (Dial's bucket queue: costs are small
// integers) and raises the potentials by them, so that the cheapest augmenting paths are exactly
// the paths of zero reduced cost; a maximum flow along those (Dinic's blocking flows) ends the
// phase. The cheapest path's cost rises every phase, so there are at most as many phases as the
// costliest augmenting path costs: a few hundred on the transport bound's lattices, each linear in
// the arcs. LEMON's network simplex, used before, took 18 s on box:200x200 -> box:100x400 (10^5
// nodes; this 4.4 s) and 2 minutes on the block at K = 16 (3.7 * 10^5 nodes; this 7.6 s): it grows
// about as the square of the nodes (docs/scale.md).

#include "planner/MinCostFlow.h"

#include "rules/Error.h"

#include <algorithm>
#include <limits>
#include <string>

namespace holon::planner {

namespace {
constexpr std::int64_t kFar = std::numeric_limits<std::int64_t>::max();
}  // namespace

int MinCostFlow::addNode() {
    supply_.push_back(0);
    return static_cast<int>(supply_.size()) - 1;
}

int MinCostFlow::addArc(int from, int to, std::int64_t capacity, std::int64_t cost) {
    if (solved_) throw InternalError("min-cost flow: an arc added after the solve");
    if (cost < 0 || cost > kMaxCost) throw InternalError("min-cost flow: arc cost " + std::to_string(cost) + " outside 0 .. " + std::to_string(kMaxCost));
    tail_.push_back(from), head_.push_back(to), capacity_.push_back(capacity), cost_.push_back(static_cast<int>(cost));
    return static_cast<int>(tail_.size()) - 1;
}

void MinCostFlow::addSupply(int node, std::int64_t amount) { supply_[static_cast<std::size_t>(node)] += amount; }

void MinCostFlow::buildResidual() {
    const std::size_t nodes = supply_.size(), arcs = tail_.size();
    if (2 * arcs >= std::numeric_limits<std::uint32_t>::max()) throw InternalError("min-cost flow: " + std::to_string(arcs) + " arcs; at most 2^31 fit");
    first_.assign(nodes + 1, 0);
    for (std::size_t k = 0; k < arcs; ++k) ++first_[static_cast<std::size_t>(tail_[k]) + 1], ++first_[static_cast<std::size_t>(head_[k]) + 1];
    for (std::size_t v = 0; v < nodes; ++v) first_[v + 1] += first_[v];
    std::vector<std::uint32_t> fill(first_.begin(), first_.end() - 1);
    to_.assign(2 * arcs, 0), partner_.assign(2 * arcs, 0), residual_.assign(2 * arcs, 0), placeCost_.assign(2 * arcs, 0), slot_.assign(arcs, 0);
    for (std::size_t k = 0; k < arcs; ++k) {
        const std::uint32_t f = fill[static_cast<std::size_t>(tail_[k])]++, r = fill[static_cast<std::size_t>(head_[k])]++;
        to_[f] = head_[k], to_[r] = tail_[k];
        partner_[f] = r, partner_[r] = f;
        residual_[f] = capacity_[k];
        placeCost_[f] = cost_[k], placeCost_[r] = -cost_[k];
        slot_[k] = f;
    }
    // The arcs as given are in the residual graph now.
    for (auto* v : {&tail_, &head_, &cost_}) std::vector<int>().swap(*v);
    std::vector<std::int64_t>().swap(capacity_);
}

std::optional<std::int64_t> MinCostFlow::solve() {
    if (solved_) throw InternalError("min-cost flow: solved twice (its arcs are gone after the first solve)");
    // A source before every supply and a sink after every demand.
    std::int64_t total = 0, balance = 0;
    const std::size_t nodes = supply_.size(), given = tail_.size();
    const int s = addNode(), t = addNode();
    for (std::size_t v = 0; v < nodes; ++v) {
        const std::int64_t amount = supply_[v];
        balance += amount;
        if (amount > 0) addArc(s, static_cast<int>(v), amount, 0), total += amount;
        if (amount < 0) addArc(static_cast<int>(v), t, -amount, 0);
    }
    solved_ = true;
    buildResidual();
    potential_.assign(supply_.size(), 0);
    std::int64_t sent = 0;
    if (balance == 0)
        while (sent < total && shortestPaths(s, t))
            while (levels(s, t)) sent += augment(s, t);
    if (balance != 0 || sent < total) return std::nullopt;
    std::int64_t cost = 0;
    for (std::size_t k = 0; k < given; ++k) cost += flow(static_cast<int>(k)) * placeCost_[slot_[k]];
    return cost;
}

bool MinCostFlow::shortestPaths(int s, int t) {
    // Dial's algorithm under reduced costs, stopped once t is settled: a node not settled by then
    // is at least as far as t, and raising its potential by t's distance keeps every reduced cost
    // non-negative (a node's potential never rises by more than t's distance).
    distance_.assign(supply_.size(), kFar);
    distance_[static_cast<std::size_t>(s)] = 0;
    if (buckets_.empty()) buckets_.resize(1);
    buckets_[0].push_back(s);
    std::size_t highest = 0;
    std::int64_t reach = kFar;  // t's distance, once settled
    for (std::size_t at = 0; at <= highest && reach == kFar; ++at) {
        for (std::size_t k = 0; k < buckets_[at].size() && reach == kFar; ++k) {
            const int v = buckets_[at][k];
            const auto d = static_cast<std::int64_t>(at);
            if (distance_[static_cast<std::size_t>(v)] != d) continue;  // queued again nearer
            if (v == t) {
                reach = d;
                break;
            }
            for (std::uint32_t p = first_[static_cast<std::size_t>(v)]; p < first_[static_cast<std::size_t>(v) + 1]; ++p) {
                if (residual_[p] == 0) continue;
                const std::int64_t nd = d + reduced(p, v);
                auto& best = distance_[static_cast<std::size_t>(to_[p])];
                if (nd >= best || nd >= distance_[static_cast<std::size_t>(t)]) continue;
                best = nd;
                const auto b = static_cast<std::size_t>(nd);
                if (b >= buckets_.size()) buckets_.resize(b + 1);
                buckets_[b].push_back(to_[p]);
                highest = std::max(highest, b);
            }
        }
    }
    for (std::size_t b = 0; b <= highest; ++b) buckets_[b].clear();
    if (reach == kFar) return false;
    for (std::size_t v = 0; v < potential_.size(); ++v) potential_[v] += std::min(distance_[v], reach);
    return true;
}

bool MinCostFlow::levels(int s, int t) {
    // Breadth-first levels over the residual arcs of zero reduced cost: Dinic's layered graph.
    level_.assign(supply_.size(), -1);
    std::vector<int>& queue = queue_;
    queue.push_back(s);
    level_[static_cast<std::size_t>(s)] = 0;
    const auto target = static_cast<std::size_t>(t);
    for (std::size_t k = 0; k < queue.size(); ++k) {
        const int v = queue[k];
        // Past t's layer no node lies on a shortest layered path to it.
        if (level_[target] >= 0 && level_[static_cast<std::size_t>(v)] >= level_[target]) break;
        for (std::uint32_t p = first_[static_cast<std::size_t>(v)]; p < first_[static_cast<std::size_t>(v) + 1]; ++p) {
            auto& l = level_[static_cast<std::size_t>(to_[p])];
            if (residual_[p] == 0 || l >= 0 || reduced(p, v) != 0) continue;
            l = level_[static_cast<std::size_t>(v)] + 1;
            queue.push_back(to_[p]);
        }
    }
    queue.clear();
    current_.assign(first_.begin(), first_.end() - 1);
    return level_[target] >= 0;
}

std::int64_t MinCostFlow::augment(int s, int t) {
    // A blocking flow in the layered graph, by depth-first search without recursion (paths run
    // for thousands of arcs); an arc once useless stays behind its node's current_ pointer and a
    // node that reaches no further leaves the layers.
    std::int64_t pushed = 0;
    path_.clear();
    int v = s;
    for (;;) {
        if (v == t) {
            std::int64_t f = kFar;
            for (std::uint32_t p : path_) f = std::min(f, residual_[p]);
            std::size_t cut = path_.size();
            for (std::size_t k = 0; k < path_.size(); ++k) {
                residual_[path_[k]] -= f, residual_[partner_[path_[k]]] += f;
                if (residual_[path_[k]] == 0 && cut == path_.size()) cut = k;
            }
            pushed += f;
            path_.resize(cut);
            v = cut == 0 ? s : to_[path_[cut - 1]];
            continue;
        }
        const auto u = static_cast<std::size_t>(v);
        std::uint32_t& p = current_[u];
        for (; p < first_[u + 1]; ++p) {
            const auto w = static_cast<std::size_t>(to_[p]);
            if (residual_[p] > 0 && level_[w] == level_[u] + 1 && reduced(p, v) == 0) break;
        }
        if (p < first_[u + 1]) {
            path_.push_back(p);
            v = to_[p];
            continue;
        }
        if (v == s) return pushed;
        level_[u] = -1;
        path_.pop_back();
        v = path_.empty() ? s : to_[path_.back()];
        ++current_[static_cast<std::size_t>(v)];
    }
}

}  // namespace holon::planner
