#pragma once
// What `holon plan` says about the proofs behind the rules it runs: the certificate `holon verify
// --every-size` wrote for the rule file and the plan's lattice (checker/Certificate.h), checked
// against the file's content, and which declared properties it proves for every region.
// --require-proof refuses to run without them.

#include "checker/Certificate.h"
#include "rules/Ir.h"

#include <nlohmann/json.hpp>
#include <string>
#include <vector>

namespace holon::cli {

struct PlanProof {
    checker::CertificateCheck check;
    std::vector<std::string> proved, notProved;  // the system's declared properties, in its order
    std::string verify;                          // the command that writes the certificate
    /// One line for the plan's summary: what is proved for every region, and plainly what is not.
    std::string line() const;
    nlohmann::json json() const;
};

/// The proof status of `rules` (a file or a bundled name, rules::rulesPath) on `lattice`.
PlanProof planProof(const std::string& rules, const rules::System& system, const std::string& lattice);

/// --require-proof[=P,Q]: the names it requires (every declared property when `spec` is empty);
/// an unknown name is bad input.
std::vector<std::string> requiredProperties(const std::string& spec, const rules::System& system);

/// Throws InputError (exit 2) naming the fix when the certificate is not valid or one of
/// `required` is not proved for every region.
void requireProof(const PlanProof& proof, const std::vector<std::string>& required);

}  // namespace holon::cli
