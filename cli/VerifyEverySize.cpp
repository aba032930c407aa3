// `holon verify --every-size`: runs the window proofs of checker/EverySize.h for the lattice of
// --lattice (or the system's own), and with --region the bounded proof of each property a window
// cannot decide, so that every property gets a verdict and a scope: "every region" or "region R".

#include "cli/VerifyEverySize.h"

#include "checker/Draw.h"
#include "checker/EverySize.h"
#include "cli/Commands.h"
#include "cli/Inputs.h"
#include "rules/Error.h"

#include <algorithm>
#include <iomanip>
#include <iostream>
#include <optional>
#include <unistd.h>

namespace holon::cli {

namespace {

const rules::Lattice& latticeFor(const EverySizeArgs& a, const rules::System& system, const std::optional<rules::Region>& region) {
    if (!a.lattice.empty()) {
        const rules::Lattice* l = rules::Lattice::byName(a.lattice);
        if (!l) throw InputError("--lattice: unknown lattice '" + a.lattice + "'; choose square2d, hex2d or cubic3d");
        if (region && &region->lattice() != l)
            throw InputError("--region " + region->spec() + " is a region of " + region->lattice().name() + ", not of --lattice " + a.lattice);
        return *l;
    }
    if (system.lattice) return rules::Lattice::get(*system.lattice);
    if (region) return region->lattice();
    throw InputError("--every-size needs the lattice: --lattice square2d, hex2d or cubic3d");
}

}  // namespace

int runEverySize(const EverySizeArgs& a) {
    auto system = loadRules(a.file, a.noWarnings);
    if (!system) return kExitBadInput;
    std::optional<rules::Region> region;
    if (!a.region.empty()) region = rules::Region::parse(a.region, 4096);
    const rules::Model model(*system, latticeFor(a, *system, region));
    checker::EverySizeOptions options;
    options.timeoutSeconds = a.obligationTimeout;
    options.budget = a.budget;
    options.memoryMiB = a.memoryMiB;
    options.properties = a.properties;
    options.smtOut = a.smtOut;
    options.smtOutOption = "--smt-out";
    const bool terminal = isatty(2) && !a.json;
    auto announce = [&](const std::string& name) {
        if (terminal) std::cerr << "\r  proving " << name << "...                    " << std::flush;
    };
    checker::EverySizeReport every = checker::verifyEverySize(model, options, announce);
    checker::VerifyReport& report = every.report;

    // What a window cannot decide gets the bounded proof on --region, its counterexamples confirmed
    // by the reference interpreter as `holon verify --region` does.
    bool unconfirmed = false;
    if (region && !every.notLocal.empty()) {
        checker::VerifyOptions bounded;
        bounded.timeoutSeconds = a.obligationTimeout;
        bounded.budget = a.budget;
        bounded.memoryMiB = a.memoryMiB;
        bounded.properties = every.notLocal;
        const checker::VerifyReport local = checker::verify(model, *region, bounded, announce);
        for (const checker::Obligation& o : local.obligations) {
            auto at = std::find_if(report.obligations.begin(), report.obligations.end(), [&](const checker::Obligation& e) { return e.result.name == o.result.name; });
            if (at == report.obligations.end()) continue;
            const std::size_t k = static_cast<std::size_t>(at - report.obligations.begin());
            *at = o;
            at->scope = "region " + region->spec();
            every.drawings[k].clear();
            if (o.result.verdict != checker::Verdict::Violated) continue;
            // verify() confirmed it with the reference interpreter (checker/Property.h).
            if (!o.result.confirmed()) {
                unconfirmed = true;
                reportInternalError("verify", "the counterexample for '" + o.result.name + "' is not confirmed: " + o.result.whyNotConfirmed());
            }
            if (o.result.trace)
                every.drawings[k] = checker::drawTraceAscii(*o.result.trace, rules::Engine(model, *region, o.result.inputs.value_or(std::vector<std::uint32_t>(region->size(), 0))));
        }
    }
    if (terminal) std::cerr << "\r" << std::string(60, ' ') << "\r";
    const int code = unconfirmed ? kExitInternal : exitCodeFor(report.overall());
    if (a.json) {
        nlohmann::json j = report.toJson();
        j["lattice"] = model.lattice().name();
        std::cout << j.dump(2) << '\n';
        return code;
    }
    int scopeWidth = 16;  // "region hex:r2" and longer region names get their column too
    for (const auto& o : report.obligations) scopeWidth = std::max(scopeWidth, static_cast<int>(o.scope.size()) + 2);
    std::cout << system->name << ": " << report.region << " (window proofs, proofs/README.md)" << (region ? "; scope 'region " + region->spec() + "': the bounded proof" : "")
              << "\n\n  " << std::left << std::setw(22) << "obligation" << std::setw(16) << "verdict" << std::setw(scopeWidth) << "scope" << std::setw(10) << "time"
              << "evidence\n";
    for (const auto& o : report.obligations)
        std::cout << "  " << std::setw(22) << o.result.name << std::setw(16) << checker::proofVerdictName(o.result.verdict) << std::setw(scopeWidth) << o.scope << std::setw(10)
                  << (std::to_string(static_cast<int>(o.result.seconds * 1000)) + " ms ") << o.result.summary << '\n';
    for (std::size_t k = 0; k < report.obligations.size(); ++k) {
        if (every.drawings[k].empty()) continue;
        const auto& r = report.obligations[k].result;
        std::cout << "\ncounterexample for '" << r.name << "'"
                  << (r.confirmed() ? " (confirmed by the reference interpreter on region " + r.witness.value("confirmed_on", std::string(a.region)) + ")"
                                    : " (NOT confirmed)")
                  << '\n'
                  << every.drawings[k];
    }
    return code;
}

}  // namespace holon::cli
