// The viewer's readers, sampling and page, without a browser (browser.sh opens the pages in one).

#include "rules/Error.h"
#include "rules/StopSignals.h"
#include "viewer/Page.h"
#include "viewer/Readers.h"

#include <doctest/doctest.h>

#include <csignal>
#include <filesystem>
#include <fstream>

using namespace holon;
namespace fs = std::filesystem;

namespace {

std::string write(const std::string& name, const std::string& text) {
    const fs::path dir = fs::temp_directory_path() / "holon_viewer_test";
    fs::create_directories(dir);
    std::ofstream(dir / name) << text;
    return (dir / name).string();
}

// A plan of planner_intermediate on square:3x1: round 0 fires two instances, one of which leaves
// a cell as it was (context), round 4 one.
const std::string kPlan =
    R"({"plan":"holon","system":"planner_intermediate","start":{"region":"square:3x1","cells":[{"at":[0,0],"label":"U"},{"at":[1,0],"label":"U"}],"inputs":{"target":[[1,0],[2,0]]}}})"
    "\n"
    R"({"round":0,"rule":"finalize","cells":[[1,0],[0,0]],"after":[{"label":"F"},{"label":"U"}]})"
    "\n"
    R"({"round":0,"rule":"path_create","cells":[[0,0]],"after":[{"label":"P","parent":"+x"}]})"
    "\n"
    R"({"round":4,"rule":"delete","cells":[[0,0],[2,0]],"after":[{},{"label":"F"}]})"
    "\n";

}  // namespace

TEST_CASE("a plan becomes one step per round: the cells each changes, and those it only looked at") {
    const viewer::Run run = viewer::readRun(write("plan.jsonl", kPlan));
    CHECK(run.kind == "plan");
    REQUIRE(run.cells.size() == 3);
    REQUIRE(run.steps.size() == 3);
    CHECK(run.inputs.size() == 1);
    CHECK(run.inputs[0].cells == std::vector<int>{1, 2});
    const auto key = [&](int cell, std::size_t step) { return run.states[viewer::configurationAt(run, step)[cell]].key; };
    CHECK(key(0, 0) == R"({"label":"U"})");
    CHECK(key(0, 1) == R"({"label":"P","parent":"+x"})");
    CHECK(key(1, 1) == R"({"label":"F"})");
    CHECK(key(0, 2) == "");
    CHECK(key(2, 2) == R"({"label":"F"})");
    CHECK(run.steps[1].changes.size() == 2);
    CHECK(run.steps[1].context.empty());  // cell 0 was looked at, then changed in the same round
    CHECK(run.steps[1].label == "round 0: finalize 1, path_create 1");
    CHECK(run.steps[2].label == "round 4: delete 1");
    // The fill colours are the SVG pictures' (checker::valueColour), one legend entry per value.
    CHECK(run.legend.size() == 3);
}

TEST_CASE("a signal caught while a plan is read for its page stops the reading (holon plan --html builds it after the run)") {
    const std::string path = write("plan.jsonl", kPlan);
    {
        const rules::StopSignals catcher(false);
        std::raise(SIGTERM);
        try {
            (void)viewer::readRun(path);
            FAIL("the plan was read to its end past the signal");
        } catch (const Interrupted& e) {
            CHECK(e.signal() == SIGTERM);
        }
    }
    CHECK(viewer::readRun(path).steps.size() == 3);  // with no catcher installed the signal is done with
}

TEST_CASE("a bad step names its file and line and the fix") {
    std::string plan = kPlan;
    const std::string p = R"({"label":"P","parent":"+x"})";
    plan.replace(plan.find(p), p.size(), R"({"label":"Q"})");
    CHECK_THROWS_WITH_AS(viewer::readRun(write("bad.jsonl", plan)), doctest::Contains("bad.jsonl:3: {\"label\":\"Q\"} is not a state of system planner_intermediate; give the rule file"),
                         InputError);
    CHECK_THROWS_WITH_AS(viewer::readRun(write("cut.jsonl", kPlan.substr(0, kPlan.size() - 10))), doctest::Contains("cut.jsonl:4: not a JSON line"), InputError);
    CHECK_THROWS_WITH_AS(viewer::readRun(write("other.json", R"({"cells": []})")), doctest::Contains("other.json:1: not a holon run"), InputError);
    CHECK_THROWS_WITH_AS(viewer::readRun(write("broken.json", "{\n  \"states\": [\n")), doctest::Contains("broken.json:3:1: not JSON"), InputError);
}

TEST_CASE("an ITF trace: the changed cells, the instance's other cells as context, the marked cells, the violation") {
    const std::string itf = R"({"#meta":{"system":"pixel","region":"square:2x1","property":"safety","description":"it broke"},"vars":["cells"],"states":[
        {"#meta":{"index":0},"cells":{"#map":[[{"#tup":[0,0]},{"state":"M"}]]}},
        {"#meta":{"index":1,"rule":"create","cells":[[1,0],[0,0]],"marked":[[1,0]]},"cells":{"#map":[[{"#tup":[0,0]},{"state":"M"}],[{"#tup":[1,0]},{"state":"M"}]]}}]})";
    const viewer::Run run = viewer::readRun(write("trace.itf.json", itf));
    CHECK(run.kind == "trace");
    REQUIRE(run.steps.size() == 2);
    CHECK(run.steps[1].changes == std::vector<std::pair<int, int>>{{1, 1}});
    CHECK(run.steps[1].context == std::vector<int>{0});
    CHECK(run.steps[1].marked == std::vector<int>{1});
    CHECK(run.violation == 1);
    CHECK(run.steps[1].label == "1: create at [1,0]");
}

TEST_CASE("sampling merges steps: every configuration shown is one of the run's, the changes within the limit") {
    viewer::Run run;
    run.cells.resize(10);
    run.states.push_back({"{\"s\":1}", "#000000", "1"});
    run.start.assign(10, 0);
    run.steps.push_back({"start", {}, {}, {}});
    for (int k = 1; k <= 100; ++k) run.steps.push_back({"step " + std::to_string(k), {{k % 10, k % 3 == 0 ? 0 : 1}}, {(k + 1) % 10}, {}});
    run.violation = 77;
    const viewer::Run original = run;
    viewer::sample(run, 30);
    const int g = run.sampled;
    CHECK(g > 1);
    CHECK(run.runSteps == 100);
    CHECK(run.violation == (77 - 1) / g + 1);  // the merged step holding step 77
    std::int64_t changes = 0;
    for (const auto& s : run.steps) changes += static_cast<std::int64_t>(s.changes.size());
    CHECK(changes <= 30);
    CHECK(changes > 0);
    for (std::size_t k = 0; k + 1 < run.steps.size(); ++k) CHECK(viewer::configurationAt(run, k) == viewer::configurationAt(original, k * static_cast<std::size_t>(g)));
    CHECK(viewer::configurationAt(run, run.steps.size() - 1) == viewer::configurationAt(original, 100));
    CHECK(run.steps[1].label == "step 1 ... step " + std::to_string(g));
    // Half as coarse would not have fitted: g is the smallest power of two that does.
    viewer::Run finer = original;
    viewer::sample(finer, changes - 1);
    CHECK(finer.sampled >= g);
}

TEST_CASE("the page holds the data once, and a label cannot end its script element") {
    viewer::Run run = viewer::readRun(write("plan2.jsonl", kPlan));
    run.steps[1].label = "</script><script>alert(1)</script>";
    const std::string html = viewer::page(run);
    CHECK(html.find("HOLON_VIEWER_DATA") == std::string::npos);
    std::size_t scripts = 0;
    for (std::size_t at = html.find("</script>"); at != std::string::npos; at = html.find("</script>", at + 1)) ++scripts;
    CHECK(scripts == 2);  // the data's and the code's
    CHECK(html.find(R"(\u003c/script>)") != std::string::npos);
    // "<!--" with "<script" made the parser miss the data's end tag: no "<" is left in the data.
    run.steps[1].label = "<!--<script>";
    const std::string commented = viewer::page(run);
    CHECK(commented.find("<!--<script>") == std::string::npos);
    CHECK(commented.find(R"(\u003c!--\u003cscript>)") != std::string::npos);
}

TEST_CASE("a monitor's trace names no region: the box around its cells, every fired instance's cells as context") {
    const std::string itf = R"({"#meta":{"system":"pixel","property":"monitor","description":"cut apart"},"vars":["cells"],"states":[
        {"#meta":{"index":0},"cells":{"#map":[[{"#tup":[2,5]},{"state":"M"}],[{"#tup":[3,5]},{"state":"M"}]]}},
        {"#meta":{"index":1,"fired":[{"rule":"destroy","cells":[[3,5]]},{"rule":"create","cells":[[2,6]]}]},"cells":{"#map":[[{"#tup":[2,5]},{"state":"M"}],[{"#tup":[2,6]},{"state":"M"}]]}}]})";
    const viewer::Run run = viewer::readRun(write("monitor.itf.json", itf));
    CHECK(run.cells.size() == 4);  // x 2..3, y 5..6
    REQUIRE(run.steps.size() == 2);
    CHECK(run.steps[1].changes.size() == 2);
    CHECK(run.steps[1].context.empty());
    CHECK(run.steps[1].label == "1: 2 instances fired");
    CHECK(run.violation == 1);
}

TEST_CASE("hostile inputs end in a located message, not a crash") {
    // A monitor's trace whose first state is empty: the lattice comes from the cells of later states.
    const std::string empty = R"({"#meta":{"system":"pixel"},"states":[{"cells":{"#map":[]}},{"cells":{"#map":[[{"#tup":[0,0]},{"state":"M"}]]}}]})";
    CHECK(viewer::readRun(write("empty_first.itf.json", empty)).cells.size() == 1);
    const std::string huge = R"({"#meta":{"system":"pixel"},"states":[{"cells":{"#map":[[{"#tup":[18446744073709551615,0]},{"state":"M"}]]}}]})";
    CHECK_THROWS_WITH_AS(viewer::readRun(write("huge.itf.json", huge)), doctest::Contains("huge.itf.json: state 0: a cell is [x, y] or [x, y, z] of integers"), InputError);
    CHECK_THROWS_WITH_AS(viewer::readRun(write("empty.itf.json", "")), doctest::Contains("empty.itf.json: the file is empty; holon view reads"), InputError);
    // As check --from refuses them: a cell listed twice in a state, a loop to a state the trace lacks.
    const std::string twice = R"({"#meta":{"system":"pixel","region":"square:2x1"},"states":[{"cells":{"#map":[[{"#tup":[0,0]},{"state":"M"}],[{"#tup":[0,0]},{"state":"M"}]]}}]})";
    CHECK_THROWS_WITH_AS(viewer::readRun(write("twice.itf.json", twice)), doctest::Contains("twice.itf.json: state 0: cell [0,0] is listed twice"), InputError);
    const std::string one = R"({"#meta":{"system":"pixel","region":"square:2x1"},"loop":LOOP,"states":[{"cells":{"#map":[[{"#tup":[0,0]},{"state":"M"}]]}}]})";
    for (const char* loop : {"1", "-1", "\"0\""}) {
        std::string bad = one;
        bad.replace(bad.find("LOOP"), 4, loop);
        CHECK_THROWS_WITH_AS(viewer::readRun(write("loop.itf.json", bad)), doctest::Contains("\"loop\" is the index of the state the last one loops back to, 0 to 0"), InputError);
    }
    std::string fine = one;
    fine.replace(fine.find("LOOP"), 4, "0");
    CHECK(viewer::readRun(write("loop.itf.json", fine)).notes.back() == "the last state loops back to state 0");
    const std::string roombots = R"({"run":"roombots","colours":[1,2],"start":{"region":"cubic:2x2x2","cells":[]}})";
    CHECK_THROWS_WITH_AS(viewer::readRun(write("rb.jsonl", roombots)), doctest::Contains("rb.jsonl:1: a Roombots run's first line lists its metamodules' \"colours\""), InputError);
    // A colour goes into the page's styles: markup there ran script when the page was opened.
    const std::string run = R"({"run":"roombots","colours":[COLOUR,"#d62728"],"start":{"region":"cubic:2x2x2","cells":[{"at":[0,0,0],"module":MODULE}]}})";
    const auto roombotsRun = [&](const std::string& colour, const std::string& module) {
        std::string text = run;
        text.replace(text.find("COLOUR"), 6, colour);
        text.replace(text.find("MODULE"), 6, module);
        return viewer::readRun(write("rb_run.jsonl", text));
    };
    CHECK(roombotsRun("\"#1f77b4\"", "1").cells.size() == 8);
    for (const char* colour : {R"("red\"><img src=x onerror=\"alert(1)\">")", R"("red")", R"("#12345g")", R"("#1234567")"}) {
        CAPTURE(colour);
        CHECK_THROWS_WITH_AS(roombotsRun(colour, "1"), doctest::Contains("as \"#rrggbb\" strings"), InputError);
    }
    // --rules names a rule system, which a Roombots run has none of: it was ignored, even a missing file.
    {
        std::string text = run;
        text.replace(text.find("COLOUR"), 6, "\"#1f77b4\"");
        text.replace(text.find("MODULE"), 6, "1");
        CHECK_THROWS_WITH_AS(viewer::readRun(write("rb_rules.jsonl", text), "pixel"), doctest::Contains("a Roombots run has no rule system"), InputError);
    }
    // A cell has its lattice's coordinates: a square plan edited to name a cubic region was drawn in 3D.
    std::string cubic = kPlan;
    cubic.replace(cubic.find("square:3x1"), 10, "cubic:3x1x1");
    CHECK_THROWS_WITH_AS(viewer::readRun(write("cubic.jsonl", cubic)), doctest::Contains("cubic.jsonl:1: cell [0,0] has 2 coordinates; a cell of cubic3d has 3"), InputError);
    // Module numbers are compared before they are narrowed: 2^32 + 1 was drawn as metamodule 1.
    for (const char* module : {"4294967297", "4294967296", "9223372036854775808", "18446744073709551615", "-1", "2"}) {
        CAPTURE(module);
        CHECK_THROWS_WITH_AS(roombotsRun("\"#1f77b4\"", module), doctest::Contains("is not a metamodule of the run"), InputError);
    }
}
