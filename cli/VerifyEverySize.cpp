// `holon verify --every-size`: runs the window proofs of checker/EverySize.h for the lattice of
// --lattice (or the system's own), and with --region the bounded proof of each property a window
// cannot decide, so that every property gets a verdict and a scope: "every region" or "region R".

#include "cli/VerifyEverySize.h"

#include "checker/Certificate.h"
#include "checker/Draw.h"
#include "checker/EverySize.h"
#include "checker/NamedRegion.h"
#include "cli/Commands.h"
#include "cli/Inputs.h"
#include "cli/WriteErrors.h"
#include "rules/Error.h"
#include "rules/OutputFile.h"
#include "rules/TextFile.h"

#include <algorithm>
#include <cstdlib>
#include <filesystem>
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

/// Writes each counterexample's trace (ITF) and picture (SVG): a window counterexample on the named
/// region the interpreter confirms it on again (checker/NamedRegion.h), a bounded one on --region.
/// Returns what was written, with the region a re-check needs.
std::vector<std::string> writeCounterexamples(const EverySizeArgs& a, const rules::Model& model, const std::optional<rules::Region>& region,
                                              const checker::VerifyReport& report, const std::optional<rules::OutputFile>& traceOut,
                                              const std::optional<rules::OutputFile>& svgOut, WriteErrors& errors) {
    std::vector<std::string> written;
    if (!traceOut && !svgOut) return written;
    std::vector<const checker::PropertyResult*> shown;
    for (const checker::Obligation& o : report.obligations)
        if (o.result.verdict == checker::Verdict::Violated && o.result.trace) shown.push_back(&o.result);
    for (const checker::PropertyResult* r : shown) {
        std::optional<checker::NamedCounterexample> named;
        if (r->witness.contains("window_radius")) {
            std::string why;
            named = checker::onNamedRegion(model, *r, why);
            if (!named) {
                std::cerr << "holon verify: the counterexample for '" << r->name << "' is not written: " << why << '\n';
                continue;
            }
        } else {
            named = checker::NamedCounterexample{*region, *r->trace, r->inputs.value_or(std::vector<std::uint32_t>(region->size(), 0))};
        }
        const rules::Engine engine(model, named->region, named->inputs);
        const bool several = shown.size() > 1;
        const std::string on = " (on " + named->region.spec() + ")";
        if (traceOut) errors.write(
            "--trace-out", pathFor(traceOut->path(), r->name, several), [&] { return checker::toItf(named->trace, engine, a.file).dump(2) + "\n"; }, written, on);
        if (svgOut)
            errors.write(
                "--svg", pathFor(svgOut->path(), r->name, several), [&] {
                    return checker::drawTraceSvg(named->trace, engine, model.system().name + " on " + named->region.spec() + ": " + r->name + " -- " + named->trace.description);
                },
                written, on);
    }
    return written;
}

/// Where the certificate goes: --certificate, or the rule file's default place for a run that
/// proves every property on windows alone (a subset, or bounded proofs standing in, would replace
/// the record `holon plan` reads with a partial one); `note` says why none is written.
std::optional<rules::OutputFile> certificateFile(const EverySizeArgs& a, const std::string& rulePath, const std::string& lattice, std::string& note) {
    if (a.noCertificate) return std::nullopt;
    if (!a.certificate.empty()) return rules::OutputFile("--certificate", a.certificate);
    if (!a.properties.empty() || !a.region.empty()) {
        note = "none written: --" + std::string(a.properties.empty() ? "region" : "property") + " makes it a partial record; give --certificate PATH to write one";
        return std::nullopt;
    }
    const std::string path = checker::certificatePath(rulePath, lattice);
    const std::string option = "the certificate (default place; --certificate PATH or --no-certificate to change it)";
    rules::prepareOutputDir(option, std::filesystem::path(path).parent_path().string());
    return rules::OutputFile(option, path);
}

/// A folder of its own under the system's temporary folder, removed with its files at the end: the
/// obligations a certificate hashes when --smt-out does not keep them.
class TempDir {
public:
    TempDir() {
        std::string pattern = (std::filesystem::temp_directory_path() / "holon-certificate-XXXXXX").string();
        if (!::mkdtemp(pattern.data())) throw InputError("cannot make a temporary folder in " + std::filesystem::temp_directory_path().string() + " for the certificate's obligations");
        path_ = pattern;
    }
    TempDir(const TempDir&) = delete;
    TempDir& operator=(const TempDir&) = delete;
    ~TempDir() {
        std::error_code ignored;
        std::filesystem::remove_all(path_, ignored);
    }
    const std::string& path() const { return path_; }

private:
    std::string path_;
};

}  // namespace

int runEverySize(const EverySizeArgs& a) {
    auto system = loadRules(a.file, a.noWarnings);
    if (!system) return kExitBadInput;
    std::optional<rules::Region> region;
    if (!a.region.empty()) region = rules::Region::parse(a.region, 4096);
    const rules::Model model(*system, latticeFor(a, *system, region));
    // Output paths are checked before the proofs, so finished work is never lost to a bad path.
    const std::string rulePath = rules::rulesPath(a.file);
    std::string certificateNote;
    const std::optional<rules::OutputFile> certificate = certificateFile(a, rulePath, model.lattice().name(), certificateNote);
    std::optional<rules::OutputFile> traceOut, svgOut;
    if (!a.traceOut.empty()) traceOut.emplace("--trace-out", a.traceOut);
    if (!a.svg.empty()) svgOut.emplace("--svg", a.svg);
    std::optional<TempDir> hashed;  // the obligations a certificate hashes, when --smt-out keeps none
    if (certificate && a.smtOut.empty()) hashed.emplace();
    checker::EverySizeOptions options;
    options.timeoutSeconds = a.obligationTimeout;
    options.budget = a.budget;
    options.memoryMiB = a.memoryMiB;
    options.properties = a.properties;
    options.smtOut = hashed ? hashed->path() : a.smtOut;
    options.smtOutOption = hashed ? "the certificate's temporary folder" : "--smt-out";
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
    // A run a limit or a signal cut short is a partial record, like one with --property: at the
    // default place it would replace the complete certificate `holon plan` reads (a stray
    // --timeout 2 left every verdict unknown there, and --require-proof refused the next plan).
    const auto cut = std::find_if(report.obligations.begin(), report.obligations.end(), [](const checker::Obligation& o) { return o.result.limited; });
    bool certified = certificate && (!a.certificate.empty() || cut == report.obligations.end()) && report.writeErrors.empty();
    if (certificate && !report.writeErrors.empty())
        certificateNote = "none written: --smt-out files it would name could not be written (below)";
    else if (certificate && !certified)
        certificateNote = "none written: a limit cut the run short (" + cut->result.name + ": " + cut->result.summary + "), and a partial record must not replace " +
                          certificate->path() + "; raise the limit, or give --certificate PATH to write it anyway";
    // A write that fails (a full disk) is said after the table, which it no longer takes with it.
    WriteErrors errors;
    for (const std::string& e : report.writeErrors) errors.add(e);
    if (certified) {
        certified = errors.attempt([&] { certificate->write(checker::certificateText(checker::certificateOf(report, rulePath, system->sourceSha256, model.lattice().name()))); },
                                   "the certificate " + certificate->path());
        if (!certified) certificateNote = "none written (below)";
        if (hashed)
            for (checker::Obligation& o : report.obligations) o.smtFile.clear();  // hashed, and gone with the temporary folder
    }
    const std::vector<std::string> written = writeCounterexamples(a, model, region, report, traceOut, svgOut, errors);
    const int code = unconfirmed ? kExitInternal : caughtSignal() != 0 ? exitCodeFor(StopReason::Interrupted, caughtSignal())
                                                                       : exitCodeFor(report.overall());
    if (a.json) {
        nlohmann::json j = report.toJson();
        j["lattice"] = model.lattice().name();
        j["certificate"] = certified ? nlohmann::json(certificate->path()) : nlohmann::json();
        std::cout << j.dump(2) << '\n';
        errors.raise();
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
        if (r.witness.value("certificate_fails", false)) {
            std::cout << "\nwindow where the local progress certificate of '" << r.name << "' fails (not a counterexample; the cell marked)\n"
                      << every.drawings[k];
            continue;
        }
        std::cout << "\ncounterexample for '" << r.name << "'"
                  << (r.confirmed() ? " (confirmed by the reference interpreter on region " + r.witness.value("confirmed_on", std::string(a.region)) + ")"
                                    : " (NOT confirmed)")
                  << '\n'
                  << every.drawings[k];
    }
    if (!written.empty()) {
        std::cout << "\nwritten:";
        for (const std::string& w : written) std::cout << "\n  " << w;
        std::cout << '\n';
    }
    noteObligationsWithoutSmt(report.obligations, a.smtOut);
    std::cout << "\ncertificate: " << (certified ? certificate->path() + " (holon plan reads it; docs/every-size.md, \"Certificates\")" : certificateNote.empty() ? "none written (--no-certificate)"
                                                                                                                                                                  : certificateNote)
              << '\n';
    errors.raise();  // a file that could not be written outranks the verdict, as in plan
    return code;
}

void noteObligationsWithoutSmt(const std::vector<checker::Obligation>& obligations, const std::string& smtOut) {
    if (smtOut.empty()) return;
    std::string stopped;
    for (const checker::Obligation& o : obligations)
        if (o.result.limited) stopped += (stopped.empty() ? "" : ", ") + o.result.name;
    // An obligation in parts (safety_1, safety_2, ...) writes each part before solving it, so one
    // cut short may lack the files of its later parts.
    if (!stopped.empty())
        std::cout << "\n--smt-out " << smtOut << " may lack files: a limit or a signal cut short " << stopped << ", whose files are written only as each is built\n";
}

}  // namespace holon::cli
