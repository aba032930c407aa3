// `holon verify FILE --region SPEC`: prove a system's properties for every configuration of a
// bounded region with Z3, print a table of obligations, and show each counterexample, confirmed by
// the reference interpreter (in checker::verify).

#include "checker/Draw.h"
#include "checker/Obligations.h"
#include "cli/Commands.h"
#include "cli/Inputs.h"
#include "cli/Limits.h"
#include "cli/VerifyEverySize.h"
#include "cli/WriteErrors.h"
#include "rules/ConfigIo.h"
#include "rules/Error.h"
#include "rules/OutputFile.h"
#include "rules/StopSignals.h"

#include <iomanip>
#include <iostream>
#include <unistd.h>

namespace holon::cli {

namespace {

struct VerifyArgs {
    std::string file, region, traceOut, svg, smtOut, lattice, certificate;
    std::vector<std::string> from, inputs, properties, noWarnings;
    int depth = 0;
    double timeout = 0;  // the whole job; 0: the option left out, no limit
    double obligationTimeout = checker::VerifyOptions{}.timeoutSeconds;
    std::uint64_t memoryMiB = kDefaultMemoryMiB;
    bool json = false, reach = false, everySize = false, noCertificate = false;
};

/// What the reference interpreter found wrong with a counterexample.
int run(const VerifyArgs& a) {
    // From the start: loading and encoding count. A signal stops the proofs (Z3's own catcher
    // is off, smt::Solver), the report so far is printed, and the exit is 128 + the signal: Z3's
    // catcher took SIGINT as one cancelled obligation and the job went on to exit 0 or 3.
    const rules::StopSignals guard(true);
    const Budget budget = Budget(a.timeout) || Budget::onSignals();
    if (a.everySize) {
        if (a.depth > 0 || a.reach || !a.from.empty() || !a.inputs.empty())
            throw InputError("--every-size proves one step on a window: --depth, --reach, --from and --input need --region without it");
        if (!a.certificate.empty() && a.noCertificate) throw InputError("--certificate and --no-certificate: give one of them");
        return runEverySize({a.file, a.lattice, a.region, a.smtOut, a.traceOut, a.svg, a.certificate, a.noCertificate, a.properties, a.noWarnings, budget,
                             a.obligationTimeout, a.memoryMiB, a.json});
    }
    if (!a.certificate.empty() || a.noCertificate)
        throw InputError(std::string(a.noCertificate ? "--no-certificate" : "--certificate") + " is for --every-size (a certificate records a proof for every region); leave it out of a bounded proof");
    if (!a.lattice.empty()) throw InputError("--lattice is for --every-size; a bounded proof takes the lattice of --region");
    if (a.region.empty()) throw InputError("--region is required: a bounded region such as square:3x3 (or --every-size --lattice L for every region)");
    auto system = loadRules(a.file, a.noWarnings);
    if (!system) return 2;
    const rules::Region region = rules::Region::parse(a.region, 4096);
    rules::Model model(*system, region.lattice());
    rules::Interpreter in(model, region);
    // Output paths are checked before the proofs, so finished work is never lost to a bad path.
    std::optional<rules::OutputFile> traceOut, svgOut;
    if (!a.traceOut.empty()) traceOut.emplace("--trace-out", a.traceOut);
    if (!a.svg.empty()) svgOut.emplace("--svg", a.svg);
    checker::VerifyOptions options;
    options.timeoutSeconds = a.obligationTimeout;
    options.budget = budget;
    options.memoryMiB = a.memoryMiB;
    options.depth = a.depth;
    options.reach = a.reach;
    options.properties = a.properties;
    options.smtOut = a.smtOut;
    options.smtOutOption = "--smt-out";
    if (a.depth > 0 && a.from.empty()) throw InputError("--depth needs initial configurations: --from CONFIG");
    if (a.reach && a.from.empty()) throw InputError("--reach needs initial configurations: --from CONFIG");
    if (!a.from.empty() && a.depth == 0 && !a.reach) throw InputError("--from gives the initial configurations of --depth and --reach, and neither is given; add one, or leave out --from");
    // Without --from every input value is quantified over, so an --input would have no effect.
    if (a.from.empty() && !a.inputs.empty())
        throw InputError("--input sets the inputs of --from configurations; without --from, verify proves for every input value");
    if (!a.from.empty()) options.initial = readStarts(in, a.from, a.inputs);
    const bool terminal = isatty(2) && !a.json;
    const auto report = checker::verify(model, region, options, [&](const std::string& name) {
        if (terminal) std::cerr << "\r  proving " << name << "...                    " << std::flush;
    });
    if (terminal) std::cerr << "\r" << std::string(60, ' ') << "\r";

    // verify() confirms every counterexample with the reference interpreter under the inputs it
    // uses. One that is not confirmed is a bug in holon: it is shown for the report, and the exit
    // code says so.
    std::vector<const checker::PropertyResult*> shown;
    bool unconfirmed = false;
    for (const auto& o : report.obligations) {
        if (o.result.verdict != checker::Verdict::Violated) continue;
        if (!o.result.confirmed()) {
            unconfirmed = true;
            reportInternalError("verify", "the counterexample for '" + o.result.name + "' is not confirmed: " + o.result.whyNotConfirmed());
        }
        shown.push_back(&o.result);
    }
    // A path from --from (NAME@bmcK, NAME@reach) is reachable: those come first.
    std::stable_partition(shown.begin(), shown.end(), [](const checker::PropertyResult* r) { return r->kind == "bmc" || r->kind == "reach"; });
    const std::vector<std::uint32_t> noInputs(region.size(), 0);
    auto drawingFor = [&](const checker::PropertyResult& r) { return rules::Engine(model, region, r.inputs.value_or(noInputs)); };
    // A write that fails (a full disk) is said after the table, which it no longer takes with it.
    WriteErrors errors;
    for (const std::string& e : report.writeErrors) errors.add(e);
    std::vector<std::string> written;
    for (const checker::PropertyResult* r : shown) {
        if (!r->trace) continue;
        const rules::Engine drawing = drawingFor(*r);
        const bool several = shown.size() > 1;
        if (traceOut) errors.write(
            "--trace-out", pathFor(traceOut->path(), r->name, several), [&] { return checker::toItf(*r->trace, drawing, a.file).dump(2) + "\n"; }, written);
        if (svgOut)
            errors.write(
                "--svg", pathFor(svgOut->path(), r->name, several), [&] {
                    return checker::drawTraceSvg(*r->trace, drawing, system->name + " on " + region.spec() + ": " + r->name + " -- " + r->trace->description);
                },
                written);
    }
    if (shown.empty()) noteNoCounterexample("verify", {{"--trace-out", traceOut ? traceOut->path() : ""}, {"--svg", svgOut ? svgOut->path() : ""}});
    const int code = unconfirmed ? kExitInternal : caughtSignal() != 0 ? exitCodeFor(StopReason::Interrupted, caughtSignal())
                                                                       : exitCodeFor(report.overall());
    if (a.json) {
        std::cout << report.toJson().dump(2) << '\n';
        errors.raise();
        return code;
    }
    std::cout << system->name << " on " << region.spec() << ": every configuration of the region"
              << (a.depth > 0 || a.reach ? " (NAME@bmcK: paths of K steps from --from; NAME@reach: every state reachable from --from)" : "")
              << "\n\n  " << std::left << std::setw(22)
              << "obligation" << std::setw(16) << "verdict" << std::setw(10) << "time"
              << "evidence\n";
    for (const auto& o : report.obligations)
        std::cout << "  " << std::setw(22) << o.result.name << std::setw(16) << checker::proofVerdictName(o.result.verdict) << std::setw(10)
                  << (std::to_string(static_cast<int>(o.result.seconds * 1000)) + " ms ") << o.result.summary << '\n';
    for (const auto& o : report.obligations) {
        if (!o.result.witness.is_object() || !o.result.witness.contains("inductive_invariant")) continue;
        // Spacer's invariant holds initially, is closed under every step and excludes the bad states.
        const auto& clauses = o.result.witness["inductive_invariant"];
        const std::size_t shown = std::min<std::size_t>(clauses.size(), 40);
        std::cout << "\ninductive invariant for '" << o.result.name << "' (" << clauses.size() << " clauses; each line holds in every reachable state):\n";
        for (std::size_t k = 0; k < shown; ++k) std::cout << "  " << clauses[k].get<std::string>() << '\n';
        if (shown < clauses.size()) std::cout << "  ... " << clauses.size() - shown << " more (--json prints all)\n";
    }
    for (const checker::PropertyResult* r : shown) {
        if (!r->trace) continue;
        std::cout << "\ncounterexample for '" << r->name << "' "
                  << (r->confirmed() ? "(confirmed by the reference interpreter)" : "(NOT confirmed by the reference interpreter: " + r->whyNotConfirmed() + ")") << '\n';
        for (const auto& o : report.obligations)
            if (o.result.name == r->name + "@reach" && o.result.verdict == checker::Verdict::Holds && !options.initial.empty() &&
                r->inputs.value_or(noInputs) == options.initial.front().inputs)
                std::cout << "(no run from the given start reaches it: '" << o.result.name << "' is proved)\n";
        std::cout << checker::drawTraceAscii(*r->trace, drawingFor(*r));  // with one mask per input
    }
    noteObligationsWithoutSmt(report.obligations, a.smtOut);
    if (shown.size() > 1 && !written.empty()) {
        std::cout << "\ntraces written:";
        for (const std::string& w : written) std::cout << ' ' << w;
        std::cout << '\n';
    }
    errors.raise();  // a file that could not be written outranks the verdict, as in plan
    return code;
}

}  // namespace

Run addVerifyCommand(CLI::App& app) {
    auto a = std::make_shared<VerifyArgs>();
    CLI::App* sub = app.add_subcommand("verify", "Prove properties for every configuration of a bounded region, or of every region (--every-size), with Z3");
    addRulesFile(sub, "file", a->file)->required();
    sub->add_option("--region", a->region, "bounded region: square:WxH, cubic:WxHxD or hex:rR (with --every-size: the bounded proof for what is not local)");
    sub->add_flag("--every-size", a->everySize, "prove conservation, rankings and local invariants for every region of the lattice (a window proof)");
    sub->add_option("--lattice", a->lattice, "with --every-size: square2d, hex2d or cubic3d (default: the system's, or --region's)");
    sub->add_option("--property", a->properties, "prove only this property (repeatable)");
    sub->add_option("--depth", a->depth, "also bounded model checking of the invariants to this depth from --from")->check(CLI::Range(1, 10000));
    sub->add_flag("--reach", a->reach, "also prove the invariants for every state reachable from --from, at any depth (Spacer)");
    sub->add_option("--from", a->from, "initial configuration for --depth and --reach (JSON or ASCII art); repeatable");
    sub->add_option("--input", a->inputs, "inputs of the initial configurations: NAME=FILE (ASCII mask), NAME=none or NAME=all; each input must be given with --from");
    addTimeout(sub, a->timeout, "the obligations not decided by then are unknown");
    sub->add_option("--obligation-timeout", a->obligationTimeout, "seconds per obligation, encoding and solving (default " + defaultText(a->obligationTimeout) + ")")->check(secondsValidator());
    addMemory(sub, a->memoryMiB, "for Z3");
    sub->add_flag("--json", a->json, "print the report as JSON");
    sub->add_option("--smt-out", a->smtOut, "write every obligation as SMT-LIB2 into this directory");
    sub->add_option("--certificate", a->certificate, "with --every-size: write the certificate here (default: certificates/STEM.LATTICE.json beside the rule file, for a run of every property without --region)");
    sub->add_flag("--no-certificate", a->noCertificate, "with --every-size: write no certificate");
    sub->add_option("--trace-out", a->traceOut, "write each counterexample as an ITF JSON trace (several: FILE with the obligation's name inserted)");
    sub->add_option("--svg", a->svg, "draw each counterexample as SVG (several: FILE with the obligation's name inserted)");
    sub->add_option("-W", a->noWarnings, "silence a warning: -W no-NAME");
    return [a] { return run(*a); };
}

}  // namespace holon::cli
