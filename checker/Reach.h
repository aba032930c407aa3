#pragma once
// Unbounded reachability on a fixed region: an invariant proved for every state reachable from
// given configurations, by Z3's Spacer engine over constrained Horn clauses.

#include "checker/SmtEncoding.h"
#include "checker/Verdict.h"
#include "rules/Budget.h"
#include "rules/Interpreter.h"
#include "rules/OutputFile.h"

#include <functional>
#include <string>
#include <vector>

namespace holon::checker {

struct ReachProof {
    Verdict verdict = Verdict::Unknown;  // Holds: no bad state is reachable; Violated: one is
    /// When proved: the inductive invariant Spacer found, as its conjuncts, each a disjunction over
    /// "(x,y)=STATE", "(x,y)!=STATE", "(x,y) in {A, B}", "(x,y) not in {A, B}" (and "NAME(x,y)" for
    /// inputs, when the initial configurations differ in them).
    std::vector<std::string> invariant;
    std::string reason;  // when unknown
    /// Written SMT-LIB2 (with `smtFile`): the three checks of the invariant found, ordinary queries
    /// that are unsat when it is a certificate. The Horn clauses themselves go to `smtFile`.
    std::vector<std::string> certificateFiles;
    bool usedKnown = false;  // the invariant assumes the `known` states (see below)
};

/// A set of states, as a formula on a state of the given encoding.
using BadStates = std::function<smt::Term(SmtEncoding&, const SmtEncoding::State&)>;

/// Shows the `bad` states unreachable from `initial`. `known`, if given, holds in every reachable
/// state (invariants proved already); a second solver then takes steps only from states satisfying
/// it, which can spare Spacer rediscovering it (or not: the first answer wins). `engine` must cover
/// every input combination (Engine(..., true)). `budget` bounds building the clauses, Spacer and
/// the certificate checks; past it the children are stopped and the verdict is unknown. A proof is only reported after the invariant Spacer
/// found has been checked as a certificate. `smtFile` (a path ending ".smt2"), if given, names the
/// Horn clauses' file; the certificate checks go next to it, under the same option in messages.
ReachProof proveUnreachable(const rules::Engine& engine, const BadStates& bad, const std::vector<rules::Configuration>& initial,
                            const Budget& budget, const rules::OutputFile* smtFile = nullptr, const BadStates& known = {});

}  // namespace holon::checker
