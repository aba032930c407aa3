// The reference interpreter on small hand-made systems: matching, rewriting with the frame
// condition, pointer references, guards, non-local filtering, and rotation closure.

#include "TestSupport.h"
#include "rules/Engine.h"
#include "rules/Printer.h"
#include "rules/TextFile.h"

using namespace holon;
using test::World;

TEST_CASE("non-local constraints filter successors: intermediate never disconnects") {
    World w = World::library("intermediate", "square:3x1");
    auto c = w.ascii("MMM");
    // Deleting the middle module would split the row; only the two ends can go.
    auto names = w.enabledRules(c);
    CHECK(std::count(names.begin(), names.end(), "destroy") == 2);
    for (const auto& i : w.in->enabled(c)) CHECK(w.in->legal(*w.in->successor(c, i)));
    // Locally the middle deletion matches, but the constraint rejects it.
    int rejected = 0;
    for (int s = 0; s < static_cast<int>(w.model->shapes().size()); ++s)
        for (rules::Vec cell : w.region.cells()) {
            rules::Instance inst{s, cell - w.model->shapes()[s].offsets[0]};
            if (w.in->matches(c, inst) && !w.in->successor(c, inst)) ++rejected;
        }
    CHECK(rejected == 2);  // the middle cell, destroyed from either neighbour
}

TEST_CASE("pointer references resolve to the direction of the referenced cell") {
    World w(test::parse("system t\nfield label: A | B\nfield ptr: dir if B\nrule r: A A => A B&ptr=@0\n"), "square:3x3");
    auto c = w.in->empty();
    c.cells[w.region.indexOf({1, 1, 0})] = static_cast<rules::CellValue>(w.value("A"));
    c.cells[w.region.indexOf({1, 0, 0})] = static_cast<rules::CellValue>(w.value("A"));
    auto enabled = w.in->enabled(c);
    REQUIRE(enabled.size() == 2);  // either cell may recruit the other
    for (const auto& i : enabled) {
        auto next = *w.in->successor(c, i);
        auto cells = *w.in->cellsOf(i);
        // The new B points from its cell back at the anchor.
        const rules::Vec from = w.region.cell(cells[1]), to = w.region.cell(cells[0]);
        CHECK(w.model->alphabet().name(next.cells[cells[1]]) == "B&ptr=" + w.region.lattice().directionName(w.region.lattice().directionOf(to - from)));
    }
}

TEST_CASE("rotation closure: pair rules have one orientation per direction, and cells outside the region never match") {
    rules::System s = test::parse("system t\nstates M\nrule grow: M _ => M M\n");
    for (const auto* l : rules::Lattice::all()) CHECK(rules::Model(s, *l).shapes().size() == static_cast<std::size_t>(l->degree()));
    World w(s, "square:2x2");
    auto c = w.ascii("M.\n..");
    CHECK(w.in->enabled(c).size() == 2);
    World h(s, "hex:r1");
    auto hc = h.in->empty();
    hc.cells[h.region.indexOf({0, 0, 0})] = 1;
    CHECK(h.in->enabled(hc).size() == 6);
}

TEST_CASE("the frame condition keeps fields a right side does not name") {
    World w(test::parse("system t\nfield res: D | C\nfield label: U | F\nrule f: F U => F F\n"), "square:2x1");
    auto c = w.in->empty();
    c.cells[0] = static_cast<rules::CellValue>(w.value("C&F"));
    c.cells[1] = static_cast<rules::CellValue>(w.value("D&U"));
    auto enabled = w.in->enabled(c);
    REQUIRE(enabled.size() == 1);
    auto next = *w.in->successor(c, enabled[0]);
    CHECK(w.at(next, 0, 0) == "C&F");
    CHECK(w.at(next, 1, 0) == "D&F");
}

TEST_CASE("guards quantify over lattice neighbours, including cells outside the region as empty") {
    World w(test::parse("system t\nstates M | N\nrule lone: M => N if no nbr # \nrule crowd: M => N if count nbr M >= 2\n"), "square:3x3");
    auto c = w.ascii("M..\n...\n..M");
    CHECK(w.enabledRules(c) == std::vector<std::string>{"lone", "lone"});
    auto d = w.ascii("MMM");
    CHECK(w.enabledRules(d) == std::vector<std::string>{"crowd"});
}

TEST_CASE("expressions: counts, mass, connected, reaches") {
    World w(test::parse(R"(system t
field label: U | P | F
field parent: dir if P
rule r: U => F
invariant tree: reaches(P, parent, F)
invariant shape: connected and connected(F) and count(P) == 2 and mass == 4
invariant small: connected and count(#) == 2 and all(# | _) and no(P)
invariant joined: connected
)"),
            "square:4x1");
    auto holds = [&](const char* name, const rules::Configuration& c) { return w.in->holds(w.system.property(name)->exprs[0], c); };
    auto c = w.in->empty();
    auto set = [&](int x, const std::string& v) { c.cells[w.region.indexOf({x, 0, 0})] = static_cast<rules::CellValue>(w.value(v)); };
    set(0, "F"), set(1, "P&parent=-x"), set(2, "P&parent=-x"), set(3, "U");
    CHECK(holds("tree", c));
    CHECK(holds("shape", c));
    set(1, "P&parent=+x");  // 1 and 2 now point at each other: a cycle
    CHECK_FALSE(holds("tree", c));
    set(1, "U");
    CHECK_FALSE(holds("tree", c));  // 2 points at a U
    set(3, "_"), set(2, "_");
    CHECK(holds("small", c));
    set(1, "_"), set(3, "F");
    CHECK_FALSE(holds("joined", c));
}

TEST_CASE("reaches(A, nbr, B): every A cell has a path through A cells to a B cell, the engine agrees") {
    World w(test::parse(R"(system t
field label: U | P | F
field parent: dir if P
rule r: U => F
invariant joined: reaches(U, nbr, P|F)
)"),
            "square:5x1");
    const rules::Expr& joined = w.system.property("joined")->exprs[0];
    auto c = w.in->empty();
    auto set = [&](int x, const std::string& v) { c.cells[w.region.indexOf({x, 0, 0})] = static_cast<rules::CellValue>(w.value(v)); };
    auto agree = [&] {
        const bool verdict = w.in->holds(joined, c);
        CHECK(rules::Engine(*w.model, w.region, c.inputs).holds(joined, c.cells.data()) == verdict);
        return verdict;
    };
    CHECK(agree());  // no U at all
    set(0, "U"), set(1, "U"), set(2, "F");
    CHECK(agree());  // 0 through 1 to the F
    set(2, "_"), set(3, "P&parent=+x"), set(4, "F");
    CHECK_FALSE(agree());  // the gap at 2 cuts 0 and 1 off
    set(2, "U");
    CHECK(agree());
    set(3, "U"), set(4, "U");
    CHECK_FALSE(agree());  // U cells only: no target
    CHECK(rules::printSystem(w.system).find("reaches(U, nbr, P | F)") != std::string::npos);
}

TEST_CASE("a region quantifier with a cell guard reads each cell's neighbourhood, @0 being the cell") {
    World w(test::parse(R"(system t
field label: U | P | F
field parent: dir if P
rule r: U => F
invariant pointed: all(F: some nbr P&parent=@0)
invariant lonely: count(U: no nbr #) == 1 and some(F: count nbr U == 2) and no(P: no nbr #)
)"),
            "square:6x1");
    auto holds = [&](const char* name, const rules::Configuration& c) { return w.in->holds(w.system.property(name)->exprs[0], c); };
    auto c = w.in->empty();
    auto set = [&](int x, const std::string& v) { c.cells[w.region.indexOf({x, 0, 0})] = static_cast<rules::CellValue>(w.value(v)); };
    set(0, "U"), set(1, "F"), set(2, "U");
    CHECK_FALSE(holds("pointed", c));  // the F has no P pointing at it
    CHECK_FALSE(holds("lonely", c));   // no U stands alone
    set(2, "P&parent=-x");
    CHECK(holds("pointed", c));
    set(0, "_"), set(3, "U"), set(2, "_"), set(1, "F");
    CHECK_FALSE(holds("pointed", c));
    set(0, "U"), set(2, "U"), set(3, "_");
    CHECK_FALSE(holds("lonely", c));  // two U, each next to the F
    c = w.in->empty();
    set(0, "U"), set(2, "U"), set(3, "F"), set(4, "U");
    CHECK(holds("lonely", c));  // U at 0 alone, the F between two U, no P
    set(5, "P&parent=-x");
    CHECK(holds("lonely", c));  // the P touches the U at 4
    set(4, "_");
    CHECK_FALSE(holds("lonely", c));  // now the P stands alone, and the F has one U
}

TEST_CASE("a copy term moves a module with its fields, blocking cells must be occupied") {
    rules::System s = test::parse(rules::readTextFile(std::string(HOLON_TEST_DIR) + "/../examples/rules/sliding_cube.holon"));
    CHECK(rules::printSystem(test::parse(rules::printSystem(s))) == rules::printSystem(s));
    World w(s, "square:3x3");
    auto c = w.in->empty();
    w.set(c, 0, 0, "M&charge=2"), w.set(c, 0, 1, "M&charge=0"), w.set(c, 1, 1, "M&charge=0");
    bool slid = false;
    for (const auto& i : w.in->enabled(c)) {
        auto next = *w.in->successor(c, i);
        if (w.at(next, 1, 0) == "M&charge=2" && w.at(next, 0, 0) == "_") slid = true;
    }
    CHECK(slid);
    w.set(c, 1, 1, "_");  // without the second wall module the slide from (0,0) to (1,0) is blocked
    w.set(c, 0, 2, "M&charge=0");
    for (const auto& i : w.in->enabled(c)) CHECK_FALSE(w.at(*w.in->successor(c, i), 1, 0) == "M&charge=2");
}

namespace {

/// How many instances of rule `name` are enabled in `c`, by the reference interpreter; the
/// compiled tables must agree.
long enabledBoth(World& w, const rules::Configuration& c, const std::string& name) {
    const auto names = w.enabledRules(c);
    const auto interpreted = std::count(names.begin(), names.end(), name);
    const rules::Engine engine(*w.model, w.region, c.inputs);
    long compiled = 0;
    engine.forEachMatch(c.cells.data(), [&](int p) { compiled += w.model->rules()[engine.instances()[p].rule].name == name; });
    CHECK(compiled == interpreted);
    return interpreted;
}

}  // namespace

TEST_CASE("a <=> rule's right-side inputs are conditions of both directions, whichever way it is written") {
    // Fired forwards, `step` tested only its left side: it moved a module onto a cell outside the
    // target, so `no(A&!target)` failed for this pair and held for the same pair written the other
    // way round (the audit's wrong verdict).
    for (const char* rule : {"rule step / back: A&target _ <=> _ A&target\n", "rule back / step: _ A&target <=> A&target _\n"}) {
        CAPTURE(rule);
        World w(test::parse(std::string("system t\nlattice square2d\nsymmetry none\nstates A\ninput target\n") + rule), "square:3x1");
        const auto count = [&](const rules::Configuration& c, const std::string& name) { return enabledBoth(w, c, name); };
        auto c = w.ascii("A..");
        w.mark(c, "target", "X..");
        CHECK(count(c, "step") == 0);  // the cell it would move to is not in the target
        CHECK(count(c, "back") == 0);
        w.mark(c, "target", "XX.");
        CHECK(count(c, "step") == 1);
        auto d = w.ascii(".A.");
        w.mark(d, "target", ".X.");
        CHECK(count(d, "back") == 0);  // the cell it would move back to is not in the target
        w.mark(d, "target", "XX.");
        CHECK(count(d, "back") == 1);
    }
}

TEST_CASE("a <=> rule's right side may say where an input does not hold: '!target' is a condition of both directions") {
    // language.md allows `!target` on either side of a `<=>` rule; the parser refused every negated
    // atom there ("does not say what the cell becomes"), though an input is not written (an audit).
    World w(test::parse("system t\nlattice square2d\nsymmetry none\nstates A\ninput target\nrule step / back: A _ <=> _ A&!target\n"), "square:3x1");
    const auto count = [&](const rules::Configuration& c, const std::string& name) { return enabledBoth(w, c, name); };
    auto c = w.ascii("A..");
    w.mark(c, "target", ".X.");
    CHECK(count(c, "step") == 0);  // it would move onto the target
    auto e = w.ascii("A..");
    w.mark(e, "target", "..X");
    CHECK(count(e, "step") == 1);
    auto d = w.ascii(".A.");
    w.mark(d, "target", ".X.");
    CHECK(count(d, "back") == 0);  // it stands on the target, which its right side excludes
    auto f = w.ascii(".A.");
    w.mark(f, "target", "X..");
    CHECK(count(f, "back") == 1);
}
