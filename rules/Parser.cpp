// Recursive-descent parser for the .holon rule language (grammar in docs/language.md).
// Names are resolved as they are parsed (a name must be declared before it is used), so the IR it
// produces is complete. Errors abort only the current declaration: the parser skips to the next line
// and goes on, so one run reports every mistake in the file (Souffle's discipline). Semantic checks
// that need the cell alphabet run afterwards in validate().

#include "rules/Parser.h"

#include "rules/Error.h"
#include "rules/Lexer.h"
#include "rules/Limits.h"
#include "rules/Validate.h"

#include <algorithm>
#include <map>
#include <set>
#include <unordered_set>

namespace holon::rules {

namespace {

const std::set<std::string> kReserved{"if",
                                      "and", "or", "not", "implies", "assuming", "by", "nbr", "none", "dir", "true",
                                      "false", "count", "all", "some", "no", "connected", "reaches", "any", "of", "except"};

int editDistance(const std::string& a, const std::string& b) {
    std::vector<int> row(b.size() + 1);
    for (std::size_t j = 0; j <= b.size(); ++j) row[j] = static_cast<int>(j);
    for (std::size_t i = 1; i <= a.size(); ++i) {
        int diagonal = row[0];
        row[0] = static_cast<int>(i);
        for (std::size_t j = 1; j <= b.size(); ++j) {
            const int up = row[j];
            row[j] = std::min({row[j] + 1, row[j - 1] + 1, diagonal + (a[i - 1] != b[j - 1])});
            diagonal = up;
        }
    }
    return row[b.size()];
}

/// "; did you mean 'x'?" for the closest candidate within two edits, or nothing.
std::string suggestion(const std::string& name, const std::vector<std::string>& candidates) {
    const std::string* best = nullptr;
    int bestDistance = 3;
    for (const std::string& c : candidates)
        if (int dist = editDistance(name, c); dist < bestDistance && dist < static_cast<int>(c.size())) best = &c, bestDistance = dist;
    return best ? "; did you mean '" + *best + "'?" : "";
}

bool isBoolExpr(const Expr& e) {
    switch (e.kind) {
    case Expr::Kind::Number:
    case Expr::Kind::Mass:
    case Expr::Kind::Add:
    case Expr::Kind::Sub:
    case Expr::Kind::Neg:
    case Expr::Kind::Count:
        return false;
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
        return true;
    }
    return true;
}

class Parser {
public:
    Parser(const std::vector<Token>& tokens, Diagnostics& d) : t_(tokens), d_(d) {}

    System run() {
        while (peek().kind != Token::Kind::End && !d_.stopped()) {
            if (peek().kind == Token::Kind::Newline) {
                ++p_;
                continue;
            }
            try {
                declaration();
                if (peek().kind != Token::Kind::Newline) fail(peek().loc, "unexpected " + describe(peek()) + " at the end of the declaration");
            } catch (const Fail&) {
                while (peek().kind != Token::Kind::Newline && peek().kind != Token::Kind::End) ++p_;
            }
        }
        return std::move(s_);
    }

private:
    struct Fail {};
    const std::vector<Token>& t_;
    Diagnostics& d_;
    System s_;
    std::size_t p_ = 0;
    std::set<std::string> ruleNames_, propertyNames_;
    bool sawSystem_ = false, sawSymmetry_ = false, sawLattice_ = false;
    // Context of the rule being parsed: pattern length for @k references, guard mode.
    int patternCells_ = -1;
    bool inGuard_ = false;

    const Token& peek(std::size_t k = 0) const { return t_[std::min(p_ + k, t_.size() - 1)]; }
    bool at(std::string_view text) const { return peek().is(text); }
    bool accept(std::string_view text) {
        if (!at(text)) return false;
        ++p_;
        return true;
    }
    const Token& next() {
        const Token& tok = peek();
        if (tok.kind != Token::Kind::End) ++p_;
        return tok;
    }
    [[noreturn]] void fail(SourceLoc loc, std::string message) {
        d_.error(loc, std::move(message));
        throw Fail{};
    }
    static std::string describe(const Token& tok) {
        switch (tok.kind) {
        case Token::Kind::Newline: return "end of line";
        case Token::Kind::End: return "end of file";
        case Token::Kind::Ident:
        case Token::Kind::Int:
        case Token::Kind::Punct: break;
        }
        return "'" + tok.text + "'";
    }
    void expect(std::string_view text, std::string_view context) {
        if (!accept(text))
            fail(peek().loc, "expected '" + std::string(text) + "' " + std::string(context) + ", found " + describe(peek()));
    }
    const Token& identifier(std::string_view what) {
        const Token& tok = peek();
        if (tok.kind != Token::Kind::Ident) fail(tok.loc, "expected " + std::string(what) + ", found " + describe(tok));
        return next();
    }
    static bool reserved(const std::string& word) {
        const auto& decl = declarationKeywords();
        return kReserved.count(word) || std::find(decl.begin(), decl.end(), word) != decl.end();
    }
    const Token& freshName(std::string_view what) {
        const Token& tok = identifier(what);
        if (reserved(tok.text)) fail(tok.loc, "'" + tok.text + "' is a keyword and cannot name " + std::string(what));
        return tok;
    }
    int integer(std::string_view what) {
        bool negative = accept("-");
        const Token& tok = peek();
        if (tok.kind != Token::Kind::Int) fail(tok.loc, "expected " + std::string(what) + ", found " + describe(tok));
        next();
        return negative ? -std::stoi(tok.text) : std::stoi(tok.text);
    }

    // ---- names ---------------------------------------------------------------------------------
    struct ValueRef {
        int field = -1, value = -1;
    };
    std::map<std::string, std::vector<ValueRef>, std::less<>> values_;  // by name: a lookup per use stays cheap
    std::vector<ValueRef> findValue(const std::string& name) const {
        auto it = values_.find(name);
        return it == values_.end() ? std::vector<ValueRef>{} : it->second;
    }
    bool nameTaken(const std::string& name) const {
        return !findValue(name).empty() || s_.fieldIndex(name) >= 0 || s_.inputIndex(name) >= 0;
    }
    ValueRef uniqueValue(const Token& tok) {
        auto found = findValue(tok.text);
        if (found.empty()) {
            std::vector<std::string> known = s_.inputs;
            for (const Field& f : s_.fields) known.insert(known.end(), f.values.begin(), f.values.end());
            const std::string hint = suggestion(tok.text, known);
            fail(tok.loc, "unknown state '" + tok.text + "'" + (hint.empty() ? "; declare it in a field before using it" : hint));
        }
        if (found.size() > 1)
            fail(tok.loc, "'" + tok.text + "' is a value of fields '" + s_.fields[found[0].field].name + "' and '" +
                              s_.fields[found[1].field].name + "'; write " + s_.fields[found[0].field].name + "=" + tok.text);
        return found[0];
    }

    // ---- declarations --------------------------------------------------------------------------
    void declaration() {
        const Token& kw = identifier("a declaration (system, field, rule, constraint, ...)");
        const std::string& k = kw.text;
        if (k == "system") return systemDecl(kw);
        if (k == "lattice") return latticeDecl(kw);
        if (k == "symmetry") return symmetryDecl(kw);
        if (k == "field") {
            const std::string& name = freshName("a field").text;
            expect(":", "after the field name, as in field label: U | P | F");
            return fieldDecl(kw.loc, name);
        }
        if (k == "states") return fieldDecl(kw.loc, "state");
        if (k == "input") return inputDecl();
        if (k == "mass") return massDecl();
        if (k == "rule") return ruleDecl(kw.loc);
        if (k == "constraint") return s_.constraints.push_back({boolExpr(), kw.loc});
        if (k == "goal") {
            if (s_.goal) fail(kw.loc, "a system has one goal; join the conditions with 'and'");
            s_.goal = boolExpr();
            return;
        }
        if (k == "invariant" || k == "ranking" || k == "progress" || k == "holonomic" || k == "conserves")
            return propertyDecl(kw);
        const std::string hint = suggestion(k, declarationKeywords());
        if (!hint.empty()) fail(kw.loc, "unknown declaration '" + k + "'" + hint);
        fail(kw.loc, "unknown declaration '" + k +
                         "'; expected system, lattice, symmetry, field, states, input, mass, rule, constraint, goal, invariant, "
                         "ranking, progress, holonomic or conserves");
    }

    void systemDecl(const Token& kw) {
        const Token& name = freshName("the system");
        if (sawSystem_) fail(kw.loc, "a file declares one system; '" + s_.name + "' was declared already");
        sawSystem_ = true;
        s_.name = name.text, s_.loc = kw.loc;
    }

    void latticeDecl(const Token& kw) {
        // The last one won: a rule drawn for square2d was read as hex.
        if (sawLattice_) fail(kw.loc, "the lattice is declared twice; keep one 'lattice' line");
        sawLattice_ = true;
        const Token& name = identifier("a lattice");
        if (!s_.rules.empty()) fail(name.loc, "declare the lattice before the rules");
        if (name.text == "any") return;
        const Lattice* lattice = Lattice::byName(name.text);
        if (!lattice) fail(name.loc, "unknown lattice '" + name.text + "'; use square2d, cubic3d, hex2d or any");
        s_.lattice = lattice->kind();
    }

    void symmetryDecl(const Token& kw) {
        static const char* const kValid = "none, rotations or rotations+reflections";
        if (sawSymmetry_) fail(kw.loc, "the symmetry is declared twice; keep one 'symmetry' line");
        const Token& word = identifier(std::string("a symmetry: ") + kValid);
        if (word.text == "none") s_.symmetry = Symmetry::None;
        else if (word.text == "rotations" && !at("+")) s_.symmetry = Symmetry::Rotations;
        else if (word.text == "rotations") {
            next();
            const Token& second = peek();
            if (!second.is("reflections")) fail(second.loc, "expected 'reflections' after 'rotations+', found " + describe(second));
            next();
            s_.symmetry = Symmetry::RotationsReflections;
        } else if (word.text == "reflections") {
            fail(word.loc, "reflections come with the rotations: write 'symmetry rotations+reflections' (or rotations, or none)");
        } else {
            fail(word.loc, "unknown symmetry '" + word.text + "'; use " + kValid);
        }
        sawSymmetry_ = true;
    }

    // A name declared twice is reported and the declaration read on, so that its other names are
    // declared and their uses give no further errors.
    void fieldDecl(SourceLoc loc, const std::string& name) {
        Field f;
        f.name = name;
        f.loc = loc;
        if (s_.fieldIndex(name) >= 0) d_.error(loc, "field '" + name + "' is declared twice");
        else if (nameTaken(name)) d_.error(loc, "'" + name + "' already names a state or an input");
        // Past a limit the declaration is still read (once reported, the rest is not an error).
        if (static_cast<int>(s_.fields.size()) == kMaxFields)
            d_.error(loc, "a system has at most " + std::to_string(kMaxFields) + " fields");
        if (accept("dir")) {
            f.kind = FieldKind::Dir;
        } else if (peek().kind == Token::Kind::Int || at("-")) {
            f.kind = FieldKind::Int;
            f.lo = integer("the lower bound");
            expect("..", "between the bounds of an integer field, as in 0..3");
            f.hi = integer("the upper bound");
            if (f.hi < f.lo) fail(loc, "empty integer range " + std::to_string(f.lo) + ".." + std::to_string(f.hi));
            if (f.hi - f.lo >= kMaxFieldValues)
                fail(loc, "a field holds at most " + std::to_string(kMaxFieldValues) + " values");
        } else {
            // A set for the duplicate search: a search of the list made 140,000 values take 37 s
            // and a 4 MiB file run for minutes past --timeout.
            std::unordered_set<std::string> seen;
            do {
                const Token& v = freshName("a state");
                if (nameTaken(v.text) || !seen.insert(v.text).second)
                    d_.error(v.loc, "'" + v.text + "' is declared twice; state names must be unique in a system");
                else {
                    if (static_cast<int>(f.values.size()) == kMaxFieldValues)
                        d_.error(v.loc, "a field holds at most " + std::to_string(kMaxFieldValues) + " values");
                    f.values.push_back(v.text);
                }
            } while (accept("|"));
        }
        if (accept("if")) {
            do {
                const Token& v = identifier("a state of an earlier field");
                ValueRef r = uniqueValue(v);
                if (f.whenField >= 0 && f.whenField != r.field)
                    fail(v.loc, "the states after 'if' must belong to one field");
                f.whenField = r.field;
                f.whenValues.push_back(r.value);
            } while (accept("|"));
        }
        const int index = static_cast<int>(s_.fields.size());
        for (int v = 0; v < static_cast<int>(f.values.size()); ++v) values_[f.values[v]].push_back({index, v});
        s_.fields.push_back(std::move(f));
    }

    void inputDecl() {
        do {
            const Token& n = freshName("an input");
            if (nameTaken(n.text)) {
                d_.error(n.loc, "'" + n.text + "' is declared twice");
                continue;
            }
            if (static_cast<int>(s_.inputs.size()) == kMaxInputs)
                d_.error(n.loc, "a system has at most " + std::to_string(kMaxInputs) + " inputs (one bit each in a cell's input mask)");
            s_.inputs.push_back(n.text);
            s_.inputLocs.push_back(n.loc);
        } while (accept(","));
    }

    Rational rational() {
        int num = integer("a mass");
        int den = 1;
        if (accept("/")) {
            den = integer("a denominator");
            if (den <= 0) fail(peek().loc, "a denominator must be positive");
        }
        return Rational(num, den);
    }

    void massDecl() {
        do {
            const Token& v = identifier("a state");
            ValueRef r = uniqueValue(v);
            expect("=", "after the state in a mass declaration, as in mass C = 3/2");
            Rational m = rational();
            for (const MassEntry& e : s_.masses)
                if (e.field == r.field && e.value == r.value) fail(v.loc, "mass of '" + v.text + "' is declared twice");
            s_.masses.push_back({r.field, r.value, m, v.loc});
            checkMassUnits(v.loc);
        } while (accept(","));
    }

    /// Mass is counted exactly, as integers over the least common denominator of the masses, in
    /// 64 bits over boards of up to 2^30 cells: a cell may hold at most 2^32 such units (summed
    /// over its fields). Beyond, the sums wrapped and a rule that conserves mass was reported as
    /// changing it.
    void checkMassUnits(SourceLoc at) {
        constexpr std::int64_t kMaxUnits = std::int64_t{1} << 32;
        // Denominators are below 10^9 and the common multiple so far at most 2^32: the next one
        // fits checkedLcm's 64 bits.
        std::int64_t lcm = 1;
        for (const MassEntry& e : s_.masses)
            if ((lcm = checkedLcm(lcm, e.mass.den())) > kMaxUnits)
                fail(at, "the masses' denominators have a least common multiple above 2^32; holon counts mass exactly as integers over it: use denominators with a smaller common multiple");
        std::map<int, std::int64_t> heaviest;  // per field, the most units one of its values holds (each below 2^62)
        for (const MassEntry& e : s_.masses) heaviest[e.field] = std::max(heaviest[e.field], (e.mass.num() < 0 ? -e.mass.num() : e.mass.num()) * (lcm / e.mass.den()));
        std::int64_t cell = 0;
        for (const auto& [field, units] : heaviest)
            if ((cell += std::min(units, kMaxUnits + 1)) > kMaxUnits)
                fail(at, "a cell can hold more than 2^32 units of mass over the masses' least common denominator; holon counts mass exactly in 64 bits: use smaller masses or denominators with a smaller common multiple");
    }

    // ---- rules ---------------------------------------------------------------------------------
    void ruleDecl(SourceLoc loc) {
        Rule r;
        r.loc = loc;
        r.name = freshName("a rule").text;
        if (accept("/")) r.reverseName = freshName("the reverse rule").text;
        for (const std::string& n : {r.name, r.reverseName})
            if (!n.empty() && !ruleNames_.insert(n).second) d_.error(loc, "rule '" + n + "' is declared twice");
        expect(":", "after the rule name");
        patternCells_ = -1;
        r.lhs = pattern();
        const Token& arrow = peek();
        if (accept("<=>")) r.bidirectional = true;
        else if (!accept("=>")) fail(peek().loc, "expected '=>' or '<=>' after the left side, found " + describe(peek()));
        r.rhs = pattern();
        if (!r.reverseName.empty() && !r.bidirectional)
            fail(loc, "only a '<=>' rule has a reverse to name; drop '/" + r.reverseName + "'");
        if (r.lhs.size() != r.rhs.size())
            fail(arrow.loc, "the left side has " + cells(r.lhs.size()) + " and the right side " + cells(r.rhs.size()) +
                                "; a rule rewrites the same cells");
        if (r.lhs.size() > kMaxRuleCells)
            fail(loc, "rule '" + r.name + "' has " + cells(r.lhs.size()) + "; a rule reads at most " + std::to_string(kMaxRuleCells));
        patternCells_ = static_cast<int>(r.lhs.size());
        checkLayout(r);
        if (accept("if")) {
            if (r.bidirectional)
                fail(peek().loc,
                     "a '<=>' rule cannot have a guard (it would hold before one direction only); "
                     "write the two directions as separate '=>' rules");
            inGuard_ = true;
            try {
                r.guard = boolExpr();
            } catch (const Fail&) {
                inGuard_ = false;
                throw;
            }
            inGuard_ = false;
        }
        checkSides(r);
        checkRefs(r);
        s_.rules.push_back(std::move(r));
    }

    static std::string cells(std::size_t n) { return std::to_string(n) + (n == 1 ? " cell" : " cells"); }

    std::vector<CellTerm> pattern() {
        std::vector<CellTerm> cells;
        while (!at("=>") && !at("<=>") && !at("if") && peek().kind != Token::Kind::Newline &&
               peek().kind != Token::Kind::End)
            cells.push_back(cellTerm(true));
        if (cells.empty()) fail(peek().loc, "expected a cell (a state, '_', '*' or '#'), found " + describe(peek()));
        return cells;
    }

    CellTerm cellTerm(bool allowOffset) {
        CellTerm c;
        c.loc = peek().loc;
        if (allowOffset && at("@") && peek(1).kind == Token::Kind::Int) {
            next();
            c.copyFrom = integer("a pattern cell index");
            return c;
        }
        if (accept("_")) c.base = CellTerm::Base::Empty;
        else if (accept("*")) c.base = CellTerm::Base::Any;
        else if (accept("#")) c.base = CellTerm::Base::Occupied;
        else {
            c.atoms.push_back(atom());
        }
        while (accept("&")) c.atoms.push_back(atom());
        for (const Atom& a : c.atoms) {
            if (a.kind != Atom::Kind::Field) continue;
            if (c.base == CellTerm::Base::Empty) fail(a.loc, "an empty cell '_' has no fields to test");
            c.base = CellTerm::Base::Occupied;
        }
        if (at("@") && peek(1).is("(")) {
            if (!allowOffset) fail(peek().loc, "positions '@(...)' belong in rule patterns only");
            next(), next();
            c.hasOffset = true;
            c.offset.x = integer("an x offset");
            expect(",", "between coordinates");
            c.offset.y = integer("a y offset");
            if (accept(",")) c.offset.z = integer("a z offset");
            expect(")", "after the coordinates");
        }
        return c;
    }

    Atom atom() {
        Atom a;
        a.loc = peek().loc;
        a.negated = accept("!");
        const Token& name = identifier("a state, a field or an input");
        if (accept("=")) {
            a.kind = Atom::Kind::Field;
            a.index = s_.fieldIndex(name.text);
            if (a.index < 0) fail(name.loc, "unknown field '" + name.text + "'");
            a.value = fieldValue(s_.fields[a.index]);
            return a;
        }
        if (int in = s_.inputIndex(name.text); in >= 0) {
            a.kind = Atom::Kind::Input;
            a.index = in;
            return a;
        }
        if (s_.fieldIndex(name.text) >= 0)
            fail(name.loc, "'" + name.text + "' is a field; test it with " + name.text + "=VALUE");
        ValueRef r = uniqueValue(name);
        a.kind = Atom::Kind::Field;
        a.index = r.field;
        a.value = {FieldValue::Kind::Literal, r.value};
        return a;
    }

    FieldValue fieldValue(const Field& f) {
        const Token& tok = peek();
        if (accept("none")) {
            if (f.kind != FieldKind::Dir && f.whenField < 0)
                fail(tok.loc, "field '" + f.name + "' is always present; 'none' applies to dir fields and fields with 'if'");
            return {FieldValue::Kind::None, 0};
        }
        if (f.kind == FieldKind::Dir) {
            expect("@", "before a pattern cell index: a dir field points at a cell of the rule, as in parent=@0");
            const Token& k = peek();
            int cell = integer("a pattern cell index");
            if (cell < 0) fail(k.loc, "pattern cell indices start at 0");
            return {FieldValue::Kind::CellRef, cell};
        }
        if (f.kind == FieldKind::Int) {
            int v = integer("an integer");
            if (v < f.lo || v > f.hi)
                fail(tok.loc, std::to_string(v) + " is outside the range " + std::to_string(f.lo) + ".." + std::to_string(f.hi) +
                                  " of field '" + f.name + "'");
            return {FieldValue::Kind::Literal, v};
        }
        const Token& v = identifier("a state of field '" + f.name + "'");
        auto it = std::find(f.values.begin(), f.values.end(), v.text);
        if (it == f.values.end()) fail(v.loc, "'" + v.text + "' is not a state of field '" + f.name + "'");
        return {FieldValue::Kind::Literal, static_cast<int>(it - f.values.begin())};
    }

    void checkLayout(const Rule& r) {
        const bool first = r.lhs[0].hasOffset;
        std::vector<Vec> seen;
        for (const auto* side : {&r.lhs, &r.rhs})
            for (std::size_t i = 0; i < side->size(); ++i) {
                const CellTerm& c = (*side)[i];
                if (side == &r.rhs) {
                    if (c.hasOffset && r.lhs[i].offset != c.offset)
                        fail(c.loc, "a right-side cell has the position of its left-side cell; drop the '@(...)'");
                    continue;
                }
                if (c.hasOffset != first)
                    fail(c.loc, "give every cell of the pattern a position '@(x,y)', or none (cells then form a line)");
                if (!c.hasOffset) continue;
                if (!s_.lattice)
                    fail(c.loc, "positions '@(...)' need a fixed lattice; declare 'lattice hex2d' (or square2d, cubic3d) first");
                if (std::find(seen.begin(), seen.end(), c.offset) != seen.end())
                    fail(c.loc, "two cells of the pattern have the same position");
                if (Lattice::get(*s_.lattice).dimension() == 2 && c.offset.z != 0)
                    fail(c.loc, "a 2D lattice has no z coordinate");
                seen.push_back(c.offset);
            }
    }

    void checkSides(const Rule& r) {
        for (const CellTerm& c : r.lhs)
            if (c.copyFrom >= 0) fail(c.loc, "'@" + std::to_string(c.copyFrom) + "' copies a state and belongs on the right side");
        for (const CellTerm& c : r.rhs) {
            if (c.copyFrom < 0) continue;
            if (r.bidirectional) fail(c.loc, "a copy '@k' makes a rule one-way; write the two directions as separate '=>' rules");
            if (c.copyFrom >= static_cast<int>(r.lhs.size()))
                fail(c.loc, "@" + std::to_string(c.copyFrom) + " names no cell: the pattern has cells @0..@" + std::to_string(r.lhs.size() - 1));
        }
        auto checkAssignable = [&](const CellTerm& c, bool inputsAllowed, const char* side) {
            if (c.base == CellTerm::Base::Occupied && c.atoms.empty())
                fail(c.loc, std::string("'#' on the ") + side + " side does not say which state the cell becomes; name it");
            std::set<int> fields;
            for (const Atom& a : c.atoms) {
                if (a.negated && a.kind != Atom::Kind::Input) fail(a.loc, std::string("a negation on the ") + side + " side does not say what the cell becomes");
                if (a.kind == Atom::Kind::Input && !inputsAllowed)
                    fail(a.loc, "inputs are read-only; move the condition '" + s_.inputs[a.index] + "' to the left side");
                if (a.kind == Atom::Kind::Field && !fields.insert(a.index).second)
                    fail(a.loc, "field '" + s_.fields[a.index].name + "' is set twice in one cell");
            }
        };
        for (const CellTerm& c : r.rhs) checkAssignable(c, r.bidirectional, "right");
        if (r.bidirectional)
            for (const CellTerm& c : r.lhs) checkAssignable(c, true, "left (the rule runs both ways)");
    }

    void checkRefs(const Rule& r) {
        // Every `@k` must name a cell of the pattern; on a line pattern, a pointer can only hold the
        // direction of an adjacent cell.
        for (const auto* side : {&r.lhs, &r.rhs})
            for (std::size_t i = 0; i < side->size(); ++i)
                for (const Atom& a : (*side)[i].atoms) {
                    if (a.value.kind != FieldValue::Kind::CellRef) continue;
                    const int k = a.value.value;
                    if (k >= patternCells_)
                        fail(a.loc, "@" + std::to_string(k) + " names no cell: the pattern has cells @0..@" +
                                        std::to_string(patternCells_ - 1));
                    const bool adjacent = r.lhs[0].hasOffset
                                              ? Lattice::get(*s_.lattice).adjacent(r.lhs[i].offset, r.lhs[k].offset)
                                              : (k == static_cast<int>(i) + 1 || k + 1 == static_cast<int>(i));
                    if (!adjacent)
                        fail(a.loc, "@" + std::to_string(k) + " is not a neighbour of this cell, so no direction points at it");
                }
    }

    // ---- properties ----------------------------------------------------------------------------
    void propertyDecl(const Token& kw) {
        Property p;
        p.loc = kw.loc;
        const std::string& k = kw.text;
        auto optionalName = [&](const std::string& fallback) {
            if (peek().kind == Token::Kind::Ident && !reserved(peek().text)) return next().text;
            return fallback;
        };
        if (k == "invariant") {
            p.kind = Property::Kind::Invariant;
            p.name = freshName("the invariant").text;
            expect(":", "after the invariant's name");
            p.exprs.push_back(boolExpr());
        } else if (k == "ranking") {
            p.kind = Property::Kind::Ranking;
            p.name = freshName("the ranking").text;
            expect(":", "after the ranking's name");
            do p.exprs.push_back(numberExpr());
            while (accept(","));
            // Resource moves (general_n's transfers) belong to the allocator, which seed 000's
            // Lemma 3 leaves out: their steps must keep the ranking instead of decreasing it.
            if (accept("except")) do {
                    const Token& r = identifier("a rule");
                    if (!ruleNames_.count(r.text)) {
                        const std::string hint = suggestion(r.text, std::vector<std::string>(ruleNames_.begin(), ruleNames_.end()));
                        fail(r.loc, "unknown rule '" + r.text + "' after 'except'" + (hint.empty() ? "; declare the rule before the ranking" : hint));
                    }
                    p.except.push_back(r.text);
                } while (accept(","));
        } else if (k == "progress") {
            p.kind = Property::Kind::Progress;
            p.name = optionalName("progress");
            if (accept("assuming")) p.exprs.push_back(boolExpr());
            if (!s_.goal) fail(kw.loc, "progress needs a goal; declare 'goal ...' before it");
        } else if (k == "holonomic") {
            p.kind = Property::Kind::Holonomic;
            p.name = optionalName("holonomy");
            if (accept("by")) {
                const Token& how = identifier("'occupancy' or 'move'");
                if (how.text == "move") p.adjacency = Property::Adjacency::Move;
                else if (how.text != "occupancy") fail(how.loc, "holonomy is 'by occupancy' or 'by move'");
                else if (peek().is("of")) {
                    Expr count = node(Expr::Kind::Count, next().loc);
                    count.pred = predicate();
                    p.exprs.push_back(std::move(count));
                }
            }
        } else {
            p.kind = Property::Kind::Conserves;
            const Token& what = identifier("'mass' or 'count'");
            if (what.text == "count") p.quantity = Property::Quantity::Count;
            else if (what.text != "mass") fail(what.loc, "a system conserves 'mass' or 'count'");
            p.name = optionalName(what.text + "_conservation");
        }
        if (!propertyNames_.insert(p.name).second) fail(kw.loc, "property '" + p.name + "' is declared twice");
        s_.properties.push_back(std::move(p));
    }

    // ---- expressions ---------------------------------------------------------------------------
    // Every tree is at most kMaxExprDepth deep, each operator of a chain counting as a level (each
    // function returns its tree with its height), and the parser's own recursion (parentheses,
    // `not`, unary minus, `implies`, a quantifier's cell guard) stops at the same depth. So neither
    // the parser nor a later pass over expressions (printer, interpreter, compiled guards, SMT
    // encoding: all recursive) can overflow the stack, and chains are built in linear time.
    struct Tree {
        Expr expr;
        int height = 1;
    };
    int nesting_ = 0;
    [[noreturn]] void tooDeep(SourceLoc loc) {
        fail(loc, "expression nested deeper than " + std::to_string(kMaxExprDepth) +
                      " levels; split it into smaller expressions (each operator of a chain such as a + b + c counts as a level)");
    }
    /// One level of the parser's recursion, left on return or on failure.
    class Nest {
    public:
        Nest(Parser& p, SourceLoc loc) : p_(p) {
            if (p_.nesting_ >= kMaxExprDepth) p_.tooDeep(loc);
            ++p_.nesting_;
        }
        ~Nest() { --p_.nesting_; }
        Nest(const Nest&) = delete;
        Nest& operator=(const Nest&) = delete;

    private:
        Parser& p_;
    };
    Expr boolExpr() { return condition().expr; }
    Tree condition() {
        SourceLoc loc = peek().loc;
        Tree e = expr();
        if (!isBoolExpr(e.expr)) fail(loc, "expected a condition, found a number; compare it, as in count(F) >= 1");
        return e;
    }
    Expr numberExpr() {
        SourceLoc loc = peek().loc;
        Expr e = expr().expr;
        if (isBoolExpr(e)) fail(loc, "expected a number, found a condition");
        return e;
    }
    Expr node(Expr::Kind kind, SourceLoc loc) {
        Expr e;
        e.kind = kind;
        e.loc = loc;
        return e;
    }
    /// A node over `kids`, which are moved, not copied (a copy per operator made chains quadratic).
    template <class... Kids>
    Tree join(Expr::Kind kind, SourceLoc loc, Kids&&... kids) {
        Tree t{node(kind, loc), 1 + std::max({kids.height...})};
        if (t.height > kMaxExprDepth) tooDeep(loc);
        t.expr.kids.reserve(sizeof...(kids));
        (t.expr.kids.push_back(std::move(kids.expr)), ...);
        return t;
    }
    void requireBool(const Expr& e, bool want) {
        if (isBoolExpr(e) != want) fail(e.loc, want ? "expected a condition here, found a number" : "expected a number here, found a condition");
    }
    Tree expr() {
        Tree lhs = disjunction();
        if (peek().is("implies")) {
            SourceLoc loc = next().loc;
            Nest nest(*this, loc);
            Tree rhs = expr();
            requireBool(lhs.expr, true), requireBool(rhs.expr, true);
            return join(Expr::Kind::Implies, loc, std::move(lhs), std::move(rhs));
        }
        return lhs;
    }
    Tree disjunction() {
        Tree e = conjunction();
        while (peek().is("or")) {
            SourceLoc loc = next().loc;
            Tree rhs = conjunction();
            requireBool(e.expr, true), requireBool(rhs.expr, true);
            e = join(Expr::Kind::Or, loc, std::move(e), std::move(rhs));
        }
        return e;
    }
    Tree conjunction() {
        Tree e = negation();
        while (peek().is("and")) {
            SourceLoc loc = next().loc;
            Tree rhs = negation();
            requireBool(e.expr, true), requireBool(rhs.expr, true);
            e = join(Expr::Kind::And, loc, std::move(e), std::move(rhs));
        }
        return e;
    }
    Tree negation() {
        if (peek().is("not")) {
            SourceLoc loc = next().loc;
            Nest nest(*this, loc);
            Tree e = negation();
            requireBool(e.expr, true);
            return join(Expr::Kind::Not, loc, std::move(e));
        }
        return comparison();
    }
    Tree comparison() {
        Tree lhs = sum();
        static const std::pair<const char*, CmpOp> ops[] = {{"==", CmpOp::Eq}, {"!=", CmpOp::Ne}, {"<=", CmpOp::Le}, {">=", CmpOp::Ge}, {"<", CmpOp::Lt}, {">", CmpOp::Gt}};
        for (auto [text, op] : ops)
            if (at(text)) {
                SourceLoc loc = next().loc;
                Tree rhs = sum();
                requireBool(lhs.expr, false), requireBool(rhs.expr, false);
                Tree e = join(Expr::Kind::Compare, loc, std::move(lhs), std::move(rhs));
                e.expr.op = op;
                return e;
            }
        return lhs;
    }
    Tree sum() {
        Tree e = unary();
        while (at("+") || at("-")) {
            SourceLoc loc = peek().loc;
            Expr::Kind kind = next().text == "+" ? Expr::Kind::Add : Expr::Kind::Sub;
            Tree rhs = unary();
            requireBool(e.expr, false), requireBool(rhs.expr, false);
            e = join(kind, loc, std::move(e), std::move(rhs));
        }
        if (at("*") || at("/"))
            fail(peek().loc,
                 "expressions add and subtract (+, -) but do not multiply or divide; write 2 * count(F) as "
                 "count(F) + count(F), and a fraction as 3/2");
        return e;
    }
    Tree unary() {
        if (at("-")) {
            SourceLoc loc = next().loc;
            Nest nest(*this, loc);
            Tree e = unary();
            requireBool(e.expr, false);
            return join(Expr::Kind::Neg, loc, std::move(e));
        }
        return primary();
    }
    Tree primary() {
        const Token& tok = peek();
        SourceLoc loc = tok.loc;
        if (tok.kind == Token::Kind::Int) {
            Expr e = node(Expr::Kind::Number, loc);
            e.value = rational();
            return {std::move(e)};
        }
        if (accept("(")) {
            Nest nest(*this, loc);
            Tree e = expr();
            expect(")", "to close the parenthesis");
            return e;
        }
        if (accept("true") || accept("false")) {
            Expr e = node(Expr::Kind::Bool, loc);
            e.value = tok.text == "true" ? 1 : 0;
            return {std::move(e)};
        }
        if (accept("mass")) {
            if (inGuard_) fail(loc, "a guard is local; total mass is a non-local condition, write it as a constraint");
            return {node(Expr::Kind::Mass, loc)};
        }
        static const std::pair<const char*, Expr::Kind> quantifiers[] = {
            {"count", Expr::Kind::Count}, {"all", Expr::Kind::All}, {"some", Expr::Kind::Some}, {"no", Expr::Kind::No}};
        for (auto [word, kind] : quantifiers)
            if (accept(word)) return quantifier(kind, loc, word);
        if (accept("connected")) {
            Expr e = node(Expr::Kind::Connected, loc);
            if (accept("nbr")) {  // local: the neighbours satisfying pred touch each other
                if (!inGuard_) fail(loc, "'connected nbr' looks at a rule's neighbourhood and belongs in a guard");
                aroundCell(e);
                e.pred = predicate();
                return {std::move(e)};
            }
            nonLocal(loc, "connected");
            if (accept("(")) {
                e.pred = predicate();
                expect(")", "after the cells of connected(...)");
            } else {
                CellTerm occupied;
                occupied.base = CellTerm::Base::Occupied;
                e.pred = {occupied};
            }
            return {std::move(e)};
        }
        if (accept("reaches")) {
            nonLocal(loc, "reaches");
            Expr e = node(Expr::Kind::Reaches, loc);
            expect("(", "after reaches, as in reaches(P, parent, F)");
            e.pred = predicate();
            expect(",", "after the cells that follow pointers");
            if (!accept("nbr")) {
                const Token& f = identifier("a dir field, or nbr");
                e.field = s_.fieldIndex(f.text);
                if (e.field < 0 || s_.fields[e.field].kind != FieldKind::Dir) fail(f.loc, "'" + f.text + "' is not a dir field (or nbr)");
            }
            expect(",", "after the field");
            e.target = predicate();
            expect(")", "to close reaches(...)");
            return {std::move(e)};
        }
        const std::string hint = tok.kind == Token::Kind::Ident
                                     ? suggestion(tok.text, {"connected", "reaches", "count", "all", "some", "no", "mass", "true", "false", "not"})
                                     : "";
        fail(loc, "expected an expression, found " + describe(tok) + hint);
    }
    void nonLocal(SourceLoc loc, const std::string& what) {
        if (inGuard_) fail(loc, "a guard is local; '" + what + "' is non-local, write it as a constraint");
    }
    Tree quantifier(Expr::Kind kind, SourceLoc loc, const std::string& word) {
        Tree t{node(kind, loc)};
        Expr& e = t.expr;
        if (accept("nbr")) {
            if (!inGuard_) fail(loc, "'" + word + " nbr' quantifies over a rule's neighbourhood and belongs in a guard");
            aroundCell(e);
            e.pred = predicate();
        } else if (accept("pattern")) {  // the rule's own cells, before the rewrite
            if (!inGuard_) fail(loc, "'" + word + " pattern' quantifies over a rule's own cells and belongs in a guard");
            e.around = Expr::kOwnCells;
            e.pred = predicate();
        } else {
            if (inGuard_) fail(loc, "a guard is local; write '" + word + " nbr ...' or '" + word + " pattern ...', or make this a constraint");
            expect("(", "after " + word + ", as in " + word + "(F)");
            e.pred = predicate();
            if (accept(":")) {  // a local condition on each of those cells, @0 being the cell
                Nest nest(*this, loc);
                const int outerCells = patternCells_;
                inGuard_ = true, patternCells_ = 1;
                try {
                    Tree guard = condition();
                    t.height = 1 + guard.height;
                    if (t.height > kMaxExprDepth) tooDeep(loc);
                    e.kids.push_back(std::move(guard.expr));
                } catch (const Fail&) {
                    inGuard_ = false, patternCells_ = outerCells;
                    throw;
                }
                inGuard_ = false, patternCells_ = outerCells;
            }
            expect(")", "to close " + word + "(...)");
        }
        return t;
    }
    /// After `nbr`: the pattern cell whose neighbours are meant, `@k` or by default @0.
    void aroundCell(Expr& e) {
        e.around = 0;
        if (accept("@")) {
            const Token& k = peek();
            e.around = integer("a pattern cell index");
            if (e.around < 0 || e.around >= patternCells_) fail(k.loc, "@" + std::to_string(e.around) + " names no cell of the pattern");
        }
    }
    CellPredicate predicate() {
        CellPredicate p;
        do {
            if (at("@") && peek(1).kind == Token::Kind::Int) {  // a guard's own pattern cell
                CellTerm c;
                c.loc = next().loc;
                c.copyFrom = integer("a pattern cell index");
                if (!inGuard_) fail(c.loc, "'@" + std::to_string(c.copyFrom) + "' names a rule's cell and belongs in rules and guards");
                if (c.copyFrom >= patternCells_) fail(c.loc, "@" + std::to_string(c.copyFrom) + " names no cell of the pattern");
                p.push_back(std::move(c));
                continue;
            }
            CellTerm c = cellTerm(false);
            for (const Atom& a : c.atoms)
                if (a.value.kind == FieldValue::Kind::CellRef && (!inGuard_ || a.value.value >= patternCells_))
                    fail(a.loc, inGuard_ ? "@" + std::to_string(a.value.value) + " names no cell of the pattern"
                                         : "'@k' names a rule's cell and belongs in rules and guards");
            p.push_back(std::move(c));
        } while (accept("|"));
        return p;
    }
};

}  // namespace

std::optional<System> parseSystem(std::string_view source, Diagnostics& diagnostics, std::string sourceName) {
    std::vector<Token> tokens = tokenize(source, diagnostics);
    System system = Parser(tokens, diagnostics).run();
    system.sourceName = std::move(sourceName);
    if (system.name.empty() && !diagnostics.hasErrors()) diagnostics.error({1, 1}, "the file declares no system; start it with 'system NAME'");
    if (diagnostics.hasErrors()) return std::nullopt;
    validate(system, diagnostics);
    if (diagnostics.hasErrors()) return std::nullopt;
    return system;
}

int System::fieldIndex(const std::string& name) const {
    for (int i = 0; i < static_cast<int>(fields.size()); ++i)
        if (fields[i].name == name) return i;
    return -1;
}

int System::inputIndex(const std::string& name) const {
    for (int i = 0; i < static_cast<int>(inputs.size()); ++i)
        if (inputs[i] == name) return i;
    return -1;
}

const Property* System::property(const std::string& name) const {
    for (const Property& p : properties)
        if (p.name == name) return &p;
    return nullptr;
}

bool System::conservesMass() const {
    return std::any_of(properties.begin(), properties.end(), [](const Property& p) { return p.kind == Property::Kind::Conserves && p.quantity == Property::Quantity::Mass; });
}

}  // namespace holon::rules
