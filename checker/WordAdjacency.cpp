// Region adjacency on words (see WordAdjacency.h).

#include "checker/WordAdjacency.h"

#include "rules/Components.h"

#include <algorithm>

namespace holon::checker {

WordAdjacency::WordAdjacency(const rules::Region& region) {
    const rules::Lattice& lattice = region.lattice();
    neighbourBits_.assign(region.size(), 0);
    for (int i = 0; i < region.size(); ++i)
        for (int d = 0; d < lattice.degree(); ++d)
            if (int j = region.neighbour(i, d); j >= 0) {
                neighbourBits_[i] |= std::uint64_t{1} << j;
                const auto left = static_cast<std::uint8_t>(std::max(0, j - i)), right = static_cast<std::uint8_t>(std::max(0, i - j));
                auto it = std::find_if(shifts_.begin(), shifts_.end(), [&](const Shift& s) { return s.left == left && s.right == right; });
                if (it == shifts_.end()) it = shifts_.insert(shifts_.end(), {0, left, right});
                it->from |= std::uint64_t{1} << i;
            }
    // An irregular region needs many shifts; then the cell-by-cell walk is cheaper.
    if (static_cast<int>(shifts_.size()) > 2 * lattice.degree()) shifts_.clear();
}

std::uint64_t WordAdjacency::cutCells(std::uint64_t set) const {
    if (!set) return 0;
    // Iterative depth-first search: a cell's low point is the earliest discovery time among its
    // neighbours (other than its parent) and its children's low points; a cell other than the
    // root is a cut cell when some child's low point is not earlier than its own discovery, the
    // root when it has two children.
    std::uint8_t discovered[64], low[64], parent[64], stack[64];
    std::uint64_t visited = 0, cut = 0;
    int top = 0, time = 0, rootChildren = 0;
    const int root = std::countr_zero(set);
    auto open = [&](int v, int from) {
        visited |= std::uint64_t{1} << v;
        discovered[v] = low[v] = static_cast<std::uint8_t>(time++);
        parent[v] = static_cast<std::uint8_t>(from);
        stack[top++] = static_cast<std::uint8_t>(v);
    };
    open(root, root);
    while (top) {
        const int v = stack[top - 1];
        if (const std::uint64_t next = neighbourBits_[v] & set & ~visited) {
            open(std::countr_zero(next), v);
            rootChildren += v == root;
            continue;
        }
        --top;
        const int p = parent[v];
        for (std::uint64_t n = neighbourBits_[v] & set & ~(std::uint64_t{1} << p); n; n &= n - 1)
            low[v] = std::min(low[v], discovered[std::countr_zero(n)]);
        if (v == root) break;
        low[p] = std::min(low[p], low[v]);
        if (p != root && low[v] >= discovered[p]) cut |= std::uint64_t{1} << p;
    }
    if (rootChildren >= 2) cut |= std::uint64_t{1} << root;
    return cut;
}

bool WordAdjacency::connected(std::uint64_t m) const {
    // By shifts, a cell with no neighbour in m fails at once.
    if (!shifts_.empty() && (m & (m - 1)) && (m & ~neighboursOf(m))) return false;
    return rules::connectedWord(m, [this](std::uint64_t r) { return around(r); });
}

bool WordAdjacency::targetsJoined(std::uint64_t now, std::uint64_t targets) const {
    // Every component of `now` holds a target, so `now` is connected exactly when one target
    // reaches all the others, and a flood from one of them can stop as soon as it has.
    // Two floods, from the lowest and the highest target, a layer each in turn: a part cut off is
    // usually small, and its flood dies out after a few layers; otherwise they meet, and the
    // merged flood goes on until it holds every target.
    std::uint64_t a = targets & (~targets + 1), b = std::uint64_t{1} << (63 - std::countl_zero(targets));
    std::uint64_t frontA = a, frontB = b;
    while (!(a & b)) {
        frontA = around(frontA) & now & ~a;
        if (!frontA) return false;
        a |= frontA;
        if (a & b) break;
        frontB = around(frontB) & now & ~b;
        if (!frontB) return false;
        b |= frontB;
    }
    std::uint64_t reached = a | b, frontier = frontA | frontB;
    while (frontier && (targets & ~reached)) {
        frontier = around(frontier) & now & ~reached;
        reached |= frontier;
    }
    return !(targets & ~reached);
}

}  // namespace holon::checker
