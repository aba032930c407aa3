// Discharging one proof obligation with Z3 (moved out of Obligations.cpp so that each property
// kind's obligation, checker/properties/, is written against it): a solver with the encoding's
// domain facts and the time the obligation has left, an optional SMT-LIB2 export of the theorem
// alone, counterexample decoding with the inputs the solver chose, and the limits (timeout, Z3 out
// of memory) that make an obligation unknown rather than stop the run.

#include "checker/ProofRunner.h"

#include "checker/Forked.h"
#include "checker/SolverLimits.h"
#include "rules/ConfigIo.h"
#include "rules/Error.h"

#include <algorithm>
#include <filesystem>

namespace holon::checker {

namespace {

std::string fileSafe(std::string s) {
    for (char& c : s)
        if (!std::isalnum(static_cast<unsigned char>(c)) && c != '_' && c != '-') c = '_';
    return s;
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

}  // namespace

std::vector<std::uint32_t> inputsOf(const smt::Model& m, smt::Context& ctx, const rules::Engine& e) {
    std::vector<std::uint32_t> in(e.region().size(), 0);
    for (int i = 0; i < e.region().size(); ++i)
        for (std::size_t k = 0; k < e.model().system().inputs.size(); ++k) {
            if (m.isTrue(ctx.boolConst("in_" + e.model().system().inputs[k] + "_" + std::to_string(i)))) in[i] |= 1u << k;
        }
    return in;
}

ProofRunner::ProofRunner(const rules::Model& model, const rules::Region& region, const VerifyOptions& options)
    : model_(model), region_(region), options_(options), engine_(model, region, {}, true) {}

Obligation ProofRunner::named(const std::string& name, const std::string& kind) {
    Obligation o;
    o.result.name = name;
    o.result.kind = kind;
    return o;
}

smt::Solver ProofRunner::newSolver(smt::Context& ctx, SmtEncoding& enc, double timeoutShare) const {
    smt::Solver solver(ctx);
    limitTime(solver, enc.budget(), timeoutShare);
    for (const smt::Term& f : enc.facts()) solver.add(f);
    return solver;
}

void ProofRunner::limitTime(smt::Solver& solver, const Budget& budget, double share) const {
    budget.check("building the formulas");
    solver.limitTime(budget, options_.timeoutSeconds * share);
}

Obligation ProofRunner::solve(const std::string& name, const std::string& kind, smt::Context& ctx, SmtEncoding& enc, const smt::Term& query,
                              const std::function<void(const smt::Model&, PropertyResult&)>& decode, const std::string& provedText,
                              double timeoutShare, const std::optional<smt::Term>& earlierLemmas) {
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
        ctx.checkStopped("solving");                   // the deadline or a signal, not the solver, stopped it
        if (outOfMemory(reason)) ctx.markExhausted();  // the answer may come from a forked child
        o.result.verdict = Verdict::Unknown;
        o.result.summary = "the solver gave up: " + unknownReason(reason);
        o.result.limited = limitReached(reason);
        break;
    }
    return o;
}

void ProofRunner::recordInputs(const smt::Model& m, smt::Context& ctx, PropertyResult& r) const {
    r.inputs = inputsOf(m, ctx, engine_);
    if (model_.system().inputs.empty()) return;
    if (!r.witness.is_object()) r.witness = nlohmann::json::object();
    r.witness["inputs"] = inputsJson(engine_, *r.inputs);
}

Obligation ProofRunner::stepwise(const std::string& name, const std::string& kind, smt::Context& ctx, SmtEncoding& enc, const smt::Term& base,
                                 const std::function<smt::Term(int)>& perInstance,
                                 const std::function<void(const smt::Model&, int, PropertyResult&)>& decode, const std::string& provedText) {
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
            o.result.limited = true;
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
            ctx.checkStopped("solving");
            o.result.verdict = Verdict::Unknown;
            o.result.summary = "the solver gave up on instance " + std::to_string(p) + ": " + unknownReason(solver.reasonUnknown());
            o.result.limited = limitReached(solver.reasonUnknown());
            break;
        }
    }
    return o;
}

rules::OutputFile ProofRunner::smtPath(const std::string& name) const {
    const std::filesystem::path dir(options_.smtOut);
    return rules::OutputFile(options_.smtOutName(), (dir / (fileSafe(model_.system().name) + "." + fileSafe(region_.spec()) + "." + fileSafe(name) + ".smt2")).string());
}

void ProofRunner::write(const std::string& name, const smt::Solver& solver, Obligation& o, const Budget& budget) {
    budget.check("writing the SMT-LIB2 file");
    const rules::OutputFile file = smtPath(name);
    o.smtFile.clear();  // bmc writes its file again at each depth
    writeSmtFile(file,
                 "; holon proof obligation: system " + model_.system().name + ", region " + region_.spec() + ", property " + name +
                     "\n; expected: unsat (the property holds for every configuration of the region)\n(set-logic ALL)\n" + solver.toSmt2(),
                 o, writeErrors_);
    if (!o.smtFile.empty()) written_.push_back(file.path());
}

int ProofRunner::placedFrom(const smt::Model& m, const smt::Term& selector) const { return m.intValue(selector); }

Obligation notEncoded(const std::string& name, const std::string& kind, const std::string& why) {
    Obligation o;
    o.result.name = name;
    o.result.kind = kind;
    o.result.summary = why;
    return o;
}

Obligation withinLimits(const std::string& name, const std::string& kind, const std::function<Obligation()>& prove) {
    const Budget clock;
    auto stopped = [&](const std::string& why) {
        Obligation o = notEncoded(name, kind, why);
        o.result.seconds = clock.elapsed();
        o.result.limited = true;
        return o;
    };
    try {
        Obligation o = prove();
        // The whole obligation's time, as its timeout counts it: building the formulas too (progress
        // under count(#) >= 1 on hex:r3 said 0.35 s, took 5 s, and was cut by a 4.5 s timeout).
        o.result.seconds = clock.elapsed();
        if (outOfMemory(o.result.summary)) recoverSolverMemory();  // Z3 said unknown rather than throwing
        return o;
    } catch (const OutOfTime& e) {
        return stopped(e.what());
    } catch (const Interrupted& e) {
        // The verdicts so far are reported (the CLI exits 128 + the signal); this obligation and
        // those after it say why they were not decided.
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

Obligation withinLimits(const std::string& name, const std::string& kind, const std::function<Obligation()>& prove, const std::vector<std::string>& written) {
    const std::size_t before = written.size();
    Obligation o = withinLimits(name, kind, prove);
    if (o.smtFile.empty())
        for (std::size_t k = before; k < written.size(); ++k)
            if (std::find(written.begin() + before, written.begin() + k, written[k]) == written.begin() + k)  // bmc writes its file again at each depth
                o.smtFile += (o.smtFile.empty() ? "" : " ") + written[k];
    return o;
}

}  // namespace holon::checker
