// Rankings (seed 000 §IV-C, Lemma 3 Termination): a vector of numbers that every step decreases
// lexicographically, except the steps of excepted rules (resource moves), which keep it.
// Explicit state: the edges that break it (a covered rule's step that does not decrease it, an
// excepted rule's that changes it); termination fails exactly when a cycle passes through a step
// of a covered rule, shown as a lasso (a livelock, on which the ranking never decreases, first;
// BGL strong components). Proof: one step from c to c', instance by instance, that breaks it.

#include "checker/ProofRunner.h"
#include "checker/properties/Kinds.h"
#include "rules/Error.h"

#include <algorithm>
#include <optional>

namespace holon::checker::properties {

namespace {

bool lexLess(const std::vector<rules::Rational>& a, const std::vector<rules::Rational>& b) {
    return std::lexicographical_compare(a.begin(), a.end(), b.begin(), b.end());
}

std::vector<rules::Rational> rankOf(const rules::Engine& e, const rules::Property& p, const CellValue* cells) {
    std::vector<rules::Rational> rank;
    for (const rules::Expr& x : p.exprs) rank.push_back(e.number(x, cells));
    return rank;
}

/// The rule by which a step of instance q from ranking `from` to `to` breaks the ranking, and how,
/// if it does: as a step of a covered rule it must decrease it, as a step of an excepted rule keep
/// it, and a shape kept once for several rules (rules::RuleShape::rules) is a step of each.
std::optional<std::pair<int, std::string>> breaker(const rules::Engine& e, const rules::Property& p, int q, const std::vector<rules::Rational>& from,
                                                   const std::vector<rules::Rational>& to) {
    const int shape = e.instances()[q].shape;
    if (const int covered = e.model().shapeRule(shape, p.except, false); covered >= 0 && !lexLess(to, from)) return std::pair{covered, std::string("does not decrease it")};
    if (const int excepted = e.model().shapeRule(shape, p.except, true); excepted >= 0 && from != to)
        return std::pair{excepted, std::string("changes it (an excepted rule must keep it)")};
    return std::nullopt;
}

/// Two strong-component runs and a shortest path, a flag per edge, and per state a vector of
/// `terms` ranking values.
PhaseCost rankingCost(std::size_t terms) { return {128.0 + 16.0 * static_cast<double>(terms), 13}; }

class Ranking : public PropertyType {
public:
    explicit Ranking(const rules::Property& p) : PropertyType(p.name, "ranking"), p_(p) {}

    std::optional<PhaseCost> cost(bool) const override { return rankingCost(p_.exprs.size()); }

    PropertyResult check(const ExploredGraph& g) const override {
        PropertyResult r = named();
        const rules::Property& p = p_;
        const rules::Model& model = g.model;
        const rules::Engine& e = g.engine;
        const Explorer* ex = &g.explorer;
        const auto ids = ex->ids();
        const auto& row = ex->rowStart();
        const auto& succ = ex->successors();
        std::vector<std::vector<rules::Rational>> rank(ex->store().capacityUsed());
        for (StateId s : ids) {
            rank[s] = rankOf(e, p, ex->cells(s).data());
        }
        // A step of an excepted rule (a resource move) must keep the ranking; every other step
        // decreases it. A step is judged by the rule of each instance that makes it: an excepted
        // rule's and a covered rule's can make the same step, which the graph holds as one edge.
        auto coveredBy = [&](std::int32_t via) { return model.shapeRule(e.instances()[via].shape, p.except, false) >= 0; };
        std::vector<char> bad(succ.size(), 0), covered(succ.size(), 0), level(succ.size(), 0);
        std::vector<std::int32_t> badVia(succ.size(), -1), coveredVia(succ.size(), -1);
        std::uint64_t badEdges = 0, firstBad = 0;
        StateId firstFrom = kNoState;
        for (StateId s : ids)
            for (std::uint64_t k = row[s]; k < row[s + 1]; ++k) {
                level[k] = rank[succ[k]] == rank[s];
                for (std::int32_t via : ex->viasOf(k)) {
                    if (coveredBy(via) && !covered[k]) covered[k] = 1, coveredVia[k] = via;
                    if (bad[k] || !breaker(e, p, via, rank[s], rank[succ[k]])) continue;
                    bad[k] = 1, badVia[k] = via;
                    if (badEdges++ == 0) firstBad = k, firstFrom = s;
                }
            }
        if (badEdges == 0) {
            holdsOrUnknown(r, g, "every step decreases it" + exceptText(p));
            return r;
        }
        r.verdict = Verdict::Violated;
        // Termination fails exactly when the reachable graph has a cycle through a step of a
        // covered rule (one not excepted), whatever mix of decreasing and non-decreasing steps
        // it takes; a cycle of excepted steps alone is the allocator's (seed 000 Lemma 3). A
        // cycle on which the ranking never decreases (a livelock: every step keeps it, since it
        // comes back) is shown first.
        const Components levelScc = strongComponents(*ex, level);
        const Components whole = strongComponents(*ex, std::vector<char>(succ.size(), 1));
        StateId cycleFrom = kNoState;
        std::uint64_t cycleEdge = 0;
        bool livelock = false;
        for (StateId s : ids)
            for (std::uint64_t k = row[s]; k < row[s + 1] && !livelock; ++k) {
                if (!covered[k]) continue;
                if (level[k] && levelScc.of[succ[k]] == levelScc.of[s]) cycleFrom = s, cycleEdge = k, livelock = true;
                else if (cycleFrom == kNoState && whole.of[succ[k]] == whole.of[s]) cycleFrom = s, cycleEdge = k;
            }
        if (cycleFrom == kNoState) {
            r.trace = traceWithStep(*ex, firstFrom, firstBad);
            r.trace->steps.back().placed = badVia[firstBad];
            const bool one = badEdges == 1;
            const std::string what = p.except.empty() ? (one ? " step does not decrease it" : " steps do not decrease it")
                                                      : std::string(one ? " step breaks it" : " steps break it") + " (a covered rule's must decrease it, an excepted rule's keep it)";
            r.summary = std::to_string(badEdges) + what + "; no cycle of the reachable graph passes through a step of a rule it covers, so " +
                        (p.except.empty() ? "runs still terminate here" : "only steps of excepted rules can repeat for ever here");
            const auto [rule, how] = *breaker(e, p, badVia[firstBad], rank[firstFrom], rank[succ[firstBad]]);
            r.trace->description = "the last step, by rule '" + model.rules()[rule].name + "', " + how;
            r.witness = {{"breaking_steps", badEdges}, {"cycle", false}, {"livelock", false}};
            return r;
        }
        // Lasso: reach the cycle, take its step, and come back by a shortest path inside the
        // same strong component (of the non-decreasing steps for a livelock); a self-loop is a
        // cycle of one step.
        const StateId next = succ[cycleEdge];
        std::vector<StateId> loop{cycleFrom};
        if (next == cycleFrom) loop.push_back(cycleFrom);
        else
            for (StateId b : GraphView(*ex, livelock ? &level : nullptr).shortestPath(next, cycleFrom)) loop.push_back(b);
        const Trace cycle = traceAlong(*ex, loop);
        Trace t = traceTo(*ex, cycleFrom);
        t.loop = static_cast<int>(t.steps.size()) - 1;
        // ITF: the last state steps back to states[loop], so the repeated state is not written twice.
        t.steps.insert(t.steps.end(), cycle.steps.begin() + 1, cycle.steps.end() - 1);
        // The cycle's own step, by a covered rule, is written out, so the trace names it: after
        // the state the lasso returns to (for a self-loop, that state again).
        if (next == cycleFrom) t.steps.push_back({ex->cells(cycleFrom), coveredVia[cycleEdge]});
        else t.steps[static_cast<std::size_t>(*t.loop) + 1].placed = coveredVia[cycleEdge];
        // Can a fair scheduler leave a livelock? Only if some step from its strong component (in
        // the whole graph) decreases the ranking; and a mixed cycle only if a step leaves its component.
        bool escapable = false;
        for (StateId s : ids)
            if (whole.of[s] == whole.of[cycleFrom])
                for (std::uint64_t k = row[s]; k < row[s + 1] && !escapable; ++k)
                    escapable = livelock ? !level[k] : whole.of[succ[k]] != whole.of[s];
        r.trace = t;
        const std::size_t length = loop.size() - 1;
        const int coveredRule = model.shapeRule(e.instances()[coveredVia[cycleEdge]].shape, p.except, false);
        r.summary = "not terminating: " +
                    (livelock ? "a cycle of " + stepCount(length) + " on which it never decreases"
                              : "a cycle of " + stepCount(length) + " that undoes what it decreases") +
                    ", through a step of rule '" + model.rules()[coveredRule].name + "'" +
                    (escapable ? " (a fair scheduler can leave it)" : " (trapped: no step leaves it)");
        r.trace->description = r.summary;
        r.witness = {{"breaking_steps", badEdges}, {"cycle", true}, {"livelock", livelock}, {"length", length}, {"escapable", escapable}};
        return r;
    }

    /// An obligation's counterexample is one step that does not decrease the ranking (an excepted
    /// rule's: that changes it).
    bool confirm(const PropertyResult& r, Evidence evidence, const rules::Interpreter& in, const rules::Engine& engine, std::string* why) const override {
        if (evidence == Evidence::Path) return PropertyType::confirm(r, evidence, in, engine, why);
        return confirmBrokenStep(r, in, engine, why, "decreases the ranking (an excepted rule's keeps it)", [&](const CellValue* before, const CellValue* after, int q) {
            return breaker(engine, p_, q, rankOf(engine, p_, before), rankOf(engine, p_, after)).has_value();
        });
    }

    Obligation prove(const ProofContext& proof) const override {
        const rules::Property& p = p_;
        ProofRunner& run = proof.run;
        const rules::Engine& e = run.engine();
        const rules::Model& model = e.model();
        smt::Context ctx(proof.budget);
        SmtEncoding enc(ctx, e, SmtEncoding::Use::Queries, proof.budget);
        auto c = enc.state("c"), d = enc.state("d");
        return run.stepwise(
            p.name, "ranking", ctx, enc, enc.legal(c) && enc.legal(d), [&](int q) { return enc.fires(q, c, d) && enc.rankingBroken(p, q, d, c); },
            [&](const smt::Model& m, int q, PropertyResult& r) {
                const std::vector<CellValue> before = enc.decode(m, c), after = enc.decode(m, d);
                const auto broken = breaker(e, p, q, rankOf(e, p, before.data()), rankOf(e, p, after.data()));
                if (!broken) throw InternalError("the solver's step keeps ranking '" + p.name + "' for every rule it is a step of");
                const auto& [rule, why] = *broken;
                r.trace = Trace{{{before, -1}, {after, q}}, {}, {}, "a step that " + why, {}};
                r.summary = "rule '" + model.rules()[rule].name + "' " + why;
                r.witness = {{"rule", model.rules()[rule].name}};
            },
            "every step decreases it lexicographically" + exceptText(p));
    }

private:
    const rules::Property& p_;
};

}  // namespace

std::unique_ptr<PropertyType> ranking(const rules::Property& p) { return std::make_unique<Ranking>(p); }

}  // namespace holon::checker::properties
