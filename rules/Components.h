#pragma once
// Connected sets of cells, one search for every grid holon has: the square, cubic and hex
// lattices of rules::Region, the padded boards of the planner and of the hex sculptor, a word of
// at most 64 cells, the directions around a cell. A grid is seen as an implicit graph (as BGL's
// implicit-graph example does): vertices are indices 0..n-1, and an adapter `edges(v, step)`
// calls step(w) for each neighbour w of v that belongs to the set searched. regionEdges and
// offsetEdges are the two adapters every grid here reduces to. Word-sized sets have their own
// form, a layer at a time over a word (`around(set)`: the cells next to a set): the explorer's
// connectivity test, which runs once per successor, stays a handful of shifts.

#include "rules/Region.h"

#include <algorithm>
#include <bit>
#include <cstdint>
#include <type_traits>
#include <vector>

namespace holon::rules {

/// A breadth-first search, reusable: the marks of a finished search are forgotten by moving on to
/// a new stamp, so a search costs what it visits, not the size of the board. Breadth first, so
/// that a search which stops once it has found what it looks for stays near where it started.
class Flood {
public:
    /// A fresh search over vertices 0..n-1 with nothing seen.
    void begin(std::size_t n) {
        if (seen_.size() < n) seen_.assign(n, 0), stamp_ = 0;
        if (++stamp_ == 0) std::fill(seen_.begin(), seen_.end(), 0), stamp_ = 1;
        queue_.clear(), head_ = 0;
    }
    bool seen(std::int64_t v) const { return seen_[static_cast<std::size_t>(v)] == stamp_; }
    /// Marks v seen and queues it; false when it was seen already.
    bool add(std::int64_t v) {
        if (seen(v)) return false;
        seen_[static_cast<std::size_t>(v)] = stamp_, queue_.push_back(v);
        return true;
    }
    /// Visits each vertex reachable from the ones added, once, in order of distance: visit(v), and
    /// if visit returns a bool, false stops the search. The number visited.
    template <class Edges, class Visit>
    std::int64_t spread(Edges&& edges, Visit&& visit) {
        const std::size_t first = head_;
        const auto step = [this](std::int64_t w) { add(w); };
        while (head_ < queue_.size()) {
            const std::int64_t v = queue_[head_++];
            if constexpr (std::is_same_v<decltype(visit(v)), bool>) {
                if (!visit(v)) break;
            } else {
                visit(v);
            }
            edges(v, step);
        }
        return static_cast<std::int64_t>(head_ - first);
    }
    template <class Edges>
    std::int64_t spread(Edges&& edges) {
        return spread(edges, [](std::int64_t) {});
    }

private:
    std::vector<std::int64_t> queue_;
    std::size_t head_ = 0;
    std::vector<std::uint32_t> seen_;
    std::uint32_t stamp_ = 0;
};

/// Whether the members form one connected set (the empty set does): members(f) calls f(v) for
/// each member, edges(v, step) steps to v's member neighbours; vertices are below n.
template <class Members, class Edges>
bool connected(Flood& flood, std::size_t n, Members&& members, Edges&& edges) {
    std::int64_t total = 0, start = -1;
    members([&](std::int64_t v) {
        if (start < 0) start = v;
        ++total;
    });
    if (total == 0) return true;
    flood.begin(n);
    flood.add(start);
    return flood.spread(edges) == total;
}

/// The connected parts of the members: visit(v, k) for every member v, k its part, the parts
/// numbered 0, 1, ... in the order `members` lists their first vertex. Returns how many.
template <class Members, class Edges, class Visit>
int components(Flood& flood, std::size_t n, Members&& members, Edges&& edges, Visit&& visit) {
    flood.begin(n);
    int count = 0;
    members([&](std::int64_t v) {
        if (!flood.add(v)) return;
        flood.spread(edges, [&](std::int64_t w) { visit(w, count); });
        ++count;
    });
    return count;
}

/// The `members` of the vertices 0..n-1 that member(v) accepts.
template <class Member>
auto verticesWhere(std::int64_t n, Member member) {
    return [n, member](auto&& f) {
        for (std::int64_t v = 0; v < n; ++v)
            if (member(v)) f(v);
    };
}

/// The adapter of a region: the neighbours of cell i inside the region that member(j) accepts.
template <class Member>
auto regionEdges(const Region& region, Member member) {
    return [&region, member](std::int64_t i, auto&& step) {
        const int degree = region.lattice().degree();
        for (int d = 0; d < degree; ++d)
            if (const int j = region.neighbour(static_cast<int>(i), d); j >= 0 && member(j)) step(j);
    };
}

/// The adapter of a padded board, where neighbour d of cell i is cell i + offset(d) and the
/// padding keeps every neighbour of a board cell on the board: those that member(j) accepts.
template <class Offset, class Member>
auto offsetEdges(int degree, Offset offset, Member member) {
    return [degree, offset, member](std::int64_t i, auto&& step) {
        for (int d = 0; d < degree; ++d)
            if (const std::int64_t j = i + offset(d); member(j)) step(j);
    };
}

/// Word-sized sets (bit i: cell i): the cells of `within` that `from` reaches through `within`,
/// a layer at a time; around(set) is the set of cells next to a cell of `set`.
template <class Word, class Around>
Word reachedWithin(Word from, Word within, Around&& around) {
    Word reached = from, frontier = from;
    while (frontier) {
        frontier = around(frontier) & within & ~reached;
        reached |= frontier;
    }
    return reached;
}

/// Whether a word-sized set is connected (the empty set is).
template <class Word, class Around>
bool connectedWord(Word set, Around&& around) {
    return !set || reachedWithin(static_cast<Word>(set & (~set + 1)), set, around) == set;
}

/// The `around` of a word-sized graph given by each cell's neighbours as a word.
template <class Word>
auto aroundByTable(const Word* neighbours) {
    return [neighbours](Word set) {
        Word out = 0;
        for (; set; set &= set - 1) out |= neighbours[std::countr_zero(set)];
        return out;
    };
}

}  // namespace holon::rules
