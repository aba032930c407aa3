#pragma once
// The explored reconfiguration graph handed to the Boost Graph Library: components, shortest
// paths and Graphviz output run as BGL algorithms on a compressed-sparse-row copy of the edges.

#include "checker/Explorer.h"

#include <memory>
#include <ostream>
#include <vector>

namespace holon::checker {

struct Components {
    std::vector<int> of;  // per state id; -1 for holes
    int count = 0;
};

/// Connected components of the graph with edge directions ignored (weak components).
Components components(const Explorer& explorer);
/// Strong components (for cycles: a livelock lives inside one).
Components strongComponents(const Explorer& explorer, const std::vector<char>& keepEdge);
/// Per state: some path of steps leads from it to one of `targets`.
std::vector<char> canReach(const Explorer& explorer, const std::vector<StateId>& targets);
/// The explored graph as a BGL compressed-sparse-row graph, built once for many queries.
class GraphView {
public:
    /// The whole graph, or only the edges `keepEdge` marks.
    explicit GraphView(const Explorer& explorer, const std::vector<char>* keepEdge = nullptr);
    ~GraphView();
    /// Breadth-first distances (in steps) from a state; -1 where unreachable.
    std::vector<int> distancesFrom(StateId from) const;
    /// A shortest path of states from `from` to `to`, empty when `to` is unreachable.
    std::vector<StateId> shortestPath(StateId from, StateId to) const;

private:
    struct Impl;
    std::unique_ptr<Impl> impl_;
};
/// Whether every edge has its reverse (all rules undo each other), so reachability is symmetric.
bool symmetric(const Explorer& explorer);
/// Graphviz: states as nodes labelled with their ASCII picture where there is one.
void writeDot(const Explorer& explorer, const rules::Interpreter& in, std::ostream& out);

}  // namespace holon::checker
