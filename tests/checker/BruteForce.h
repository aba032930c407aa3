#pragma once
// An independent oracle for pixel with connectivity: enumerate every subset of a region's cells,
// flood-fill it, and count legal configurations, directed edges and components with union-find.
// It shares nothing with the explorer but the Region's neighbour table.

#include "rules/Region.h"

#include <cstdint>
#include <numeric>
#include <vector>

namespace holon::test {

struct PixelCounts {
    std::uint64_t legal = 0, edges = 0, components = 0;
};

inline bool connectedSubset(const rules::Region& r, std::uint32_t set) {
    if (!set) return false;  // pixel requires at least one metamodule
    std::uint32_t seen = set & (~set + 1), grown = 0;
    while (grown != seen) {
        grown = seen;
        for (int i = 0; i < r.size(); ++i)
            if ((seen >> i) & 1u)
                for (int d = 0; d < r.lattice().degree(); ++d)
                    if (int j = r.neighbour(i, d); j >= 0 && ((set >> j) & 1u)) seen |= 1u << j;
    }
    return seen == set;
}

inline PixelCounts pixelBruteForce(const rules::Region& r) {
    const std::uint32_t all = 1u << r.size();
    std::vector<char> legal(all);
    for (std::uint32_t s = 0; s < all; ++s) legal[s] = connectedSubset(r, s);
    std::vector<std::uint32_t> root(all);
    std::iota(root.begin(), root.end(), 0u);
    auto find = [&](std::uint32_t x) {
        while (root[x] != x) x = root[x] = root[root[x]];
        return x;
    };
    PixelCounts c;
    for (std::uint32_t s = 0; s < all; ++s) {
        if (!legal[s]) continue;
        ++c.legal;
        for (int i = 0; i < r.size(); ++i) {
            const std::uint32_t t = s ^ (1u << i);
            if (legal[t]) ++c.edges, root[find(s)] = find(t);
        }
    }
    for (std::uint32_t s = 0; s < all; ++s) c.components += legal[s] && find(s) == s;
    return c;
}

}  // namespace holon::test
