#pragma once
// Every connected set of cells of a region of at most 64 cells, each exactly once: Wernicke's
// ESU enumeration (Wernicke 2006, "Efficient detection of network motifs") on words. A set is
// grown from its lowest cell v; a cell joins only as an exclusive neighbour of the cell that
// brings it (adjacent to that cell and to nothing already in or beside the set) and only if it
// comes after v, which makes every connected set's growth unique. `--all` uses it where the
// constraints require connectivity: pixel on square:5x5 has 2,301,877 connected sets among 2^25
// subsets.

#include <bit>
#include <cstdint>
#include <vector>

namespace holon::checker {

class ConnectedSets {
public:
    /// `neighbours[i]`: the cells adjacent to cell i, as a word.
    explicit ConnectedSets(std::vector<std::uint64_t> neighbours) : neighbours_(std::move(neighbours)) {}
    int cells() const { return static_cast<int>(neighbours_.size()); }
    /// Calls f(set) for every connected set whose lowest cell is v, until f returns false.
    template <class F>
    void forEachFrom(int v, F&& f) const {
        const std::uint64_t after = ~((std::uint64_t{2} << v) - 1);  // cells above v
        grow(std::uint64_t{1} << v, neighbours_[v] & after, neighbours_[v] | (std::uint64_t{1} << v), after, f);
    }

private:
    /// False once f has asked to stop.
    template <class F>
    bool grow(std::uint64_t set, std::uint64_t extension, std::uint64_t closed, std::uint64_t after, F& f) const {
        if (!f(set)) return false;
        while (extension) {
            const int w = std::countr_zero(extension);
            extension &= extension - 1;
            const std::uint64_t exclusive = neighbours_[w] & ~closed & after;
            if (!grow(set | (std::uint64_t{1} << w), extension | exclusive, closed | neighbours_[w], after, f)) return false;
        }
        return true;
    }

    std::vector<std::uint64_t> neighbours_;
};

}  // namespace holon::checker
