// Certificates of --every-size proofs. A certificate names the rule file by its SHA-256, the
// lattice, the holon version and, per property, the verdict, its scope and the SHA-256 of each
// exported obligation (the SMT-LIB2 text proofs/ re-checks with z3 and cvc5). Its own "seal", the
// SHA-256 of the rest as compact JSON (nlohmann sorts keys, so the text is canonical), catches an
// edit by hand; it is no signature: whoever can write the file can recompute it, and the real
// re-check is running the proof again (`holon verify --every-size`) or the exported obligations.

#include "checker/Certificate.h"

#include "rules/ConfigIo.h"
#include "rules/Error.h"
#include "rules/Sha256.h"
#include "rules/TextFile.h"

#include <filesystem>
#include <nlohmann/json.hpp>
#include <sstream>

namespace holon::checker {

namespace {

constexpr const char* kKind = "holon certificate: proofs for every region";

nlohmann::json toJson(const Certificate& c) {
    nlohmann::json properties = nlohmann::json::array();
    for (const CertifiedProperty& p : c.properties) {
        nlohmann::json obligations = nlohmann::json::array();
        for (const auto& [file, hash] : p.obligations) obligations.push_back({{"file", file}, {"sha256", hash}});
        properties.push_back({{"name", p.name}, {"kind", p.kind}, {"verdict", p.verdict}, {"scope", p.scope}, {"evidence", p.evidence}, {"obligations", obligations}});
    }
    return {{"certificate", kKind},
            {"holon", c.holon},
            {"rules", {{"file", c.rulesFile}, {"sha256", c.rulesSha256}}},
            {"system", c.system},
            {"lattice", c.lattice},
            {"properties", properties}};
}

std::string sealOf(const nlohmann::json& body) { return rules::sha256Hex(body.dump()); }

/// A string field, or throws InputError naming it.
std::string field(const nlohmann::json& j, const char* key) {
    if (!j.is_object() || !j.contains(key) || !j[key].is_string()) throw InputError(std::string("no string field \"") + key + "\"");
    return j[key].get<std::string>();
}

Certificate fromJson(const nlohmann::json& j) {
    Certificate c;
    if (field(j, "certificate") != kKind) throw InputError("\"certificate\" is not \"" + std::string(kKind) + "\"");
    c.holon = field(j, "holon");
    c.rulesFile = field(j["rules"], "file");
    c.rulesSha256 = field(j["rules"], "sha256");
    c.system = field(j, "system");
    c.lattice = field(j, "lattice");
    if (!j.contains("properties") || !j["properties"].is_array()) throw InputError("no list \"properties\"");
    for (const nlohmann::json& p : j["properties"]) {
        CertifiedProperty q{field(p, "name"), field(p, "kind"), field(p, "verdict"), field(p, "scope"), field(p, "evidence"), {}};
        // holon writes each property once with one of its verdicts: a file edited and sealed again
        // with a property twice was read by its first entry.
        if (c.property(q.name)) throw InputError("property '" + q.name + "' is listed twice");
        if (q.verdict != "proved" && q.verdict != "counterexample" && q.verdict != "unknown")
            throw InputError("property '" + q.name + "' has verdict '" + q.verdict + "', not proved, counterexample or unknown");
        if (!p.contains("obligations") || !p["obligations"].is_array()) throw InputError("property '" + q.name + "' has no list \"obligations\"");
        for (const nlohmann::json& o : p["obligations"]) q.obligations.emplace_back(field(o, "file"), field(o, "sha256"));
        c.properties.push_back(std::move(q));
    }
    return c;
}

}  // namespace

bool CertifiedProperty::provedEverywhere() const { return verdict == "proved" && scope == "every region"; }

const CertifiedProperty* Certificate::property(const std::string& name) const {
    for (const CertifiedProperty& p : properties)
        if (p.name == name) return &p;
    return nullptr;
}

std::string holonVersion() { return HOLON_VERSION; }

std::string certificatePath(const std::string& ruleFile, const std::string& lattice) {
    const std::filesystem::path file(ruleFile);
    return (file.parent_path() / "certificates" / (file.stem().string() + "." + lattice + ".json")).string();
}

Certificate certificateOf(const VerifyReport& report, const std::string& ruleFile, const std::string& rulesSha256, const std::string& lattice) {
    Certificate c;
    c.rulesFile = std::filesystem::path(ruleFile).filename().string();
    c.rulesSha256 = rulesSha256;
    c.system = report.system;
    c.lattice = lattice;
    c.holon = holonVersion();
    for (const Obligation& o : report.obligations) {
        CertifiedProperty p{o.result.name, o.result.kind, proofVerdictName(o.result.verdict), o.scope, o.result.summary, {}};
        std::istringstream files(o.smtFile);
        for (std::string path; files >> path;)
            p.obligations.emplace_back(std::filesystem::path(path).filename().string(), rules::sha256Hex(rules::readTextFile(path, std::size_t{1} << 30)));
        c.properties.push_back(std::move(p));
    }
    return c;
}

std::string certificateText(const Certificate& c) {
    nlohmann::json j = toJson(c);
    j["seal"] = sealOf(j);
    return j.dump(2) + "\n";
}

CertificateCheck checkCertificate(const std::string& path, const std::string& rulesSha256, const std::string& lattice) {
    CertificateCheck check;
    check.path = path;
    std::error_code error;
    if (!std::filesystem::exists(path, error)) {
        check.why = "there is no certificate " + path;
        return check;
    }
    check.status = CertificateStatus::Unreadable;
    // holon writes a certificate as a regular file; anything else (a FIFO) would block every plan
    // of these rules, --require-proof or not, deaf to --timeout.
    if (!std::filesystem::is_regular_file(path, error)) {
        check.why = path + " is not a certificate: not a regular file";
        return check;
    }
    nlohmann::json j;
    try {
        j = nlohmann::json::parse(rules::readTextFile(path, std::size_t{1} << 26));
        check.certificate = fromJson(j);
    } catch (const nlohmann::json::exception& e) {
        check.why = path + " is not a certificate: not JSON (" + rules::jsonErrorText(e) + ")";
        return check;
    } catch (const InputError& e) {
        check.why = path + " is not a certificate: " + e.what();
        return check;
    }
    const std::string seal = j.contains("seal") && j["seal"].is_string() ? j["seal"].get<std::string>() : "";
    j.erase("seal");
    const Certificate& c = check.certificate;
    if (seal != sealOf(j)) {
        check.status = CertificateStatus::Tampered;
        check.why = path + " was edited after holon wrote it (its seal does not match its content)";
    } else if (c.holon != holonVersion()) {
        check.status = CertificateStatus::OtherHolon;
        check.why = path + " was written by holon " + c.holon + ", not by this holon " + holonVersion();
    } else if (c.rulesSha256 != rulesSha256) {
        check.status = CertificateStatus::Stale;
        check.why = path + " is stale: it was written for another version of the rule file (sha256 " + c.rulesSha256.substr(0, 12) + "..., the file is now " +
                    rulesSha256.substr(0, 12) + "...)";
    } else if (c.lattice != lattice) {
        check.status = CertificateStatus::OtherLattice;
        check.why = path + " is for the " + c.lattice + " lattice, not " + lattice;
    } else {
        check.status = CertificateStatus::Valid;
    }
    return check;
}

}  // namespace holon::checker
