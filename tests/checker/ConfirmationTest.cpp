// Counterexamples come confirmed from the library: a caller of checker::check or checker::verify
// (not only the CLI) gets each trace replayed through the reference interpreter, and a trace that
// does not replay is reported as not confirmed.

#include "CheckSupport.h"
#include "checker/Obligations.h"
#include "checker/Property.h"
#include "rules/Library.h"

namespace holon {

namespace {

rules::System broken(const std::string& stem) {
    return test::parse(rules::readTextFile(std::string(HOLON_TEST_DIR) + "/checker/broken/" + stem + ".holon"));
}

const rules::Property& conserved(const rules::System& s) {
    for (const rules::Property& p : s.properties)
        if (p.kind == rules::Property::Kind::Conserves) return p;
    FAIL("no conserves property");
    return s.properties.front();
}

}  // namespace

TEST_CASE("check() on a broken system returns its counterexample replayed, without the CLI") {
    const test::Checked c = test::checkAll(broken("general1_leaky"), "square:3x2");
    const checker::PropertyResult& mass = c.property(conserved(c.world.system).name);
    REQUIRE(mass.verdict == checker::Verdict::Violated);
    REQUIRE(mass.trace);
    REQUIRE(mass.confirmation);
    CHECK(mass.confirmed());
    CHECK(mass.witness["replayed"] == true);
    CHECK(mass.witness["trace"]["states"].size() == mass.trace->steps.size());

    // The confirmation is the reference interpreter's, not a formality: a step whose successor
    // is not the next state fails it.
    checker::PropertyResult tampered = mass;
    tampered.trace->steps.back().cells = tampered.trace->steps.front().cells;
    std::string why;
    const auto type = checker::propertyType(conserved(c.world.system));
    CHECK_FALSE(type->confirm(tampered, checker::Evidence::Path, *c.world.in, *c.kept.engine, &why));
    CHECK(why.find("successor differs") != std::string::npos);
}

TEST_CASE("verify() on a broken system returns its counterexample confirmed, without the CLI") {
    test::World w(broken("general1_leaky"), "square:3x2");
    checker::VerifyOptions o;
    o.timeoutSeconds = 60;
    const auto report = checker::verify(*w.model, w.region, o);
    const std::string name = conserved(w.system).name;
    const auto it = std::find_if(report.obligations.begin(), report.obligations.end(), [&](const auto& ob) { return ob.result.name == name; });
    REQUIRE(it != report.obligations.end());
    REQUIRE(it->result.verdict == checker::Verdict::Violated);
    CHECK(it->result.confirmed());
    CHECK(it->result.witness["confirmed"] == true);
    CHECK(it->result.witness.contains("trace"));
}

}  // namespace holon
