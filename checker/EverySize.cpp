// Proofs for every region (issue 31). Conservation, a ranking's decrease and the inductiveness of
// an invariant made of per-cell conditions are each about one step of one rule instance. A step
// reads and writes a bounded pattern, and lattices are translation invariant, so every step of
// every region is a translate of a step of one of the shapes placed at the origin of a window
// (Window.h) whose cells are free. The query per property is the bounded one with its
// hypotheses cut down to what the window can state honestly:
//   conserves   the focus instance fires and the amount on its pattern changes
//   ranking     the focus instance fires and the ranking does not decrease (or, excepted, changes)
//   invariant   the focus instance fires, every conjunct holds at every window cell whose
//               neighbours are in the window, and conjunct k fails at a cell within the conjuncts'
//               radius of the pattern (nothing else can change); a some/connected/reaches
//               conjunct: its frame condition fails instead (EverySizeInvariant.h plans the conjuncts)
// Non-local constraints are dropped (the query only gets more models). UNSAT is then a proof for
// every region; proofs/README.md argues it cell by cell. A model is a window counterexample, which
// may be spurious (the window is not a region): it counts only once the bounded encoding has
// completed it on a concrete region around the window, with the instance and the cells it reads
// fixed, and the reference interpreter has replayed the step and seen the property break.

#include "checker/EverySize.h"

#include "checker/Draw.h"
#include "checker/EverySizeInvariant.h"
#include "checker/EverySizeProgress.h"
#include "checker/ProofRunner.h"
#include "checker/Property.h"
#include "checker/SmtEncoding.h"
#include "checker/SolverLimits.h"
#include "checker/StepObligation.h"
#include "checker/Window.h"
#include "rules/Error.h"
#include "rules/OutputFile.h"
#include "rules/Printer.h"

#include <algorithm>
#include <filesystem>
#include <map>
#include <memory>

namespace holon::checker {

namespace {

using rules::CellValue;
using State = SmtEncoding::State;
using Cells = std::vector<CellValue>;

std::string fileSafe(std::string s) {
    for (char& c : s)
        if (!std::isalnum(static_cast<unsigned char>(c)) && c != '_' && c != '-') c = '_';
    return s;
}

std::vector<std::uint32_t> inputsOf(const smt::Model& m, const SmtEncoding& enc) {
    std::vector<std::uint32_t> in;
    for (const auto& bits : enc.inputBits()) {
        std::uint32_t v = 0;
        for (std::size_t k = 0; k < bits.size(); ++k)
            if (m.isTrue(bits[k])) v |= 1u << k;
        in.push_back(v);
    }
    return in;
}

class Prover {
public:
    Prover(const rules::Model& model, const EverySizeOptions& options) : model_(model), options_(options) {}
    /// The --smt-out files that could not be written (VerifyReport::writeErrors).
    const std::vector<std::string>& writeErrors() const { return writeErrors_; }
    /// The --smt-out files written so far, in order (withinLimits).
    const std::vector<std::string>& written() const { return written_; }

    /// The window of `margin`, made once per margin.
    const Window& window(int margin) {
        auto& w = windows_[margin];
        if (!w) w = std::make_unique<Window>(model_, margin);
        return *w;
    }

    Obligation prove(const StepObligation& ob, std::string& drawing) {
        const Budget budget = options_.obligationBudget();
        const Window& w = window(ob.margin);
        Obligation o;
        o.result.name = ob.name;
        o.result.kind = ob.kind;
        o.scope = "every region";
        smt::Context ctx(budget);
        SmtEncoding enc(ctx, w.engine(), SmtEncoding::Use::Queries, budget);
        const State c = enc.state("c"), d = enc.state("d");
        std::vector<smt::Term> act, body;
        for (std::size_t k = 0; k < (ob.atCell ? 1 : w.focus().size()); ++k) {
            const int q = w.focus()[k];
            act.push_back(ctx.boolConst("instance_" + std::to_string(q)));
            body.push_back(ob.onWindow(enc, w, q, c, d));
        }
        smt::Solver solver(ctx);
        for (const smt::Term& f : enc.facts()) solver.add(f);
        for (std::size_t k = 0; k < act.size(); ++k) solver.add(smt::implies(act[k], body[k]));
        if (!options_.smtOut.empty()) {
            budget.check("writing the SMT-LIB2 file");
            const rules::OutputFile file(options_.smtOutName(),
                                         (std::filesystem::path(options_.smtOut) /
                                          (fileSafe(model_.system().name) + ".every-size." + model_.lattice().name() + "." + fileSafe(ob.name) + ".smt2"))
                                             .string());
            smt::Solver copy(ctx);
            for (const smt::Term& f : enc.facts()) copy.add(f);
            for (std::size_t k = 0; k < act.size(); ++k) copy.add(smt::implies(act[k], body[k]));
            copy.add(smt::anyOf(ctx, act));
            writeSmtFile(file,
                         "; holon proof obligation for every region: system " + model_.system().name + ", lattice " + model_.lattice().name() + ", property " + ob.name +
                             "\n; window: every rule shape with its first cell at the origin, and every point within " + std::to_string(ob.margin) +
                             " steps of its pattern, free (" + std::to_string(w.region().size()) +
                             " cells; proofs/README.md)\n; expected: unsat (the property holds on every region of the lattice)\n(set-logic ALL)\n" + copy.toSmt2(),
                         o, writeErrors_);
            if (!o.smtFile.empty()) written_.push_back(o.smtFile);
        }
        o.result.verdict = Verdict::Holds;
        o.result.summary = ob.proved + " (window of radius " + std::to_string(ob.margin) + ", " + std::to_string(w.region().size()) + " cells)";
        for (std::size_t k = 0; k < act.size(); ++k) {
            budget.check("solving");
            solver.limitTime(budget);
            const smt::Result r = solver.check({act[k]});
            if (r == smt::Result::Unsat) continue;
            if (r == smt::Result::Unknown) {
                ctx.checkStopped("solving");
                o.result.verdict = Verdict::Unknown;
                o.result.summary = "the solver gave up on rule " + ruleOf(w, w.focus()[k]) + ": " + unknownReason(solver.reasonUnknown());
                o.result.limited = limitReached(solver.reasonUnknown());
                break;
            }
            const smt::Model m = solver.model();
            if (ob.atCell) {
                // Drawn with the model's inputs, the cell the certificate is about marked.
                const Trace window{{{enc.decode(m, c), -1}}, {}, ob.name, ob.broken, {w.region().indexOf({0, 0, 0})}};
                drawing = drawTraceAscii(window, rules::Engine(model_, w.region(), inputsOf(m, enc)));
                o.result.verdict = Verdict::Unknown;
                o.result.summary = "not proved for every size: a window cell " + ob.broken + "; that is no counterexample on a region";
                o.result.witness = {{"window_radius", ob.margin}, {"window_cells", w.region().size()}, {"certificate_fails", true}};
                break;
            }
            refuted(ob, w, w.focus()[k], enc.decode(m, c), inputsOf(m, enc), budget, o, drawing);
            break;
        }
        return o;
    }

private:
    std::string ruleOf(const Window& w, int q) const { return model_.stepRules(w.engine().instances()[q].shape, true); }

    /// A window counterexample: completed on the window grown by one (the bounded encoding, with the
    /// instance's pattern and the cells its guard reads fixed), then replayed by the interpreter.
    void refuted(const StepObligation& ob, const Window& w, int q, const Cells& windowBefore, const std::vector<std::uint32_t>& windowInputs,
                 const Budget& budget, Obligation& o, std::string& drawing) {
        const rules::Region concrete = w.region().grown(1);  // the window's cells keep their indices
        const rules::Engine open(model_, concrete, {}, true);
        const int placed = open.instanceAt(concrete.indexOf({0, 0, 0}), w.engine().instances()[q].shape);
        const std::string rule = ruleOf(w, q);
        // Every rule that makes this step, as the message names them: the shape is kept once.
        nlohmann::json names = nlohmann::json::array();
        for (int r : model_.stepRuleList(w.engine().instances()[q].shape)) names.push_back(model_.rules()[r].name);
        o.result.witness = {{"rule", names[0]}, {"rules", names}, {"window_radius", ob.margin}, {"window_cells", w.region().size()}};
        std::string why;
        std::optional<Trace> trace;
        std::vector<std::uint32_t> inputs;
        try {
            smt::Context ctx(budget);
            SmtEncoding enc(ctx, open, SmtEncoding::Use::Queries, budget);
            const State c = enc.state("c"), d = enc.state("d");
            smt::Term query = ob.onRegion(enc, placed, c, d);
            for (int i : w.around(q, ruleRadius(model_))) {
                query = query && c.is[i][windowBefore[i]];
                for (std::size_t k = 0; k < enc.inputBits()[i].size(); ++k)
                    query = query && (((windowInputs[i] >> k) & 1u) ? enc.inputBits()[i][k] : !enc.inputBits()[i][k]);
            }
            smt::Solver solver(ctx);
            solver.add(query);
            solver.add(enc.instantiate().all);
            for (const smt::Term& f : enc.facts()) solver.add(f);
            solver.limitTime(budget);
            switch (solver.check()) {
            case smt::Result::Sat: {
                const smt::Model m = solver.model();
                inputs = inputsOf(m, enc);
                trace = Trace{{{enc.decode(m, c), -1}, {enc.decode(m, d), placed}}, {}, ob.name, ob.broken, {}};
                break;
            }
            case smt::Result::Unsat: why = "no configuration of " + concrete.spec() + " around it breaks the property"; break;
            case smt::Result::Unknown:
                ctx.checkStopped("completing the counterexample");
                why = "the solver gave up completing it: " + unknownReason(solver.reasonUnknown());
                break;
            }
        } catch (const OutOfTime& e) {
            why = e.what();
        }
        if (trace) {
            // Confirmed as verify() confirms a bounded counterexample: by the property's own type.
            const rules::Engine engine(model_, concrete, inputs);
            const rules::Interpreter in(model_, concrete);
            const auto type = propertyType(*ob.property);
            o.result.trace = trace;
            o.result.inputs = inputs;
            confirmInto(o.result, *type, Evidence::Obligation, in, engine, "confirmed");
            if (o.result.confirmed()) {
                type->explain(o.result, in, engine);
                drawing = drawTraceAscii(*trace, engine);
                o.result.verdict = Verdict::Violated;
                o.result.summary = "rule " + rule + " " + ob.broken + " (a window counterexample, confirmed on region " + concrete.spec() + " by the reference interpreter)";
                o.result.witness["confirmed_on"] = concrete.spec();
                return;
            }
            why = o.result.whyNotConfirmed();
            o.result.trace.reset();
            o.result.inputs.reset();
        }
        o.result.witness["confirmed"] = false;
        o.result.verdict = Verdict::Unknown;
        o.result.summary = "not proved for every size: rule " + rule + " " + ob.broken + " on the window, but that is not confirmed on region " + concrete.spec() + " (" + why + ")";
        o.result.witness["why_unconfirmed"] = why;
    }

    const rules::Model& model_;
    const EverySizeOptions& options_;
    std::map<int, std::unique_ptr<Window>> windows_;
    std::vector<std::string> writeErrors_, written_;
};

/// Conservation of mass or of the module count: the amount on the pattern (the frame keeps the rest).
StepObligation conserves(const rules::Model& model, const rules::Property& p) {
    const bool byMass = p.quantity == rules::Property::Quantity::Mass;
    auto changed = [byMass](SmtEncoding& enc, const rules::Engine& e, int q, const State& c, const State& d) {
        smt::Context& ctx = c.is[0][0].context();
        smt::Term before = ctx.intVal(0), after = ctx.intVal(0);
        auto cellAmount = [&](const State& s, int cell) { return byMass ? enc.cellMassUnits(s, cell) : smt::ite(s.is[cell][0], ctx.intVal(0), ctx.intVal(1)); };
        const rules::Engine::Placed& placed = e.instances()[q];
        for (int k = 0; k < placed.size; ++k) before = before + cellAmount(c, placed.cells[k]), after = after + cellAmount(d, placed.cells[k]);
        return enc.fires(q, c, d) && before != after;
    };
    StepObligation ob;
    ob.name = p.name, ob.kind = "conserves", ob.margin = ruleRadius(model), ob.property = &p;
    ob.proved = "every rule keeps it, on every region";
    ob.broken = std::string("changes the ") + (byMass ? "mass" : "count");
    ob.onWindow = [changed](SmtEncoding& enc, const Window& w, int q, const State& c, const State& d) { return changed(enc, w.engine(), q, c, d); };
    ob.onRegion = [changed](SmtEncoding& enc, int q, const State& c, const State& d) {
        return enc.legal(c) && enc.legal(d) && changed(enc, enc.engine(), q, c, d);
    };
    return ob;
}

/// A ranking: its change is a sum over the cells a step can affect. A count with a cell guard
/// (count(H: no nbr _)) changes within one step of the pattern and reads one further: margin 2.
StepObligation ranking(const rules::Model& model, const rules::Property& p) {
    int countRadius = 0;
    for (const rules::Expr& x : p.exprs) countRadius = std::max(countRadius, readRadius(x));
    auto notDecreased = [&p](SmtEncoding& enc, int q, const State& c, const State& d) { return enc.fires(q, c, d) && enc.rankingBroken(p, q, d, c); };
    StepObligation ob;
    ob.name = p.name, ob.kind = "ranking", ob.margin = std::max(ruleRadius(model), 2 * countRadius), ob.property = &p;
    ob.proved = "every step decreases it lexicographically" + exceptText(p) + ", on every region";
    ob.broken = "does not decrease it (or, excepted, changes it)";
    ob.onWindow = [notDecreased](SmtEncoding& enc, const Window&, int q, const State& c, const State& d) { return notDecreased(enc, q, c, d); };
    ob.onRegion = [notDecreased](SmtEncoding& enc, int q, const State& c, const State& d) { return enc.legal(c) && enc.legal(d) && notDecreased(enc, q, c, d); };
    return ob;
}

}  // namespace

EverySizeReport verifyEverySize(const rules::Model& model, const EverySizeOptions& options, const std::function<void(const std::string&)>& onObligation) {
    const rules::System& system = model.system();
    if (!options.smtOut.empty()) rules::prepareOutputDir(options.smtOutName(), options.smtOut);
    for (const std::string& name : options.properties)
        if (!system.property(name)) throw InputError("system '" + system.name + "' has no property '" + name + "'");
    rules::requirePatternsNear(model, "a proof for every size (its window around each rule)");
    limitSolverMemory(options.memoryMiB);
    EverySizeReport out;
    out.report.system = system.name;
    out.report.region = "every region of the " + model.lattice().name() + " lattice";
    Prover prover(model, options);
    auto add = [&](Obligation o, std::string drawing = "") {
        out.report.obligations.push_back(std::move(o));
        out.drawings.push_back(std::move(drawing));
    };
    auto undecided = [&](const rules::Property& p, const std::string& why) {
        Obligation o;
        o.result.name = p.name, o.result.kind = rules::propertyKindName(p.kind);
        o.result.summary = "not proved for every size: " + why;
        o.scope = "every region";
        out.notLocal.push_back(p.name);
        add(o);
    };
    // Runs one step obligation within its limits (withinLimits): a timeout, a signal or Z3 out of
    // memory is unknown, and the verdicts so far are reported.
    auto run = [&](const StepObligation& ob) {
        if (onObligation) onObligation(ob.name);
        std::string drawing;
        Obligation o = withinLimits(
            ob.name, ob.kind, [&] { return prover.prove(ob, drawing); }, prover.written());
        o.scope = "every region";
        return std::make_pair(o, drawing);
    };
    // Invariants conjunct by conjunct (checker/EverySizeInvariant.h); the first that fails decides. `local`:
    // no conjunct was left undecided for want of a window argument.
    struct Proved {
        Obligation o;
        std::string drawing;
        bool local = true;
    };
    auto invariant = [&](const rules::Property& p) {
        const InvariantPlan plan = planInvariant(model, p, prover.window(0).engine());
        if (plan.steps.empty()) {
            Proved u{{}, "", false};
            u.o.result.name = p.name, u.o.result.kind = "invariant", u.o.scope = "every region";
            u.o.result.summary = "not proved for every size: " + plan.undecided;
            return u;
        }
        Obligation total;
        total.result.name = p.name, total.result.kind = "invariant", total.scope = "every region";
        total.result.verdict = Verdict::Holds;
        std::string drawing;
        for (const StepObligation& step : plan.steps) {
            auto [part, d] = run(step);
            total.result.seconds += part.result.seconds;
            if (!part.smtFile.empty()) total.smtFile += (total.smtFile.empty() ? "" : " ") + part.smtFile;
            total.result.summary = part.result.summary;
            if (part.result.verdict == Verdict::Holds) continue;
            part.result.name = p.name;
            part.result.seconds = total.result.seconds;
            part.smtFile = total.smtFile;
            total = part, drawing = d;
            break;
        }
        if (total.result.verdict == Verdict::Holds) {
            if (!plan.undecided.empty()) {
                total.result.verdict = Verdict::Unknown;
                total.result.summary = "not proved for every size: " + plan.undecided;
                return Proved{total, drawing, false};
            } else if (!plan.trusted.empty()) {
                total.result.summary += "; " + plan.trusted;
            }
        }
        return Proved{total, drawing, true};
    };
    auto asked = [&](const rules::Property& p) {
        return options.properties.empty() || std::find(options.properties.begin(), options.properties.end(), p.name) != options.properties.end();
    };
    std::vector<const rules::Property*> provedInvariants, progresses;
    for (const rules::Property& p : system.properties) {
        if (!asked(p)) continue;
        switch (p.kind) {
        case rules::Property::Kind::Conserves: {
            auto [o, drawing] = run(conserves(model, p));
            add(o, drawing);
            break;
        }
        case rules::Property::Kind::Ranking: {
            std::string why;
            for (const rules::Expr& x : p.exprs)
                if (why.empty()) why = notLocalNumber(x, prover.window(0).engine());
            if (!why.empty()) {
                undecided(p, why);
                break;
            }
            auto [o, drawing] = run(ranking(model, p));
            add(o, drawing);
            break;
        }
        case rules::Property::Kind::Invariant: {
            Proved r = invariant(p);
            if (r.o.result.verdict == Verdict::Holds) provedInvariants.push_back(&p);
            if (!r.local) out.notLocal.push_back(p.name);
            add(r.o, r.drawing);
            break;
        }
        case rules::Property::Kind::Progress: progresses.push_back(&p); break;
        case rules::Property::Kind::Holonomic:
            undecided(p, "holonomy relates two whole configurations, not one step on a window");
            break;
        }
    }
    // Progress assumes the invariants proved for every region, also those not asked for.
    for (const rules::Property& p : system.properties)
        if (!progresses.empty() && p.kind == rules::Property::Kind::Invariant && !asked(p) && invariant(p).o.result.verdict == Verdict::Holds)
            provedInvariants.push_back(&p);
    for (const rules::Property* p : progresses) {
        const ProgressPlan plan = planProgress(model, *p, provedInvariants, prover.window(0).engine());
        if (plan.steps.empty()) {
            undecided(*p, plan.undecided);
            continue;
        }
        auto [o, drawing] = run(plan.steps[0]);
        if (o.result.verdict != Verdict::Holds && o.result.verdict != Verdict::Unknown) throw InternalError("a progress certificate refuted progress");
        if (o.result.verdict == Verdict::Unknown) out.notLocal.push_back(p->name);
        add(o, drawing);
    }
    out.report.writeErrors = prover.writeErrors();
    return out;
}

}  // namespace holon::checker
