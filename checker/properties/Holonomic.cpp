// Holonomy (seed 000 §II-C): configurations adjacent in state space -- one cell's occupancy
// toggled, or one module moved to an empty neighbour -- are one rule step apart, or unreachable
// from each other. Explicit state: over the whole explored graph (Holonomy.cpp). Proof: no such
// pair at all (strong holonomy), else paths between the two of a pair sought by deepening, so the
// first found is a shortest one, the counterexample the explorer draws too. A proved
// counterexample is confirmed as two legal adjacent configurations that no single step joins,
// with its path replayed.

#include "checker/Holonomy.h"
#include "checker/ProofRunner.h"
#include "checker/properties/Kinds.h"

#include <cmath>

namespace holon::checker::properties {

namespace {

/// The cost of `holon check`'s phase: the components, and per state and edge what Holonomy.cpp holds.
constexpr PhaseCost kHolonomyCost{64 + kComponentsCost.perState, 4};

class Holonomic : public PropertyType {
public:
    explicit Holonomic(const rules::Property& p) : PropertyType(p.name, "holonomic"), p_(p) {}

    // Beyond the limits when the components were: it holds them too.
    std::optional<PhaseCost> cost(bool complete) const override { return complete ? std::optional(kHolonomyCost) : std::nullopt; }

    PropertyResult check(const ExploredGraph& g) const override {
        if (g.complete) return checkHolonomy(g.explorer, g.components, p_, g.budget);
        PropertyResult r = named();
        r.summary = "needs the whole graph; the search stopped at a limit";
        return r;
    }

    Obligation prove(const ProofContext& proof) const override {
        const rules::Property& p = p_;
        ProofRunner& run = proof.run;
        const Budget& budget = proof.budget;
        const rules::Engine& e = run.engine();
        const rules::Model& model = e.model();
        const rules::Region& region = e.region();
        smt::Context ctx(budget);
        SmtEncoding enc(ctx, e, SmtEncoding::Use::Queries, budget);
        const bool byMove = p.adjacency == rules::Property::Adjacency::Move;
        if (!byMove && (model.alphabet().size() > 2 || !p.exprs.empty()))
            return notEncoded(p.name, "holonomic", "holonomy modulo transfers is checked by holon check (it needs reachability)");
        // One definition with `holon check` (Holonomy.cpp): an adjacent pair with no rule step
        // between them breaks holonomy only when the second is reachable from the first. With
        // no such pair at all (strong holonomy) it holds; otherwise paths from the first of such
        // a pair to the second are sought by deepening, so the first found is a shortest one,
        // the counterexample the explorer draws too.
        const int n = region.size();
        const std::string adjacency = byMove ? "module move" : "occupancy toggle";
        auto adjacent = [&](const SmtEncoding::State& c, const SmtEncoding::State& d) {
            auto same = [&](int i, int j) {
                smt::Term all = ctx.boolVal(true);
                for (int v = 0; v < model.alphabet().size(); ++v) all = all && c.is[i][v] == d.is[j][v];
                return all;
            };
            smt::Term any = ctx.boolVal(false);
            if (!byMove) {
                // Exactly one cell differs (its occupancy toggles: one occupied state).
                for (int i = 0; i < n; ++i) {
                    smt::Term only = !same(i, i);
                    for (int j = 0; j < n; ++j)
                        if (j != i) only = only && same(j, j);
                    any = any || only;
                }
                return any;
            }
            // One module moves to an empty neighbour, keeping its state.
            for (int i = 0; i < n; ++i)
                for (int dir = 0; dir < region.lattice().degree(); ++dir) {
                    const int j = region.neighbour(i, dir);
                    if (j < 0) continue;
                    smt::Term move = !c.is[i][0] && c.is[j][0] && d.is[i][0] && same(i, j);
                    for (int k = 0; k < n; ++k)
                        if (k != i && k != j) move = move && same(k, k);
                    any = any || move;
                }
            return any;
        };
        const SmtEncoding::State first = enc.state("c");
        auto unjoined = [&](const SmtEncoding::State& d) {
            smt::Term q = adjacent(first, d);
            for (int placed = 0; placed < static_cast<int>(e.instances().size()); ++placed) q = q && !enc.fires(placed, first, d);
            return q;
        };
        const smt::Term legalFirst = enc.legal(first);
        const auto partner = enc.state("d");
        const std::string proved = "configurations one " + adjacency + " apart are one rule step apart (so no such pair is left to be reachable)";
        Obligation o = run.solve(
            p.name, "holonomic", ctx, enc, legalFirst && enc.legal(partner) && unjoined(partner),
            [](const smt::Model&, PropertyResult&) {}, proved);
        if (o.result.verdict != Verdict::Violated) {
            return o;
        }
        // Strong holonomy fails: deepen from paths of two steps.
        std::vector<SmtEncoding::State> path{first};
        std::vector<smt::Term> selectors;
        smt::Term steps = ctx.boolVal(true), lemmas = enc.instantiate().all;
        auto decode = [&](const smt::Model& m, PropertyResult& r) {
            Trace t;
            for (std::size_t k = 0; k < path.size(); ++k) t.steps.push_back({enc.decode(m, path[k]), k ? run.placedFrom(m, selectors[k - 1]) : -1});
            const std::size_t distance = t.steps.size() - 1;
            t.description = "two configurations one " + adjacency + " apart need " + stepCount(distance);
            r.trace = t;
            r.summary = "configurations one " + adjacency + " apart, with no rule step between them, are " + stepCount(distance) + " apart";
            r.witness = {{"distance", distance}, {"adjacency", byMove ? "move" : "occupancy"}};
        };
        const double configurations = std::pow(static_cast<double>(model.alphabet().size()), n);
        for (int k = 1;; ++k) {
            path.push_back(enc.state("p" + std::to_string(k)));
            selectors.push_back(ctx.intConst("step" + std::to_string(k)));
            steps = steps && enc.step(path[k - 1], path[k], selectors.back());
            if (k == 1) continue;  // a pair one step apart is joined
            if (k > configurations - 1) {
                // A shortest path visits each configuration once: none of such a pair is reachable.
                o = ProofRunner::named(p.name, "holonomic");
                o.result.verdict = Verdict::Holds;
                o.result.summary = "configurations one " + adjacency + " apart are one rule step apart, or unreachable (no path of up to " +
                                   stepCount(k - 1) + " joins them, and a shortest path is shorter than the " +
                                   std::to_string(static_cast<long long>(configurations)) + " configurations)";
                break;
            }
            if (budget.expired() || budget.interrupted()) {
                o = ProofRunner::named(p.name, "holonomic");
                o.result.summary = "undecided: legal configurations one " + adjacency + " apart with no rule step between them exist, and no path of up to " +
                                   stepCount(k - 1) + " joins such a pair (" + (budget.interrupted() ? "a signal" : "timeout") + ")";
                break;
            }
            lemmas = lemmas && enc.instantiate().all;
            o = run.solve(p.name, "holonomic", ctx, enc, legalFirst && steps && unjoined(path[k]), decode, proved, 1.0, lemmas);
            if (o.result.verdict != Verdict::Holds) break;  // a shortest path, or the solver gave up
        }
        return o;
    }

    bool confirm(const PropertyResult& r, Evidence evidence, const rules::Interpreter& in, const rules::Engine& engine, std::string* why) const override {
        if (evidence == Evidence::Path) return PropertyType::confirm(r, evidence, in, engine, why);
        auto fail = [&](const std::string& m) {
            if (why) *why = m;
            return false;
        };
        if (!r.trace || r.trace->steps.empty()) return fail("the counterexample has no trace");
        const rules::Region& region = engine.region();
        rules::Configuration c = in.empty();
        c.inputs = engine.inputs();
        c.cells = r.trace->steps.front().cells;
        // Adjacent, no single step between them, and the path from the first to the second replays.
        rules::Configuration d = c;
        d.cells = r.trace->steps.back().cells;
        if (!in.legal(c) || !in.legal(d)) return fail("a state is not legal");
        std::vector<int> differ;
        for (int i = 0; i < region.size(); ++i)
            if (c.cells[i] != d.cells[i]) differ.push_back(i);
        const bool byMove = r.witness.value("adjacency", "") == "move";
        auto neighbours = [&](int i, int j) {
            for (int dir = 0; dir < region.lattice().degree(); ++dir)
                if (region.neighbour(i, dir) == j) return true;
            return false;
        };
        const bool adjacent =
            byMove ? differ.size() == 2 && neighbours(differ[0], differ[1]) && (c.cells[differ[0]] == 0) != (c.cells[differ[1]] == 0) &&
                         c.cells[differ[0]] == d.cells[differ[1]] && c.cells[differ[1]] == d.cells[differ[0]]
                   : differ.size() == 1 && (c.cells[differ[0]] == 0) != (d.cells[differ[0]] == 0);
        if (!adjacent) return fail("the two states are not one " + std::string(byMove ? "module move" : "occupancy toggle") + " apart");
        for (const auto& i : in.enabled(c))
            if (in.successor(c, i)->cells == d.cells) return fail("a rule step does connect them");
        return replay(*r.trace, engine, in, why);
    }

private:
    const rules::Property& p_;
};

}  // namespace

std::unique_ptr<PropertyType> holonomic(const rules::Property& p) { return std::make_unique<Holonomic>(p); }

}  // namespace holon::checker::properties
