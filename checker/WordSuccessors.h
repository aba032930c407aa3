#pragma once
// The explorer's successor generator on regions of at most 64 cells: the edges of seed 000 §II-B's
// reconfiguration graph (one rule instance each) computed with word operations. A configuration
// is stored plane-major (StateLayout), so each plane is a word and the cells in each state are a
// few word operations; every instance is matched at once (WordMatcher, the bitboard move
// generation of chess programs) and a successor is the stored words XOR a delta. An instance whose
// left side admits one state per cell has one delta, computed when the generator is built; the
// others compute theirs from the states of their cells. Legality is decided on the successor's
// words (WordConstraints::legalAfter, legalOn). Larger regions keep the cell-by-cell path; tests
// hold both to the reference interpreter.

#include "checker/StateStore.h"
#include "checker/WordConstraints.h"
#include "checker/WordMatcher.h"

#include <cstdint>
#include <memory>
#include <vector>

namespace holon::checker {

class WordSuccessors {
public:
    static constexpr int kMaxPlanes = 6;          // alphabets of at most 64 states
    static constexpr int kMaxWords = kMaxPlanes;  // 64 cells per plane
    /// Usable when the region has at most 64 cells and the alphabet at most 64 states.
    static bool fits(const rules::Engine& engine);
    /// `layout` must be plane-major.
    WordSuccessors(const WordConstraints& constraints, const StateLayout& layout);

    static constexpr int kMaxFilters = 8;
    /// One configuration, read once for all its successors.
    struct Loaded {
        std::uint64_t allowed[kMaxFilters];  // per filter, the cells whose removal keeps its word connected
        std::uint64_t occupied[64];          // per state, the cells in it
        CellValue cells[64];                 // filled when `withCells` was asked or a rule needs them
        WordConstraints::LegalBefore legal;  // when the constraints are decided on words
    };
    /// `prune`: successors that a connectivity constraint rules out are not listed at all (a
    /// search that decides legality); otherwise (--all, where the store decides) they may be.
    void load(const std::uint64_t* packed, Loaded& out, bool withCells, bool prune) const;
    /// f(placed, delta, indexDelta) for every enabled instance: the successor's stored words are
    /// the configuration's XOR `delta`, and its candidate index (the sum of state x alphabet^cell)
    /// is the configuration's plus `indexDelta`, modulo 2^64.
    template <class F>
    void forEach(const Loaded& l, F&& f) const {
        std::uint64_t delta[kMaxWords];
        matcher_->forEachMatch(l.occupied, l.allowed, l.cells, [&](int p) {
            if (fixed_[p])
                return f(p, &fixedDelta_[static_cast<std::size_t>(p) * words_], fixedIndexDelta_[p]);
            f(p, delta, computeDelta(p, l.cells, delta));
        });
    }
    /// No other instance ever has the same effect in a configuration where both are enabled, so
    /// the edge needs no de-duplication.
    bool unique(int placed) const { return unique_[placed] != 0; }
    /// Every constraint holds in the successor `packed` of `parent` (a legal configuration) by
    /// instance `placed`, listed by forEach after a pruning load. For an instance with a fixed delta the constraint words are the
    /// parent's changed by a fixed amount; connectivity is decided around the cells that changed.
    bool legal(const std::uint64_t* packed, const Loaded& parent, int placed) const;

private:
    /// Writes the delta of an instance whose cells' states decide it; returns its index delta.
    std::uint64_t computeDelta(int placed, const CellValue* cells, std::uint64_t* delta) const;
    void occupiedOf(const std::uint64_t* packed, std::uint64_t* occupied) const;
    void findUnique(const std::vector<CellValue>& pinned);
    /// Filters for the matcher: shapes all of whose instances remove their pattern cell k from
    /// a word that must stay connected match only where that cell is not a cut cell.
    void addFilters();

    const rules::Engine* engine_;
    const WordConstraints* constraints_;
    const StateLayout* layout_;
    int alphabet_, planes_, words_;
    bool needCells_;                         // some rule has a guard or an instance without a fixed delta
    std::vector<std::uint64_t> placeValue_;  // alphabet^cell, modulo 2^64
    std::vector<char> fixed_;                // per instance
    std::vector<char> unique_;               // per instance
    std::vector<std::uint64_t> fixedDelta_;  // [instance * words]
    std::vector<std::uint64_t> fixedIndexDelta_;
    std::vector<WordConstraints::WordChange> fixedChange_;  // per instance, when fixed and on words
    std::vector<WordConstraints::Check> checks_;            // fixed instances' compiled changes, back to back
    std::vector<std::uint32_t> firstCheck_;                 // per instance and one past the end: its checks in checks_
    std::unique_ptr<WordMatcher> matcher_;                  // the engine's instances, with the filters
    std::vector<int> filteredWord_;                         // per filter: the constraint word whose cut cells it excludes
};

}  // namespace holon::checker
