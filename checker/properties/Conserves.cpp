// Conservation of mass or of the number of modules (seed 000 §IV-C). Explicit state: the amount of
// every explored state, compared across every recorded edge; the first step that changes it is the
// counterexample. Proof: region-independent, each rule at one placement -- its left side, its
// rewrite, and a different amount over its own cells before and after.

#include "checker/ProofRunner.h"
#include "checker/properties/Kinds.h"

#include <algorithm>

namespace holon::checker::properties {

namespace {

constexpr PhaseCost kConservesCost{8, 0};

/// The amount a configuration holds: its mass in units, or its number of modules.
std::int64_t amountOf(const rules::Engine& e, bool byMass, const CellValue* cells) {
    if (byMass) return e.massUnits(cells);
    return std::count_if(cells, cells + e.region().size(), [](CellValue v) { return v != 0; });
}

class Conserves : public PropertyType {
public:
    explicit Conserves(const rules::Property& p) : PropertyType(p.name, "conserves"), p_(p) {}

    std::optional<PhaseCost> cost(bool) const override { return kConservesCost; }

    PropertyResult check(const ExploredGraph& g) const override {
        PropertyResult r = named();
        const rules::Property& p = p_;
        const rules::Engine& e = g.engine;
        const Explorer* ex = &g.explorer;
        const auto ids = ex->ids();
        const auto& row = ex->rowStart();
        const auto& succ = ex->successors();
        const bool byMass = p.quantity == rules::Property::Quantity::Mass;
        std::vector<std::int64_t> amount(ex->store().capacityUsed(), 0);
        for (StateId s : ids) {
            const auto cells = ex->cells(s);
            amount[s] = amountOf(e, byMass, cells.data());
        }
        for (StateId s : ids)
            for (std::uint64_t k = row[s]; k < row[s + 1] && r.verdict != Verdict::Violated; ++k)
                if (amount[succ[k]] != amount[s]) {
                    r.verdict = Verdict::Violated;
                    r.trace = traceWithStep(*ex, s, k);
                    const auto& rule = e.model().rules()[e.instances()[ex->successorVia()[k]].rule];
                    r.summary = "rule '" + rule.name + "' changes the " + (byMass ? "mass" : "count");
                    r.trace->description = r.summary;
                    r.witness = {{"rule", rule.name}, {"before", rules::Rational(amount[s], byMass ? e.massDenominator() : 1).str()}, {"after", rules::Rational(amount[succ[k]], byMass ? e.massDenominator() : 1).str()}};
                }
        if (r.verdict != Verdict::Violated) holdsOrUnknown(r, g, "every one of the " + std::to_string(ex->stats().edges) + " steps keeps it");
        return r;
    }

    /// An obligation's counterexample is one step that changes the amount.
    bool confirm(const PropertyResult& r, Evidence evidence, const rules::Interpreter& in, const rules::Engine& engine, std::string* why) const override {
        if (evidence == Evidence::Path) return PropertyType::confirm(r, evidence, in, engine, why);
        const bool byMass = p_.quantity == rules::Property::Quantity::Mass;
        return confirmBrokenStep(r, in, engine, why, "keeps the amount", [&](const CellValue* before, const CellValue* after, int) {
            return amountOf(engine, byMass, before) != amountOf(engine, byMass, after);
        });
    }

    Obligation prove(const ProofContext& proof) const override {
        const rules::Property& p = p_;
        ProofRunner& run = proof.run;
        const rules::Engine& e = run.engine();
        const rules::Model& model = e.model();
        smt::Context ctx(proof.budget);
        SmtEncoding enc(ctx, e, SmtEncoding::Use::Queries, proof.budget);
        // Region-independent: each rule's own cells, before and after, at one placement.
        const bool byMass = p.quantity == rules::Property::Quantity::Mass;
        auto before = enc.state("c"), after = enc.state("d");
        smt::Term anyRule = ctx.boolVal(false);
        std::vector<int> firstPlaced(model.rules().size(), -1);
        for (int q = 0; q < static_cast<int>(e.instances().size()); ++q)
            if (firstPlaced[e.instances()[q].rule] < 0) firstPlaced[e.instances()[q].rule] = q;
        smt::Term selector = ctx.intConst("rule_instance");
        for (int q : firstPlaced) {
            if (q < 0) continue;
            const auto& placed = e.instances()[q];
            smt::Term lhs = enc.legal(before) && enc.fires(q, before, after) && enc.legal(after);
            smt::Term amountBefore = ctx.intVal(0), amountAfter = ctx.intVal(0);
            auto amount = [&](const SmtEncoding::State& s, int c) {
                return byMass ? enc.cellMassUnits(s, c) : smt::ite(s.is[c][0], ctx.intVal(0), ctx.intVal(1));
            };
            for (int k = 0; k < placed.size; ++k) {
                amountBefore = amountBefore + amount(before, placed.cells[k]);
                amountAfter = amountAfter + amount(after, placed.cells[k]);
            }
            anyRule = anyRule || (selector == q && lhs && amountBefore != amountAfter);
        }
        auto decode = [&](const smt::Model& m, PropertyResult& r) {
            const int q = run.placedFrom(m, selector);
            const std::string rule = model.rules()[e.instances()[q].rule].name;
            Trace t;
            t.steps.push_back({enc.decode(m, before), -1});
            t.steps.push_back({enc.decode(m, after), q});
            t.description = "rule '" + rule + "' changes the " + (byMass ? "mass" : "count");
            r.trace = t;
            r.summary = t.description;
            r.witness = {{"rule", rule}};
        };
        return run.solve(p.name, "conserves", ctx, enc, anyRule, decode, "every rule keeps it");
    }

private:
    const rules::Property& p_;
};

}  // namespace

std::unique_ptr<PropertyType> conserves(const rules::Property& p) { return std::make_unique<Conserves>(p); }

}  // namespace holon::checker::properties
