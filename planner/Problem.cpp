// Planning problems for seed 000's U/P/F planner (§IV-A): exactly one seed metamodule in
// start ∩ target labelled F, every other start metamodule U. Theorem 1's preconditions are
// checked up front, each failure a message naming the fix: the start and the target connected,
// and a mass the target can hold (Definition 4, "#(E) supports T"). Where the system has
// resources (general_n), the start is all destroyers D except as many creators C, placed at random,
// as the target needs to reach its mass — the least mass that supports T.

#include "planner/Problem.h"

#include "rules/Error.h"
#include "rules/Limits.h"

#include <algorithm>
#include <numeric>

namespace holon::planner {

namespace {

using rules::Rational;

int valueIndex(const rules::Field& f, std::string_view name) {
    auto it = std::find(f.values.begin(), f.values.end(), name);
    return it == f.values.end() ? -1 : static_cast<int>(it - f.values.begin());
}

void requireConnected(const Shape& s, const char* role) {
    const auto parts = components(s.cells, s.dimension);
    if (parts.size() <= 1) return;
    throw InputError(std::string(role) + " shape '" + s.name + "' is not connected: it has " + std::to_string(parts.size()) +
                     " pieces, e.g. " + showCell(parts[0][0], s.dimension) + " and " + showCell(parts[1][0], s.dimension) +
                     " are not joined; the planner keeps the ensemble connected, so join the pieces");
}

/// The state whose fields take the given values and every other field its first value or none.
rules::CellValue findState(const rules::Alphabet& alphabet, const std::vector<std::pair<int, int>>& wanted) {
    for (int v = 1; v < alphabet.size(); ++v) {
        const std::vector<int>& f = alphabet.fields(static_cast<rules::CellValue>(v));
        bool ok = true;
        for (std::size_t i = 0; i < f.size() && ok; ++i) {
            auto it = std::find_if(wanted.begin(), wanted.end(), [&](auto& w) { return w.first == static_cast<int>(i); });
            ok = it != wanted.end() ? f[i] == it->second : (f[i] == rules::kAbsent || f[i] == 0);
        }
        if (ok) return static_cast<rules::CellValue>(v);
    }
    throw InternalError("the planner's start state is not in the alphabet");
}

}  // namespace

PlannerSchema PlannerSchema::of(const rules::System& system) {
    PlannerSchema s;
    const std::string fix =
        "; the planner needs a field 'label: U | P | F' and an input 'target' "
        "(see rules/library/planner_intermediate.holon)";
    for (std::size_t i = 0; i < system.fields.size(); ++i)
        if (system.fields[i].name == "label") s.label = static_cast<int>(i);
    if (s.label < 0) throw InputError("system '" + system.name + "' has no field 'label'" + fix);
    const rules::Field& label = system.fields[s.label];
    s.unknown = valueIndex(label, "U"), s.path = valueIndex(label, "P"), s.final = valueIndex(label, "F");
    if (label.kind != rules::FieldKind::Enum || s.unknown < 0 || s.path < 0 || s.final < 0)
        throw InputError("system '" + system.name + "': field 'label' lacks U, P or F" + fix);
    for (std::size_t i = 0; i < system.fields.size(); ++i)
        if (system.fields[i].name == "parent" && system.fields[i].kind == rules::FieldKind::Dir) s.parent = static_cast<int>(i);
    for (std::size_t i = 0; i < system.inputs.size(); ++i)
        if (system.inputs[i] == "target") s.target = static_cast<int>(i);
    if (s.target < 0) throw InputError("system '" + system.name + "' has no input 'target'" + fix);
    if (!system.constraints.empty())
        throw InputError("system '" + system.name + "' declares a non-local constraint (line " + std::to_string(system.constraints.front().loc.line) +
                         "); the planner is distributed and only runs local rules: state the property as an invariant and prove it with holon verify");
    if (!system.masses.empty()) {
        s.resource = system.masses.front().field;
        Rational best(-1);
        for (const rules::MassEntry& m : system.masses) {
            if (m.field != s.resource) throw InputError("system '" + system.name + "': the planner needs every mass on one resource field");
            if (m.mass == Rational(1)) s.full = m.value;
            if (best < m.mass) best = m.mass, s.creator = m.value;
        }
        s.extra = best - Rational(1);
        if (s.full < 0) throw InputError("system '" + system.name + "': no resource value has mass 1 (a full metamodule, D)");
    }
    return s;
}

std::optional<GoalMass> goalMass(const Problem& problem, int combo) {
    const rules::RuleTables& tables = *problem.tables;
    std::optional<GoalMass> g;
    for (int v = 0; v < tables.alphabet(); ++v) {
        const auto value = static_cast<rules::CellValue>(v);
        if (!tables.test(problem.goal, combo, value)) continue;
        const std::int64_t m = tables.massUnitsOf(value);
        g = g ? GoalMass{std::min(g->least, m), std::max(g->most, m)} : GoalMass{m, m};
    }
    return g;
}

Problem makeProblem(const rules::Model& model, Shape start, Shape target, std::optional<Vec> seed, std::uint64_t randomSeed, std::uint64_t memoryBytes,
                    const std::function<void()>& checkpoint) {
    Problem p;
    p.model = &model;
    p.schema = PlannerSchema::of(model.system());
    const rules::Lattice& lattice = model.lattice();
    for (const Shape* s : {&start, &target})
        if (s->dimension != lattice.dimension())
            throw InputError("shape '" + s->name + "' is " + std::to_string(s->dimension) + "D but the lattice " + lattice.name() + " is " +
                             std::to_string(lattice.dimension()) + "D; give both shapes in the same dimension");
    // The board's memory, checked before anything board-sized is made (the connectivity check too).
    p.tables = std::make_unique<rules::RuleTables>(model, std::vector<std::uint32_t>{1u << p.schema.target});
    Vec lo = start.cells[0], hi = start.cells[0];
    for (const Shape* sh : {&start, &target})
        for (Vec v : sh->cells) lo = {std::min(lo.x, v.x), std::min(lo.y, v.y), std::min(lo.z, v.z)}, hi = {std::max(hi.x, v.x), std::max(hi.y, v.y), std::max(hi.z, v.z)};
    {
        const std::uint64_t pad = 2 * static_cast<std::uint64_t>(BoxEngine::reach(*p.tables));
        const auto side = [&](int l, int h) { return static_cast<std::uint64_t>(std::int64_t{h} - l + 1) + pad; };
        const std::uint64_t cells = rules::checkedProduct({side(lo.x, hi.x), side(lo.y, hi.y), lattice.dimension() == 3 ? side(lo.z, hi.z) : 1});
        rules::requireMemory(rules::checkedProduct({cells, planBytesPerCell(p.tables->shapeCount(), lattice.degree(), p.schema.resource >= 0)}), memoryBytes,
                             "the plan's board (" + rules::countText(cells) + " cells: the box around start and target)");
    }
    requireConnected(target, "target");
    checkpoint();
    requireConnected(start, "start");
    checkpoint();
    std::vector<Vec> both;
    std::set_intersection(start.cells.begin(), start.cells.end(), target.cells.begin(), target.cells.end(), std::back_inserter(both));
    if (both.empty()) throw InputError("start '" + start.name + "' and target '" + target.name + "' do not overlap; the planner grows the target from a seed in both");
    if (seed) {
        if (!std::binary_search(both.begin(), both.end(), *seed))
            throw InputError("seed " + showCell(*seed, lattice.dimension()) + " is not in both start and target; choose a cell of their overlap");
        p.seed = *seed;
    } else {
        // The overlap cell nearest the overlap's centre: the F tree then grows evenly.
        double cx = 0, cy = 0, cz = 0;
        for (Vec v : both) cx += v.x, cy += v.y, cz += v.z;
        cx /= double(both.size()), cy /= double(both.size()), cz /= double(both.size());
        auto d2 = [&](Vec v) { return (v.x - cx) * (v.x - cx) + (v.y - cy) * (v.y - cy) + (v.z - cz) * (v.z - cz); };
        p.seed = *std::min_element(both.begin(), both.end(), [&](Vec a, Vec b) { return d2(a) < d2(b); });
    }
    const std::int64_t s = static_cast<std::int64_t>(start.cells.size()), t = static_cast<std::int64_t>(target.cells.size()), o = static_cast<std::int64_t>(both.size());
    p.toCreate = t - o, p.toDelete = s - o;

    // Resources: the least mass that supports T (Definition 4).
    const rules::Alphabet& alphabet = model.alphabet();
    const PlannerSchema& schema = p.schema;
    if (schema.resource >= 0) {
        const Rational extra = schema.extra;
        const Rational deficit = Rational(t - s);
        if (Rational(0) < deficit) {
            if (!(Rational(0) < extra)) throw InputError("the start has less mass than the target needs and no resource value carries more than 1");
            const Rational k = deficit * Rational(extra.den(), extra.num());
            p.creators = (k.num() + k.den() - 1) / k.den();
        }
        // The most mass the start can carry: every one of its s metamodules a creator, worth 1 + extra.
        if (p.creators > s)
            throw InputError("not enough mass: start '" + start.name + "' holds at most " + (Rational(s) + Rational(s) * extra).str() +
                             " metamodules' worth with every resource a creator, target '" + target.name + "' needs " + std::to_string(t) +
                             "; enlarge the start or shrink the target");
        const Rational mass = Rational(s) + Rational(p.creators) * extra;
        if (Rational(t) + Rational(t) * extra < mass)
            throw InputError("too much mass: start '" + start.name + "' has mass " + std::to_string(s) + " but target '" + target.name + "' can hold at most " +
                             (Rational(t) + Rational(t) * extra).str() + "; the planner would be stuck (Lemma 2 needs #(E) to support T); enlarge the target");
    }

    // The board: the bounding box of start and target, padded so every rule reaches only board cells.
    const auto& goal = model.system().goal;
    if (!goal || goal->kind != rules::Expr::Kind::All)
        throw InputError("system '" + model.system().name + "' needs a goal of the form all(P), as in 'goal all(F&target | _&!target)'; the planner stops when every cell satisfies P");
    p.goal = p.tables->compilePredicate(goal->pred, nullptr, {});
    p.board = std::make_unique<Board>(lattice, lo, hi - lo + Vec{1, 1, 1}, BoxEngine::reach(*p.tables));
    const Board& board = *p.board;
    std::vector<std::uint8_t> combo(static_cast<std::size_t>(board.size()), BoxEngine::kOutside);
    const auto plain = static_cast<std::uint8_t>(p.tables->comboIndex(0)), inTarget = static_cast<std::uint8_t>(p.tables->comboIndex(1u << schema.target));
    board.forEachInside([&](std::int64_t i, Vec) { combo[i] = plain; });
    for (Vec v : target.cells) combo[board.index(v)] = inTarget;
    p.engine = std::make_unique<BoxEngine>(*p.tables, board, std::move(combo));
    checkpoint();

    std::vector<std::pair<int, int>> unknown = {{schema.label, schema.unknown}}, final = {{schema.label, schema.final}};
    if (schema.resource >= 0) unknown.push_back({schema.resource, schema.full}), final.push_back({schema.resource, schema.full});
    const auto u = static_cast<BoxEngine::Value>(findState(alphabet, unknown));
    p.cells.assign(static_cast<std::size_t>(board.size()), 0);
    for (Vec v : start.cells) p.cells[board.index(v)] = u;
    p.cells[board.index(p.seed)] = static_cast<BoxEngine::Value>(findState(alphabet, final));
    if (p.creators > 0) {
        std::vector<Vec> others;
        for (Vec v : start.cells)
            if (v != p.seed) others.push_back(v);
        std::mt19937_64 rng(randomSeed);
        std::shuffle(others.begin(), others.end(), rng);
        std::vector<std::pair<int, int>> creator = {{schema.label, schema.unknown}, {schema.resource, schema.creator}};
        const auto c = static_cast<BoxEngine::Value>(findState(alphabet, creator));
        for (std::int64_t i = 0; i < p.creators && i < static_cast<std::int64_t>(others.size()); ++i) p.cells[board.index(others[i])] = c;
        if (p.creators > static_cast<std::int64_t>(others.size()))  // the seed too
            p.cells[board.index(p.seed)] = static_cast<BoxEngine::Value>(findState(alphabet, {{schema.label, schema.final}, {schema.resource, schema.creator}}));
    }
    p.start = std::move(start), p.target = std::move(target);
    return p;
}

}  // namespace holon::planner
