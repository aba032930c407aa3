#pragma once
// Certificates of proofs for every region (issue 31): what `holon verify FILE --every-size` proved
// about one rule file on one lattice, written as JSON so that `holon plan` can say which
// properties of the rules it runs are proved for every region, and refuse a certificate that no
// longer matches them. docs/every-size.md ("Certificates") describes the format.

#include "checker/Obligations.h"

#include <string>
#include <utility>
#include <vector>

namespace holon::checker {

struct CertifiedProperty {
    std::string name, kind, verdict, scope, evidence;  // verdict: proved, counterexample, unknown
    /// The exported obligations (SMT-LIB2, as proofs/ exports them): file name and SHA-256.
    std::vector<std::pair<std::string, std::string>> obligations;
    /// Proved, with the scope "every region".
    bool provedEverywhere() const;
};

struct Certificate {
    std::string rulesFile, rulesSha256, system, lattice, holon;  // rulesFile: the file's name, without its folder
    std::vector<CertifiedProperty> properties;
    const CertifiedProperty* property(const std::string& name) const;
};

/// The holon version that writes and accepts certificates.
std::string holonVersion();

/// Where a rule file's certificate for a lattice lives, unless --certificate says otherwise:
/// `certificates/STEM.LATTICE.json` in the rule file's folder (rules/library/certificates/ for a
/// bundled system).
std::string certificatePath(const std::string& ruleFile, const std::string& lattice);

/// The certificate of an --every-size report on the rule file `ruleFile`, whose text has the
/// SHA-256 `rulesSha256` (rules::System::sourceSha256). Each obligation's smtFile (space-separated
/// paths) is read back and hashed.
Certificate certificateOf(const VerifyReport& report, const std::string& ruleFile, const std::string& rulesSha256, const std::string& lattice);

/// The certificate as JSON text: deterministic (no time, no path beyond the file's name), with a
/// "seal", the SHA-256 of the rest, so that an edit by hand shows.
std::string certificateText(const Certificate& c);

enum class CertificateStatus { Valid,
                               Missing,
                               Unreadable,    // not a certificate (not JSON, fields missing)
                               Tampered,      // the seal does not match the content
                               Stale,         // the rule file has changed since
                               OtherLattice,  // written for another lattice
                               OtherHolon };  // written by another holon version

struct CertificateCheck {
    CertificateStatus status = CertificateStatus::Missing;
    std::string path, why;    // why: what is wrong with it, in a sentence; empty when valid
    Certificate certificate;  // as read; trust it only when valid
};

/// Reads the certificate at `path` and checks it against the rule file's SHA-256 (of its text, as
/// rules::System::sourceSha256) and the lattice.
CertificateCheck checkCertificate(const std::string& path, const std::string& rulesSha256, const std::string& lattice);

}  // namespace holon::checker
