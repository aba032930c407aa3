// Certificates of proofs for every region (checker/Certificate.h): the text is deterministic, and
// checkCertificate tells a valid one from one that is missing, not a certificate, edited by hand,
// stale, for another lattice or written by another holon (the last cannot be made through the
// CLI, so it is tested here; the others also end to end in tests/cli).

#include "checker/Certificate.h"

#include "rules/Sha256.h"

#include <doctest/doctest.h>

#include <filesystem>
#include <fstream>
#include <sys/stat.h>

using namespace holon;
using checker::CertificateStatus;

namespace {

const std::string kRules = "system s\nstates A\n";

checker::Certificate sample() {
    checker::VerifyReport report;
    report.system = "s";
    checker::Obligation o;
    o.result.name = "termination", o.result.kind = "ranking", o.result.verdict = checker::Verdict::Holds;
    o.result.summary = "every step decreases it";
    o.scope = "every region";
    report.obligations.push_back(o);
    return checker::certificateOf(report, "/some/folder/s.holon", rules::sha256Hex(kRules), "square2d");
}

std::string written(const std::string& name, const std::string& text) {
    const std::string path = (std::filesystem::temp_directory_path() / ("holon_certificate_test_" + name + ".json")).string();
    std::ofstream(path) << text;
    return path;
}

}  // namespace

TEST_CASE("a certificate's text is deterministic and names the file without its folder") {
    const checker::Certificate c = sample();
    CHECK(checker::certificateText(c) == checker::certificateText(sample()));
    CHECK(c.rulesFile == "s.holon");
    CHECK(c.rulesSha256 == rules::sha256Hex(kRules));
    CHECK(c.properties.at(0).provedEverywhere());
    CHECK(checker::certificatePath("/some/folder/s.holon", "hex2d") == "/some/folder/certificates/s.hex2d.json");
}

TEST_CASE("checkCertificate trusts only a certificate that matches") {
    const std::string text = checker::certificateText(sample());
    CHECK(checker::checkCertificate(written("valid", text), rules::sha256Hex(kRules), "square2d").status == CertificateStatus::Valid);
    CHECK(checker::checkCertificate("/nonexistent/c.json", rules::sha256Hex(kRules), "square2d").status == CertificateStatus::Missing);
    CHECK(checker::checkCertificate(written("stale", text), rules::sha256Hex(kRules + "// edited\n"), "square2d").status == CertificateStatus::Stale);
    CHECK(checker::checkCertificate(written("lattice", text), rules::sha256Hex(kRules), "hex2d").status == CertificateStatus::OtherLattice);
    CHECK(checker::checkCertificate(written("json", "{\"certificate\": "), rules::sha256Hex(kRules), "square2d").status == CertificateStatus::Unreadable);
    CHECK(checker::checkCertificate(written("fields", "{\"certificate\": \"x\"}"), rules::sha256Hex(kRules), "square2d").status == CertificateStatus::Unreadable);

    std::string edited = text;
    edited.replace(edited.find("\"proved\""), 8, "\"unknown\"");
    CHECK(checker::checkCertificate(written("tampered", edited), rules::sha256Hex(kRules), "square2d").status == CertificateStatus::Tampered);

    checker::Certificate older = sample();
    older.holon = "0.0.1";  // sealed by its own writer: only the version tells
    const checker::CertificateCheck check = checker::checkCertificate(written("older", checker::certificateText(older)), rules::sha256Hex(kRules), "square2d");
    CHECK(check.status == CertificateStatus::OtherHolon);
    CHECK(check.why.find("written by holon 0.0.1, not by this holon " + checker::holonVersion()) != std::string::npos);

    // Sealed again after an edit holon never makes: a property twice (the first entry was read), or
    // a verdict holon does not write.
    checker::Certificate twice = sample();
    twice.properties.push_back(twice.properties.front());
    twice.properties.back().verdict = "unknown";
    const checker::CertificateCheck dup = checker::checkCertificate(written("twice", checker::certificateText(twice)), rules::sha256Hex(kRules), "square2d");
    CHECK(dup.status == CertificateStatus::Unreadable);
    CHECK(dup.why.find("property 'termination' is listed twice") != std::string::npos);
    checker::Certificate odd = sample();
    odd.properties.front().verdict = "maybe";
    CHECK(checker::checkCertificate(written("verdict", checker::certificateText(odd)), rules::sha256Hex(kRules), "square2d").status == CertificateStatus::Unreadable);
    // A FIFO at the certificate's place blocked every plan of the rules.
    const std::string fifo = (std::filesystem::temp_directory_path() / "holon_certificate_test_fifo.json").string();
    std::filesystem::remove(fifo);
    REQUIRE(::mkfifo(fifo.c_str(), 0600) == 0);
    const checker::CertificateCheck notFile = checker::checkCertificate(fifo, rules::sha256Hex(kRules), "square2d");
    CHECK(notFile.status == CertificateStatus::Unreadable);
    CHECK(notFile.why.find("not a regular file") != std::string::npos);
    std::filesystem::remove(fifo);
}
