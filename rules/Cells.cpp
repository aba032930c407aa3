// Cell-level semantics of the rule language, shared by rule patterns, guards and configuration
// predicates. Field atoms imply that the cell is occupied; `@k` is the direction from this cell to
// pattern cell k; a right side sets the fields it names and keeps the others (frame condition), and
// a field whose `if` condition stops holding is dropped.

#include "rules/Cells.h"

namespace holon::rules {

namespace {

bool atomHolds(const Atom& a, CellValue value, const CellContext& at) {
    if (a.kind == Atom::Kind::Input) return at.ignoreInputs || (((at.inputs >> a.index) & 1u) != 0) != a.negated;
    if (value == 0) return false;
    const int actual = at.alphabet->fields(value)[a.index];
    bool equal = false;
    switch (a.value.kind) {
    case FieldValue::Kind::Literal: equal = actual == a.value.value; break;
    case FieldValue::Kind::None: equal = actual == kAbsent; break;
    case FieldValue::Kind::CellRef: {
        if (!at.pattern) return false;
        const int d = at.lattice->directionOf((*at.pattern)[a.value.value] - at.position);
        equal = d >= 0 && actual == d;
        break;
    }
    }
    return equal != a.negated;
}

}  // namespace

bool matchesTerm(const CellTerm& term, CellValue value, const CellContext& at) {
    if (term.copyFrom >= 0) return at.pattern && at.position == (*at.pattern)[term.copyFrom];  // `@k` in a guard
    if (term.base == CellTerm::Base::Empty && value != 0) return false;
    if (term.base == CellTerm::Base::Occupied && value == 0) return false;
    for (const Atom& a : term.atoms)
        if (!atomHolds(a, value, at)) return false;
    return true;
}

bool matchesPredicate(const CellPredicate& pred, CellValue value, const CellContext& at) {
    for (const CellTerm& t : pred)
        if (matchesTerm(t, value, at)) return true;
    return false;
}

int rewriteTerm(const CellTerm& rhs, CellValue value, const CellContext& at, int* missingField) {
    if (rhs.base == CellTerm::Base::Empty) return 0;
    bool assigns = false;
    for (const Atom& a : rhs.atoms) assigns |= a.kind == Atom::Kind::Field;
    if (!assigns) return value;
    const Alphabet& alphabet = *at.alphabet;
    std::vector<int> fields = value ? alphabet.fields(value) : std::vector<int>(alphabet.fields(1).size(), kAbsent);
    std::vector<bool> set(fields.size(), false);
    for (const Atom& a : rhs.atoms) {
        if (a.kind != Atom::Kind::Field) continue;
        set[a.index] = true;
        switch (a.value.kind) {
        case FieldValue::Kind::Literal: fields[a.index] = a.value.value; break;
        case FieldValue::Kind::None: fields[a.index] = kAbsent; break;
        case FieldValue::Kind::CellRef: {
            const int d = at.pattern ? at.lattice->directionOf((*at.pattern)[a.value.value] - at.position) : -1;
            fields[a.index] = d >= 0 ? d : kAbsent;
            break;
        }
        }
    }
    // Conditional fields: drop those whose condition no longer holds; a field that has just come on
    // must have been given a value.
    const auto& schema = alphabet.schema();
    for (std::size_t f = 0; f < fields.size(); ++f) {
        const Field& field = schema[f];
        const bool active = field.whenField < 0 || [&] {
            for (int w : field.whenValues)
                if (fields[field.whenField] == w) return true;
            return false;
        }();
        if (!active) {
            fields[f] = kAbsent;
            continue;
        }
        const bool mayBeNone = field.kind == FieldKind::Dir && field.whenField < 0;
        const bool wasActive = value != 0 && alphabet.fields(value)[f] != kAbsent;
        if (fields[f] == kAbsent && !mayBeNone && !set[f] && !wasActive) {
            if (missingField) *missingField = static_cast<int>(f);
            return -1;
        }
    }
    return alphabet.find(fields);
}

}  // namespace holon::rules
