// Proof obligations (issue: Z3 proofs; seed 000 §IV-C). Each property becomes a satisfiability
// query whose models are counterexamples, so UNSAT is a proof for every configuration of the region,
// not only the reachable ones:
//   conserves     for each rule: left side, rewrite, and different mass before and after
//   invariant     inductive: I(c), legal(c), one step to c', not I(c')  (Lemma 1, Safety)
//   progress      I(c) for every invariant, not goal(c), the assumption, and no instance enabled (Lemma 2)
//   ranking       one step from c to c' that does not decrease the ranking lexicographically (Lemma 3)
//   holonomic     legal c and c' one toggle (or one module move) apart, and no instance from c to c'
//   bmc           from the given configurations, k steps, some state violating an invariant
//   reach         from the given configurations, any number of steps (Horn clauses; Reach.cpp)
// Every query can be written as SMT-LIB2 for independent re-checking (proofs/).

#include "checker/Obligations.h"

#include "checker/Forked.h"

#include "checker/Reach.h"
#include "checker/SmtEncoding.h"
#include "checker/SolverLimits.h"
#include "rules/ConfigIo.h"
#include "rules/Error.h"
#include "rules/OutputFile.h"

#include <chrono>
#include <cmath>
#include <filesystem>
#include <limits>
#include <optional>

namespace holon::checker {

bool VerifyReport::counterexample() const {
    for (const Obligation& o : obligations)
        if (o.result.verdict == Verdict::Violated) return true;
    return false;
}

Verdict VerifyReport::overall() const {
    Verdict v = Verdict::Holds;
    for (const Obligation& o : obligations) v = combine(v, o.result.verdict);
    return v;
}

nlohmann::json VerifyReport::toJson() const {
    nlohmann::json props = nlohmann::json::array();
    for (const Obligation& o : obligations)
        props.push_back({{"name", o.result.name}, {"kind", o.result.kind}, {"verdict", proofVerdictName(o.result.verdict)}, {"summary", o.result.summary}, {"witness", o.result.witness}, {"seconds", o.result.seconds}, {"smt_file", o.smtFile.empty() ? nlohmann::json(nullptr) : nlohmann::json(o.smtFile)}, {"scope", o.scope.empty() ? "region " + region : o.scope}});
    return {{"system", system}, {"region", region}, {"properties", props}};
}

namespace {

/// How --smt-out is named in messages: the caller's option, or a description without one.
std::string smtOutOption(const VerifyOptions& o) { return o.smtOutOption.empty() ? "the SMT-LIB2 folder" : o.smtOutOption; }

std::string fileSafe(std::string s) {
    for (char& c : s)
        if (!std::isalnum(static_cast<unsigned char>(c)) && c != '_' && c != '-') c = '_';
    return s;
}

std::vector<std::uint32_t> inputsOf(const smt::Model& m, smt::Context& ctx, const rules::Engine& e) {
    std::vector<std::uint32_t> in(e.region().size(), 0);
    for (int i = 0; i < e.region().size(); ++i)
        for (std::size_t k = 0; k < e.model().system().inputs.size(); ++k) {
            if (m.isTrue(ctx.boolConst("in_" + e.model().system().inputs[k] + "_" + std::to_string(i)))) in[i] |= 1u << k;
        }
    return in;
}

/// Per-cell input bits by input name, as a configuration's JSON writes them: {"target": [[0, 0], ...]}.
nlohmann::json inputsJson(const rules::Engine& e, const std::vector<std::uint32_t>& bits) {
    nlohmann::json out = nlohmann::json::object();
    const auto& names = e.model().system().inputs;
    for (std::size_t k = 0; k < names.size(); ++k) {
        nlohmann::json cells = nlohmann::json::array();
        for (int i = 0; i < e.region().size(); ++i)
            if ((bits[i] >> k) & 1u) cells.push_back(rules::pointJson(e.region().lattice(), e.region().cell(i)));
        out[names[k]] = cells;
    }
    return out;
}

class Runner {
public:
    Runner(const rules::Model& model, const rules::Region& region, const VerifyOptions& options)
        : model_(model), region_(region), options_(options), engine_(model, region, {}, true) {}

    static Obligation named(const std::string& name, const std::string& kind) {
        Obligation o;
        o.result.name = name;
        o.result.kind = kind;
        return o;
    }

    /// A solver with the encoding's domain facts and the obligation's time left.
    smt::Solver newSolver(smt::Context& ctx, SmtEncoding& enc, double timeoutShare = 1.0) const {
        smt::Solver solver(ctx);
        limitTime(solver, enc.budget(), timeoutShare);
        for (const smt::Term& f : enc.facts()) solver.add(f);
        return solver;
    }

    /// The solver's timeout: what the obligation has left, or `share` of the whole if less (a
    /// side query). Throws OutOfTime when nothing is left.
    void limitTime(smt::Solver& solver, const Budget& budget, double share = 1.0) const {
        budget.check("building the formulas");
        if (!budget.limited()) return;
        const double seconds = std::min(options_.timeoutSeconds * share, budget.remaining());
        solver.setTimeout(std::max(1u, static_cast<unsigned>(seconds * 1000)));
    }

    /// Solves `query` (after the encoding's domain facts); a model becomes a counterexample via
    /// `decode`. The encoding's lemmas (and `earlierLemmas`) help the solver but are not written
    /// with --smt-out: an exported obligation is the theorem alone, so that a re-check does not
    /// rest on the argument that makes them valid.
    Obligation solve(const std::string& name, const std::string& kind, smt::Context& ctx, SmtEncoding& enc, const smt::Term& query,
                     const std::function<void(const smt::Model&, PropertyResult&)>& decode, const std::string& provedText,
                     double timeoutShare = 1.0, const std::optional<smt::Term>& earlierLemmas = std::nullopt) {
        const auto start = std::chrono::steady_clock::now();
        Obligation o = named(name, kind);
        const SmtEncoding::Lemmas lemmas = enc.instantiate();
        auto check = [&](const smt::Term& chosen) {
            smt::Solver solver = newSolver(ctx, enc, timeoutShare);
            solver.add(query);
            solver.add(chosen);
            if (earlierLemmas) solver.add(*earlierLemmas);
            return std::make_pair(solver.check(), solver);
        };
        if (!options_.smtOut.empty()) {
            smt::Solver exported = newSolver(ctx, enc, timeoutShare);
            exported.add(query);
            write(name, exported, o, enc.budget());
        }
        // With two sets of lemmas, both are tried at once on the two cores and the first definite
        // answer counts (Z3 is deterministic: a satisfiable answer is found again here for its model).
        const smt::Term* chosen = &lemmas.all;
        std::optional<smt::Result> result;
        std::string reason;
        if (lemmas.differ) {
            constexpr int unknown = static_cast<int>(smt::Result::Unknown);
            std::vector<ForkedJob> jobs;
            for (const smt::Term* variant : {&lemmas.all, &lemmas.lean})
                jobs.push_back([&, variant](bool forked) -> nlohmann::json {
                    if (forked) shareSolverMemory(2);
                    const auto [r, solver] = check(*variant);
                    return {{"result", static_cast<int>(r)}, {"reason", r == smt::Result::Unknown ? solver.reasonUnknown() : ""}};
                });
            const ForkedAnswer answer =
                firstDecisive(
                    jobs, [](const nlohmann::json& a) { return a.contains("result") && a["result"] != unknown; }, enc.budget());
            result = static_cast<smt::Result>(answer.answer.value("result", unknown));
            reason = answer.answer.value("reason", answer.answer.value("error", std::string("no answer")));
            if (answer.job == 1) chosen = &lemmas.lean;
        }
        std::optional<smt::Solver> solver;
        if (!result || *result == smt::Result::Sat) {
            auto [r, s] = check(*chosen);
            result = r;
            if (r == smt::Result::Unknown) reason = s.reasonUnknown();
            solver = s;
        }
        o.result.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
        switch (*result) {
        case smt::Result::Unsat:
            o.result.verdict = Verdict::Holds;
            o.result.summary = provedText;
            break;
        case smt::Result::Sat:
            o.result.verdict = Verdict::Violated;
            decode(solver->model(), o.result);
            recordInputs(solver->model(), ctx, o.result);
            if (o.result.trace) o.result.trace->property = name;
            break;
        case smt::Result::Unknown:
            o.result.verdict = Verdict::Unknown;
            o.result.summary = "the solver gave up: " + unknownReason(reason);
            break;
        }
        return o;
    }

    const rules::Engine& engine() const { return engine_; }

    /// A counterexample holds for the inputs the solver chose (free, or fixed to a problem's): they
    /// go with it into the confirmation, the pictures and the trace, and by name into the witness.
    void recordInputs(const smt::Model& m, smt::Context& ctx, PropertyResult& r) const {
        r.inputs = inputsOf(m, ctx, engine_);
        if (model_.system().inputs.empty()) return;
        if (!r.witness.is_object()) r.witness = nlohmann::json::object();
        r.witness["inputs"] = inputsJson(engine_, *r.inputs);
    }

    /// A step obligation solved instance by instance on one incremental solver: `base` holds for
    /// every instance, `perInstance(p)` is guarded by an activation literal, and each instance is
    /// checked under its literal. The SMT-LIB2 export is the equivalent single query "base and
    /// exactly one instance".
    Obligation stepwise(const std::string& name, const std::string& kind, smt::Context& ctx, SmtEncoding& enc, const smt::Term& base,
                        const std::function<smt::Term(int)>& perInstance,
                        const std::function<void(const smt::Model&, int, PropertyResult&)>& decode, const std::string& provedText) {
        const auto start = std::chrono::steady_clock::now();
        Obligation o = named(name, kind);
        const int count = static_cast<int>(engine_.instances().size());
        const smt::Term lemmas = enc.instantiate().all;
        smt::Solver solver = newSolver(ctx, enc);
        solver.add(base);
        solver.add(lemmas);
        std::vector<smt::Term> act;
        for (int p = 0; p < count; ++p) {
            act.push_back(ctx.boolConst("instance_" + std::to_string(p)));
            solver.add(smt::implies(act.back(), perInstance(p)));
        }
        if (!options_.smtOut.empty()) {
            smt::Solver exported(ctx);
            for (const smt::Term& f : enc.facts()) exported.add(f);
            exported.add(base);
            for (int p = 0; p < count; ++p) exported.add(smt::implies(act[p], perInstance(p)));
            exported.add(smt::anyOf(ctx, act));
            write(name, exported, o, enc.budget());
        }
        o.result.verdict = Verdict::Holds;
        o.result.summary = provedText;
        for (int p = 0; p < count; ++p) {
            if (enc.budget().expired()) {
                o.result.verdict = Verdict::Unknown;
                o.result.summary = "timeout after " + std::to_string(p) + " of " + std::to_string(count) + " instances";
                break;
            }
            limitTime(solver, enc.budget());
            const smt::Result r = solver.check({act[p]});
            if (r == smt::Result::Sat) {
                o.result.verdict = Verdict::Violated;
                decode(solver.model(), p, o.result);
                recordInputs(solver.model(), ctx, o.result);
                if (o.result.trace) o.result.trace->property = name;
                break;
            }
            if (r == smt::Result::Unknown) {
                o.result.verdict = Verdict::Unknown;
                o.result.summary = "the solver gave up on instance " + std::to_string(p) + ": " + unknownReason(solver.reasonUnknown());
                break;
            }
        }
        o.result.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
        return o;
    }

    /// Where obligation `name` is written under --smt-out (the folder is prepared by verify()).
    rules::OutputFile smtPath(const std::string& name) const {
        const std::filesystem::path dir(options_.smtOut);
        return rules::OutputFile(smtOutOption(options_), (dir / (fileSafe(model_.system().name) + "." + fileSafe(region_.spec()) + "." + fileSafe(name) + ".smt2")).string());
    }

    void write(const std::string& name, const smt::Solver& solver, Obligation& o, const Budget& budget) {
        budget.check("writing the SMT-LIB2 file");
        const rules::OutputFile file = smtPath(name);
        file.write("; holon proof obligation: system " + model_.system().name + ", region " + region_.spec() + ", property " + name +
                   "\n; expected: unsat (the property holds for every configuration of the region)\n(set-logic ALL)\n" + solver.toSmt2());
        o.smtFile = file.path();
    }

    int placedFrom(const smt::Model& m, const smt::Term& selector) const { return m.intValue(selector); }

    const rules::Model& model_;
    const rules::Region& region_;
    const VerifyOptions& options_;
    rules::Engine engine_;
};

/// An obligation holon does not encode: verdict unknown, with the reason.
Obligation notEncoded(const std::string& name, const std::string& kind, const std::string& why) {
    Obligation o;
    o.result.name = name;
    o.result.kind = kind;
    o.result.summary = why;
    return o;
}

const char* kindName(rules::Property::Kind kind) {
    switch (kind) {
    case rules::Property::Kind::Conserves: return "conserves";
    case rules::Property::Kind::Invariant: return "invariant";
    case rules::Property::Kind::Ranking: return "ranking";
    case rules::Property::Kind::Progress: return "progress";
    case rules::Property::Kind::Holonomic: return "holonomic";
    }
    throw InternalError("verify: a property kind with no name");
}

/// Runs one obligation, whose Z3 context lives inside `prove`. One cut short by a limit is unknown,
/// with the limit named, and the next obligation goes on: its budget spent while the formulas were
/// built, or Z3 out of memory (reset here, once its context is gone). Any other Z3 failure is an
/// InternalError.
Obligation withinLimits(const std::string& name, const std::string& kind, const std::function<Obligation()>& prove) {
    const Budget clock;
    auto stopped = [&](const std::string& why) {
        Obligation o = notEncoded(name, kind, why);
        o.result.seconds = clock.elapsed();
        return o;
    };
    try {
        Obligation o = prove();
        if (outOfMemory(o.result.summary)) recoverSolverMemory();  // Z3 said unknown rather than throwing
        return o;
    } catch (const OutOfTime& e) {
        return stopped(e.what());
    } catch (const smt::Failure& e) {
        Obligation o = stopped(solverFailure(e));
        recoverSolverMemory();
        return o;
    } catch (const std::bad_alloc&) {  // from Z3's own containers, or holon's
        Obligation o = stopped("out of memory: " + unknownReason("out of memory"));
        recoverSolverMemory();
        return o;
    }
}

/// Progress fails at s (Lemma 2): outside the goal, under the property's assumption, and no
/// instance is enabled. With non-local constraints s is legal and an instance is enabled only if
/// its successor is legal too (seed 000 §II-C): each one fails to match or leads to an illegal
/// configuration (its successor written over s's variables, no new ones).
smt::Term stuck(SmtEncoding& enc, const SmtEncoding::State& s, const rules::Engine& e, const rules::Property& progress) {
    const rules::System& system = e.model().system();
    smt::Term q = system.goal ? !enc.holds(*system.goal, s, false) : s.is[0][0].context().boolVal(true);
    if (!progress.exprs.empty()) q = q && enc.holds(progress.exprs[0], s, true);
    const bool constrained = !system.constraints.empty();
    if (constrained) q = q && enc.legal(s);
    for (int placed = 0; placed < static_cast<int>(e.instances().size()); ++placed)
        q = q && (constrained ? !(enc.matches(placed, s) && enc.legal(enc.successor(placed, s), false)) : !enc.matches(placed, s));
    enc.leftSideSets(s);
    return q;
}

/// The concrete test of the same.
bool stuckAt(const std::vector<CellValue>& c, const rules::Engine& e, const rules::Property& progress) {
    const rules::System& system = e.model().system();
    if (system.goal && e.holds(*system.goal, c.data())) return false;
    if (!progress.exprs.empty() && !e.holds(progress.exprs[0], c.data())) return false;
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

/// Whether conjunct k of an invariant follows from conjuncts 0..k-1 in the same state: those hold
/// after every step (proved before it, in order), so then conjunct k does too, without a query
/// per rule instance. Planner Safety's `connected` follows from the tree conjuncts (1.8-2.3 s on
/// square:5x5, against 11-21 s instance by instance; single runs each). Gets a quarter of the time; `total` counts it.
bool impliedByEarlier(Runner& run, const std::string& name, const std::vector<const rules::Expr*>& conjuncts, std::size_t k, Obligation& total,
                      const Budget& budget) {
    smt::Context ctx(budget);
    SmtEncoding enc(ctx, run.engine(), SmtEncoding::Use::Queries, budget);
    auto d = enc.state("d");
    smt::Term q = enc.legal(d);
    for (std::size_t j = 0; j < k; ++j) q = q && enc.holds(*conjuncts[j], d, true);
    q = q && !enc.holds(*conjuncts[k], d, false);
    Obligation part = run.solve(
        name, "invariant", ctx, enc, q, [](const smt::Model&, PropertyResult&) {}, "", 0.25);
    total.result.seconds += part.result.seconds;
    if (part.result.verdict != Verdict::Holds) return false;
    if (!part.smtFile.empty()) total.smtFile += (total.smtFile.empty() ? "" : " ") + part.smtFile;
    return true;
}

/// Inductiveness of an invariant (Lemma 1, Safety), every conjunct within one budget.
Obligation proveInductive(Runner& run, const rules::Property& p, const Budget& budget) {
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
        total.result.seconds += part.result.seconds;
        if (!part.smtFile.empty()) total.smtFile += (total.smtFile.empty() ? "" : " ") + part.smtFile;
        if (part.result.verdict != Verdict::Holds) {
            part.result.name = p.name;
            part.result.seconds = total.result.seconds;
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

}  // namespace

VerifyReport verify(const rules::Model& model, const rules::Region& region, const VerifyOptions& options,
                    const std::function<void(const std::string&)>& onObligation) {
    const rules::System& system = model.system();
    // The folder first: a proof that takes minutes is not thrown away for a path.
    if (!options.smtOut.empty()) rules::prepareOutputDir(smtOutOption(options), options.smtOut);
    limitSolverMemory(options.memoryMiB);
    VerifyReport report;
    report.system = system.name;
    report.region = region.spec();
    Runner run(model, region, options);
    const rules::Engine& e = run.engine();
    auto selected = [&](const std::string& name) {
        return options.properties.empty() || std::find(options.properties.begin(), options.properties.end(), name) != options.properties.end();
    };
    for (const std::string& name : options.properties)
        if (!system.property(name)) throw InputError("system '" + system.name + "' has no property '" + name + "'");
    std::vector<const rules::Property*> invariants;
    for (const rules::Property& p : system.properties)
        if (p.kind == rules::Property::Kind::Invariant) invariants.push_back(&p);
    auto announce = [&](const std::string& name) {
        if (onObligation) onObligation(name);
    };
    for (const rules::Property& p : system.properties) {
        if (!selected(p.name)) continue;
        announce(p.name);
        const Budget budget = Budget(options.timeoutSeconds) || options.budget;
        report.obligations.push_back(withinLimits(p.name, kindName(p.kind), [&]() -> Obligation {
            smt::Context ctx(budget);
            SmtEncoding enc(ctx, e, SmtEncoding::Use::Queries, budget);
            switch (p.kind) {
            case rules::Property::Kind::Conserves: {
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
            case rules::Property::Kind::Invariant: {
                return proveInductive(run, p, budget);
            }
            case rules::Property::Kind::Ranking: {
                auto c = enc.state("c"), d = enc.state("d");
                auto kept = [&](int q) { return model.ruleNamed(e.instances()[q].rule, p.except); };
                return run.stepwise(
                    p.name, "ranking", ctx, enc, enc.legal(c) && enc.legal(d),
                    [&](int q) { return enc.fires(q, c, d) && !(kept(q) ? enc.keptAfter(p.exprs, q, d, c) : enc.lexLessAfter(p.exprs, q, d, c)); },
                    [&](const smt::Model& m, int q, PropertyResult& r) {
                        const std::string why = kept(q) ? "changes it (an excepted rule must keep it)" : "does not decrease it";
                        r.trace = Trace{{{enc.decode(m, c), -1}, {enc.decode(m, d), q}}, {}, {}, "a step that " + why, {}};
                        r.summary = "rule '" + model.rules()[e.instances()[q].rule].name + "' " + why;
                        r.witness = {{"rule", model.rules()[e.instances()[q].rule].name}};
                    },
                    "every step decreases it lexicographically" + exceptText(p));
            }
            case rules::Property::Kind::Progress: {
                auto c = enc.state("c");
                smt::Term q = stuck(enc, c, e, p);
                for (const rules::Property* inv : invariants) q = q && enc.holds(inv->exprs[0], c, true);
                auto decode = [&](const smt::Model& m, PropertyResult& r) {
                    Trace t;
                    t.steps.push_back({enc.decode(m, c), -1});
                    t.description = "every invariant holds, the goal is not reached, and no rule is enabled" +
                                    std::string(system.constraints.empty() ? "" : " (or each leads to an illegal configuration)");
                    r.trace = t;
                    r.summary = t.description;
                    r.witness = nlohmann::json::object();
                };
                return run.solve(p.name, "progress", ctx, enc, q, decode, "outside the goal, some rule is enabled wherever the invariants hold");
            }
            case rules::Property::Kind::Holonomic: {
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
                double spent = o.result.seconds;
                const double configurations = std::pow(static_cast<double>(model.alphabet().size()), n);
                for (int k = 1;; ++k) {
                    path.push_back(enc.state("p" + std::to_string(k)));
                    selectors.push_back(ctx.intConst("step" + std::to_string(k)));
                    steps = steps && enc.step(path[k - 1], path[k], selectors.back());
                    if (k == 1) continue;  // a pair one step apart is joined
                    if (k > configurations - 1) {
                        // A shortest path visits each configuration once: none of such a pair is reachable.
                        o = Runner::named(p.name, "holonomic");
                        o.result.verdict = Verdict::Holds;
                        o.result.summary = "configurations one " + adjacency + " apart are one rule step apart, or unreachable (no path of up to " +
                                           stepCount(k - 1) + " joins them, and a shortest path is shorter than the " +
                                           std::to_string(static_cast<long long>(configurations)) + " configurations)";
                        break;
                    }
                    if (budget.expired()) {
                        o = Runner::named(p.name, "holonomic");
                        o.result.summary = "undecided: legal configurations one " + adjacency + " apart with no rule step between them exist, and no path of up to " +
                                           stepCount(k - 1) + " joins such a pair (timeout)";
                        break;
                    }
                    lemmas = lemmas && enc.instantiate().all;
                    o = run.solve(p.name, "holonomic", ctx, enc, legalFirst && steps && unjoined(path[k]), decode, proved, 1.0, lemmas);
                    spent += o.result.seconds;
                    o.result.seconds = spent;
                    if (o.result.verdict != Verdict::Holds) break;  // a shortest path, or the solver gave up
                }
                o.result.seconds = spent;
                return o;
            }
            }
            throw InternalError("verify: a property kind with no obligation");
        }));
    }

    // What --depth and --reach show unreachable: a state breaking an invariant, or (progress) a
    // reachable deadlock outside the goal. Each comes symbolically and as a test on a concrete state
    // (which cuts a decoded path at its first bad state).
    struct Target {
        const rules::Property* property;
        BadStates bad;
        std::function<bool(const std::vector<CellValue>&, const rules::Engine&)> isBad;
        std::string failure;  // "invariant 'safety' fails", "deadlock outside the goal"
    };
    std::vector<Target> targets;
    for (const rules::Property& p : system.properties) {
        if (!selected(p.name)) continue;
        if (p.kind == rules::Property::Kind::Invariant)
            targets.push_back({&p, [&p](SmtEncoding& enc, const SmtEncoding::State& s) { return !enc.holds(p.exprs[0], s, false); },
                               [&p](const std::vector<CellValue>& c, const rules::Engine& en) { return !en.holds(p.exprs[0], c.data()); },
                               "invariant '" + p.name + "' fails"});
        else if (p.kind == rules::Property::Kind::Progress)
            targets.push_back({&p, [&p, &e](SmtEncoding& enc, const SmtEncoding::State& s) { return stuck(enc, s, e, p); },
                               [&p](const std::vector<CellValue>& c, const rules::Engine& en) { return stuckAt(c, en, p); },
                               "a deadlock outside the goal"});
    }

    // Bounded model checking from the given configurations, deepening to at most `depth` steps
    // (and the timeout): a bad state within k steps, for k = 0, 1, ..., so the first one found
    // is at the end of a shortest path. The last query asked is the whole obligation.
    auto bmc = [&](const Target& target, int depth, const std::string& name) {
        const Budget budget = Budget(options.timeoutSeconds) || options.budget;
        smt::Context ctx(budget);
        SmtEncoding enc(ctx, e, SmtEncoding::Use::Queries, budget);
        std::vector<SmtEncoding::State> path{enc.state("s0")};
        std::vector<smt::Term> selectors;
        smt::Term start = ctx.boolVal(false);
        for (const rules::Configuration& c : options.initial) start = start || (enc.configurationIs(path[0], c.cells) && enc.inputsAre(c.inputs));
        smt::Term steps = ctx.boolVal(true), someBad = target.bad(enc, path[0]);
        smt::Term lemmas = enc.instantiate().all;  // kept for the deeper queries
        auto decode = [&](const smt::Model& m, PropertyResult& r) {
            // The start the model chose may be any of the given configurations, each with its inputs.
            const rules::Engine concrete(model, region, inputsOf(m, ctx, e));
            Trace t;
            for (std::size_t k = 0; k < path.size(); ++k) {
                t.steps.push_back({enc.decode(m, path[k]), k ? run.placedFrom(m, selectors[k - 1]) : -1});
                if (target.isBad(t.steps.back().cells, concrete)) break;
            }
            t.description = target.failure + " after " + stepCount(t.steps.size() - 1);
            r.trace = t;
            r.summary = t.description;
            r.witness = {{"depth", t.steps.size() - 1}};
        };
        const std::string proved = "holds on every path of up to " + std::to_string(depth) + " steps from the given configurations";
        Obligation o = run.solve(name, "bmc", ctx, enc, start && someBad, decode, proved, 1.0, lemmas);
        for (int k = 1; k <= depth && o.result.verdict == Verdict::Holds; ++k) {
            const double spent = o.result.seconds;
            if (budget.expired()) {
                o.result.verdict = Verdict::Unknown;
                o.result.summary = "timeout at depth " + std::to_string(k);
                break;
            }
            path.push_back(enc.state("s" + std::to_string(k)));
            selectors.push_back(ctx.intConst("step" + std::to_string(k)));
            steps = steps && enc.step(path[k - 1], path[k], selectors.back());
            someBad = someBad || target.bad(enc, path[k]);
            lemmas = lemmas && enc.instantiate().all;
            o = run.solve(name, "bmc", ctx, enc, start && steps && someBad, decode, proved, 1.0, lemmas);
            o.result.seconds += spent;
        }
        return o;
    };
    if (options.depth > 0 && !options.initial.empty())
        for (const Target& t : targets) {
            if (t.property->kind != rules::Property::Kind::Invariant) continue;
            const std::string name = t.property->name + "@bmc" + std::to_string(options.depth);
            announce(name);
            report.obligations.push_back(withinLimits(name, "bmc", [&] { return bmc(t, options.depth, name); }));
        }

    // Every reachable state, without a depth bound: Horn clauses for Spacer (Reach.cpp). A
    // refutation says some reachable state is bad; the shortest path to one is found by deepening BMC.
    // Invariants that hold in every reachable state -- inductive and true initially, or proved
    // @reach -- restrict the steps the later Horn clauses consider. Inductiveness not asked for is
    // proved here without being reported or exported.
    std::vector<const rules::Property*> known;
    if (options.reach && !options.initial.empty()) {
        VerifyOptions quiet = options;
        quiet.smtOut.clear();
        Runner quietRun(model, region, quiet);
        const rules::Engine atStart(model, region, options.initial.front().inputs);
        for (const rules::Property* p : invariants) {
            const bool initially = std::all_of(options.initial.begin(), options.initial.end(), [&](const rules::Configuration& c) {
                return c.inputs == options.initial.front().inputs && atStart.holds(p->exprs[0], c.cells.data());
            });
            if (!initially) continue;
            auto asked = std::find_if(report.obligations.begin(), report.obligations.end(), [&](const Obligation& o) { return o.result.name == p->name; });
            const Budget budget = Budget(options.timeoutSeconds) || options.budget;
            const auto proved = [&] { return withinLimits(p->name, "invariant", [&] { return proveInductive(quietRun, *p, budget); }).result.verdict; };
            if ((asked != report.obligations.end() ? asked->result.verdict : proved()) == Verdict::Holds) known.push_back(p);
        }
    }
    auto knownAt = [&](SmtEncoding& enc, const SmtEncoding::State& s) {
        smt::Term all = s.is[0][0].context().boolVal(true);
        for (const rules::Property* p : known) all = all && enc.holds(p->exprs[0], s, true);
        return all;
    };
    if (options.reach && !options.initial.empty())
        for (const Target& t : targets) {
            const std::string name = t.property->name + "@reach";
            announce(name);
            const std::optional<rules::OutputFile> file = options.smtOut.empty() ? std::nullopt : std::optional(run.smtPath(name));
            const bool isKnown = std::find(known.begin(), known.end(), t.property) != known.end();
            const ReachProof proof = isKnown ? ReachProof{} : proveUnreachable(e, t.bad, options.initial, Budget(options.timeoutSeconds) || options.budget, file ? &*file : nullptr, known.empty() ? BadStates() : BadStates(knownAt));
            Obligation o = Runner::named(name, "reach");
            for (const std::string& f : proof.certificateFiles) o.smtFile += (o.smtFile.empty() ? "" : " ") + f;
            o.result.verdict = proof.verdict;
            o.result.seconds = proof.seconds;
            if (isKnown) {
                o.result.verdict = Verdict::Holds;
                o.result.summary = "holds in every reachable state: it is inductive and holds initially";
            } else if (proof.verdict == Verdict::Holds) {
                std::string given;
                if (proof.usedKnown)
                    for (const rules::Property* k : known) given += (given.empty() ? ", given " : " and ") + k->name;
                o.result.summary = "holds in every reachable state (inductive invariant of " + std::to_string(proof.invariant.size()) + " clauses" + given + ")";
                o.result.witness = {{"inductive_invariant", proof.invariant}};
                if (t.property->kind == rules::Property::Kind::Invariant) known.push_back(t.property);
            } else if (proof.verdict == Verdict::Unknown) {
                o.result.summary = "the solver gave up: " + unknownReason(proof.reason);
            } else {
                o.result.verdict = Verdict::Unknown;
                o.result.summary = "a bad state is reachable, but no trace to it within the timeout";
                Obligation shortest = withinLimits(name, "reach", [&] { return bmc(t, std::numeric_limits<int>::max(), name); });
                o.result.seconds += shortest.result.seconds;
                if (shortest.result.verdict == Verdict::Violated) {
                    shortest.result.kind = "reach";
                    shortest.result.seconds = o.result.seconds;
                    shortest.smtFile = o.smtFile;
                    o = shortest;
                }
            }
            report.obligations.push_back(o);
        }
    return report;
}

bool confirmCounterexample(const PropertyResult& r, const rules::Model& model, const rules::Region& region, std::string* why) {
    if (!r.trace || r.trace->steps.empty()) {
        if (why) *why = "the counterexample has no trace";
        return false;
    }
    const std::vector<std::uint32_t> inputs = r.inputs.value_or(std::vector<std::uint32_t>(region.size(), 0));
    const rules::Engine engine(model, region, inputs);
    rules::Interpreter in(model, region);
    rules::Configuration c = in.empty();
    c.inputs = inputs;
    c.cells = r.trace->steps.front().cells;
    auto fail = [&](const std::string& m) {
        if (why) *why = m;
        return false;
    };
    if (r.kind == "progress") {
        if (!in.legal(c)) return fail("the state is not legal");
        if (in.atGoal(c)) return fail("the state is a goal");
        if (!in.enabled(c).empty()) return fail("a rule is enabled");
        return true;
    }
    if (r.kind == "holonomic") {
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
    return replay(*r.trace, engine, in, why);
}

}  // namespace holon::checker
