// `holon plan`'s proof status (issue 31, "verified plans, literally"): a bounded proof does not
// cover a run on a million metamodules, a proof for every region does. The certificate is found
// where `holon verify --every-size` writes it by default (checker::certificatePath of the rule
// file rules::rulesPath resolves), and trusted only when it matches the rule file's SHA-256, the
// plan's lattice and this holon, and its seal is intact; anything else is said as it is.

#include "cli/PlanProof.h"

#include "rules/Error.h"
#include "rules/Library.h"
#include "rules/TextFile.h"

#include <algorithm>
#include <sstream>

namespace holon::cli {

namespace {

std::string joined(const std::vector<std::string>& names) {
    std::string out;
    for (const std::string& n : names) out += (out.empty() ? "" : ", ") + n;
    return out;
}

std::string statusName(checker::CertificateStatus s) {
    switch (s) {
    case checker::CertificateStatus::Valid: return "valid";
    case checker::CertificateStatus::Missing: return "missing";
    case checker::CertificateStatus::Unreadable: return "unreadable";
    case checker::CertificateStatus::Tampered: return "tampered";
    case checker::CertificateStatus::Stale: return "stale";
    case checker::CertificateStatus::OtherLattice: return "other lattice";
    case checker::CertificateStatus::OtherHolon: return "other holon version";
    }
    return "unknown";
}

/// "a,b": as --require-proof takes them.
std::string commaList(const std::vector<std::string>& names) {
    std::string out;
    for (const std::string& n : names) out += (out.empty() ? "" : ",") + n;
    return out;
}

bool valid(const PlanProof& p) { return p.check.status == checker::CertificateStatus::Valid; }

}  // namespace

PlanProof planProof(const std::string& rules, const rules::System& system, const std::string& lattice) {
    const std::string path = rules::rulesPath(rules, "--rules");
    PlanProof proof;
    proof.check = checker::checkCertificate(checker::certificatePath(path, lattice), system.sourceSha256, lattice);
    proof.verify = "holon verify " + rules + " --every-size --lattice " + lattice;
    for (const rules::Property& p : system.properties) {
        const checker::CertifiedProperty* c = valid(proof) ? proof.check.certificate.property(p.name) : nullptr;
        (c && c->provedEverywhere() ? proof.proved : proof.notProved).push_back(p.name);
    }
    return proof;
}

std::string PlanProof::line() const {
    const std::string lattice = check.certificate.lattice.empty() ? "the lattice" : check.certificate.lattice;
    if (!valid(*this))
        return "NO proof for every region: the rules run without one (" + check.why + "); to prove what can be: " + verify;
    std::string out = proved.empty() ? "nothing proved for every region" : joined(proved) + " proved for every region of " + lattice;
    out += " (certificate " + check.path + ")";
    if (!notProved.empty()) out += "; NOT proved for every region: " + joined(notProved);
    return out;
}

nlohmann::json PlanProof::json() const {
    return {{"certificate", check.path}, {"status", statusName(check.status)}, {"why", check.why}, {"proved", proved}, {"not_proved", notProved}};
}

std::vector<std::string> requiredProperties(const std::string& spec, const rules::System& system) {
    std::vector<std::string> names;
    if (spec.empty()) {
        for (const rules::Property& p : system.properties) names.push_back(p.name);
        return names;
    }
    std::istringstream in(spec);
    for (std::string name; std::getline(in, name, ',');) {
        if (!system.property(name)) {
            std::vector<std::string> declared;
            for (const rules::Property& p : system.properties) declared.push_back(p.name);
            throw InputError("--require-proof=" + spec + ": system '" + system.name + "' has no property '" + name + "'; it declares " + joined(declared));
        }
        names.push_back(name);
    }
    return names;
}

void requireProof(const PlanProof& proof, const std::vector<std::string>& required) {
    if (!valid(proof)) throw InputError("--require-proof: " + proof.check.why + "; write the certificate with: " + proof.verify);
    std::vector<std::string> missing;
    std::string why;
    for (const std::string& name : required) {
        if (std::find(proof.proved.begin(), proof.proved.end(), name) != proof.proved.end()) continue;
        missing.push_back(name);
        const checker::CertifiedProperty* c = proof.check.certificate.property(name);
        why += "\n  " + name + ": " + (c ? c->verdict + " (" + c->scope + "): " + c->evidence : "not in the certificate");
    }
    if (missing.empty()) return;
    throw InputError("--require-proof: " + joined(missing) + (missing.size() == 1 ? " is" : " are") + " not proved for every region (certificate " + proof.check.path + "):" +
                     why + "\n  prove " + (missing.size() == 1 ? "it" : "them") + " and write the certificate again with: " + proof.verify +
                     (proof.proved.empty() ? "" : "\n  or require only what is proved: --require-proof=" + commaList(proof.proved)));
}

}  // namespace holon::cli
