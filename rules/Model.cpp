// A system on a lattice. The alphabet enumerates the cell states (seed 000 §III: D, C, B1..Bn-1; the
// planner's U/P/F labels with their parent pointers). Rule shapes close each generator under the
// system's symmetry group on the lattice (by default the full point group, rotations and
// reflections), in the spirit of Abrams and Ghrist's generator catalogues (seed 000 §II-C): a
// template written once along one direction applies in every orientation, and a one-sided template
// on both sides. Orientations that rewrite the same cells in the same way (a pair along the z axis
// turned about z; a line of cells mirrored in its own axis; the reverse of a self-inverse transfer)
// are kept once, found by comparing structural keys.

#include "rules/Model.h"

#include "rules/Error.h"
#include "rules/Printer.h"

#include <algorithm>
#include <set>

namespace holon::rules {

namespace {

std::string vecText(Vec v) { return "(" + std::to_string(v.x) + "," + std::to_string(v.y) + "," + std::to_string(v.z) + ")"; }

}  // namespace

Alphabet::Alphabet(const System& system, const Lattice& lattice) : system_(&system), lattice_(&lattice) {
    values_.push_back({});  // the vacuum
    std::vector<int> current(system.fields.size(), kAbsent);
    auto enumerate = [&](auto&& self, std::size_t f) -> void {
        if (f == system.fields.size()) {
            if (values_.size() > 65535) throw InputError("system '" + system.name + "' has more than 65535 cell states; use fewer or smaller fields");
            index_[current] = static_cast<int>(values_.size());
            values_.push_back(current);
            return;
        }
        const Field& field = system.fields[f];
        const bool active = field.whenField < 0 ||
                            std::count(field.whenValues.begin(), field.whenValues.end(), current[field.whenField]) > 0;
        std::vector<int> domain;
        if (!active) domain = {kAbsent};
        else if (field.kind == FieldKind::Enum)
            for (int v = 0; v < static_cast<int>(field.values.size()); ++v) domain.push_back(v);
        else if (field.kind == FieldKind::Int)
            for (int v = field.lo; v <= field.hi; ++v) domain.push_back(v);
        else {
            if (field.whenField < 0) domain.push_back(kAbsent);  // an unconditional pointer may hold none
            for (int d = 0; d < lattice.degree(); ++d) domain.push_back(d);
        }
        for (int v : domain) {
            current[f] = v;
            self(self, f + 1);
        }
        current[f] = kAbsent;
    };
    if (!system.fields.empty()) enumerate(enumerate, 0);
    else {
        index_[{}] = 1;
        values_.push_back({});
    }
    // Mass: the sum of the declared masses of a state's values; 1 per occupied cell when none are declared.
    mass_.assign(values_.size(), Rational(system.masses.empty() ? 1 : 0));
    mass_[0] = 0;
    for (std::size_t v = 1; v < values_.size(); ++v)
        for (const MassEntry& m : system.masses)
            if (values_[v][m.field] == m.value) mass_[v] += m.mass;
    glyph_.assign(values_.size(), 0);
    for (std::size_t v = 1; v < values_.size(); ++v) {
        std::string n;
        bool plain = true;
        for (std::size_t f = 0; f < system.fields.size(); ++f) {
            const Field& field = system.fields[f];
            if (values_[v][f] == kAbsent) continue;
            if (field.kind == FieldKind::Enum) n += field.values[values_[v][f]];
            else if (values_[v][f] != kAbsent && !(field.kind == FieldKind::Int && values_[v][f] == field.lo)) plain = false;
        }
        if (system.fields.empty()) n = "#";
        if (plain && n.size() == 1 && n != "." && n != "_") glyph_[v] = n[0];
    }
}

int Alphabet::find(const std::vector<int>& fields) const {
    auto it = index_.find(fields);
    return it == index_.end() ? -1 : it->second;
}

int Alphabet::byGlyph(char c) const {
    for (int v = 1; v < size(); ++v)
        if (glyph_[v] == c) return v;
    return -1;
}

std::string Alphabet::name(CellValue v) const {
    if (v == 0) return "_";
    std::string out;
    for (std::size_t f = 0; f < system_->fields.size(); ++f) {
        const Field& field = system_->fields[f];
        const int x = values_[v][f];
        if (x == kAbsent) continue;
        if (field.kind == FieldKind::Enum) out += (out.empty() ? "" : "&") + field.values[x];
        else
            out += (out.empty() ? "" : "&") + field.name + "=" +
                   (field.kind == FieldKind::Dir ? lattice_->directionName(x) : std::to_string(x));
    }
    return out.empty() ? "#" : out;
}

namespace {

/// The guard part of a structural key. Conjuncts are sorted, since their order means nothing: a
/// reflection that swaps two cells the guard treats alike (hole_delete's shepherds on either side
/// of the deletion node) then gives the key of the unreflected orientation.
void conjunctKeys(const System& s, const Expr& e, const RefPrinter& ref, std::vector<std::string>& out) {
    if (e.kind != Expr::Kind::And) {
        out.push_back("[" + printExpr(s, e, ref) + "]");
        return;
    }
    for (const Expr& k : e.kids) conjunctKeys(s, k, ref, out);
}

}  // namespace

Model::Model(const System& system, const Lattice& lattice)
    : system_(&system), lattice_(&lattice), alphabet_(system, lattice) {
    if (system.lattice && *system.lattice != lattice.kind())
        throw InputError("system '" + system.name + "' is written for the " + Lattice::get(*system.lattice).name() +
                         " lattice; choose a region of that lattice");
    for (const Rule& r : system.rules) {
        rules_.push_back({r.name, &r, false});
        if (r.bidirectional) rules_.push_back({r.reverseName.empty() ? r.name + ".rev" : r.reverseName, &r, true});
    }
    const std::span<const LinearMap> group = symmetries();
    struct Orientation {
        std::vector<Vec> offsets;
        std::string key;
    };
    std::vector<std::vector<Orientation>> orientations(rules_.size());
    for (std::size_t ri = 0; ri < rules_.size(); ++ri) {
        const DirectedRule& dr = rules_[ri];
        const auto& lhs = dr.lhs();
        for (const LinearMap& map : group) {
            std::vector<Vec> offsets;
            for (std::size_t i = 0; i < lhs.size(); ++i) {
                Vec base = dr.rule->lhs[0].hasOffset ? dr.rule->lhs[i].offset
                                                     : Vec{static_cast<int>(i) * lattice.direction(0).x,
                                                           static_cast<int>(i) * lattice.direction(0).y,
                                                           static_cast<int>(i) * lattice.direction(0).z};
                offsets.push_back(map.apply(base));
            }
            // Key: cells sorted by position relative to the lowest one; references (@k, parent=@k,
            // nbr@k) become offsets, so two orientations agree exactly when they read and write the
            // same cells in the same way, whatever index each cell has.
            Vec low = *std::min_element(offsets.begin(), offsets.end());
            auto refFrom = [&](Vec from) {
                return RefPrinter([&, from](int k) { return vecText(offsets[k] - from); });
            };
            std::vector<std::string> cells;
            for (std::size_t i = 0; i < lhs.size(); ++i)
                cells.push_back(vecText(offsets[i] - low) + printTerm(system, lhs[i], refFrom(offsets[i])) + ">" +
                                printTerm(system, dr.rhs()[i], refFrom(offsets[i])));
            std::sort(cells.begin(), cells.end());
            std::string key;
            for (const std::string& c : cells) key += c + ";";
            if (const Expr* g = dr.guard()) {
                std::vector<std::string> conjuncts;
                conjunctKeys(system, *g, refFrom(low), conjuncts);
                std::sort(conjuncts.begin(), conjuncts.end());
                key += "if";
                for (const std::string& c : conjuncts) key += c;
            }
            orientations[ri].push_back({std::move(offsets), std::move(key)});
        }
    }
    // The rotations claim their rewrites first, for every rule; a reflection keeps only what no
    // rotation of any rule gives. So a rule keeps the instances it had under rotations alone, and a
    // reflection adds none where the rules are already mirror-symmetric as a set (hex_pivot's
    // pivot_back is pivot mirrored).
    const std::size_t proper = std::min(group.size(), lattice.rotations().size());
    std::map<std::string, int> owner;
    std::vector<std::vector<bool>> kept(rules_.size(), std::vector<bool>(group.size(), false));
    for (auto [from, to] : {std::pair<std::size_t, std::size_t>{0, proper}, {proper, group.size()}})
        for (std::size_t ri = 0; ri < rules_.size(); ++ri)
            for (std::size_t g = from; g < to; ++g)
                kept[ri][g] = owner.emplace(orientations[ri][g].key, static_cast<int>(ri)).second;
    std::map<std::string, std::size_t> shapeOfKey;
    for (std::size_t ri = 0; ri < rules_.size(); ++ri)
        for (std::size_t g = 0; g < group.size(); ++g)
            if (kept[ri][g]) {
                shapeOfKey.emplace(orientations[ri][g].key, shapes_.size());
                shapes_.push_back({static_cast<int>(ri), static_cast<int>(g), orientations[ri][g].offsets, {static_cast<int>(ri)}});
            }
    for (std::size_t ri = 0; ri < rules_.size(); ++ri)
        for (const Orientation& o : orientations[ri]) {
            std::vector<int>& also = shapes_[shapeOfKey.at(o.key)].rules;
            if (std::find(also.begin(), also.end(), static_cast<int>(ri)) == also.end()) also.push_back(static_cast<int>(ri));
        }
    // A duplicate: every orientation of the rule is an orientation of some earlier rule.
    std::map<std::string, int> earlier;
    for (std::size_t ri = 0; ri < rules_.size(); ++ri) {
        bool covered = true;
        int repeats = -1;
        for (const Orientation& o : orientations[ri]) {
            auto it = earlier.find(o.key);
            if (it == earlier.end()) covered = false;
            else repeats = it->second;
        }
        if (covered && repeats >= 0) duplicates_.push_back({static_cast<int>(ri), repeats});
        for (const Orientation& o : orientations[ri]) earlier.emplace(o.key, static_cast<int>(ri));
    }
}

bool Model::ruleNamed(int rule, const std::vector<std::string>& names) const {
    const DirectedRule& r = rules_[rule];
    return std::find(names.begin(), names.end(), r.name) != names.end() || std::find(names.begin(), names.end(), r.rule->name) != names.end();
}

std::vector<int> Model::stepRuleList(int shape) const {
    const RuleShape& s = shapes_[static_cast<std::size_t>(shape)];
    std::vector<int> list{s.rule};
    for (int r : s.rules)
        if (rules_[r].rule != rules_[s.rule].rule) list.push_back(r);
    return list;
}

std::string Model::stepRules(int shape, bool quoted) const {
    const auto name = [&](int r) { return quoted ? "'" + rules_[r].name + "'" : rules_[r].name; };
    const std::vector<int> list = stepRuleList(shape);
    std::string out = name(list[0]);
    for (std::size_t k = 1; k < list.size(); ++k) out += (k == 1 ? " (also " : ", ") + name(list[k]);
    return list.size() == 1 ? out : out + ")";
}

int Model::shapeRule(int shape, const std::vector<std::string>& names, bool named) const {
    for (int r : shapes_[static_cast<std::size_t>(shape)].rules)
        if (ruleNamed(r, names) == named) return r;
    return -1;
}

int Model::shapeCount(int rule) const {
    return static_cast<int>(std::count_if(shapes_.begin(), shapes_.end(), [&](const RuleShape& s) { return s.rule == rule; }));
}

void requirePatternsNear(const Model& model, const std::string& what) {
    for (const RuleShape& shape : model.shapes())
        for (Vec o : shape.offsets) {
            const Vec d = o - shape.offsets.front();
            if (std::max({std::abs(d.x), std::abs(d.y), std::abs(d.z)}) <= kMaxPatternReach) continue;
            const Rule& rule = *model.rules()[shape.rule].rule;
            throw InputError(model.system().sourceName + ":" + std::to_string(rule.loc.line) + ":" + std::to_string(rule.loc.col) + ": rule '" + rule.name +
                             "' has a cell " + std::to_string(std::max({std::abs(d.x), std::abs(d.y), std::abs(d.z)})) + " steps from its first, and " + what +
                             " needs a rule's cells within " + std::to_string(kMaxPatternReach) + " steps of each other; bring them nearer");
        }
}

}  // namespace holon::rules
