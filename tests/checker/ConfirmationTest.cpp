// Counterexamples come confirmed from the library: a caller of checker::check or checker::verify
// (not only the CLI) gets each trace replayed through the reference interpreter, and a trace that
// does not replay is reported as not confirmed.

#include "CheckSupport.h"
#include "checker/Obligations.h"
#include "checker/Property.h"
#include "rules/Library.h"

namespace holon {

namespace {

const rules::Property& conserved(const rules::System& s) {
    for (const rules::Property& p : s.properties)
        if (p.kind == rules::Property::Kind::Conserves) return p;
    FAIL("no conserves property");
    return s.properties.front();
}

}  // namespace

TEST_CASE("check() on a broken system returns its counterexample replayed, without the CLI") {
    const test::Checked c = test::checkAll(test::brokenSystem("general1_leaky"), "square:3x2");
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
    test::World w(test::brokenSystem("general1_leaky"), "square:3x2");
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

TEST_CASE("an obligation's counterexample is confirmed only when its step breaks the property") {
    // A transfer (C D -> D C) replays but keeps the mass: as evidence that mass is not conserved
    // it is refused, with the interpreter's reason; the creation that conjures a D is accepted.
    test::World w(test::brokenSystem("general1_leaky"), "square:3x2");
    const rules::Configuration start = w.ascii("CD.\n...");
    const rules::Engine engine(*w.model, w.region, start.inputs);
    const auto type = checker::propertyType(conserved(w.system));
    auto stepBy = [&](const std::string& rule) {
        checker::PropertyResult r;
        for (int q = 0; q < static_cast<int>(engine.instances().size()); ++q) {
            if (w.model->rules()[engine.instances()[q].rule].name != rule || !engine.matches(start.cells.data(), q)) continue;
            std::vector<rules::CellValue> after = start.cells;
            rules::CellValue saved[rules::Engine::kMaxCells];
            engine.apply(after.data(), q, saved);
            r.trace = checker::Trace{{{start.cells, -1}, {after, q}}, {}, {}, "one step", {}};
            return r;
        }
        FAIL("no enabled instance of " << rule);
        return r;
    };
    std::string why;
    CHECK_FALSE(type->confirm(stepBy("transfer"), checker::Evidence::Obligation, *w.in, engine, &why));
    CHECK(why.find("keeps the amount") != std::string::npos);
    CHECK(type->confirm(stepBy("create"), checker::Evidence::Obligation, *w.in, engine, &why));
}

}  // namespace holon
