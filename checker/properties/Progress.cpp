// Progress and deadlock freedom (seed 000 §II, Lemma 2): outside the goal (and where a progress
// property's assumption holds) some rule is enabled. Deadlock freedom is progress with no
// assumption, built in for every system with a goal; one type checks, proves and confirms both,
// differing only in their words. Explicit state: the terminal states of the explored graph,
// each tried on the region grown by the rules' reach so that a state stuck only because the
// region ends (an edge effect) is not called a deadlock. Proof: a state where every invariant
// holds, outside the goal, with no instance enabled; the same stuck states are what --reach shows
// unreachable. A proved counterexample is confirmed as a legal stuck state outside the goal.

#include "checker/ProofRunner.h"
#include "checker/properties/Kinds.h"

#include <algorithm>
#include <cstdint>
#include <limits>

namespace holon::checker::properties {

namespace {

/// How far a rule instance reaches, in lattice steps: the largest pattern, twice its radius (an
/// instance touching the region lies within this of it).
/// In 64 bits, then capped: a rule reaching 999,999,999 cells away made 2 * radius wrap negative,
/// the reach became 1, and stuck states only the far cell could free were called deadlocks
/// (progress "violated", where it is unknown at 1,000 cells away).
int ruleReach(const rules::Model& model) {
    std::int64_t radius = 0;
    for (const rules::RuleShape& s : model.shapes())
        for (rules::Vec v : s.offsets) radius = std::max(radius, std::int64_t{std::abs(v.x)} + std::abs(v.y) + std::abs(v.z));
    return static_cast<int>(std::clamp<std::int64_t>(2 * radius, 1, std::numeric_limits<int>::max()));
}

/// A rule with a far position (`_@(1000,1000)`) grows a 3-cell region to tens of millions of
/// cells: growing it ran for minutes, past the deadline, the memory bound and signals.
constexpr std::size_t kMaxGrownCells = std::size_t{1} << 20;

/// The region grown by the rules' reach, where a stuck state is tried to tell a deadlock from an
/// edge effect; none when it would have more than kMaxGrownCells cells.
std::optional<rules::Region> edgeRegion(const rules::Model& model, const rules::Region& region) { return region.grown(ruleReach(model), kMaxGrownCells); }

std::string unclassifiableWhy(const rules::Model& model) {
    return "the rules reach " + std::to_string(ruleReach(model)) + " lattice steps, and the region grown by that has more than " + std::to_string(kMaxGrownCells) +
           " cells to tell a deadlock from an edge effect on";
}

/// Whether a state stuck on the region is an edge effect: on the grown region (`wide`: outside
/// cells empty, inputs false) some rule instance is enabled.
bool edgeEffect(const rules::Interpreter& wide, const std::vector<CellValue>& cells, const std::vector<std::uint32_t>& inputs) {
    rules::Configuration c = wide.empty();
    std::copy(cells.begin(), cells.end(), c.cells.begin());
    std::copy(inputs.begin(), inputs.end(), c.inputs.begin());
    return !wide.enabled(c).empty();
}

/// The same as a formula over state `s` of `enc`: no instance of the grown region that needs a
/// cell outside the region is enabled, outside cells empty and their inputs false (the grown
/// region keeps the region's cell indices). What a proof adds so that it calls a state a deadlock
/// exactly where check does; nothing when no instance outside can be enabled.
std::optional<smt::Term> noEdgeEffect(SmtEncoding& enc, const SmtEncoding::State& s, const rules::Engine& e, const rules::Region& grown) {
    smt::Context& ctx = s.is[0][0].context();
    const rules::Engine wide(e.model(), grown, {}, true);
    const int n = e.region().size();
    // Every instance of the grown region counts (check asks the interpreter whether any is
    // enabled there), but two kinds need no formula. An instance that needs something in a cell
    // outside, which is empty, or an input there, which is false, is never enabled (most of them).
    // An instance of the region's own is enabled there exactly as on the region -- `stuck` says it
    // is not -- unless constraints judge its successor (their values change with the region:
    // count(_), connected(_)) or its guard reads a neighbour outside.
    const bool constrained = !e.model().system().constraints.empty();
    const int emptyCombo = wide.tables().comboIndex(0);
    // What an instance reads, as the tables know it (RuleTables::readSites): its pattern cells and
    // the neighbours its guard names.
    auto seesOutside = [&](const rules::Engine::Placed& p) {
        for (const rules::RuleTables::Site& site : wide.tables().readSites(p.shape))
            if (const int m = site.direction < 0 ? p.cells[site.cell] : grown.neighbour(p.cells[site.cell], site.direction); m < 0 || m >= n) return true;
        return false;
    };
    std::vector<int> open;
    for (int placed = 0; placed < static_cast<int>(wide.instances().size()); ++placed) {
        const rules::Engine::Placed& p = wide.instances()[placed];
        if (std::all_of(p.cells, p.cells + p.size, [&](std::int32_t c) { return c < n; })) {
            if (constrained || seesOutside(p)) open.push_back(placed);
            continue;
        }
        bool possible = true;
        for (int k = 0; k < p.size && possible; ++k) possible = p.cells[k] < n || wide.lhsAccepts(placed, k, emptyCombo, 0);
        if (possible) open.push_back(placed);
    }
    if (open.empty()) return std::nullopt;  // nothing to add: the query stays as it was, byte for byte
    smt::Term all = ctx.boolVal(true);
    // The grown state is s on the region's cells (the grown region keeps their indices) and empty
    // outside; an input bit is named by its cell, so the region's are s's own.
    SmtEncoding outer(ctx, wide, SmtEncoding::Use::Queries, enc.budget());
    SmtEncoding::State g = s;
    for (int i = n; i < grown.size(); ++i) {
        std::vector<smt::Term> row;
        for (std::size_t v = 0; v < s.is[0].size(); ++v) row.push_back(ctx.boolVal(v == 0));
        g.is.push_back(row);
        for (const smt::Term& bit : outer.inputBits()[i]) all = all && !bit;
    }
    // Under connectivity each instance's successor is a formula over the grown region: the
    // obligation's budget is read between them (a hex:r1 design built for 284 s past a 10 s limit).
    for (int placed : open)
        enc.budget().check("building the formulas"), all = all && (constrained ? !(outer.matches(placed, g) && outer.legal(outer.successor(placed, g), false)) : !outer.matches(placed, g));
    for (const smt::Term& f : outer.facts()) all = all && f;
    return all;
}

/// States with no enabled rule, outside the goal and where `assume` holds, split into deadlocks and
/// edge effects of the bounded region: on the region grown by the rules' reach (outside cells empty,
/// inputs false) some instance is enabled, so only the region's bound stops the system, not the
/// design. Every stuck state is tried on the grown region, within the budget; those left when it
/// runs out stay unclassified (never called deadlocks: an edge effect reported as a flaw is a wrong
/// answer). A cap of 10,000 left 6,383 of square:3x7's 16,383 stuck states unclassified, and the
/// verdict unknown, where trying all of them takes 0.1 s.
Stuck stuckStates(const Explorer& ex, const rules::Engine& e, const rules::Expr* assume, const Budget& budget) {
    const rules::Model& model = e.model();
    Stuck out;
    // After the deadline nothing is classified: growing a region of 4 million cells and building
    // its interpreter took a second past --timeout.
    const bool inTime = !budget.expired() && !budget.interrupted();
    const std::optional<rules::Region> grown = inTime ? edgeRegion(model, e.region()) : std::nullopt;
    std::optional<rules::Interpreter> wide;
    if (grown) wide.emplace(model, *grown);
    out.unclassifiedWhy = !inTime || grown ? "the job's budget ran out first" : unclassifiableWhy(model);
    for (StateId s : ex.terminal()) {
        const auto cells = ex.cells(s);
        if (model.system().goal && e.holds(*model.system().goal, cells.data())) continue;
        if (assume && !e.holds(*assume, cells.data())) continue;
        if (!wide || budget.expired() || budget.interrupted()) {
            ++out.unclassified;
            continue;
        }
        (edgeEffect(*wide, cells, e.inputs()) ? out.edgeEffects : out.deadlocks).push_back(s);
    }
    return out;
}

/// What a verdict adds about edge effects: ", except 3 states stuck only at the region's edge ...".
std::string edgeText(const Stuck& stuck) {
    if (stuck.edgeEffects.empty()) return "";
    return "; " + std::to_string(stuck.edgeEffects.size()) + " states are stuck only at the region's edge (a rule instance needs cells outside it)";
}

/// A property decided by stuck states: violated by a deadlock (the nearest has a trace), else
/// unknown while the search or the classification is incomplete, else holds.
void judgeStuck(PropertyResult& r, const Explorer& ex, const Stuck& stuck, bool complete, const std::string& which,
                const std::string& description, const char* countKey, const std::string& holdsText) {
    r.witness = nullptr;
    if (!violatedAtNearest(
            r, ex, stuck.deadlocks, [](StateId) { return true; }, which, description, countKey)) {
        r.verdict = complete && stuck.unclassified == 0 ? Verdict::Holds : Verdict::Unknown;
        r.summary = !complete            ? "no violation among the " + std::to_string(ex.stats().states) + " states explored before the limit"
                    : stuck.unclassified ? std::to_string(stuck.unclassified) + " stuck states not classified (deadlock or edge effect): " + stuck.unclassifiedWhy
                                         : holdsText;
        r.summary += edgeText(stuck);
    }
    r.witness["edge_effects"] = stuck.edgeEffects.size();
    r.witness["unclassified"] = stuck.unclassified;
}

/// Progress fails at s (Lemma 2): outside the goal, under the property's assumption, and no
/// instance is enabled. With non-local constraints s is legal and an instance is enabled only if
/// its successor is legal too (seed 000 §II-C): each one fails to match or leads to an illegal
/// configuration (its successor written over s's variables, no new ones).
smt::Term stuck(SmtEncoding& enc, const SmtEncoding::State& s, const rules::Engine& e, const rules::Expr* assumption) {
    const rules::System& system = e.model().system();
    smt::Term q = system.goal ? !enc.holds(*system.goal, s, false) : s.is[0][0].context().boolVal(true);
    if (assumption) q = q && enc.holds(*assumption, s, true);
    const bool constrained = !system.constraints.empty();
    if (constrained) q = q && enc.legal(s);
    for (int placed = 0; placed < static_cast<int>(e.instances().size()); ++placed)
        q = q && (constrained ? !(enc.matches(placed, s) && enc.legal(enc.successor(placed, s), false)) : !enc.matches(placed, s));
    enc.leftSideSets(s);
    return q;
}

/// The concrete test of the same.
bool stuckAt(const std::vector<CellValue>& c, const rules::Engine& e, const rules::Expr* assumption) {
    const rules::System& system = e.model().system();
    if (system.goal && e.holds(*system.goal, c.data())) return false;
    if (assumption && !e.holds(*assumption, c.data())) return false;
    std::vector<CellValue> next;
    for (int placed = 0; placed < static_cast<int>(e.instances().size()); ++placed) {
        if (!e.matches(c.data(), placed)) continue;
        CellValue saved[rules::Engine::kMaxCells];
        next = c;
        e.apply(next.data(), placed, saved);
        if (e.legal(next.data())) return false;
    }
    return true;
}

/// How a verdict of progress or of deadlock freedom reads.
struct Words {
    std::string which, description;
    const char* countKey;
    std::string holds;
};

class Progress : public PropertyType {
public:
    Progress(std::string name, std::string kind, const rules::Expr* assumption, Words words)
        : PropertyType(std::move(name), std::move(kind)), assumption_(assumption), words_(std::move(words)) {}

    PropertyResult check(const ExploredGraph& g) const override {
        PropertyResult r = named();
        auto known = g.stuck.find(assumption_);
        if (known == g.stuck.end()) known = g.stuck.emplace(assumption_, stuckStates(g.explorer, g.engine, assumption_, g.budget)).first;
        judgeStuck(r, g.explorer, known->second, g.complete, words_.which, words_.description, words_.countKey, words_.holds);
        return r;
    }

    Obligation prove(const ProofContext& proof) const override {
        ProofRunner& run = proof.run;
        const rules::Engine& e = run.engine();
        const rules::System& system = e.model().system();
        smt::Context ctx(proof.budget);
        SmtEncoding enc(ctx, e, SmtEncoding::Use::Queries, proof.budget);
        auto c = enc.state("c");
        smt::Term q = stuck(enc, c, e, assumption_);
        // A state stuck only because the region ends is no deadlock, as in check; where the grown
        // region is too large to say, a stuck state found is not called one either (below).
        const std::optional<rules::Region> grown = edgeRegion(e.model(), e.region());
        if (grown)
            if (const std::optional<smt::Term> deadlock = noEdgeEffect(enc, c, e, *grown)) q = q && *deadlock;
        for (const rules::Property* inv : proof.invariants) q = q && enc.holds(inv->exprs[0], c, true);
        auto decode = [&](const smt::Model& m, PropertyResult& r) {
            Trace t;
            t.steps.push_back({enc.decode(m, c), -1});
            t.description = "every invariant holds, the goal is not reached, and no rule is enabled" +
                            std::string(system.constraints.empty() ? "" : " (or each leads to an illegal configuration)");
            r.trace = t;
            r.summary = t.description;
            r.witness = nlohmann::json::object();
        };
        Obligation o = run.solve(name(), kind(), ctx, enc, q, decode,
                                 "outside the goal, some rule is enabled wherever the invariants hold (or, at the region's edge, would be on a larger region)");
        if (!grown && o.result.verdict == Verdict::Violated) {
            o.result.verdict = Verdict::Unknown;
            o.result.summary = "a stuck state outside the goal, not classified (deadlock or edge effect): " + unclassifiableWhy(e.model());
            o.result.trace.reset();
        }
        return o;
    }

    std::optional<BadTarget> target(const rules::Engine& e) const override {
        const rules::Expr* assumption = assumption_;
        // Deadlocks as check and prove() call them: not the states stuck only at the region's edge.
        // Where the grown region is too large to say, every stuck state is a target (a rule
        // reaching hundreds of cells away).
        auto grown = std::make_shared<std::optional<rules::Region>>(edgeRegion(e.model(), e.region()));
        return BadTarget{[assumption, &e, grown](SmtEncoding& enc, const SmtEncoding::State& s) {
                             smt::Term bad = stuck(enc, s, e, assumption);
                             if (*grown)
                                 if (const std::optional<smt::Term> deadlock = noEdgeEffect(enc, s, e, **grown)) bad = bad && *deadlock;
                             return bad;
                         },
                         [assumption, grown](const std::vector<CellValue>& c, const rules::Engine& en) {
                             if (!stuckAt(c, en, assumption)) return false;
                             return !*grown || !edgeEffect(rules::Interpreter(en.model(), **grown), c, en.inputs());
                         },
                         "a deadlock outside the goal"};
    }

    /// A proved counterexample is one state: legal, where the assumption holds, outside the goal, with
    /// nothing enabled.
    bool confirm(const PropertyResult& r, Evidence evidence, const rules::Interpreter& in, const rules::Engine& engine, std::string* why) const override {
        // A path (--reach, --depth) must replay and end in a deadlock; a proof's counterexample is
        // that one state.
        if (evidence == Evidence::Path && !PropertyType::confirm(r, evidence, in, engine, why)) return false;
        auto fail = [&](const std::string& m) {
            if (why) *why = m;
            return false;
        };
        if (!r.trace || r.trace->steps.empty()) return fail("the counterexample has no trace");
        rules::Configuration c = in.empty();
        c.inputs = engine.inputs();
        c.cells = evidence == Evidence::Path ? r.trace->steps.back().cells : r.trace->steps.front().cells;
        if (!in.legal(c)) return fail("the state is not legal");
        if (assumption_ && !in.holds(*assumption_, c)) return fail("the progress assumption does not hold there");
        if (in.atGoal(c)) return fail("the state is a goal");
        if (!in.enabled(c).empty()) return fail("a rule is enabled");
        if (const std::optional<rules::Region> grown = edgeRegion(in.model(), in.region());
            grown && edgeEffect(rules::Interpreter(in.model(), *grown), c.cells, c.inputs))
            return fail("it is stuck only at the region's edge: on a larger region a rule is enabled");
        return true;
    }

private:
    const rules::Expr* assumption_;  // none: deadlock freedom
    Words words_;
};

}  // namespace

std::unique_ptr<PropertyType> progress(const rules::Property& p) {
    return std::make_unique<Progress>(p.name, "progress", p.exprs.empty() ? nullptr : &p.exprs[0],
                                      Words{"outside the goal with no enabled rule", "stuck outside the goal: no rule is enabled", "stuck",
                                            "some rule is enabled in every state outside the goal"});
}

std::unique_ptr<PropertyType> deadlock() {
    return std::make_unique<Progress>("deadlock", "deadlock", nullptr,
                                      Words{"with no enabled rule outside the goal", "a deadlock: no rule is enabled and the goal is not reached", "deadlocks",
                                            "every state outside the goal has an enabled rule"});
}

}  // namespace holon::checker::properties
