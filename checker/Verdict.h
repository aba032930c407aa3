#pragma once
// The outcome of checking one property, with its evidence.

#include "checker/Trace.h"
#include "rules/Ir.h"

#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

namespace holon::checker {

enum class Verdict { Holds,
                     Violated,
                     Unknown };

/// The verdict of several properties together: violated if any is, else unknown if any is.
inline Verdict combine(Verdict a, Verdict b) {
    if (a == Verdict::Violated || b == Verdict::Violated) return Verdict::Violated;
    if (a == Verdict::Unknown || b == Verdict::Unknown) return Verdict::Unknown;
    return Verdict::Holds;
}

/// As the explorer says it: holds, violated, unknown.
inline std::string verdictName(Verdict v) {
    return v == Verdict::Holds ? "holds" : v == Verdict::Violated ? "violated"
                                                                  : "unknown";
}
/// As a proof says it: proved, counterexample, unknown.
inline std::string proofVerdictName(Verdict v) {
    return v == Verdict::Holds ? "proved" : v == Verdict::Violated ? "counterexample"
                                                                   : "unknown";
}

/// How a ranking's excepted rules read in a verdict: ", and every step of transfer keeps it".
inline std::string exceptText(const rules::Property& ranking) {
    std::string names;
    for (std::size_t i = 0; i < ranking.except.size(); ++i)
        names += (i == 0 ? "" : i + 1 == ranking.except.size() ? " and "
                                                               : ", ") +
                 ranking.except[i];
    return names.empty() ? "" : ", and every step of " + names + " keeps it";
}

/// The reference interpreter's judgement of a counterexample (checker/Property.h): its trace
/// replays, and it has what it claims. One that is not confirmed is a bug in holon.
struct Confirmation {
    bool confirmed = false;
    std::string why;  // what failed, when not confirmed
};

struct PropertyResult {
    std::string name, kind;
    Verdict verdict = Verdict::Unknown;
    std::string summary;               // one line for the table
    nlohmann::json witness = nullptr;  // machine-readable evidence
    double seconds = 0;
    /// Unknown because a limit (time, memory) or a signal cut the work short, not because the
    /// solver could not decide: a record of such a run is partial (no certificate replaces one).
    bool limited = false;
    std::optional<Trace> trace;
    /// Per cell, the input bits (bit k: input k) the evidence holds under, where the check chose
    /// them (verify's solver, over every input value or the given ones); unset: the problem's.
    std::optional<std::vector<std::uint32_t>> inputs;
    /// Set by check() and verify() on every counterexample they return.
    std::optional<Confirmation> confirmation;
    bool confirmed() const { return confirmation && confirmation->confirmed; }
    /// Why it is not confirmed (meaningful when !confirmed()).
    std::string whyNotConfirmed() const { return confirmation ? confirmation->why : "it was not checked"; }
};

/// For an invariant false in `last`: names the first conjunct that is false (in r.witness["conjunct"]
/// and at the end of r.summary) and returns the phrase added (": conjunct 4 of 5, '...', is false").
std::string nameFailingConjunct(PropertyResult& r, const rules::Property& invariant, const rules::Interpreter& in, const rules::Configuration& last);

}  // namespace holon::checker
