// Compiles every rule shape of a system into decision tables (see RuleTables.h). The cell
// semantics come from rules/Cells (matchesTerm, rewriteTerm), the same functions the reference
// interpreter calls, so a table entry is the interpreter's answer for that (inputs, state) pair.

#include "rules/RuleTables.h"

#include "rules/Cells.h"
#include "rules/Error.h"

#include <algorithm>
#include <numeric>

namespace holon::rules {

namespace {
void setBit(std::vector<std::uint64_t>& bits, std::size_t i) { bits[i >> 6] |= std::uint64_t{1} << (i & 63); }
}  // namespace

RuleTables::Mask RuleTables::compileTerm(const CellTerm& term, const std::vector<Vec>* pattern, Vec position,
                                         const CellTerm* alsoInputs) const {
    Mask m;
    m.bits.assign((combos_.size() * alphabet_ + 63) / 64, 0);
    for (std::size_t c = 0; c < combos_.size(); ++c) {
        CellContext at{&model_->alphabet(), &model_->lattice(), position, combos_[c], pattern, false};
        for (int v = 0; v < alphabet_; ++v) {
            bool ok = matchesTerm(term, static_cast<CellValue>(v), at);
            if (ok && alsoInputs)
                for (const Atom& a : alsoInputs->atoms)
                    if (a.kind == Atom::Kind::Input) {
                        CellTerm only;
                        only.atoms = {a};
                        ok = ok && matchesTerm(only, static_cast<CellValue>(v), at);
                    }
            if (ok) setBit(m.bits, c * alphabet_ + v);
        }
    }
    return m;
}

RuleTables::Mask RuleTables::compilePredicate(const CellPredicate& pred, const std::vector<Vec>* pattern, Vec position) const {
    Mask m;
    m.bits.assign((combos_.size() * alphabet_ + 63) / 64, 0);
    for (const CellTerm& t : pred) {
        Mask one = compileTerm(t, pattern, position, nullptr);
        for (std::size_t i = 0; i < m.bits.size(); ++i) m.bits[i] |= one.bits[i];
    }
    return m;
}

RuleTables::GuardNode RuleTables::compileGuard(const Expr& e, const RuleShape& shape) const {
    GuardNode g;
    g.kind = e.kind, g.op = e.op, g.value = e.value, g.around = e.around;
    for (const Expr& k : e.kids) g.kids.push_back(compileGuard(k, shape));
    if (e.around >= 0)
        for (int d = 0; d < model_->lattice().degree(); ++d)
            g.perSite.push_back(compilePredicate(e.pred, &shape.offsets, shape.offsets[e.around] + model_->lattice().direction(d)).bits);
    if (e.around == Expr::kOwnCells)
        for (Vec v : shape.offsets) g.perSite.push_back(compilePredicate(e.pred, &shape.offsets, v).bits);
    for (const std::vector<std::uint64_t>& mask : g.perSite) {
        const auto [any, all] = acceptedStates(mask);
        g.anyCombo.push_back(any), g.allCombo.push_back(all);
    }
    return g;
}

std::pair<std::uint64_t, std::uint64_t> RuleTables::acceptedStates(const std::vector<std::uint64_t>& bits) const {
    std::uint64_t any = 0, all = 0;
    for (int v = 0; v < std::min(alphabet_, 64); ++v) {
        bool some = false, every = true;
        for (std::size_t c = 0; c < combos_.size(); ++c) {
            const bool accepted = bit(bits, static_cast<int>(c), static_cast<CellValue>(v));
            some = some || accepted, every = every && accepted;
        }
        any |= std::uint64_t{some} << v, all |= std::uint64_t{every} << v;
    }
    return {any, all};
}

RuleTables::GuardNode RuleTables::compileCellGuard(const Expr& guard) const {
    RuleShape one;
    one.offsets = {Vec{}};
    return compileGuard(guard, one);
}

namespace {

/// The pattern cells a guard quantifies around (its sites are their neighbours).
void guardCentres(const RuleTables::GuardNode& g, std::vector<int>& out) {
    if (g.around >= 0) out.push_back(g.around);
    for (const auto& kid : g.kids) guardCentres(kid, out);
}

}  // namespace

std::vector<RuleTables::Site> RuleTables::readSites(int s) const {
    const Shape& t = shapes_[s];
    std::vector<Site> sites;
    for (int k = 0; k < static_cast<int>(t.lhs.size()); ++k) sites.push_back({k, -1});
    if (!t.hasGuard) return sites;
    std::vector<int> centres;
    guardCentres(t.guard, centres);
    std::sort(centres.begin(), centres.end());
    centres.erase(std::unique(centres.begin(), centres.end()), centres.end());
    for (int k : centres)
        for (int d = 0; d < model_->lattice().degree(); ++d) sites.push_back({k, d});
    return sites;
}

bool RuleTables::distinguishes(int s, Site site, CellValue v, CellValue w) const {
    auto differ = [&](const std::vector<std::uint64_t>& bits) {
        for (int c = 0; c < comboCount(); ++c)
            if (bit(bits, c, v) != bit(bits, c, w)) return true;
        return false;
    };
    // A quantifier tests its sites: the neighbours of pattern cell `around`, or the pattern cells.
    auto guardDiffers = [&](const auto& self, const GuardNode& g) -> bool {
        if (site.direction >= 0 && g.around == site.cell && differ(g.perSite[static_cast<std::size_t>(site.direction)])) return true;
        if (site.direction < 0 && g.around == Expr::kOwnCells && differ(g.perSite[static_cast<std::size_t>(site.cell)])) return true;
        for (const GuardNode& kid : g.kids)
            if (self(self, kid)) return true;
        return false;
    };
    const Shape& t = shapes_[s];
    if (site.direction < 0 && differ(t.lhs[static_cast<std::size_t>(site.cell)].bits)) return true;
    return t.hasGuard && guardDiffers(guardDiffers, t.guard);
}

bool RuleTables::mayWrite(int s, int k, int combo) const {
    const Shape& t = shapes_[s];
    if (t.copyFrom[k] >= 0) return t.copyFrom[k] != k;
    for (int c = combo < 0 ? 0 : combo; c < (combo < 0 ? comboCount() : combo + 1); ++c)
        for (int v = 0; v < alphabet_; ++v)
            if (test(t.lhs[k], c, static_cast<CellValue>(v)) && t.rhs[k][v] != v) return true;
    return false;
}

int RuleTables::comboIndex(std::uint32_t inputs) const {
    auto it = std::find(combos_.begin(), combos_.end(), inputs);
    return it == combos_.end() ? -1 : static_cast<int>(it - combos_.begin());
}

RuleTables::RuleTables(const Model& model, std::vector<std::uint32_t> combos, const std::vector<int>& onlyShapes)
    : model_(&model), alphabet_(model.alphabet().size()) {
    combos_.push_back(0);
    for (std::uint32_t c : combos)
        if (std::find(combos_.begin(), combos_.end(), c) == combos_.end()) combos_.push_back(c);
    const Lattice& lattice = model.lattice();
    for (int d = 0; d < lattice.degree(); ++d) {
        std::uint32_t touching = 0;
        for (int e = 0; e < lattice.degree(); ++e)
            if (lattice.adjacent(lattice.direction(d), lattice.direction(e))) touching |= 1u << e;
        directionNeighbours_.push_back(touching);
    }
    for (const RuleShape& shape : model.shapes()) {
        if (!onlyShapes.empty() && std::find(onlyShapes.begin(), onlyShapes.end(), static_cast<int>(shapes_.size())) == onlyShapes.end()) {
            shapes_.emplace_back();
            continue;
        }
        const DirectedRule& rule = model.rules()[shape.rule];
        if (shape.offsets.size() > kMaxCells) throw InternalError("rule '" + rule.name + "' has more cells than the parser admits");
        Shape t;
        for (std::size_t k = 0; k < shape.offsets.size(); ++k) {
            t.lhs.push_back(compileTerm(rule.lhs()[k], &shape.offsets, shape.offsets[k], &rule.rhs()[k]));  // the right side's inputs hold in both directions
            const CellTerm& rhs = rule.rhs()[k];
            t.copyFrom.push_back(rhs.copyFrom);
            std::vector<CellValue> table;
            if (rhs.copyFrom < 0) {
                CellContext at{&model.alphabet(), &lattice, shape.offsets[k], 0, &shape.offsets, false};
                for (int v = 0; v < alphabet_; ++v) {
                    const int w = rewriteTerm(rhs, static_cast<CellValue>(v), at);
                    table.push_back(static_cast<CellValue>(w < 0 ? v : w));
                }
            }
            t.rhs.push_back(std::move(table));
        }
        if (const Expr* g = rule.guard()) {
            t.hasGuard = true;
            t.guard = compileGuard(*g, shape);
        }
        shapes_.push_back(std::move(t));
    }
    shapesByFirst_.assign(combos_.size() * alphabet_, {});
    for (std::size_t c = 0; c < combos_.size(); ++c)
        for (int v = 0; v < alphabet_; ++v)
            for (int sh = 0; sh < static_cast<int>(shapes_.size()); ++sh)
                if (!shapes_[sh].lhs.empty() && test(shapes_[sh].lhs[0], static_cast<int>(c), static_cast<CellValue>(v))) shapesByFirst_[c * alphabet_ + v].push_back(sh);
    // Masses as integers over the least common denominator.
    for (int v = 0; v < alphabet_; ++v) massDen_ = checkedLcm(massDen_, model.alphabet().mass(static_cast<CellValue>(v)).den());
    for (int v = 0; v < alphabet_; ++v) {
        Rational m = model.alphabet().mass(static_cast<CellValue>(v));
        mass_.push_back(m.num() * (massDen_ / m.den()));
    }
}

}  // namespace holon::rules
