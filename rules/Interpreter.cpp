// The reference semantics of the rule language (seed 000 §II-C). A generator instance is enabled
// when its left side matches, its guard holds, and the configuration it produces passes every
// non-local constraint: "all possible next configurations can be found by applying each generator at
// each admissible location, and then filtering the resulting set of configurations through all
// non-local constraints". Cells outside the region read as empty with no inputs; rules never write
// there. This file favours obviousness over speed: the fast engines are tested against it.

#include "rules/Interpreter.h"

#include "rules/Components.h"

#include <algorithm>

namespace holon::rules {

Interpreter::Interpreter(const Model& model, const Region& region) : model_(&model), region_(&region) {}

Configuration Interpreter::empty() const {
    return {std::vector<CellValue>(region_->size(), 0), std::vector<std::uint32_t>(region_->size(), 0)};
}

CellValue Interpreter::valueAt(Vec position, const Configuration& c) const {
    const int i = region_->indexOf(position);
    return i < 0 ? 0 : c.cells[i];
}

CellContext Interpreter::context(Vec position, const Configuration& c, const Placement* at) const {
    const int i = region_->indexOf(position);
    return {&model_->alphabet(), &model_->lattice(), position, i < 0 ? 0u : c.inputs[i], at ? &at->positions : nullptr, false};
}

std::optional<std::vector<int>> Interpreter::cellsOf(const Instance& instance) const {
    std::vector<int> cells;
    for (Vec o : model_->shapes()[instance.shape].offsets) {
        const int i = region_->indexOf(instance.anchor + o);
        if (i < 0) return std::nullopt;
        cells.push_back(i);
    }
    return cells;
}

bool Interpreter::matches(const Configuration& c, const Instance& instance) const {
    const RuleShape& shape = model_->shapes()[instance.shape];
    const DirectedRule& rule = model_->rules()[shape.rule];
    Placement at;
    for (Vec o : shape.offsets) {
        if (!region_->contains(instance.anchor + o)) return false;
        at.positions.push_back(instance.anchor + o);
    }
    for (std::size_t i = 0; i < at.positions.size(); ++i)
        if (!matchesTerm(rule.lhs()[i], valueAt(at.positions[i], c), context(at.positions[i], c, &at))) return false;
    // The input atoms of a `<=>` rule's right side are conditions of both directions (only such a
    // rule may have them): fired forwards, a move onto `A&target` needs the target there too. Read
    // only backwards, a rule pair's verdicts depended on which way round it was written.
    for (std::size_t i = 0; i < at.positions.size(); ++i)
        for (const Atom& a : rule.rhs()[i].atoms) {
            CellTerm inputOnly;
            inputOnly.atoms = {a};
            if (a.kind == Atom::Kind::Input && !matchesTerm(inputOnly, valueAt(at.positions[i], c), context(at.positions[i], c, &at)))
                return false;
        }
    return !rule.guard() || holdsAt(*rule.guard(), c, &at);
}

Blocked Interpreter::blocked(const Configuration& c, const Instance& instance) const {
    const RuleShape& shape = model_->shapes()[instance.shape];
    const DirectedRule& rule = model_->rules()[shape.rule];
    Placement at;
    for (Vec o : shape.offsets) at.positions.push_back(instance.anchor + o);
    Blocked why;
    for (std::size_t i = 0; i < at.positions.size(); ++i) {
        const CellContext here = context(at.positions[i], c, &at);
        bool ok = matchesTerm(rule.lhs()[i], valueAt(at.positions[i], c), here);
        for (const Atom& a : rule.rhs()[i].atoms) {
            CellTerm inputOnly;
            inputOnly.atoms = {a};
            ok = ok && (a.kind != Atom::Kind::Input || matchesTerm(inputOnly, valueAt(at.positions[i], c), here));
        }
        if (!ok) why.cells.push_back(static_cast<int>(i));
    }
    if (!rule.guard()) return why;
    const std::vector<const Expr*> parts = conjuncts(*rule.guard());
    for (std::size_t k = 0; k < parts.size() && why.conjunct < 0; ++k) {
        const Expr& e = *parts[k];
        if (holdsAt(e, c, &at)) continue;
        why.conjunct = static_cast<int>(k);
        if ((e.kind != Expr::Kind::No && e.kind != Expr::Kind::All) || (e.around < 0 && e.around != Expr::kOwnCells) || !e.kids.empty()) continue;
        std::vector<Vec> around;
        if (e.around >= 0)
            for (Vec d : model_->lattice().directions()) around.push_back(at.positions[e.around] + d);
        else
            around = at.positions;
        for (Vec p : around)
            if (matchesPredicate(e.pred, valueAt(p, c), context(p, c, &at)) == (e.kind == Expr::Kind::No)) why.witnesses.push_back(p);
    }
    return why;
}

Configuration Interpreter::apply(const Configuration& c, const Instance& instance) const {
    Configuration next = c;
    applyInPlace(next, instance);
    return next;
}

void Interpreter::applyInPlace(Configuration& c, const Instance& instance) const {
    const RuleShape& shape = model_->shapes()[instance.shape];
    const DirectedRule& rule = model_->rules()[shape.rule];
    Placement at;
    for (Vec o : shape.offsets) at.positions.push_back(instance.anchor + o);
    CellValue next[kMaxRuleCells];
    for (std::size_t i = 0; i < at.positions.size(); ++i) {
        const int cell = region_->indexOf(at.positions[i]);
        if (const int k = rule.rhs()[i].copyFrom; k >= 0) {
            next[i] = c.cells[region_->indexOf(at.positions[k])];
            continue;
        }
        const int value = rewriteTerm(rule.rhs()[i], c.cells[cell], context(at.positions[i], c, &at));
        // validate() proved every right side complete on every state its left side admits.
        next[i] = static_cast<CellValue>(value < 0 ? c.cells[cell] : value);
    }
    for (std::size_t i = 0; i < at.positions.size(); ++i) c.cells[region_->indexOf(at.positions[i])] = next[i];
}

std::optional<Configuration> Interpreter::successor(const Configuration& c, const Instance& instance) const {
    if (!matches(c, instance)) return std::nullopt;
    Configuration next = apply(c, instance);
    if (!legal(next)) return std::nullopt;
    return next;
}

std::vector<Instance> Interpreter::enabled(const Configuration& c) const {
    std::vector<Instance> out;
    const int shapes = static_cast<int>(model_->shapes().size());
    for (int s = 0; s < shapes; ++s) {
        const Vec first = model_->shapes()[s].offsets[0];
        // Anchor every shape so that its first cell runs over the region.
        for (Vec cell : region_->cells()) {
            Instance instance{s, cell - first};
            if (successor(c, instance)) out.push_back(instance);
        }
    }
    return out;
}

bool Interpreter::legal(const Configuration& c) const {
    for (const Constraint& k : model_->system().constraints)
        if (!holds(k.expr, c)) return false;
    return true;
}

bool Interpreter::atGoal(const Configuration& c) const {
    return model_->system().goal && holds(*model_->system().goal, c);
}

std::vector<const Expr*> conjuncts(const Expr& e) {
    if (e.kind != Expr::Kind::And) return {&e};
    std::vector<const Expr*> out;
    for (const Expr& k : e.kids)
        for (const Expr* c : conjuncts(k)) out.push_back(c);
    return out;
}

int Interpreter::firstFalseConjunct(const Expr& e, const Configuration& c) const {
    const auto parts = conjuncts(e);
    for (std::size_t k = 0; k < parts.size(); ++k)
        if (!holds(*parts[k], c)) return static_cast<int>(k);
    return -1;
}

bool Interpreter::holds(const Expr& e, const Configuration& c) const { return holdsAt(e, c, nullptr); }
Rational Interpreter::number(const Expr& e, const Configuration& c) const { return numberAt(e, c, nullptr); }

Rational Interpreter::mass(const Configuration& c) const {
    Rational m;
    for (CellValue v : c.cells) m += model_->alphabet().mass(v);
    return m;
}

int Interpreter::occupied(const Configuration& c) const {
    int n = 0;
    for (CellValue v : c.cells) n += v != 0;
    return n;
}

int Interpreter::countCells(const Expr& e, const Configuration& c, const Placement* at, bool withCellGuard) const {
    int n = 0;
    if (e.around >= 0) {
        const Vec centre = at->positions[e.around];
        for (Vec d : model_->lattice().directions())
            n += matchesPredicate(e.pred, valueAt(centre + d, c), context(centre + d, c, at));
        return n;
    }
    if (e.around == Expr::kOwnCells) {
        for (Vec p : at->positions) n += matchesPredicate(e.pred, valueAt(p, c), context(p, c, at));
        return n;
    }
    for (int i = 0; i < region_->size(); ++i) {
        if (!matchesPredicate(e.pred, c.cells[i], context(region_->cell(i), c, at))) continue;
        if (withCellGuard && !e.kids.empty()) {  // a cell guard, read with @0 at this cell
            Placement here;
            here.positions = {region_->cell(i)};
            if (!holdsAt(e.kids[0], c, &here)) continue;
        }
        ++n;
    }
    return n;
}

bool Interpreter::holdsAt(const Expr& e, const Configuration& c, const Placement* at) const {
    switch (e.kind) {
    case Expr::Kind::Bool: return e.value.num() != 0;
    case Expr::Kind::And: return holdsAt(e.kids[0], c, at) && holdsAt(e.kids[1], c, at);
    case Expr::Kind::Or: return holdsAt(e.kids[0], c, at) || holdsAt(e.kids[1], c, at);
    case Expr::Kind::Implies: return !holdsAt(e.kids[0], c, at) || holdsAt(e.kids[1], c, at);
    case Expr::Kind::Not: return !holdsAt(e.kids[0], c, at);
    case Expr::Kind::Compare: return compare(e.op, numberAt(e.kids[0], c, at), numberAt(e.kids[1], c, at));
    case Expr::Kind::Some: return countCells(e, c, at) > 0;
    case Expr::Kind::No: return countCells(e, c, at) == 0;
    case Expr::Kind::All: {
        if (!e.kids.empty()) return countCells(e, c, at) == countCells(e, c, at, false);  // every pred cell satisfies the cell guard
        const int total = e.around >= 0                 ? model_->lattice().degree()
                          : e.around == Expr::kOwnCells ? static_cast<int>(at->positions.size())
                                                        : region_->size();
        return countCells(e, c, at) == total;
    }
    case Expr::Kind::Connected: {
        if (e.around < 0) return connected(e.pred, c);
        // The neighbours of the pattern cell that satisfy pred, joined by lattice adjacency.
        const Lattice& lattice = model_->lattice();
        const Vec centre = at->positions[e.around];
        std::vector<Vec> members;
        for (Vec d : lattice.directions())
            if (matchesPredicate(e.pred, valueAt(centre + d, c), context(centre + d, c, at))) members.push_back(centre + d);
        std::vector<std::uint64_t> adjacent(members.size(), 0);  // members.size() <= degree <= 12
        for (std::size_t a = 0; a < members.size(); ++a)
            for (std::size_t b = 0; b < members.size(); ++b)
                if (lattice.adjacent(members[a], members[b])) adjacent[a] |= std::uint64_t{1} << b;
        return connectedWord((std::uint64_t{1} << members.size()) - 1, aroundByTable(adjacent.data()));
    }
    case Expr::Kind::Reaches: return reaches(e, c);
    case Expr::Kind::Number:
    case Expr::Kind::Mass:
    case Expr::Kind::Add:
    case Expr::Kind::Sub:
    case Expr::Kind::Neg:
    case Expr::Kind::Count:
        break;  // numbers never reach here: the parser types every expression
    }
    return false;
}

Rational Interpreter::numberAt(const Expr& e, const Configuration& c, const Placement* at) const {
    switch (e.kind) {
    case Expr::Kind::Number: return e.value;
    case Expr::Kind::Mass: return mass(c);
    case Expr::Kind::Add: return numberAt(e.kids[0], c, at) + numberAt(e.kids[1], c, at);
    case Expr::Kind::Sub: return numberAt(e.kids[0], c, at) - numberAt(e.kids[1], c, at);
    case Expr::Kind::Neg: return -numberAt(e.kids[0], c, at);
    case Expr::Kind::Count: return countCells(e, c, at);
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
        break;  // conditions never reach here: the parser types every expression
    }
    return 0;
}

bool Interpreter::connected(const CellPredicate& pred, const Configuration& c) const {
    std::vector<char> member(region_->size(), 0);
    for (int i = 0; i < region_->size(); ++i) member[i] = matchesPredicate(pred, c.cells[i], context(region_->cell(i), c, nullptr));
    const auto isMember = [&](std::int64_t i) { return member[i] != 0; };
    Flood flood;
    return rules::connected(flood, member.size(), verticesWhere(region_->size(), isMember), regionEdges(*region_, isMember));
}

bool Interpreter::reaches(const Expr& e, const Configuration& c) const {
    // Every pred cell follows its pointer through pred cells to a target cell, with no cycle and no
    // pointer leaving the region. Memoised: 0 unknown, 1 on the current walk, 2 good, 3 bad.
    const int n = region_->size();
    std::vector<char> state(n, 0);
    auto isPred = [&](int i) { return matchesPredicate(e.pred, c.cells[i], context(region_->cell(i), c, nullptr)); };
    auto isTarget = [&](int i) { return matchesPredicate(e.target, c.cells[i], context(region_->cell(i), c, nullptr)); };
    if (e.field < 0) {
        // Along lattice adjacency: search backwards from the targets through pred cells; every
        // pred cell must be found.
        Flood flood;
        flood.begin(n);
        const auto edges = regionEdges(*region_, isPred);
        for (int i = 0; i < n; ++i)
            if (isTarget(i)) edges(i, [&](std::int64_t j) { flood.add(j); });
        flood.spread(edges);
        for (int i = 0; i < n; ++i)
            if (isPred(i) && !flood.seen(i)) return false;
        return true;
    }
    for (int start = 0; start < n; ++start) {
        if (state[start] || !isPred(start)) continue;
        std::vector<int> walk;
        int i = start;
        char verdict = 3;
        while (true) {
            if (state[i] == 2 || state[i] == 3) {
                verdict = state[i];
                break;
            }
            if (state[i] == 1) break;  // a cycle
            state[i] = 1;
            walk.push_back(i);
            const int d = c.cells[i] == 0 ? kAbsent : model_->alphabet().fields(c.cells[i])[e.field];
            const int j = d == kAbsent ? -1 : region_->neighbour(i, d);
            if (j < 0) break;
            if (isTarget(j)) {
                verdict = 2;
                break;
            }
            if (!isPred(j)) break;
            i = j;
        }
        for (int w : walk) state[w] = verdict;
        if (verdict == 3) return false;
    }
    return true;
}

}  // namespace holon::rules
