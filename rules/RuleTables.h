#pragma once
// A system's rules compiled into decision tables, independent of where they are placed: for every
// rule shape and pattern cell a bit mask over (input combination, cell state) for the left side, a
// state -> state table for the right side, and guards as per-direction masks. The explorer's
// Engine places these tables on a region; the planner places them on a padded box by index
// arithmetic. Both therefore run exactly the same compiled rules.

#include "rules/Components.h"
#include "rules/Limits.h"
#include "rules/Model.h"

#include <bit>
#include <cstdint>
#include <vector>

namespace holon::rules {

class RuleTables {
public:
    static constexpr int kMaxCells = kMaxRuleCells;  // the parser refuses larger rules, with their place

    /// A bit set over (input combination, cell state).
    struct Mask {
        std::vector<std::uint64_t> bits;
    };
    /// A guard compiled for one shape: quantifier nodes hold one mask per site they look at, the
    /// neighbour in lattice direction d of pattern cell `around` (`nbr`), or pattern cell d itself
    /// (`pattern`, around == Expr::kOwnCells).
    struct GuardNode {
        Expr::Kind kind = Expr::Kind::Bool;
        CmpOp op = CmpOp::Eq;
        Rational value;
        std::vector<GuardNode> kids;
        int around = -1;
        std::vector<std::vector<std::uint64_t>> perSite;
        // Per site, the states (below 64) accepted under some / every input combination: most
        // cells are decided by their state alone, without loading their combination.
        std::vector<std::uint64_t> anyCombo, allCombo;
    };
    struct Shape {
        std::vector<Mask> lhs;
        std::vector<std::vector<CellValue>> rhs;  // empty for a copy term
        std::vector<int> copyFrom;                // pattern cell whose old state is copied, or -1
        bool hasGuard = false;
        GuardNode guard;
    };

    /// `combos`: the input combinations (bit sets over the system's inputs) the tables must cover;
    /// combination 0 (no input set) is always index 0, used for cells outside the region.
    /// `onlyShapes`, when not empty: the shapes compiled; the others keep their index with no
    /// table (a drawing of one rule of 870 compiled them all, once per orientation).
    RuleTables(const Model& model, std::vector<std::uint32_t> combos, const std::vector<int>& onlyShapes = {});

    const Model& model() const { return *model_; }
    int alphabet() const { return alphabet_; }
    int comboCount() const { return static_cast<int>(combos_.size()); }
    std::uint32_t comboInputs(int combo) const { return combos_[combo]; }
    /// Index of an input combination, or -1 when the tables do not cover it.
    int comboIndex(std::uint32_t inputs) const;
    int shapeCount() const { return static_cast<int>(shapes_.size()); }
    const Shape& shape(int s) const { return shapes_[s]; }
    /// Shapes whose first pattern cell accepts state v under input combination `combo`.
    const std::vector<std::int32_t>& shapesByFirst(int combo, CellValue v) const {
        return shapesByFirst_[static_cast<std::size_t>(combo) * alphabet_ + v];
    }

    bool test(const Mask& m, int combo, CellValue v) const { return bit(m.bits, combo, v); }
    /// The states below 64 that `bits` (a mask over (combination, state)) accepts under some
    /// combination, and under every one: most cells are decided by these without their combination.
    std::pair<std::uint64_t, std::uint64_t> acceptedStates(const std::vector<std::uint64_t>& bits) const;
    /// Whether a set of lattice directions (bit d for direction d) is connected when two
    /// directions are joined if their neighbour cells are adjacent (`connected nbr` guards).
    bool directionsConnected(std::uint32_t set) const { return connectedWord(set, aroundByTable(directionNeighbours_.data())); }
    bool guardAccepts(const GuardNode& node, int site, int combo, CellValue v) const { return bit(node.perSite[site], combo, v); }
    Mask compilePredicate(const CellPredicate& pred, const std::vector<Vec>* pattern, Vec position) const;
    /// A quantifier's cell guard (`all(H: no nbr _)`): a guard of a one-cell pattern.
    GuardNode compileCellGuard(const Expr& guard) const;

    /// A cell an instance of a shape reads: pattern cell `cell` itself (direction -1) or its
    /// neighbour in lattice direction `direction`.
    struct Site {
        int cell, direction;
        friend bool operator==(const Site&, const Site&) = default;
    };
    /// The read side of every footprint (the path search's interference, the planner's conflict
    /// test and influence): every pattern cell, and the neighbours of each pattern cell a guard
    /// quantifier names (`nbr@k`), which is all a guard reads (the parser keeps guards local;
    /// `pattern` quantifiers read the pattern cells). Nothing wider: a wider stencil would make the
    /// planner's sync rounds smaller than maximal.
    std::vector<Site> readSites(int shape) const;
    /// Whether an instance of a shape can tell state v from state w at one of its read sites, under
    /// some input combination: the site's left-side test, or a guard quantifier's test of it, accepts
    /// one and not the other. Where none can, a cell changing from v to w there enables or disables
    /// no instance of the shape (the planner's demand stencils skip it).
    bool distinguishes(int shape, Site site, CellValue v, CellValue w) const;
    /// The write side: whether pattern cell k of a shape may change, i.e. is a copy of another cell
    /// or rewrites some state its left side accepts under input combination `combo` (under any
    /// combination, where `combo` is -1) to another.
    bool mayWrite(int shape, int k, int combo = -1) const;

    std::int64_t massUnitsOf(CellValue v) const { return mass_[v]; }
    std::int64_t massDenominator() const { return massDen_; }

    /// Evaluates a compiled guard. `at` gives the cells around the instance: `at.value(i)`,
    /// `at.combo(i)` and `at.neighbour(i, d)` (-1 outside), where i is a pattern cell's index as
    /// listed in `cells`.
    template <class Cells>
    bool guard(const GuardNode& g, const Cells& at, const std::int32_t* cells) const {
        switch (g.kind) {
        case Expr::Kind::Bool: return g.value.num() != 0;
        case Expr::Kind::And: return guard(g.kids[0], at, cells) && guard(g.kids[1], at, cells);
        case Expr::Kind::Or: return guard(g.kids[0], at, cells) || guard(g.kids[1], at, cells);
        case Expr::Kind::Implies: return !guard(g.kids[0], at, cells) || guard(g.kids[1], at, cells);
        case Expr::Kind::Not: return !guard(g.kids[0], at, cells);
        case Expr::Kind::Compare: return compare(g.op, guardNumber(g.kids[0], at, cells), guardNumber(g.kids[1], at, cells));
        case Expr::Kind::Some: return guardAny(g, at, cells);
        case Expr::Kind::No: return !guardAny(g, at, cells);
        case Expr::Kind::All: return guardCount(g, at, cells) == static_cast<int>(g.perSite.size());
        case Expr::Kind::Connected: return directionsConnected(guardMembers(g, at, cells));
        case Expr::Kind::Number:
        case Expr::Kind::Mass:
        case Expr::Kind::Add:
        case Expr::Kind::Sub:
        case Expr::Kind::Neg:
        case Expr::Kind::Count:
        case Expr::Kind::Reaches:  // the parser refuses these in guards
            break;
        }
        return false;
    }

private:
    bool bit(const std::vector<std::uint64_t>& bits, int combo, CellValue v) const {
        const std::size_t i = static_cast<std::size_t>(combo) * alphabet_ + v;
        return (bits[i >> 6] >> (i & 63)) & 1u;
    }
    /// Whether the guard accepts `cell` as its site d (a cell outside the region, -1, counts as
    /// empty with no input set).
    template <class Cells>
    bool acceptsSite(const GuardNode& g, int d, const Cells& at, std::int64_t cell) const {
        if (cell < 0) return guardAccepts(g, d, 0, 0);
        const CellValue v = at.value(cell);
        if (v < 64) {
            if (!((g.anyCombo[d] >> v) & 1u)) return false;
            if ((g.allCombo[d] >> v) & 1u) return true;
        }
        return guardAccepts(g, d, at.combo(cell), v);
    }
    /// The guard's sites it accepts, as bits.
    template <class Cells>
    std::uint32_t guardMembers(const GuardNode& g, const Cells& at, const std::int32_t* cells) const {
        if (g.around < 0) [[unlikely]]
            return ownCellMembers(g, at, cells);
        std::uint32_t set = 0;
        const auto centre = cells[g.around];
        for (int d = 0; d < static_cast<int>(g.perSite.size()); ++d) set |= static_cast<std::uint32_t>(acceptsSite(g, d, at, at.neighbour(centre, d))) << d;
        return set;
    }
    /// guardMembers of a quantifier over the pattern's own cells (rare: kept out of the hot path).
    template <class Cells>
    [[gnu::noinline]] std::uint32_t ownCellMembers(const GuardNode& g, const Cells& at, const std::int32_t* cells) const {
        std::uint32_t set = 0;
        for (int d = 0; d < static_cast<int>(g.perSite.size()); ++d) set |= static_cast<std::uint32_t>(acceptsSite(g, d, at, cells[d])) << d;
        return set;
    }
    template <class Cells>
    int guardCount(const GuardNode& g, const Cells& at, const std::int32_t* cells) const {
        return std::popcount(guardMembers(g, at, cells));
    }
    /// Whether some site is accepted: guardCount(...) > 0, stopping at the first.
    template <class Cells>
    bool guardAny(const GuardNode& g, const Cells& at, const std::int32_t* cells) const {
        if (g.around < 0) [[unlikely]]
            return ownCellMembers(g, at, cells) != 0;
        const auto centre = cells[g.around];
        for (int d = 0; d < static_cast<int>(g.perSite.size()); ++d)
            if (acceptsSite(g, d, at, at.neighbour(centre, d))) return true;
        return false;
    }
    template <class Cells>
    Rational guardNumber(const GuardNode& g, const Cells& at, const std::int32_t* cells) const {
        switch (g.kind) {
        case Expr::Kind::Number: return g.value;
        case Expr::Kind::Add: return guardNumber(g.kids[0], at, cells) + guardNumber(g.kids[1], at, cells);
        case Expr::Kind::Sub: return guardNumber(g.kids[0], at, cells) - guardNumber(g.kids[1], at, cells);
        case Expr::Kind::Neg: return -guardNumber(g.kids[0], at, cells);
        case Expr::Kind::Count: return guardCount(g, at, cells);
        case Expr::Kind::Mass:  // the parser refuses it in guards
        case Expr::Kind::Bool:
        case Expr::Kind::And:
        case Expr::Kind::Or:
        case Expr::Kind::Not:
        case Expr::Kind::Implies:
        case Expr::Kind::Compare:
        case Expr::Kind::All:
        case Expr::Kind::Some:
        case Expr::Kind::No:
        case Expr::Kind::Connected:
        case Expr::Kind::Reaches:
            break;
        }
        return 0;
    }
    Mask compileTerm(const CellTerm& term, const std::vector<Vec>* pattern, Vec position, const CellTerm* alsoInputs) const;
    GuardNode compileGuard(const Expr& e, const RuleShape& shape) const;

    const Model* model_;
    int alphabet_;
    std::vector<std::uint32_t> combos_;
    std::vector<Shape> shapes_;
    std::vector<std::vector<std::int32_t>> shapesByFirst_;
    std::vector<std::int64_t> mass_;
    std::int64_t massDen_ = 1;
    std::vector<std::uint32_t> directionNeighbours_;  // per direction: the directions whose cells touch its cell
};

}  // namespace holon::rules
