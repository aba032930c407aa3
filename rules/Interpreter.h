#pragma once
// The reference interpreter: the semantics of a system on a bounded region. Every other engine
// (explorer, SMT encoding, compiled planner) is tested against this one.

#include "rules/Cells.h"
#include "rules/Model.h"
#include "rules/Region.h"

#include <cstdint>
#include <optional>
#include <vector>

namespace holon::rules {

/// The state of every cell of a region, and the read-only inputs the problem sets per cell (bit i:
/// input i of the system).
struct Configuration {
    std::vector<CellValue> cells;
    std::vector<std::uint32_t> inputs;
    friend bool operator==(const Configuration&, const Configuration&) = default;
};

/// A rule shape placed on the lattice: pattern cell i sits at anchor + shape.offsets[i].
struct Instance {
    int shape = 0;
    Vec anchor;
    friend bool operator==(const Instance&, const Instance&) = default;
};

/// Why an instance is not enabled, for a person (the rule a stuck cell waits on).
struct Blocked {
    std::vector<int> cells;      // pattern cells whose state the left side rejects
    int conjunct = -1;           // the first false conjunct of the guard (conjuncts(guard)), or -1
    std::vector<Vec> witnesses;  // for a false neighbour or own-cells quantifier: the cells that make
                                 // it false (`no nbr U`: the U neighbours; `all`: those that are not)
    bool enabled() const { return cells.empty() && conjunct < 0; }
};

/// The top-level conjuncts of `e` (`a and (b and c)` gives a, b, c), left to right.
std::vector<const Expr*> conjuncts(const Expr& e);

class Interpreter {
public:
    Interpreter(const Model& model, const Region& region);
    const Model& model() const { return *model_; }
    const Region& region() const { return *region_; }

    Configuration empty() const;
    /// Region indices of the instance's cells, or nothing when one lies outside the region.
    std::optional<std::vector<int>> cellsOf(const Instance& instance) const;
    /// The left side and the guard hold (the local part of being enabled).
    bool matches(const Configuration& c, const Instance& instance) const;
    /// The configuration after firing; requires matches(c, instance).
    Configuration apply(const Configuration& c, const Instance& instance) const;
    /// apply() in place: every new state is computed from the old ones before any is written, so
    /// the result is the same; a step costs its pattern, not a copy of the configuration.
    void applyInPlace(Configuration& c, const Instance& instance) const;
    /// What keeps an instance (every cell in the region) from matching; Blocked::enabled() when it matches.
    Blocked blocked(const Configuration& c, const Instance& instance) const;
    /// matches, and the result satisfies every non-local constraint: the successor, or nothing.
    std::optional<Configuration> successor(const Configuration& c, const Instance& instance) const;
    /// Every instance with a successor, in a fixed order (shape, then anchor).
    std::vector<Instance> enabled(const Configuration& c) const;
    /// All non-local constraints hold.
    bool legal(const Configuration& c) const;

    bool holds(const Expr& e, const Configuration& c) const;
    /// The index (in conjuncts(e)) of the first conjunct of `e` that is false in `c`; -1 when `e` holds.
    int firstFalseConjunct(const Expr& e, const Configuration& c) const;
    Rational number(const Expr& e, const Configuration& c) const;
    Rational mass(const Configuration& c) const;
    int occupied(const Configuration& c) const;
    /// The goal of the system, or false when it declares none.
    bool atGoal(const Configuration& c) const;

private:
    struct Placement {
        std::vector<Vec> positions;
    };
    bool holdsAt(const Expr& e, const Configuration& c, const Placement* at) const;
    Rational numberAt(const Expr& e, const Configuration& c, const Placement* at) const;
    /// Cells satisfying a quantifier's predicate (around a pattern cell or in the region) and, for a
    /// region quantifier with `withCellGuard`, its cell guard.
    int countCells(const Expr& e, const Configuration& c, const Placement* at, bool withCellGuard = true) const;
    bool connected(const CellPredicate& pred, const Configuration& c) const;
    bool reaches(const Expr& e, const Configuration& c) const;
    CellContext context(Vec position, const Configuration& c, const Placement* at) const;
    CellValue valueAt(Vec position, const Configuration& c) const;

    const Model* model_;
    const Region* region_;
};

}  // namespace holon::rules
