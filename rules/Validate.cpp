// Semantic validation of a system, run after parsing on every lattice the system can be placed on.
// The decisive check is completeness of right sides: for every rule shape and every state its left
// side admits, the rewrite must give a state of the alphabet (a P must receive its parent pointer).
// Because the alphabet is finite this is decided by enumeration, not approximated.

#include "rules/Validate.h"

#include "rules/Cells.h"
#include "rules/Error.h"
#include "rules/Model.h"

#include <set>

namespace holon::rules {

namespace {

void collectAtoms(const CellTerm& t, std::set<std::pair<int, int>>& values, std::set<int>& inputs) {
    for (const Atom& a : t.atoms) {
        if (a.kind == Atom::Kind::Input) inputs.insert(a.index);
        else if (a.value.kind == FieldValue::Kind::Literal) values.insert({a.index, a.value.value});
    }
}

void collectExpr(const Expr& e, std::set<std::pair<int, int>>& values, std::set<int>& inputs) {
    for (const CellTerm& t : e.pred) collectAtoms(t, values, inputs);
    for (const CellTerm& t : e.target) collectAtoms(t, values, inputs);
    for (const Expr& k : e.kids) collectExpr(k, values, inputs);
}

void checkRightSides(const System& system, const Model& model, Diagnostics& d, std::set<const Rule*>& reported) {
    const Alphabet& alphabet = model.alphabet();
    // Whether a rewrite is complete does not depend on the orientation: one shape per rule suffices.
    std::set<int> checked;
    for (const RuleShape& shape : model.shapes()) {
        const DirectedRule& rule = model.rules()[shape.rule];
        if (reported.count(rule.rule) || !checked.insert(shape.rule).second) continue;
        for (std::size_t i = 0; i < shape.offsets.size(); ++i) {
            if (rule.rhs()[i].copyFrom >= 0) continue;  // a copied state is complete
            CellContext at{&alphabet, &model.lattice(), shape.offsets[i], 0, &shape.offsets, true};
            for (int v = 0; v < alphabet.size(); ++v) {
                if (!matchesTerm(rule.lhs()[i], static_cast<CellValue>(v), at)) continue;
                int missing = -1;
                if (rewriteTerm(rule.rhs()[i], static_cast<CellValue>(v), at, &missing) >= 0) continue;
                const CellTerm& where = rule.rhs()[i];
                std::string message = "rule '" + rule.name + "': cell @" + std::to_string(i) + " turns state '" +
                                      alphabet.name(static_cast<CellValue>(v)) + "' into an incomplete state";
                if (missing >= 0) message += ": field '" + system.fields[missing].name + "' must be set here";
                d.error(where.loc, message);
                reported.insert(rule.rule);
                break;
            }
            if (reported.count(rule.rule)) break;
        }
    }
}

}  // namespace

/// Arithmetic is exact in 64-bit fractions (Rational): the constants of one expression whose
/// denominators have a common multiple above 2^32 could not all be summed. Reported at the constant
/// that takes it past; Rational still refuses, without a place, any sum of counts too large.
void checkDenominators(const Expr& e, std::int64_t& lcm, bool& reported, Diagnostics& d) {
    // Denominators are below 10^9 and the common multiple so far at most 2^32: checkedLcm's 64 bits hold the next.
    if (e.kind == Expr::Kind::Number && !reported && (lcm = checkedLcm(lcm, e.value.den())) > (std::int64_t{1} << 32)) {
        d.error(e.loc, "the denominators of this expression's numbers have a least common multiple above 2^32; holon computes with exact 64-bit fractions: use denominators with a smaller common multiple");
        reported = true;
    }
    for (const Expr& k : e.kids) checkDenominators(k, lcm, reported, d);
}

void checkDenominators(const Expr& e, Diagnostics& d) {
    std::int64_t lcm = 1;
    bool reported = false;
    checkDenominators(e, lcm, reported, d);
}

void validate(const System& system, Diagnostics& d) {
    std::vector<const Lattice*> lattices;
    if (system.lattice) lattices.push_back(&Lattice::get(*system.lattice));
    else lattices = Lattice::all();
    std::set<const Rule*> reported;
    for (const Lattice* lattice : lattices) {
        try {
            Model model(system, *lattice);
            checkRightSides(system, model, d, reported);
            if (lattice != lattices.front()) continue;
            for (auto [dup, original] : model.duplicates()) {
                const DirectedRule& a = model.rules()[dup];
                const DirectedRule& b = model.rules()[original];
                if (a.rule == b.rule) continue;  // a self-inverse '<=>' rule such as transfer
                d.warning(a.rule->loc, "duplicate-rule",
                          "rule '" + a.name + "' does nothing that rule '" + b.name + "' does not already do");
            }
        } catch (const InputError& e) {
            d.error({1, 1}, e.what());
            return;
        }
    }
    if (system.rules.empty()) d.warning(system.loc, "no-rules", "system '" + system.name + "' has no rules");

    std::set<std::pair<int, int>> usedValues;
    std::set<int> usedInputs;
    for (const Rule& r : system.rules) {
        for (const CellTerm& t : r.lhs) collectAtoms(t, usedValues, usedInputs);
        for (const CellTerm& t : r.rhs) collectAtoms(t, usedValues, usedInputs);
        if (r.guard) collectExpr(*r.guard, usedValues, usedInputs);
    }
    for (const Rule& r : system.rules)
        if (r.guard) checkDenominators(*r.guard, d);
    for (const Constraint& c : system.constraints) checkDenominators(c.expr, d);
    if (system.goal) checkDenominators(*system.goal, d);
    for (const Property& p : system.properties)
        for (const Expr& e : p.exprs) checkDenominators(e, d);
    std::set<std::pair<int, int>> anywhere = usedValues;
    for (const Constraint& c : system.constraints) collectExpr(c.expr, anywhere, usedInputs);
    if (system.goal) collectExpr(*system.goal, anywhere, usedInputs);
    for (const Property& p : system.properties)
        for (const Expr& e : p.exprs) collectExpr(e, anywhere, usedInputs);
    for (int f = 0; f < static_cast<int>(system.fields.size()); ++f) {
        const Field& field = system.fields[f];
        if (field.kind != FieldKind::Enum || field.values.size() < 2) continue;
        for (int v = 0; v < static_cast<int>(field.values.size()); ++v)
            if (!usedValues.count({f, v}))
                d.warning(field.loc, "unused-value", "no rule mentions state '" + field.values[v] + "'");
    }
    for (int i = 0; i < static_cast<int>(system.inputs.size()); ++i)
        if (!usedInputs.count(i)) d.warning(system.inputLocs[i], "unused-input", "input '" + system.inputs[i] + "' is never read");
    for (int f = 0; f < static_cast<int>(system.fields.size()); ++f) {
        int massed = 0;
        for (const MassEntry& m : system.masses) massed += m.field == f;
        const Field& field = system.fields[f];
        if (massed > 0 && massed < static_cast<int>(field.values.size()))
            d.warning(field.loc, "unmassed-value",
                      "some states of field '" + field.name + "' have a mass and others not; those count 0");
    }
}

}  // namespace holon::rules
