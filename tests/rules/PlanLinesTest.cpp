// The one reader of plan JSON Lines (rules/PlanLines.h), shared by holon replay and holon view:
// what each of their former copies alone did now holds for both. The start's offset is added to
// every cell (replay did it, the viewer too), blank lines are skipped (the viewer's), a fault must
// be a loss of one cell (replay's), and every error names FILE:LINE.

#include "rules/Error.h"
#include "rules/PlanLines.h"

#include <doctest/doctest.h>
#include <sstream>

using namespace holon;

TEST_CASE("plan lines: offset added, blank lines skipped, faults checked, errors at FILE:LINE") {
    std::istringstream in(R"({"plan":"holon","system":"s","start":{"region":"square:3x3","offset":[1,2],"cells":[]}})"
                          "\n{\"round\":0,\"rule\":\"r\",\"cells\":[[0,0],[1,-1]],\"after\":[{},{}]}\n\n"
                          "{\"round\":1,\"fault\":\"lose\",\"cells\":[[0,-2]]}\n");
    rules::PlanLineReader reader(in, "p.jsonl");
    CHECK(reader.kind() == "plan");
    rules::PlanLine line;
    REQUIRE(reader.next(line));
    CHECK(line.rule == "r");
    CHECK(line.cells == std::vector<rules::Vec>{{1, 2, 0}, {2, 1, 0}});
    REQUIRE(reader.next(line));
    CHECK(reader.lineNumber() == 4);
    CHECK(line.fault);
    CHECK(line.cells == std::vector<rules::Vec>{{1, 0, 0}});
    CHECK_FALSE(reader.next(line));

    const auto fails = [](const std::string& text) {
        std::istringstream bad(R"({"run":"hex","start":{}})"
                               "\n" +
                               text + "\n");
        rules::PlanLineReader r(bad, "b.jsonl");
        rules::PlanLine l;
        r.next(l);
    };
    CHECK_THROWS_WITH_AS(fails(R"({"round":0,"fault":"drop","cells":[[0,0]]})"), doctest::Contains("b.jsonl:2: a fault must be"), InputError);
    CHECK_THROWS_WITH_AS(fails(R"({"round":0,"rule":"r","cells":[[0,0]],"after":[]})"), doctest::Contains("b.jsonl:2: a step must be"), InputError);
    CHECK_THROWS_WITH_AS(fails(R"({"round":0,"rule":"r","cells":[[2147483647,0]],"after":[{}]})"), doctest::Contains("b.jsonl:2: a cell is [x, y] or [x, y, z] of integers"), InputError);
    CHECK_THROWS_WITH_AS(fails("{oops"), doctest::Contains("b.jsonl:2: not a JSON line"), InputError);
    // What holon writes and nothing else: an edited file was replayed as legal.
    const auto lines = [](const std::string& text) {
        std::istringstream plan(R"({"plan":"holon","start":{"region":"square:3x3","cells":[]}})"
                                "\n" +
                                text);
        rules::PlanLineReader r(plan, "e.jsonl");
        rules::PlanLine l;
        while (r.next(l)) {
        }
    };
    const std::string step = R"({"round":2,"rule":"r","cells":[[0,0]],"after":[{}]})";
    CHECK_NOTHROW(lines(step + "\n" + step + "\n"));
    CHECK_THROWS_WITH_AS(lines(step + "\n" + R"({"round":1,"rule":"r","cells":[[0,0]],"after":[{}]})"), doctest::Contains("e.jsonl:3: round 1 after round 2"), InputError);
    CHECK_THROWS_WITH_AS(lines(R"({"round":-1,"rule":"r","cells":[[0,0]],"after":[{}]})"), doctest::Contains("e.jsonl:2: round -1; rounds count from 0"), InputError);
    CHECK_THROWS_WITH_AS(lines(R"({"round":0,"fault":"lose","cells":[[0,0]]})"), doctest::Contains("rounds count from 1 for a loss"), InputError);
    CHECK_THROWS_WITH_AS(lines(R"({"round":0,"rule":"r","cells":[[0,0]],"after":[{}],"bogus":1})"), doctest::Contains("e.jsonl:2: unknown key \"bogus\""), InputError);
    CHECK_THROWS_WITH_AS(lines(R"({"round":0,"rule":"r","cells":[[0,0,0]],"after":[{}]})"), doctest::Contains("has 3 coordinates, the plan's cells 2"), InputError);
    std::istringstream notObject("[1]\n");
    CHECK_THROWS_WITH_AS(rules::PlanLineReader(notObject, "n.jsonl"), doctest::Contains("n.jsonl:1: expected a JSON object"), InputError);
}
