#pragma once
// `holon verify`: proof obligations for every configuration of a bounded region, discharged by Z3.

#include "checker/Trace.h"
#include "checker/Verdict.h"
#include "rules/Budget.h"
#include "rules/Engine.h"
#include "rules/Interpreter.h"
#include "rules/OutputFile.h"

#include <functional>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

namespace holon::checker {

/// What every proof run takes, on a bounded region (VerifyOptions) or for every size
/// (EverySize.h): the limits of one obligation and of the job, the properties asked, and where
/// the SMT-LIB2 files go.
struct ProofOptions {
    double timeoutSeconds = 120;          // per obligation: building, writing and solving it
    Budget budget;                        // the whole job's: no obligation runs past it
    std::uint64_t memoryMiB = 0;          // Z3's memory limit for this process; 0: none
    std::vector<std::string> properties;  // empty: all
    std::string smtOut;                   // directory for SMT-LIB2 files, or empty
    std::string smtOutOption;             // how the caller names smtOut in messages (its option); empty: "the SMT-LIB2 folder"
    /// One obligation's budget, from now: its own timeout within the job's.
    Budget obligationBudget() const { return Budget(timeoutSeconds) || budget; }
    /// The name of smtOut in messages: smtOutOption, or "the SMT-LIB2 folder".
    std::string smtOutName() const { return smtOutOption.empty() ? "the SMT-LIB2 folder" : smtOutOption; }
};

struct VerifyOptions : ProofOptions {
    int depth = 0;       // > 0: bounded model checking from `initial`
    bool reach = false;  // every state reachable from `initial` (Spacer)
    std::vector<rules::Configuration> initial;
};

struct Obligation {
    PropertyResult result;  // verdict Holds = proved, Violated = counterexample
    std::string smtFile;    // written file, if any
    /// What the verdict covers: "every region" (EverySize.h), or empty for the report's region.
    std::string scope;
};

/// Writes one --smt-out file for obligation `o` (its smtFile names it once written). A write that
/// fails is kept in `errors` instead of ending the job: the report is worth more than the file.
void writeSmtFile(const rules::OutputFile& file, const std::string& text, Obligation& o, std::vector<std::string>& errors);

struct VerifyReport {
    std::string system, region;
    std::vector<Obligation> obligations;
    /// --smt-out files that could not be written (a full disk): the proofs went on without them,
    /// and the caller reports these after the table (exit 2), as for every output.
    std::vector<std::string> writeErrors;
    bool counterexample() const;
    /// Every obligation's verdict combined: a counterexample wins, then unknown.
    Verdict overall() const;
    nlohmann::json toJson() const;
};

/// Builds and discharges every obligation of the system's properties on the region. Every
/// counterexample is decoded from the model and confirmed by the reference interpreter (its
/// result's `confirmation`, witness["confirmed"]; checker/Property.h says what each kind's claims):
/// one not confirmed is a bug in holon.
/// The smtOut folder is created (or checked) first, before any work; it and every file written
/// into it throw InputError with the reason when they cannot be written.
VerifyReport verify(const rules::Model& model, const rules::Region& region, const VerifyOptions& options,
                    const std::function<void(const std::string&)>& onObligation = {});

}  // namespace holon::checker
