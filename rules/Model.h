#pragma once
// A system placed on a lattice: its finite cell alphabet, its directed rules and the rule shapes
// obtained by closing every rule under the system's symmetry group on that lattice.

#include "rules/Ir.h"

#include <climits>
#include <cstdint>
#include <map>
#include <span>
#include <string>
#include <vector>

namespace holon::rules {

using CellValue = std::uint16_t;  // index into the alphabet; 0 is the vacuum
constexpr int kAbsent = INT_MIN;  // a conditional field that is switched off, or a dir field holding none

/// Every cell state of a system on one lattice: all assignments of the fields that respect their
/// `if` conditions, numbered from 1 (0 is the vacuum).
class Alphabet {
public:
    Alphabet(const System& system, const Lattice& lattice);
    int size() const { return static_cast<int>(values_.size()); }
    /// Field values of a state (kAbsent where a field is off); empty for the vacuum.
    const std::vector<int>& fields(CellValue v) const { return values_[v]; }
    /// The state with exactly these field values, or -1 when the assignment is not in the alphabet.
    int find(const std::vector<int>& fields) const;
    Rational mass(CellValue v) const { return mass_[v]; }
    /// Human-readable name: "F", "P(parent=+x)", "C&lock=E".
    std::string name(CellValue v) const;
    /// The one-character name of a state for ASCII art, or 0 when it has none.
    char glyph(CellValue v) const { return glyph_[v]; }
    int byGlyph(char c) const;
    const std::vector<Field>& schema() const { return system_->fields; }
    const Lattice& lattice() const { return *lattice_; }

private:
    const System* system_;
    const Lattice* lattice_;
    std::vector<std::vector<int>> values_;
    std::map<std::vector<int>, int> index_;
    std::vector<Rational> mass_;
    std::vector<char> glyph_;
};

/// One direction of a rule: a `<=>` rule gives two.
struct DirectedRule {
    std::string name;
    const Rule* rule = nullptr;
    bool reversed = false;
    const std::vector<CellTerm>& lhs() const { return reversed ? rule->rhs : rule->lhs; }
    const std::vector<CellTerm>& rhs() const { return reversed ? rule->lhs : rule->rhs; }
    const Expr* guard() const { return rule->guard ? &*rule->guard : nullptr; }
};

/// A rule in one orientation: the offsets of its pattern cells from the anchor.
struct RuleShape {
    int rule = 0;      // index into Model::rules()
    int symmetry = 0;  // index into Lattice::pointGroup(): below rotations().size() a rotation
    std::vector<Vec> offsets;
    /// Every rule a step of this shape is a step of: `rule`, then each other rule with an
    /// orientation that reads and writes the same cells in the same way (a duplicate rule, or a
    /// mirror twin); the shape is kept once, but a property that names rules (a ranking's
    /// `except`) judges the step as each one's.
    std::vector<int> rules;
};

class Model {
public:
    /// Throws InputError when the system is fixed to another lattice.
    Model(const System& system, const Lattice& lattice);
    const System& system() const { return *system_; }
    const Lattice& lattice() const { return *lattice_; }
    const Alphabet& alphabet() const { return alphabet_; }
    const std::vector<DirectedRule>& rules() const { return rules_; }
    /// Grouped by rule, in rule order; within a rule, in the order of the lattice's point group.
    const std::vector<RuleShape>& shapes() const { return shapes_; }
    /// The group the rules are closed under: the system's symmetry on this lattice.
    std::span<const LinearMap> symmetries() const { return lattice_->symmetries(system_->symmetry); }
    /// Number of shapes of each directed rule after deduplication (0: the rule repeats another).
    int shapeCount(int rule) const;
    /// Directed rule `rule` is among `names` (a `<=>` rule's name covers both directions).
    bool ruleNamed(int rule, const std::vector<std::string>& names) const;
    /// A step's name: its shape's owner, then "(also t)" for each rule written apart from it that
    /// makes the same step (a two-way rule's reverse is the same rule written once); `quoted` puts
    /// each name in single quotes.
    std::string stepRules(int shape, bool quoted) const;
    /// The rules stepRules names, owner first.
    std::vector<int> stepRuleList(int shape) const;
    /// The first rule of the shape named in `names` (`named`), or not named there (`!named`); -1
    /// when there is none.
    int shapeRule(int shape, const std::vector<std::string>& names, bool named) const;
    /// Directed rules whose every orientation repeats an orientation of earlier rules, with one of
    /// them. Such a rule may still own shapes: a rewrite a reflection of an earlier rule would also
    /// give is kept under the rule whose rotation gives it.
    const std::vector<std::pair<int, int>>& duplicates() const { return duplicates_; }

private:
    const System* system_;
    const Lattice* lattice_;
    Alphabet alphabet_;
    std::vector<DirectedRule> rules_;
    std::vector<RuleShape> shapes_;
    std::vector<std::pair<int, int>> duplicates_;
};

/// How far (steps along any axis) a rule's cells may lie from its first cell where a job lays
/// out the rule itself: a drawing, the every-size window. Exploring a region needs no such bound.
constexpr int kMaxPatternReach = 64;

/// Throws InputError at the rule (FILE:LINE:COL) whose cells lie farther than kMaxPatternReach
/// from its first; `what` says which job needs them near ("a drawing of a rule"). A rule reaching
/// 10^9 cells away was laid out on a box of 10^18 cells: an internal error, or a false "out of
/// memory" (1,000 away: a 906 MB drawing).
void requirePatternsNear(const Model& model, const std::string& what);

}  // namespace holon::rules
