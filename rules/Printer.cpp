// The canonical printer of the rule IR. Its output is the normal form of a .holon file: parsing it
// gives back an equal IR (tested for every library file). The same term and expression printers,
// with references (`@k`, `parent=@k`, `nbr@k`) replaced by offsets, give the structural keys that
// deduplicate rule orientations.

#include "rules/Printer.h"

#include "rules/Error.h"

#include <sstream>

namespace holon::rules {

namespace {

std::string refText(const RefPrinter& ref, int k) { return ref ? ref(k) : "@" + std::to_string(k); }

/// " nbr" or " nbr@k"; with a RefPrinter the quantified cell too is named by it, so a structural key
/// says where the neighbours are, not which pattern index they surround.
std::string nbrText(int around, const RefPrinter& ref) {
    if (ref) return " nbr" + ref(around);
    return around ? " nbr@" + std::to_string(around) : " nbr";
}

std::string valueText(const System& s, const Atom& a, const RefPrinter& ref) {
    const Field& f = s.fields[a.index];
    switch (a.value.kind) {
    case FieldValue::Kind::None: return f.name + "=none";
    case FieldValue::Kind::CellRef: return f.name + "=" + refText(ref, a.value.value);
    case FieldValue::Kind::Literal:
        if (f.kind == FieldKind::Enum) return f.values[a.value.value];
        return f.name + "=" + std::to_string(a.value.value);
    }
    return {};
}

std::string cmpText(CmpOp op) {
    switch (op) {
    case CmpOp::Eq: return "==";
    case CmpOp::Ne: return "!=";
    case CmpOp::Lt: return "<";
    case CmpOp::Le: return "<=";
    case CmpOp::Gt: return ">";
    case CmpOp::Ge: return ">=";
    }
    return "==";
}

/// Binding strength, as in the parser: implies < or < and < not < compare < +,- < unary minus < atoms.
int precedence(const Expr& e) {
    switch (e.kind) {
    case Expr::Kind::Implies: return 1;
    case Expr::Kind::Or: return 2;
    case Expr::Kind::And: return 3;
    case Expr::Kind::Not: return 4;
    case Expr::Kind::Compare: return 5;
    case Expr::Kind::Add:
    case Expr::Kind::Sub: return 6;
    case Expr::Kind::Neg: return 7;
    case Expr::Kind::Number: return e.value.isInteger() ? 8 : 7;  // 3/2 prints as a fraction: keep it whole
    case Expr::Kind::Bool:
    case Expr::Kind::Mass:
    case Expr::Kind::Count:
    case Expr::Kind::All:
    case Expr::Kind::Some:
    case Expr::Kind::No:
    case Expr::Kind::Connected:
    case Expr::Kind::Reaches:
        return 8;  // atoms
    }
    return 8;
}

}  // namespace

std::string printTerm(const System& s, const CellTerm& term, const RefPrinter& ref) {
    if (term.copyFrom >= 0) return ref ? "copy" + ref(term.copyFrom) : "@" + std::to_string(term.copyFrom);
    std::string out;
    bool implied = term.base == CellTerm::Base::Occupied && !term.atoms.empty() && [&] {
        for (const Atom& a : term.atoms)
            if (a.kind == Atom::Kind::Field) return true;
        return false;
    }();
    if (term.base == CellTerm::Base::Empty) out = "_";
    else if (term.base == CellTerm::Base::Occupied && !implied) out = "#";
    else if (term.base == CellTerm::Base::Any && term.atoms.empty()) out = "*";
    for (const Atom& a : term.atoms) {
        if (!out.empty()) out += "&";
        if (a.negated) out += "!";
        out += a.kind == Atom::Kind::Input ? s.inputs[a.index] : valueText(s, a, ref);
    }
    return out;
}

std::string printPredicate(const System& s, const CellPredicate& pred, const RefPrinter& ref) {
    std::string out;
    for (const CellTerm& t : pred) out += (out.empty() ? "" : " | ") + printTerm(s, t, ref);
    return out;
}

std::string printExpr(const System& s, const Expr& e, const RefPrinter& ref) {
    // A child is parenthesised when it binds more loosely than its parent, or as tightly on the side
    // the parser would not group it (left-associative operators group to the left; implies to the right).
    auto sub = [&](const Expr& k, bool tighter) {
        const bool bare = precedence(k) > precedence(e) || (!tighter && precedence(k) == precedence(e));
        return bare ? printExpr(s, k, ref) : "(" + printExpr(s, k, ref) + ")";
    };
    auto binary = [&](const char* op) {
        const bool rightAssoc = e.kind == Expr::Kind::Implies;
        const bool chain = e.kind != Expr::Kind::Compare;
        return sub(e.kids[0], rightAssoc || !chain) + " " + op + " " + sub(e.kids[1], !rightAssoc || !chain);
    };
    auto quant = [&](const char* word) {
        if (e.around >= 0) return std::string(word) + nbrText(e.around, ref) + " " + printPredicate(s, e.pred, ref);
        if (e.around == Expr::kOwnCells) return std::string(word) + " pattern " + printPredicate(s, e.pred, ref);
        const std::string cellGuard = e.kids.empty() ? "" : ": " + printExpr(s, e.kids[0], ref);
        return std::string(word) + "(" + printPredicate(s, e.pred, ref) + cellGuard + ")";
    };
    switch (e.kind) {
    case Expr::Kind::Bool: return e.value.num() ? "true" : "false";
    case Expr::Kind::Number: return e.value.num() < 0 ? "-" + (-e.value).str() : e.value.str();
    case Expr::Kind::Mass: return "mass";
    case Expr::Kind::And: return binary("and");
    case Expr::Kind::Or: return binary("or");
    case Expr::Kind::Implies: return binary("implies");
    case Expr::Kind::Not: return "not " + sub(e.kids[0], false);
    case Expr::Kind::Compare: return binary(cmpText(e.op).c_str());
    case Expr::Kind::Add: return binary("+");
    case Expr::Kind::Sub: return binary("-");
    case Expr::Kind::Neg: return "-" + sub(e.kids[0], false);
    case Expr::Kind::Count: return quant("count");
    case Expr::Kind::All: return quant("all");
    case Expr::Kind::Some: return quant("some");
    case Expr::Kind::No: return quant("no");
    case Expr::Kind::Connected: {
        if (e.around >= 0) return "connected" + nbrText(e.around, ref) + " " + printPredicate(s, e.pred, ref);
        const bool everything = e.pred.size() == 1 && e.pred[0].base == CellTerm::Base::Occupied && e.pred[0].atoms.empty();
        return everything ? "connected" : "connected(" + printPredicate(s, e.pred, ref) + ")";
    }
    case Expr::Kind::Reaches:
        return "reaches(" + printPredicate(s, e.pred, ref) + ", " + (e.field < 0 ? "nbr" : s.fields[e.field].name) + ", " +
               printPredicate(s, e.target, ref) + ")";
    }
    return {};
}

std::string printRule(const System& s, const Rule& r) {
    std::ostringstream out;
    out << "rule " << r.name;
    if (!r.reverseName.empty()) out << " / " << r.reverseName;
    out << ":";
    for (const CellTerm& c : r.lhs) {
        out << ' ' << printTerm(s, c);
        if (c.hasOffset) {
            out << "@(" << c.offset.x << ',' << c.offset.y;
            if (s.lattice && Lattice::get(*s.lattice).dimension() == 3) out << ',' << c.offset.z;
            out << ')';
        }
    }
    out << (r.bidirectional ? " <=>" : " =>");
    for (const CellTerm& c : r.rhs) out << ' ' << printTerm(s, c);
    if (r.guard) out << " if " << printExpr(s, *r.guard);
    return out.str();
}

std::string printSystem(const System& s) {
    std::ostringstream out;
    out << "system " << s.name << '\n';
    if (s.lattice) out << "lattice " << Lattice::get(*s.lattice).name() << '\n';
    if (s.symmetry != System{}.symmetry) out << "symmetry " << symmetryName(s.symmetry) << '\n';
    for (const Field& f : s.fields) {
        out << "field " << f.name << ": ";
        if (f.kind == FieldKind::Dir) out << "dir";
        else if (f.kind == FieldKind::Int) out << f.lo << ".." << f.hi;
        else
            for (std::size_t i = 0; i < f.values.size(); ++i) out << (i ? " | " : "") << f.values[i];
        if (f.whenField >= 0) {
            out << " if ";
            for (std::size_t i = 0; i < f.whenValues.size(); ++i)
                out << (i ? " | " : "") << s.fields[f.whenField].values[f.whenValues[i]];
        }
        out << '\n';
    }
    for (const std::string& in : s.inputs) out << "input " << in << '\n';
    if (!s.masses.empty()) {
        out << "mass ";
        for (std::size_t i = 0; i < s.masses.size(); ++i)
            out << (i ? ", " : "") << s.fields[s.masses[i].field].values[s.masses[i].value] << " = " << s.masses[i].mass.str();
        out << '\n';
    }
    for (const Rule& r : s.rules) out << printRule(s, r) << '\n';
    for (const Constraint& c : s.constraints) out << "constraint " << printExpr(s, c.expr) << '\n';
    if (s.goal) out << "goal " << printExpr(s, *s.goal) << '\n';
    for (const Property& p : s.properties) {
        switch (p.kind) {
        case Property::Kind::Invariant: out << "invariant " << p.name << ": " << printExpr(s, p.exprs[0]); break;
        case Property::Kind::Ranking:
            out << "ranking " << p.name << ":";
            for (std::size_t i = 0; i < p.exprs.size(); ++i) out << (i ? ", " : " ") << printExpr(s, p.exprs[i]);
            for (std::size_t i = 0; i < p.except.size(); ++i) out << (i ? ", " : " except ") << p.except[i];
            break;
        case Property::Kind::Progress:
            out << "progress";
            if (p.name != "progress") out << ' ' << p.name;
            if (!p.exprs.empty()) out << " assuming " << printExpr(s, p.exprs[0]);
            break;
        case Property::Kind::Holonomic:
            out << "holonomic " << (p.name == "holonomy" ? "" : p.name + " ") << "by " << (p.adjacency == Property::Adjacency::Move ? "move" : "occupancy");
            if (!p.exprs.empty()) out << " of " << printPredicate(s, p.exprs[0].pred);
            break;
        case Property::Kind::Conserves:
            out << "conserves " << (p.quantity == Property::Quantity::Mass ? "mass" : "count");
            if (p.name != (p.quantity == Property::Quantity::Mass ? "mass_conservation" : "count_conservation")) out << ' ' << p.name;
            break;
        }
        out << '\n';
    }
    return out.str();
}

const char* propertyKindName(Property::Kind kind) {
    switch (kind) {
    case Property::Kind::Invariant: return "invariant";
    case Property::Kind::Progress: return "progress";
    case Property::Kind::Ranking: return "ranking";
    case Property::Kind::Holonomic: return "holonomic";
    case Property::Kind::Conserves: return "conserves";
    }
    throw InternalError("a property kind with no name");
}

}  // namespace holon::rules
