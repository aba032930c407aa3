#pragma once
// Discharging one proof obligation with Z3: the solver, the SMT-LIB2 export, and the limits that
// make an obligation unknown. Each property kind's obligation (checker/properties/) is written
// against it; verify() (Obligations.cpp) runs them.

#include "checker/Obligations.h"
#include "checker/Smt.h"
#include "checker/SmtEncoding.h"
#include "rules/Budget.h"
#include "rules/Engine.h"
#include "rules/OutputFile.h"

#include <functional>
#include <optional>
#include <string>
#include <vector>

namespace holon::checker {

/// Per cell, the input bits a model chose.
std::vector<std::uint32_t> inputsOf(const smt::Model& m, smt::Context& ctx, const rules::Engine& e);

class ProofRunner {
public:
    ProofRunner(const rules::Model& model, const rules::Region& region, const VerifyOptions& options);

    static Obligation named(const std::string& name, const std::string& kind);

    /// A solver with the encoding's domain facts and the obligation's time left.
    smt::Solver newSolver(smt::Context& ctx, SmtEncoding& enc, double timeoutShare = 1.0) const;

    /// The solver's timeout: what the obligation has left, or `share` of the whole if less (a
    /// side query). Throws OutOfTime when nothing is left.
    void limitTime(smt::Solver& solver, const Budget& budget, double share = 1.0) const;

    /// Solves `query` (after the encoding's domain facts); a model becomes a counterexample via
    /// `decode`. The encoding's lemmas (and `earlierLemmas`) help the solver but are not written
    /// with --smt-out: an exported obligation is the theorem alone, so that a re-check does not
    /// rest on the argument that makes them valid. The obligation's time is withinLimits' to
    /// measure, as for every obligation: it times the whole of it.
    Obligation solve(const std::string& name, const std::string& kind, smt::Context& ctx, SmtEncoding& enc, const smt::Term& query,
                     const std::function<void(const smt::Model&, PropertyResult&)>& decode, const std::string& provedText,
                     double timeoutShare = 1.0, const std::optional<smt::Term>& earlierLemmas = std::nullopt);

    const rules::Engine& engine() const { return engine_; }

    /// A counterexample holds for the inputs the solver chose (free, or fixed to a problem's): they
    /// go with it into the confirmation, the pictures and the trace, and by name into the witness.
    void recordInputs(const smt::Model& m, smt::Context& ctx, PropertyResult& r) const;

    /// A step obligation solved instance by instance on one incremental solver: `base` holds for
    /// every instance, `perInstance(p)` is guarded by an activation literal, and each instance is
    /// checked under its literal. The SMT-LIB2 export is the equivalent single query "base and
    /// exactly one instance".
    Obligation stepwise(const std::string& name, const std::string& kind, smt::Context& ctx, SmtEncoding& enc, const smt::Term& base,
                        const std::function<smt::Term(int)>& perInstance,
                        const std::function<void(const smt::Model&, int, PropertyResult&)>& decode, const std::string& provedText);

    /// Where obligation `name` is written under --smt-out (the folder is prepared by verify()).
    rules::OutputFile smtPath(const std::string& name) const;

    void write(const std::string& name, const smt::Solver& solver, Obligation& o, const Budget& budget);
    /// Every file write() wrote, in order: an obligation a limit cut short after its file was
    /// written still names it (withinLimits returns a fresh obligation).
    const std::vector<std::string>& written() const { return written_; }
    /// The files write() could not write, with the reasons (VerifyReport::writeErrors).
    const std::vector<std::string>& writeErrors() const { return writeErrors_; }

    int placedFrom(const smt::Model& m, const smt::Term& selector) const;

private:
    const rules::Model& model_;
    const rules::Region& region_;
    const VerifyOptions& options_;
    rules::Engine engine_;
    std::vector<std::string> written_, writeErrors_;
};

/// An obligation holon does not encode: verdict unknown, with the reason.
Obligation notEncoded(const std::string& name, const std::string& kind, const std::string& why);

/// Runs one obligation, whose Z3 context lives inside `prove`. One cut short by a limit is unknown,
/// with the limit named, and the next obligation goes on: its budget spent while the formulas were
/// built, or Z3 out of memory (reset here, once its context is gone). Any other Z3 failure is an
/// InternalError.
Obligation withinLimits(const std::string& name, const std::string& kind, const std::function<Obligation()>& prove);
/// The same, for a prover that lists the --smt-out files it writes in `written`: an obligation a
/// limit cut short after its file was written still names it (smt_file was null).
Obligation withinLimits(const std::string& name, const std::string& kind, const std::function<Obligation()>& prove, const std::vector<std::string>& written);

}  // namespace holon::checker
