// Invariants (seed 000 §II, Lemma 1 Safety). Explicit state: checked on every state as the explorer
// stores it, so the first violation found by the breadth-first search has a shortest trace, its
// failing cells crossed and its false conjunct named. Proof: inductiveness, one conjunct at a
// time -- I(c), legal c and c', one step, the conjunct false in c' -- skipping a conjunct that
// follows from the ones before it. Its bad states (the invariant false) are what --depth and
// --reach show unreachable.

#include "checker/FailureCells.h"
#include "checker/ProofRunner.h"
#include "checker/properties/Kinds.h"

#include <mutex>

namespace holon::checker::properties {

namespace {

/// Whether conjunct k of an invariant follows from conjuncts 0..k-1 in the same state: those hold
/// after every step (proved before it, in order), so then conjunct k does too, without a query
/// per rule instance. Planner Safety's `connected` follows from the tree conjuncts (1.8-2.3 s on
/// square:5x5, against 11-21 s instance by instance; single runs each). Gets a quarter of the time; `total` names its exported file.
bool impliedByEarlier(ProofRunner& run, const std::string& name, const std::vector<const rules::Expr*>& conjuncts, std::size_t k, Obligation& total,
                      const Budget& budget) {
    smt::Context ctx(budget);
    SmtEncoding enc(ctx, run.engine(), SmtEncoding::Use::Queries, budget);
    auto d = enc.state("d");
    smt::Term q = enc.legal(d);
    for (std::size_t j = 0; j < k; ++j) q = q && enc.holds(*conjuncts[j], d, true);
    q = q && !enc.holds(*conjuncts[k], d, false);
    Obligation part = run.solve(
        name, "invariant", ctx, enc, q, [](const smt::Model&, PropertyResult&) {}, "", 0.25);
    if (part.result.verdict != Verdict::Holds) return false;
    if (!part.smtFile.empty()) total.smtFile += (total.smtFile.empty() ? "" : " ") + part.smtFile;
    return true;
}

/// Inductiveness of an invariant (Lemma 1, Safety), every conjunct within one budget.
Obligation proveInductive(ProofRunner& run, const rules::Property& p, const Budget& budget) {
    const rules::Engine& e = run.engine();
    const rules::Model& model = e.model();
    // Inductiveness, one conjunct of the invariant at a time: I(c), a step, and the conjunct
    // failing in the successor. Smaller queries, the same theorem.
    std::vector<const rules::Expr*> conjuncts;
    std::function<void(const rules::Expr&)> split = [&](const rules::Expr& x) {
        if (x.kind == rules::Expr::Kind::And) split(x.kids[0]), split(x.kids[1]);
        else conjuncts.push_back(&x);
    };
    split(p.exprs[0]);
    Obligation total;
    total.result.name = p.name;
    total.result.kind = "invariant";
    total.result.verdict = Verdict::Holds;
    total.result.summary = "inductive: every step from a state where it holds keeps it";
    std::vector<std::string> implied;
    for (std::size_t k = 0; k < conjuncts.size(); ++k) {
        if (k > 0 && impliedByEarlier(run, p.name + "." + std::to_string(k + 1), conjuncts, k, total, budget)) {
            implied.push_back(std::to_string(k + 1));
            continue;
        }
        smt::Context cctx(budget);
        SmtEncoding cenc(cctx, e, SmtEncoding::Use::Queries, budget);
        auto c = cenc.state("c"), d = cenc.state("d");
        const smt::Term base = cenc.legal(c) && cenc.holds(p.exprs[0], c, true) && cenc.legal(d) && !cenc.holds(*conjuncts[k], d, false);
        Obligation part = run.stepwise(
            p.name + "." + std::to_string(k + 1), "invariant", cctx, cenc, base, [&](int q) { return cenc.fires(q, c, d); },
            [&](const smt::Model& m, int q, PropertyResult& r) {
                r.trace = Trace{{{cenc.decode(m, c), -1}, {cenc.decode(m, d), q}}, {}, {}, "a step from a state where it holds to one where it fails: not inductive", {}};
                r.summary = r.trace->description;
                r.witness = {{"rule", model.rules()[e.instances()[q].rule].name}, {"conjunct", k + 1}};
            },
            "");
        if (!part.smtFile.empty()) total.smtFile += (total.smtFile.empty() ? "" : " ") + part.smtFile;
        if (part.result.verdict != Verdict::Holds) {
            part.result.name = p.name;
            part.smtFile = total.smtFile;
            total = part;
            if (total.result.verdict == Verdict::Unknown) total.result.summary += " (conjunct " + std::to_string(k + 1) + ")";
            break;
        }
    }
    if (total.result.verdict == Verdict::Holds && !implied.empty()) {
        std::string which;
        for (const std::string& k : implied) which += (which.empty() ? "" : ", ") + k;
        total.result.summary += "; conjunct" + std::string(implied.size() > 1 ? "s " : " ") + which + " follow" +
                                (implied.size() > 1 ? "" : "s") + " from the ones before";
    }
    return total;
}

class Invariant : public PropertyType {
public:
    explicit Invariant(const rules::Property& p) : PropertyType(p.name, "invariant"), p_(p) {}

    bool watchesStates() const override { return true; }
    void onState(const rules::Engine& e, StateId id, const CellValue* cells) override {
        if (e.holds(p_.exprs[0], cells)) return;
        std::lock_guard<std::mutex> lock(mutex_);
        if (violations_.size() < 64) violations_.push_back(id);
    }
    bool decided() const override {
        std::lock_guard<std::mutex> lock(mutex_);
        return !violations_.empty();
    }

    PropertyResult check(const ExploredGraph& g) const override {
        PropertyResult r = named();
        const rules::Property& p = p_;
        const rules::Engine& e = g.engine;
        const Explorer* ex = &g.explorer;
        const auto& bad = violations_;
        if (bad.empty()) {
            holdsOrUnknown(r, g, "holds in all " + std::to_string(ex->stats().states) + " states");
            return r;
        }
        // The violation closest to an initial state.
        StateId best = bad[0];
        for (StateId s : bad)
            if (ex->pathTo(s).size() < ex->pathTo(best).size()) best = s;
        r.verdict = Verdict::Violated;
        r.trace = traceTo(*ex, best);
        // Mark what a person should look at: the cells that make it false.
        const auto last = ex->cells(best);
        r.trace->marked = failureCells(e, p.exprs[0], last.data());
        r.witness = {{"distance", r.trace->steps.size() - 1}};
        r.summary = "violated after " + stepCount(r.trace->steps.size() - 1);
        const std::string which = nameFailingConjunct(r, p, rules::Interpreter(g.model, g.region), {last, e.inputs()});
        r.trace->description = "invariant '" + p.name + "' fails after " + stepCount(r.trace->steps.size() - 1) + which +
                               (r.trace->marked.empty() ? "" : "; crossed cells show where");
        return r;
    }

    Obligation prove(const ProofContext& proof) const override { return proveInductive(proof.run, p_, proof.budget); }

    std::optional<BadTarget> target(const rules::Engine&) const override {
        const rules::Property& p = p_;
        return BadTarget{[&p](SmtEncoding& enc, const SmtEncoding::State& s) { return !enc.holds(p.exprs[0], s, false); },
                         [&p](const std::vector<CellValue>& c, const rules::Engine& en) { return !en.holds(p.exprs[0], c.data()); },
                         "invariant '" + p.name + "' fails", true};
    }

    /// An obligation's counterexample is one step from a configuration where the invariant holds to
    /// one where it fails.
    bool confirm(const PropertyResult& r, Evidence evidence, const rules::Interpreter& in, const rules::Engine& engine, std::string* why) const override {
        if (evidence == Evidence::Path) return PropertyType::confirm(r, evidence, in, engine, why);
        return confirmBrokenStep(r, in, engine, why, "does not go from a configuration where it holds to one where it fails",
                                 [&](const CellValue* before, const CellValue* after, int) {
                                     return engine.holds(p_.exprs[0], before) && !engine.holds(p_.exprs[0], after);
                                 });
    }

    void explain(PropertyResult& r, const rules::Interpreter& in, const rules::Engine& engine) const override {
        if (r.trace) nameFailingConjunct(r, p_, in, {r.trace->steps.back().cells, engine.inputs()});
    }

private:
    const rules::Property& p_;
    mutable std::mutex mutex_;
    std::vector<StateId> violations_;  // the first 64 found
};

}  // namespace

std::unique_ptr<PropertyType> invariant(const rules::Property& p) { return std::make_unique<Invariant>(p); }

}  // namespace holon::checker::properties
