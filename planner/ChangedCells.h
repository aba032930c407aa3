#pragma once
// How the allocators and the deletion order find the cells a round changed: a copy of the cells
// as of their previous update, compared a cache line at a time. A pass over every cell's
// neighbourhood each round made 10^6 metamodules take hours; this pass reads 64 unchanged cells
// as eight 8-byte words from each copy and one branch.

#include "planner/BoxEngine.h"

#include <cstdint>
#include <cstring>
#include <vector>

namespace holon::planner {

/// Calls visit(x, seen[x]) for every cell x whose value differs from seen[x], then sets seen[x].
template <class Visit>
void forEachChangedCell(const std::vector<BoxEngine::Value>& cells, std::vector<BoxEngine::Value>& seen, Visit&& visit) {
    static_assert(sizeof(BoxEngine::Value) == 1);
    const std::size_t n = cells.size();
    auto visitRange = [&](std::size_t from, std::size_t to) {
        for (std::size_t x = from; x < to; ++x)
            if (cells[x] != seen[x]) {
                visit(static_cast<std::int64_t>(x), seen[x]);
                seen[x] = cells[x];
            }
    };
    constexpr std::size_t kLine = 64;
    std::size_t w = 0;
    for (; w + kLine <= n; w += kLine) {
        std::uint64_t differ = 0;
        for (std::size_t k = 0; k < kLine; k += 8) {
            std::uint64_t a, b;
            std::memcpy(&a, cells.data() + w + k, 8), std::memcpy(&b, seen.data() + w + k, 8);
            differ |= a ^ b;
        }
        if (differ) visitRange(w, w + kLine);
    }
    visitRange(w, n);
}

}  // namespace holon::planner
