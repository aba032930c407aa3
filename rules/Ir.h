#pragma once
// The rule IR: one metamodule system as written in a .holon file. Every engine of holon (the
// reference interpreter, the explorer, the SMT encoding, the compiled planner) reads this.
// Names are resolved to indices by the parser; source locations serve diagnostics only and do not
// take part in equality, so print -> re-parse round trips compare equal.

#include "rules/Lattice.h"
#include "rules/Rational.h"

#include <optional>
#include <string>
#include <vector>

namespace holon::rules {

struct SourceLoc {
    int line = 0, col = 0;
    friend bool operator==(const SourceLoc&, const SourceLoc&) { return true; }
};

enum class FieldKind { Enum,
                       Dir,
                       Int };

/// A named per-cell field with a finite domain. A field may exist only while an earlier enum field
/// holds one of some values (`field parent: dir if P`); elsewhere it is absent.
struct Field {
    std::string name;
    FieldKind kind = FieldKind::Enum;
    std::vector<std::string> values;  // Enum: the value names
    int lo = 0, hi = 0;               // Int: the inclusive range
    int whenField = -1;               // index of the enum field that switches this one on, or -1
    std::vector<int> whenValues;      // values of whenField for which this field exists
    SourceLoc loc;
    friend bool operator==(const Field&, const Field&) = default;
};

struct MassEntry {
    int field = 0, value = 0;
    Rational mass;
    SourceLoc loc;
    friend bool operator==(const MassEntry&, const MassEntry&) = default;
};

/// The right-hand side of `field=...`: a literal, `none`, or the direction toward pattern cell k.
struct FieldValue {
    enum class Kind { Literal,
                      None,
                      CellRef } kind = Kind::Literal;
    int value = 0;  // Literal: enum index or integer; CellRef: k
    friend bool operator==(const FieldValue&, const FieldValue&) = default;
};

/// One conjunct of a cell term: a field test/assignment or an input test, possibly negated.
struct Atom {
    enum class Kind { Field,
                      Input } kind = Kind::Field;
    bool negated = false;
    int index = 0;  // field or input index
    FieldValue value;
    SourceLoc loc;
    friend bool operator==(const Atom&, const Atom&) = default;
};

/// What one cell must be (on a left side, in a guard or expression) or becomes (on a right side).
struct CellTerm {
    enum class Base { Empty,
                      Any,
                      Occupied } base = Base::Any;  // `_`, `*`, `#` (field atoms imply #)
    std::vector<Atom> atoms;
    bool hasOffset = false;
    Vec offset;         // explicit position in lattice coordinates, `@(x,y)`
    int copyFrom = -1;  // `@k`: on a right side the cell takes the state pattern cell k had (a move);
                        // in a guard's predicate the cell is pattern cell k (`connected nbr # | @2`)
    SourceLoc loc;
    friend bool operator==(const CellTerm&, const CellTerm&) = default;
};

/// A disjunction of cell terms, as in `F&target | _&!target`.
using CellPredicate = std::vector<CellTerm>;

enum class CmpOp { Eq,
                   Ne,
                   Lt,
                   Le,
                   Gt,
                   Ge };

template <class Number>  // Rational, or std::int64_t where both sides are integers
bool compare(CmpOp op, const Number& a, const Number& b) {
    switch (op) {
    case CmpOp::Eq: return a == b;
    case CmpOp::Ne: return a != b;
    case CmpOp::Lt: return a < b;
    case CmpOp::Le: return a <= b;
    case CmpOp::Gt: return a > b;
    case CmpOp::Ge: return a >= b;
    }
    return false;
}

/// Configuration-level and guard expressions.
struct Expr {
    enum class Kind {
        Bool,    // value.num() != 0
        Number,  // value
        Mass,    // total mass of the configuration
        And,
        Or,
        Not,
        Implies,
        Compare,  // kids[0] op kids[1]
        Add,
        Sub,
        Neg,
        // Number of cells satisfying pred (in the region, or around pattern cell `around`). In the
        // region, an optional kids[0] is a local guard read with @0 at the cell (`count(H: no nbr _)`):
        // only cells where it holds count, and all(T: G) means every T cell satisfies G.
        Count,
        All,
        Some,
        No,
        Connected,  // the cells satisfying pred form one connected set; with `around` (guards): the
                    // neighbours of that pattern cell satisfying pred are connected among themselves
        Reaches,    // every pred cell follows `field` through pred cells to a target cell, acyclically;
                    // with field < 0 (`nbr`): steps to lattice neighbours, so some path through pred
                    // cells leads to a target cell
    } kind = Kind::Bool;
    Rational value;
    CmpOp op = CmpOp::Eq;
    std::vector<Expr> kids;
    CellPredicate pred, target;
    int field = -1;
    // Guards: >= 0 quantifies over the lattice neighbours of pattern cell `around` (`count nbr@k T`),
    // kOwnCells over the rule's own pattern cells (`count pattern T`); -1: over the region.
    int around = -1;
    static constexpr int kOwnCells = -2;
    SourceLoc loc;
    friend bool operator==(const Expr&, const Expr&) = default;
};

struct Rule {
    std::string name, reverseName;  // reverseName: the backward direction of a `<=>` rule
    bool bidirectional = false;
    std::vector<CellTerm> lhs, rhs;
    std::optional<Expr> guard;
    SourceLoc loc;
    friend bool operator==(const Rule&, const Rule&) = default;
};

struct Constraint {
    Expr expr;
    SourceLoc loc;
    friend bool operator==(const Constraint&, const Constraint&) = default;
};

struct Property {
    enum class Kind { Invariant,
                      Progress,
                      Ranking,
                      Holonomic,
                      Conserves } kind = Kind::Invariant;
    std::string name;
    std::vector<Expr> exprs;          // Invariant: {expr}; Progress: {assumption} or {}; Ranking: the components;
                                      // Holonomic: {count(P)} where P says which cells hold a complete
                                      // metamodule (`by occupancy of D | C`), or {}
    std::vector<std::string> except;  // Ranking: rules whose steps must keep it instead (resource moves)
    enum class Adjacency { Occupancy,
                           Move } adjacency = Adjacency::Occupancy;  // Holonomic
    enum class Quantity { Mass,
                          Count } quantity = Quantity::Mass;  // Conserves
    SourceLoc loc;
    friend bool operator==(const Property&, const Property&) = default;
};

struct System {
    std::string name;
    SourceLoc loc{1, 1};                 // the 'system' line, for warnings about the whole system
    std::optional<LatticeKind> lattice;  // none: the system works on every lattice
    // The rules hold in every orientation this group gives; a design with gravity or a handedness
    // narrows it (`symmetry rotations`, `symmetry none`).
    Symmetry symmetry = Symmetry::RotationsReflections;
    std::vector<Field> fields;
    std::vector<std::string> inputs;
    std::vector<SourceLoc> inputLocs;  // where each input was declared
    std::vector<MassEntry> masses;
    std::vector<Rule> rules;
    std::vector<Constraint> constraints;
    std::optional<Expr> goal;
    std::vector<Property> properties;
    std::string sourceName;  // file the system came from, for messages
    /// SHA-256 of the text it was parsed from (rules::loadSystem), which a certificate names
    /// (checker/Certificate.h); the file is not read again for it, since a pipe gives its text once.
    std::string sourceSha256;
    friend bool operator==(const System& a, const System& b) {
        return a.name == b.name && a.lattice == b.lattice && a.symmetry == b.symmetry && a.fields == b.fields && a.inputs == b.inputs &&
               a.masses == b.masses && a.rules == b.rules && a.constraints == b.constraints &&
               a.goal == b.goal && a.properties == b.properties;
    }

    int fieldIndex(const std::string& name) const;
    int inputIndex(const std::string& name) const;
    const Property* property(const std::string& name) const;
    /// Whether the system declares `conserves mass`: what the planner's monitor, its disk
    /// metamodules and its bound on rounds take as given (holon verify proves it).
    bool conservesMass() const;
};

}  // namespace holon::rules
