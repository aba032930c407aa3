#pragma once
// `holon verify FILE --every-size --lattice L [--region R]`: the proofs for every region of a
// lattice (checker/EverySize.h); with --region, the properties that are not local get the bounded
// proof on R instead, and say so in their scope. It writes a certificate for `holon plan` and, on
// request, each confirmed counterexample as an ITF trace and an SVG picture.

#include "checker/Obligations.h"
#include "rules/Budget.h"

#include <cstdint>
#include <string>
#include <vector>

namespace holon::cli {

struct EverySizeArgs {
    std::string file, lattice, region, smtOut, traceOut, svg;
    /// Where the certificate goes (checker/Certificate.h); empty: the rule file's default place
    /// when every property is proved on windows alone (no --property, no --region), else none.
    std::string certificate;
    bool noCertificate = false;
    std::vector<std::string> properties, noWarnings;
    Budget budget;                 // the whole job's
    double obligationTimeout = 0;  // seconds per property
    std::uint64_t memoryMiB = 0;
    bool json = false;
};

int runEverySize(const EverySizeArgs& a);

/// After either verify table: the obligations a limit or a signal cut short, whose files `smtOut`
/// (--smt-out) may lack, so that a partial folder is not taken for the whole set.
void noteObligationsWithoutSmt(const std::vector<checker::Obligation>& obligations, const std::string& smtOut);

}  // namespace holon::cli
