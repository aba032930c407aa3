// Unbounded reachability for a fixed region (issue: Z3 proofs, obligation 5). Bounded model
// checking only speaks about paths up to k steps, and an inductiveness proof (holon verify's
// invariant obligation) fails whenever the invariant is true of every reachable state but not
// closed under steps from unreachable ones -- planner_general2's first safety invariant was such a
// case. Constrained Horn clauses state the question exactly,
//     init(s)            -> reach(s)
//     reach(a), step(a,b) -> reach(b)
//     reach(s), not I(s)  -> false
// and a solution (Z3's Spacer engine: IC3/PDR generalised to Horn clauses; Komuravelli, Gurfinkel
// and Chaki, CAV 2014) is an interpretation of `reach` that contains the initial states, is closed
// under steps and implies I: an inductive strengthening of I that a person can read. The step and the
// invariant come from the one SMT encoding (SmtEncoding), so the semantics are the interpreter's.

#include "checker/Reach.h"

#include "checker/Forked.h"
#include "checker/SmtEncoding.h"
#include "checker/SolverLimits.h"
#include "rules/Error.h"

#include <algorithm>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <nlohmann/json.hpp>

namespace holon::checker {

namespace {

/// body -> head, closed over every constant in it (each Horn clause is its own universal sentence).
smt::Term clause(const smt::Term& body, const smt::Term& head) { return smt::universalClosure(smt::implies(body, head)); }

/// An argument of the reach relation: cell `cell` holds state `state`, or (state < 0) an input bit.
struct Atom {
    int cell, state;
    std::string where, text;  // "(x,y)" and "(x,y)=STATE" or "NAME(x,y)"
};

/// The solved relation as infix text; `atoms[k]` names argument k.
std::string infix(const smt::Term& e, const std::vector<Atom>& atoms, int outer = 0) {
    auto joined = [&](const char* op, int prec) {
        std::string s;
        for (unsigned k = 0; k < e.arity(); ++k) s += (k ? op : "") + infix(e.arg(k), atoms, prec + 1);
        return prec < outer ? "(" + s + ")" : s;
    };
    switch (e.op()) {
    case smt::Term::Op::Var: return atoms.at(e.varIndex()).text;
    case smt::Term::Op::True: return "true";
    case smt::Term::Op::False: return "false";
    case smt::Term::Op::Not: return "not " + infix(e.arg(0), atoms, 4);
    case smt::Term::Op::And: return joined(" and ", 2);
    case smt::Term::Op::Or: return joined(" or ", 1);
    case smt::Term::Op::Implies: return joined(" -> ", 0);
    case smt::Term::Op::Eq: return joined(" == ", 3);
    case smt::Term::Op::Xor: return joined(" != ", 3);
    case smt::Term::Op::Other: return e.str();
    }
    return e.str();
}

/// One conjunct of the invariant. A disjunction's positive atoms on one cell read as
/// "(x,y) in {A, B}", or as the complement, "(x,y) not in {C, D}", when that is shorter (each cell
/// holds exactly one state).
std::string clauseText(const smt::Term& e, const std::vector<Atom>& atoms, const rules::Alphabet& alphabet) {
    std::vector<smt::Term> literals;
    if (e.op() == smt::Term::Op::Or)
        for (unsigned k = 0; k < e.arity(); ++k) literals.push_back(e.arg(k));
    else
        literals.push_back(e);
    std::vector<std::pair<int, std::vector<int>>> byCell;  // in order of first mention
    std::vector<std::string> rest;
    auto atomOf = [&](const smt::Term& x) { return x.op() == smt::Term::Op::Var ? &atoms.at(x.varIndex()) : nullptr; };
    for (const smt::Term& l : literals) {
        const Atom* atom = atomOf(l);
        const Atom* negated = l.op() == smt::Term::Op::Not ? atomOf(l.arg(0)) : nullptr;
        if (negated && negated->state >= 0) {
            rest.push_back(negated->where + "!=" + alphabet.name(static_cast<rules::CellValue>(negated->state)));
            continue;
        }
        if (!atom || atom->state < 0) {
            rest.push_back(infix(l, atoms, 2));
            continue;
        }
        auto it = std::find_if(byCell.begin(), byCell.end(), [&](const auto& g) { return g.first == atom->cell; });
        if (it == byCell.end()) it = byCell.insert(byCell.end(), {atom->cell, {}});
        it->second.push_back(atom->state);
    }
    std::string text;
    auto add = [&](const std::string& part) { text += (text.empty() ? "" : " or ") + part; };
    for (const auto& group : byCell) {
        const int cell = group.first;  // not a structured binding: clang 14 cannot capture those
        const std::vector<int>& states = group.second;
        const std::string where = std::find_if(atoms.begin(), atoms.end(), [&](const Atom& a) { return a.cell == cell; })->where;
        // The listed states or their complement, whichever is shorter.
        std::vector<int> others;
        for (int v = 0; v < alphabet.size(); ++v)
            if (std::find(states.begin(), states.end(), v) == states.end()) others.push_back(v);
        const bool positive = states.size() <= others.size();
        const std::vector<int>& named = positive ? states : others;
        std::string names;
        for (int v : named) names += (names.empty() ? "" : ", ") + alphabet.name(static_cast<rules::CellValue>(v));
        if (named.size() == 1) add(where + (positive ? "=" : "!=") + names);
        else add(where + (positive ? " in {" : " not in {") + names + "}");
    }
    for (const std::string& r : rest) add(r);
    return text;
}

/// The conjuncts of `found` (over the reach relation's arguments) without those the others imply,
/// given that each cell holds one state: Spacer's lemmas overlap ("(0,0)=_" next to
/// "(0,0)!=S&to=1"). `onState` is `found` on state `s`, conjunct for conjunct.
std::vector<smt::Term> irredundant(const smt::Term& found, const smt::Term& onState, const SmtEncoding::State& s, smt::Context& ctx) {
    std::vector<smt::Term> kept, concrete;
    const bool conjunction = found.op() == smt::Term::Op::And;
    for (unsigned k = 0; k < (conjunction ? found.arity() : 1); ++k) {
        kept.push_back(conjunction ? found.arg(k) : found);
        concrete.push_back(conjunction ? onState.arg(k) : onState);
    }
    smt::Solver oneState(ctx);
    for (const auto& row : s.is) {
        oneState.add(smt::anyOf(ctx, row));
        for (std::size_t a = 0; a < row.size(); ++a)
            for (std::size_t b = a + 1; b < row.size(); ++b) oneState.add(!(row[a] && row[b]));
    }
    for (std::size_t k = kept.size(); k-- > 0;) {
        oneState.push();
        for (std::size_t j = 0; j < kept.size(); ++j)
            if (j != k) oneState.add(concrete[j]);
        oneState.add(!concrete[k]);
        const bool implied = oneState.check() == smt::Result::Unsat;
        oneState.pop();
        if (implied) kept.erase(kept.begin() + static_cast<long>(k)), concrete.erase(concrete.begin() + static_cast<long>(k));
    }
    return kept;
}

/// The Horn clauses, built and solved in this process.
ReachProof solveHorn(smt::Context& ctx, const rules::Engine& engine, const BadStates& bad, const BadStates& known,
                     const std::vector<rules::Configuration>& initial, const Budget& budget, const std::string& smtOption, const std::string& smtFile) {
    const rules::Region& region = engine.region();
    const rules::Model& model = engine.model();
    const int alphabet = model.alphabet().size();
    const auto& inputNames = model.system().inputs;
    // Inputs never change along a path. When every initial configuration has the same inputs they
    // are fixed in every clause; otherwise they are arguments of reach, set by the initial clause.
    const bool sharedInputs = std::all_of(initial.begin(), initial.end(), [&](const auto& c) { return c.inputs == initial.front().inputs; });

    SmtEncoding enc(ctx, engine, SmtEncoding::Use::HornClauses, budget);
    std::vector<Atom> atoms;
    for (int i = 0; i < region.size(); ++i) {
        const rules::Vec v = region.cell(i);
        const std::string where = "(" + std::to_string(v.x) + "," + std::to_string(v.y) + (region.lattice().dimension() == 3 ? "," + std::to_string(v.z) : "") + ")";
        for (int s = 0; s < alphabet; ++s) atoms.push_back({i, s, where, where + "=" + model.alphabet().name(static_cast<rules::CellValue>(s))});
        if (!sharedInputs)
            for (const std::string& in : inputNames) atoms.push_back({i, -1, where, in + where});
    }
    const smt::Relation reach = ctx.relation("reach", static_cast<unsigned>(atoms.size()));
    auto argsOf = [&](const SmtEncoding::State& s) {
        std::vector<smt::Term> args;
        for (int i = 0; i < region.size(); ++i) {
            for (int v = 0; v < alphabet; ++v) args.push_back(s.is[i][v]);
            if (!sharedInputs)
                for (const smt::Term& bit : enc.inputBits()[i]) args.push_back(bit);
        }
        return args;
    };
    auto at = [&](const SmtEncoding::State& s) { return reach(argsOf(s)); };
    // Each clause carries the facts (one state per cell, rank bounds, witnesses) made while building it.
    std::size_t factsFrom = 0;
    auto newFacts = [&] {
        smt::Term all = sharedInputs ? enc.inputsAre(initial.front().inputs) : ctx.boolVal(true);
        for (std::size_t k = factsFrom; k < enc.facts().size(); ++k) all = all && enc.facts()[k];
        factsFrom = enc.facts().size();
        return all;
    };

    const SmtEncoding::State s = enc.state("s");
    smt::Term init = ctx.boolVal(false);
    for (const rules::Configuration& c : initial) init = init || (enc.configurationIs(s, c.cells) && (sharedInputs ? ctx.boolVal(true) : enc.inputsAre(c.inputs)));
    const smt::Term initBody = newFacts() && init;
    const SmtEncoding::State a = enc.state("a"), b = enc.state("b");
    // Facts are collected after each body is built: building makes them. The encoding's lemmas
    // (SmtEncoding::instantiate) are left out: they made Spacer 30 times slower.
    const smt::Term stepped = known(enc, a) && enc.step(a, b, ctx.intConst("instance"));
    const smt::Term stepBody = stepped && newFacts();
    const SmtEncoding::State q = enc.state("q");
    const smt::Term isBad = known(enc, q) && bad(enc, q);
    const smt::Term badBody = isBad && newFacts();

    smt::Solver solver(ctx, smt::Solver::Logic::Horn);
    // Spacer and each certificate check get the time left.
    auto limitTime = [&](smt::Solver& s) {
        budget.check("building the Horn clauses");
        s.limitTime(budget);
    };
    solver.add(clause(initBody, at(s)));
    solver.add(clause(stepBody && at(a), at(b)));
    solver.add(clause(badBody && at(q), ctx.boolVal(false)));

    ReachProof proof;
    auto header = [&](const std::string& expected) {
        return "; holon reachability proof: system " + model.system().name + ", region " + region.spec() + "\n; expected: " + expected + "\n";
    };
    if (!smtFile.empty()) {
        budget.check("writing the SMT-LIB2 file");
        rules::OutputFile(smtOption, smtFile)
            .write(header("sat (the model's `reach` is an inductive invariant excluding the bad states)") + "(set-logic HORN)\n" + solver.toSmt2());
    }

    limitTime(solver);
    const smt::Result r = solver.check();
    if (r == smt::Result::Unsat) proof.verdict = Verdict::Violated;
    if (r == smt::Result::Unknown) proof.reason = solver.reasonUnknown();
    if (r == smt::Result::Sat) {
        // Spacer's answer is a certificate; it is checked here with three ordinary queries that
        // any SMT solver can re-check (--smt-out writes them): it holds initially, every step
        // keeps it, and no bad state satisfies it.
        const smt::Model m = solver.model();
        const std::optional<smt::Term> definition = m.definition(reach);
        const smt::Term found = definition ? definition->simplify() : ctx.boolVal(true);
        auto inv = [&](const SmtEncoding::State& st) { return found.substituteVars(argsOf(st)); };
        const std::pair<const char*, smt::Term> checks[] = {
            {"init", initBody && !inv(s)}, {"step", stepBody && inv(a) && !inv(b)}, {"safe", badBody && inv(q)}};
        proof.verdict = Verdict::Holds;
        for (const auto& [part, query] : checks) {
            smt::Solver check(ctx);
            limitTime(check);
            check.add(query);
            if (!smtFile.empty()) {
                const std::string file = smtFile.substr(0, smtFile.size() - 5) + "." + part + ".smt2";
                rules::OutputFile(smtOption, file).write(header(std::string("unsat (certificate check '") + part + "' of Spacer's invariant)") + "(set-logic ALL)\n" + check.toSmt2());
                proof.certificateFiles.push_back(file);
            }
            if (check.check() != smt::Result::Unsat) {
                proof.verdict = Verdict::Unknown;
                proof.reason = std::string("Spacer's invariant failed its certificate check '") + part + "'";
                break;
            }
        }
        if (proof.verdict == Verdict::Holds)
            for (const smt::Term& c : irredundant(found, inv(s), s, ctx)) proof.invariant.push_back(clauseText(c, atoms, model.alphabet()));
    }
    return proof;
}

nlohmann::json toJson(const ReachProof& p) {
    return {{"verdict", static_cast<int>(p.verdict)}, {"invariant", p.invariant}, {"reason", p.reason}, {"files", p.certificateFiles}, {"used_known", p.usedKnown}};
}

ReachProof reachProofFromJson(const nlohmann::json& answer) {
    ReachProof proof;
    if (answer.contains("error")) {
        proof.reason = answer["error"].get<std::string>();
        return proof;
    }
    proof.verdict = static_cast<Verdict>(answer["verdict"].get<int>());
    proof.invariant = answer["invariant"].get<std::vector<std::string>>();
    proof.reason = answer["reason"].get<std::string>();
    proof.certificateFiles = answer["files"].get<std::vector<std::string>>();
    proof.usedKnown = answer["used_known"].get<bool>();
    return proof;
}

/// "dir/x.smt2" -> "dir/x.v1.smt2": the file of portfolio variant k.
std::string variantFile(const std::string& smtFile, std::size_t k) {
    return smtFile.empty() ? smtFile : smtFile.substr(0, smtFile.size() - 5) + ".v" + std::to_string(k) + ".smt2";
}

}  // namespace

// Spacer runs in forked children (Forked.h): with Z3 4.8.12, deleting a context after Spacer took
// three times as long as the proof itself (planner_general2 on square:3x2: 2.9 s to prove, 8 s to
// free it). With known invariants there are two children, a portfolio on the two cores: one
// restricts steps to the known invariants, one does not. Neither dominates (measured before Safety
// gained reaches(U, nbr, P|F): general2 Progress on 3x2, 1.5 s with safety, 112 s without;
// general3, a timeout with, 31 s without); the first definite answer wins.
ReachProof proveUnreachable(const rules::Engine& engine, const BadStates& bad, const std::vector<rules::Configuration>& initial,
                            const Budget& budget, const rules::OutputFile* out, const BadStates& known) {
    const std::string smtFile = out ? out->path() : std::string(), smtOption = out ? out->option() : std::string();
    const BadStates nothing = [](SmtEncoding&, const SmtEncoding::State& st) { return st.is[0][0].context().boolVal(true); };
    std::vector<BadStates> variants{known ? known : nothing};
    if (known) variants.push_back(nothing);
    std::vector<ForkedJob> jobs;
    for (std::size_t k = 0; k < variants.size(); ++k)
        jobs.push_back([&, k](bool forked) {
            auto solve = [&](smt::Context& ctx) {
                ReachProof p = solveHorn(ctx, engine, bad, variants[k], initial, budget, smtOption, variantFile(smtFile, k));
                p.usedKnown = known && k == 0;
                return toJson(p);
            };
            if (forked) {
                shareSolverMemory(static_cast<int>(variants.size()));
                return solve(*new smt::Context());  // never freed: the child ends with _exit
            }
            smt::Context ctx(budget);
            return solve(ctx);
        });
    const ForkedAnswer answer = firstDecisive(
        jobs, [](const nlohmann::json& a) { return a.contains("verdict") && static_cast<Verdict>(a["verdict"].get<int>()) != Verdict::Unknown; }, budget);
    ReachProof best = answer.job >= 0 ? reachProofFromJson(answer.answer) : ReachProof{};
    // No child answered (the solvers overran the grace past the budget): the reason firstDecisive
    // gives, not "the solver gave up: ".
    if (answer.job < 0) best.reason = answer.answer.value("error", std::string("timeout: no solver process answered"));
    const int winner = best.verdict != Verdict::Unknown ? answer.job : -1;
    // The winner's files take the plain names; the others' are removed, with the temporaries of a
    // loser stopped in the middle of a write (OutputFile writes beside the file, then renames).
    if (!smtFile.empty()) {
        const std::string plain = smtFile.substr(0, smtFile.size() - 5);
        for (std::size_t k = 0; k < variants.size(); ++k) {
            const std::string variant = variantFile(smtFile, k), stem = variant.substr(0, variant.size() - 5);
            for (const char* part : {"", ".init", ".step", ".safe"}) {
                const std::string file = stem + part + ".smt2";
                if (winner != static_cast<int>(k)) std::remove(file.c_str());
                else if (std::rename(file.c_str(), (plain + part + ".smt2").c_str()) != 0 && errno != ENOENT)
                    throw InputError(smtOption + " " + plain + part + ".smt2: cannot move the finished file into place: " + std::strerror(errno));
            }
            const std::filesystem::path folder = std::filesystem::path(stem).parent_path();
            const std::string prefix = std::filesystem::path(stem).filename().string() + ".";
            std::error_code ec;
            for (const auto& entry : std::filesystem::directory_iterator(folder.empty() ? "." : folder, ec)) {
                const std::string name = entry.path().filename().string();
                if (name.rfind(prefix, 0) == 0 && name.find(".smt2.tmp-") != std::string::npos) std::filesystem::remove(entry.path(), ec);
            }
            if (winner == static_cast<int>(k))
                for (std::string& f : best.certificateFiles) f = plain + f.substr(stem.size());
        }
    }
    return best;
}

}  // namespace holon::checker
