// BGL on the explored graph. The explorer keeps successor lists in compressed rows; here they are
// read into boost::compressed_sparse_row_graph and the library's algorithms do the rest
// (disjoint sets for weak components, strong_components, breadth_first_search with a predecessor
// recorder), as STYLE.md asks: run BGL's algorithms on the reconfiguration graph rather than
// writing our own.

#include "checker/Graph.h"

#include "rules/ConfigIo.h"
#include "rules/Error.h"

#include <algorithm>
#include <boost/graph/breadth_first_search.hpp>
#include <boost/graph/compressed_sparse_row_graph.hpp>
#include <boost/graph/strong_components.hpp>
#include <boost/pending/disjoint_sets.hpp>
#include <iterator>

namespace holon::checker {

namespace {

using Csr = boost::compressed_sparse_row_graph<boost::directedS, boost::no_property, boost::no_property, boost::no_property,
                                               std::uint32_t, std::uint64_t>;

/// The explorer's edges as (source, target) pairs in source order, for the CSR constructor that
/// takes sorted edges in one pass: the graph is built straight from the explorer's rows.
class RowEdges {
public:
    using iterator_category = std::input_iterator_tag;
    using value_type = std::pair<std::uint32_t, std::uint32_t>;
    using difference_type = std::ptrdiff_t;
    using pointer = const value_type*;
    using reference = const value_type&;
    RowEdges(const Explorer& ex, const std::vector<char>* keep, std::size_t source) : ex_(&ex), keep_(keep), source_(source) {
        e_ = source_ < rows() ? ex.rowStart()[source_] : 0;
        settle();
    }
    reference operator*() const { return current_; }
    pointer operator->() const { return &current_; }
    RowEdges& operator++() {
        ++e_;
        settle();
        return *this;
    }
    bool operator==(const RowEdges& o) const { return source_ == o.source_ && (source_ == rows() || e_ == o.e_); }

private:
    std::size_t rows() const { return ex_->rowStart().size() - 1; }
    void settle() {  // on the next kept edge, or at the end
        const auto& row = ex_->rowStart();
        while (source_ < rows()) {
            for (; e_ < row[source_ + 1]; ++e_)
                if (!keep_ || (*keep_)[e_]) {
                    current_ = {static_cast<std::uint32_t>(source_), ex_->successors()[e_]};
                    return;
                }
            ++source_;
        }
    }
    const Explorer* ex_;
    const std::vector<char>* keep_;
    std::size_t source_;
    std::uint64_t e_ = 0;
    value_type current_{};
};

Csr buildCsr(const Explorer& ex, const std::vector<char>* keep = nullptr) {
    if (!ex.hasEdges()) throw InternalError("the graph was explored without recording edges");
    const std::size_t n = ex.rowStart().size() - 1;
    const std::size_t edges = keep ? static_cast<std::size_t>(std::count(keep->begin(), keep->end(), 1)) : ex.successors().size();
    return Csr(boost::edges_are_sorted, RowEdges(ex, keep, 0), RowEdges(ex, keep, n), static_cast<Csr::vertices_size_type>(n),
               static_cast<Csr::edges_size_type>(edges));
}

/// The graph with every edge reversed: a counting sort by target.
Csr buildReversedCsr(const Explorer& ex) {
    if (!ex.hasEdges()) throw InternalError("the graph was explored without recording edges");
    const auto& row = ex.rowStart();
    const auto& succ = ex.successors();
    const std::size_t n = row.size() - 1;
    std::vector<std::uint64_t> start(n + 1, 0);
    for (StateId t : succ) ++start[t + 1];
    for (std::size_t v = 0; v < n; ++v) start[v + 1] += start[v];
    std::vector<std::pair<std::uint32_t, std::uint32_t>> edges(start[n]);
    std::vector<std::uint64_t> fill(start.begin(), start.end() - 1);
    for (std::size_t s = 0; s < n; ++s)
        for (std::uint64_t e = row[s]; e < row[s + 1]; ++e) edges[fill[succ[e]]++] = {succ[e], static_cast<std::uint32_t>(s)};
    return Csr(boost::edges_are_sorted, edges.begin(), edges.end(), static_cast<Csr::vertices_size_type>(n),
               static_cast<Csr::edges_size_type>(edges.size()));
}

}  // namespace

Components components(const Explorer& ex) {
    // Weak components by union-find over the edges (BGL's disjoint sets): no copy of the graph,
    // where a both-ways CSR for connected_components held every edge twice (pixel on 5x5: 78 M).
    if (!ex.hasEdges()) throw InternalError("the graph was explored without recording edges");
    const auto& row = ex.rowStart();
    const auto& succ = ex.successors();
    const std::size_t n = row.size() - 1;
    std::vector<std::uint32_t> rank(n), parent(n);
    const boost::typed_identity_property_map<std::uint32_t> index;
    auto rankOf = boost::make_iterator_property_map(rank.begin(), index);
    auto parentOf = boost::make_iterator_property_map(parent.begin(), index);
    boost::disjoint_sets<decltype(rankOf), decltype(parentOf)> sets(rankOf, parentOf);
    for (std::size_t v = 0; v < n; ++v) sets.make_set(static_cast<std::uint32_t>(v));
    for (std::size_t s = 0; s < n; ++s)
        for (std::uint64_t e = row[s]; e < row[s + 1]; ++e) sets.union_set(static_cast<std::uint32_t>(s), succ[e]);
    Components c;
    c.of.assign(n, -1);
    // Numbered in order of their first state; holes are -1 and the count covers real states only.
    std::vector<int> number(n, -1);
    for (std::size_t v = 0; v < n; ++v) {
        if (ex.store().isHole(static_cast<StateId>(v))) continue;
        int& k = number[sets.find_set(static_cast<std::uint32_t>(v))];
        if (k < 0) k = c.count++;
        c.of[v] = k;
    }
    return c;
}

Components strongComponents(const Explorer& ex, const std::vector<char>& keepEdge) {
    Csr g = buildCsr(ex, &keepEdge);
    Components c;
    c.of.assign(num_vertices(g), -1);
    c.count = static_cast<int>(boost::strong_components(g, boost::make_iterator_property_map(c.of.begin(), get(boost::vertex_index, g))));
    return c;
}

std::vector<char> canReach(const Explorer& ex, const std::vector<StateId>& targets) {
    // Breadth-first from all targets at once on the reversed graph: what it discovers can reach one.
    Csr g = buildReversedCsr(ex);
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

GraphView::GraphView(const Explorer& ex, const std::vector<char>* keepEdge) : impl_(new Impl{buildCsr(ex, keepEdge)}) {}
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
        for (char ch : label) escaped += ch == '\n' ? std::string("\\l") : ch == '"' ? std::string("\\\"")
                                                                                     : std::string(1, ch);
        out << "  s" << s << " [label=\"" << escaped << "\"" << (ex.isInitial(s) ? ", penwidth=2" : "") << "];\n";
    }
    for (std::size_t s = 0; s + 1 < row.size(); ++s)
        for (std::uint64_t e = row[s]; e < row[s + 1]; ++e)
            out << "  s" << s << " -> s" << succ[e] << " [label=\""
                << model.rules()[ex.engine().instances()[via[e]].rule].name << "\"];\n";
    out << "}\n";
}

}  // namespace holon::checker
