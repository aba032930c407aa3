// Print -> re-parse round trips: every library file and every valid golden file re-parses from its
// printed form to an equal IR, and printing is a fixed point.

#include "TestSupport.h"
#include "rules/Library.h"
#include "rules/Printer.h"
#include "rules/TextFile.h"

#include <filesystem>

using namespace holon;

TEST_CASE("every library file round-trips through the printer") {
    const auto files = rules::libraryFiles();
    CHECK(files.size() >= 10);
    for (const std::string& file : files) {
        CAPTURE(file);
        rules::Diagnostics d(file, rules::readTextFile(file));
        auto original = rules::parseSystem(rules::readTextFile(file), d);
        REQUIRE(original.has_value());
        const std::string printed = rules::printSystem(*original);
        rules::Diagnostics d2("printed", printed);
        auto reparsed = rules::parseSystem(printed, d2);
        INFO(printed << d2.render());
        REQUIRE(reparsed.has_value());
        CHECK(*reparsed == *original);
        CHECK(rules::printSystem(*reparsed) == printed);
    }
}

TEST_CASE("the printer keeps every construct") {
    const std::string text = R"(system everything
lattice square2d
symmetry rotations
field res: D | C | B1
field label: U | P | F if D | C
field parent: dir if P
field age: 0..3 if U
field lock: dir
input target, seed
mass D = 1, C = 3/2, B1 = 1/2
rule a / b: C&lock=none _&target <=> D&lock=@1 B1&lock=@0
rule c: #&!target * => _ * if no nbr U | P&parent=@0 and count nbr@1 F >= 2 or not some nbr D
rule d: U&age=2 => F
rule e: F@(0,0) _@(1,0) _@(0,1) => F D&F D&F
rule m: F@(0,0) _@(1,0) #@(0,1) => _ @0 *
constraint connected and count(#) <= 10 - 1 and mass >= 3/2
constraint all(F&target | _&!target) implies -count(P) < 0
goal all(F&target | _&!target)
invariant safe: some(F) and connected(F) and reaches(P, parent, F) and reaches(U, nbr, F | P)
invariant local: all(P: some nbr F | P&parent=@0) and count(F: count nbr # >= 2) >= 1 and no(U: no nbr P)
ranking measure: -count(F), count(U) + count(P), 2
progress p assuming mass >= count(target)
holonomic h by move
conserves count cnt
)";
    rules::System s = test::parse(text);
    const std::string printed = rules::printSystem(s);
    rules::System again = test::parse(printed);
    CHECK(again == s);
    CHECK(rules::printSystem(again) == printed);
    CHECK(s.rules.size() == 5);
    CHECK(s.properties.size() == 6);
}
