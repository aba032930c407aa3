// BGL on the explored graph. The explorer keeps successor lists in compressed rows; here they are
// copied into boost::compressed_sparse_row_graph and the library's algorithms do the rest
// (connected_components, strong_components, breadth_first_search with a predecessor recorder), as
// STYLE.md asks: run BGL's algorithms on the reconfiguration graph rather than writing our own.

#include "checker/Graph.h"

#include "rules/ConfigIo.h"
#include "rules/Error.h"

#include <algorithm>
#include <boost/graph/breadth_first_search.hpp>
#include <boost/graph/compressed_sparse_row_graph.hpp>
#include <boost/graph/connected_components.hpp>
#include <boost/graph/strong_components.hpp>

namespace holon::checker {

namespace {

using Csr = boost::compressed_sparse_row_graph<boost::directedS, boost::no_property, boost::no_property, boost::no_property,
                                               std::uint32_t, std::uint64_t>;

Csr buildCsr(const Explorer& ex, bool bothWays, const std::vector<char>* keep = nullptr, bool reversed = false) {
    if (!ex.hasEdges()) throw InputError("internal: the graph was explored without recording edges");
    const auto& row = ex.rowStart();
    const auto& succ = ex.successors();
    const std::size_t n = row.size() - 1;
    // Edges sorted by (source, target) without a comparison sort over all of them: a counting
    // sort by source, then each row sorted on its own (rows are short and sort in cache).
    auto forEach = [&](auto&& f) {
        for (std::size_t s = 0; s < n; ++s)
            for (std::uint64_t e = row[s]; e < row[s + 1]; ++e) {
                if (keep && !(*keep)[e]) continue;
                const auto from = static_cast<std::uint32_t>(s), to = succ[e];
                if (reversed) f(to, from);
                else f(from, to);
                if (bothWays) f(to, from);
            }
    };
    std::vector<std::uint64_t> start(n + 1, 0);
    forEach([&](std::uint32_t from, std::uint32_t) { ++start[from + 1]; });
    for (std::size_t v = 0; v < n; ++v) start[v + 1] += start[v];
    std::vector<std::pair<std::uint32_t, std::uint32_t>> edges(start[n]);
    std::vector<std::uint64_t> fill(start.begin(), start.end() - 1);
    forEach([&](std::uint32_t from, std::uint32_t to) { edges[fill[from]++] = {from, to}; });
    for (std::size_t v = 0; v < n; ++v) std::sort(edges.begin() + static_cast<std::ptrdiff_t>(start[v]), edges.begin() + static_cast<std::ptrdiff_t>(start[v + 1]));
    return Csr(boost::edges_are_sorted, edges.begin(), edges.end(), n);
}

}  // namespace

Components components(const Explorer& ex) {
    // A symmetric directed CSR graph is a valid undirected graph for connected_components.
    Csr g = buildCsr(ex, true);
    Components c;
    c.of.assign(num_vertices(g), -1);
    boost::connected_components(g, boost::make_iterator_property_map(c.of.begin(), get(boost::vertex_index, g)));
    // Relabel so holes are -1 and the count covers real states only.
    std::vector<int> relabel(c.of.size(), -1);
    for (std::size_t v = 0; v < c.of.size(); ++v) {
        if (ex.store().isHole(static_cast<StateId>(v))) {
            c.of[v] = -1;
            continue;
        }
        int& r = relabel[c.of[v]];
        if (r < 0) r = c.count++;
        c.of[v] = r;
    }
    return c;
}

Components strongComponents(const Explorer& ex, const std::vector<char>& keepEdge) {
    Csr g = buildCsr(ex, false, &keepEdge);
    Components c;
    c.of.assign(num_vertices(g), -1);
    c.count = static_cast<int>(boost::strong_components(g, boost::make_iterator_property_map(c.of.begin(), get(boost::vertex_index, g))));
    return c;
}

std::vector<char> canReach(const Explorer& ex, const std::vector<StateId>& targets) {
    // Breadth-first from all targets at once on the reversed graph: what it discovers can reach one.
    Csr g = buildCsr(ex, false, nullptr, true);
    std::vector<char> reach(num_vertices(g), 0);
    if (targets.empty()) return reach;
    struct Mark : boost::default_bfs_visitor {
        std::vector<char>* reach;
        void discover_vertex(std::uint32_t v, const Csr&) const { (*reach)[v] = 1; }
    } mark;
    mark.reach = &reach;
    boost::queue<std::uint32_t> queue;
    std::vector<boost::default_color_type> color(num_vertices(g), boost::white_color);
    boost::breadth_first_search(g, targets.begin(), targets.end(), queue, mark,
                                boost::make_iterator_property_map(color.begin(), get(boost::vertex_index, g)));
    return reach;
}

struct GraphView::Impl {
    Csr graph;
};

GraphView::GraphView(const Explorer& ex) : impl_(new Impl{buildCsr(ex, false)}) {}
GraphView::~GraphView() = default;

std::vector<int> GraphView::distancesFrom(StateId from) const {
    const Csr& g = impl_->graph;
    std::vector<int> dist(num_vertices(g), -1);
    dist[from] = 0;
    boost::breadth_first_search(
        g, from,
        boost::visitor(boost::make_bfs_visitor(boost::record_distances(
            boost::make_iterator_property_map(dist.begin(), get(boost::vertex_index, g)), boost::on_tree_edge()))));
    return dist;
}

std::vector<StateId> GraphView::shortestPath(StateId from, StateId to) const {
    const Csr& g = impl_->graph;
    std::vector<std::uint32_t> pred(num_vertices(g), kNoState);
    pred[from] = from;
    boost::breadth_first_search(
        g, from,
        boost::visitor(boost::make_bfs_visitor(boost::record_predecessors(
            boost::make_iterator_property_map(pred.begin(), get(boost::vertex_index, g)), boost::on_tree_edge()))));
    if (pred[to] == kNoState) return {};
    std::vector<StateId> path{to};
    while (path.back() != from) path.push_back(pred[path.back()]);
    std::reverse(path.begin(), path.end());
    return path;
}

bool symmetric(const Explorer& ex) {
    const auto& row = ex.rowStart();
    const auto& succ = ex.successors();
    for (std::size_t s = 0; s + 1 < row.size(); ++s)
        for (std::uint64_t e = row[s]; e < row[s + 1]; ++e) {
            const StateId t = succ[e];
            if (std::find(succ.begin() + row[t], succ.begin() + row[t + 1], static_cast<StateId>(s)) == succ.begin() + row[t + 1])
                return false;
        }
    return true;
}

void writeDot(const Explorer& ex, const rules::Interpreter& in, std::ostream& out) {
    const auto& row = ex.rowStart();
    const auto& succ = ex.successors();
    const auto& via = ex.successorVia();
    const rules::Model& model = ex.engine().model();
    out << "digraph reconfiguration {\n  node [shape=box, fontname=\"monospace\"];\n";
    rules::Configuration c = in.empty();
    c.inputs = ex.engine().inputs();
    for (StateId s : ex.ids()) {
        c.cells = ex.cells(s);
        std::string label;
        try {
            label = rules::configToAscii(in, c);
        } catch (const InputError&) {
            label = "state " + std::to_string(s);
        }
        std::string escaped;
        for (char ch : label) escaped += ch == '\n' ? std::string("\\l") : ch == '"' ? std::string("\\\"") : std::string(1, ch);
        out << "  s" << s << " [label=\"" << escaped << "\"" << (ex.isInitial(s) ? ", penwidth=2" : "") << "];\n";
    }
    for (std::size_t s = 0; s + 1 < row.size(); ++s)
        for (std::uint64_t e = row[s]; e < row[s + 1]; ++e)
            out << "  s" << s << " -> s" << succ[e] << " [label=\""
                << model.rules()[ex.engine().instances()[via[e]].rule].name << "\"];\n";
    out << "}\n";
}

}  // namespace holon::checker
