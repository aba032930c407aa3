// Counterexamples a person can read and a tool can replay (issue 26): every state of an ITF trace
// reads back as the configuration it was written from, cells and inputs, for every broken system's
// counterexample; the pictures draw every field of a cell and every input.

#include "CheckSupport.h"
#include "checker/Draw.h"

#include <regex>

using namespace holon;
using checker::Verdict;

namespace {

test::Checked checkFromJson(rules::System system, const std::string& spec, const std::string& path) {
    test::Checked c{test::World(std::move(system), spec), {}, {}};
    checker::CheckOptions o;
    o.initial.push_back(rules::readConfigFile(*c.world.in, path));
    c.report = checker::check(*c.world.model, c.world.region, o, &c.kept);
    return c;
}

/// Every trace of the report, written as ITF text and read back state by state, gives the trace's
/// own states with the engine's inputs. Returns how many traces it compared.
int roundTrip(const test::Checked& c) {
    int traces = 0;
    const std::uint32_t all = (1u << c.world.system.inputs.size()) - 1;
    for (const auto& p : c.report.properties) {
        if (!p.trace) continue;
        CAPTURE(p.name);
        ++traces;
        const auto itf = nlohmann::json::parse(checker::toItf(*p.trace, *c.kept.engine, "test").dump(2));
        const int n = static_cast<int>(p.trace->steps.size());
        for (int k = 0; k < n; ++k) {
            CAPTURE(k);
            std::uint32_t named = 0;
            const rules::Configuration read = rules::configFromItf(*c.world.in, itf, k, &named);
            CHECK(read.cells == p.trace->steps[k].cells);
            CHECK(read.inputs == c.kept.engine->inputs());
            CHECK(named == all);  // every input is in the trace, even one that holds nowhere
        }
        CHECK(rules::configFromItf(*c.world.in, itf, std::nullopt).cells == p.trace->steps.back().cells);
    }
    return traces;
}

const char* kTwoHoles =
    "     M M M M M M\n    M M M M M M M\n   M M M M M M M M\n  M M M M M H H M M\n M M H H M H C H M M\n"
    "M M H C H M H H M M M\n M M H H M M M M M M\n  M M M M M M M M M\n   M M M M M M M M\n    M M M M M M "
    "M\n     M M M M M M\n";

}  // namespace

TEST_CASE("ITF round trip: a system with several fields and a pointer, state by state") {
    // planner_general1 without the deletion guard: res and label on every cell, parent on P cells,
    // and the target input; the counterexample deletes a P whose child points at it.
    auto c = checkFromJson(test::brokenSystem("planner_general1_no_guard"), "square:4x1",
                           std::string(HOLON_TEST_DIR) + "/cli/general1_no_guard_start.json");
    const auto& safety = c.property("safety");
    REQUIRE(safety.verdict == Verdict::Violated);
    REQUIRE(safety.trace->steps.size() >= 3);
    const auto itf = checker::toItf(*safety.trace, *c.kept.engine, "test");
    // Each cell carries every field by name; the input is a set of positions.
    bool sawPointer = false;
    for (const auto& state : itf["states"])
        for (const auto& entry : state["cells"]["#map"]) {
            CHECK(entry[0].contains("#tup"));
            CHECK(entry[1].contains("res"));
            CHECK(entry[1].contains("label"));
            CHECK(entry[1].contains("parent") == (entry[1]["label"] == "P"));
            sawPointer = sawPointer || entry[1].contains("parent");
        }
    CHECK(sawPointer);
    CHECK(itf["vars"] == nlohmann::json{"cells", "inputs"});
    CHECK(itf["states"][0]["inputs"]["target"]["#set"].size() == 2);
    CHECK(roundTrip(c) >= 1);
}

TEST_CASE("ITF round trip: an unconditional pointer that points nowhere is written as none") {
    const test::Checked c = test::checkLockedTransfers(test::brokenSystem("general_lock2_ranked"));
    const auto& r = c.property("partial");
    REQUIRE(r.trace);
    const auto itf = checker::toItf(*r.trace, *c.kept.engine, "test");
    const auto& first = itf["states"][0]["cells"]["#map"][0][1];
    CHECK(first["lock"] == "none");
    CHECK(roundTrip(c) >= 1);
}

TEST_CASE("ITF round trip: every broken system's counterexample reads back, cells and inputs") {
    int traces = 0;
    traces += roundTrip(
        test::checkFrom(test::brokenSystem("planner_no_guard"), "square:4x3", "UFU.\nUUU.\nUUU.", ".###\n.###\n.###"));
    traces += roundTrip(checkFromJson(test::brokenSystem("planner_general1_no_guard"), "square:4x1",
                                      std::string(HOLON_TEST_DIR) + "/cli/general1_no_guard_start.json"));
    traces += roundTrip(test::checkAll(test::brokenSystem("general1_leaky"), "square:3x1"));
    traces += roundTrip(test::checkAll(test::brokenSystem("transfer_livelock"), "square:3x1"));
    traces += roundTrip(test::checkFrom(test::brokenSystem("hex_delete_shared"), "hex:r5", kTwoHoles, ""));
    traces += roundTrip(checkFromJson(test::brokenSystem("roombots_no_exclusion"), "square:4x4",
                                      std::string(HOLON_TEST_DIR) + "/cli/reserve_crossing_3walks.json"));
    traces += roundTrip(checkFromJson(test::brokenSystem("roombots_blocking_wait"), "square:4x4",
                                      std::string(HOLON_TEST_DIR) + "/cli/reserve_crossing_3walks.json"));
    // The lock system on a cubic region: 3D positions and pointers along z.
    test::Checked lock{test::World(test::brokenSystem("general_lock2_ranked"), "cubic:2x1x2"), {}, {}};
    checker::CheckOptions o;
    o.all = true;
    lock.report = checker::check(*lock.world.model, lock.world.region, o, &lock.kept);
    traces += roundTrip(lock);
    CHECK(traces >= 8);
}

TEST_CASE("a malformed ITF trace or a bad index is refused with the place and the fix") {
    test::World w = test::World::library("planner_intermediate", "square:2x1");
    auto bad = [&](const std::string& text, std::optional<int> index, const std::string& message) {
        CHECK_THROWS_WITH_AS(rules::configFromItf(*w.in, nlohmann::json::parse(text), index),
                             doctest::Contains(message.c_str()), InputError);
    };
    const std::string good = R"({"#meta":{"region":"square:2x1"},"vars":["cells","inputs"],"states":[
        {"cells":{"#map":[[{"#tup":[0,0]},{"label":"F"}]]},"inputs":{"target":{"#set":[{"#tup":[0,0]}]}}},
        {"cells":{"#map":[[{"#tup":[0,0]},{"label":"F"}],[{"#tup":[1,0]},{"label":"P","parent":"-x"}]]},"inputs":{"target":{"#set":[]}}}]})";
    const auto last = rules::configFromItf(*w.in, nlohmann::json::parse(good), std::nullopt);
    CHECK(w.at(last, 1, 0) == "P&parent=-x");
    std::uint32_t named = 0;
    const auto first = rules::configFromItf(*w.in, nlohmann::json::parse(good), 0, &named);
    CHECK(first.inputs[0] == 1u);
    CHECK(named == 1u);
    bad(good, 2, "the trace has 2 states, numbered 0 to 1");
    bad(R"({"#meta":{"region":"square:3x3"},"states":[{"cells":{"#map":[]}}]})", 0,
        "run with rules::Region square:3x3");
    bad(R"({"states":[]})", std::nullopt, "the trace has no states");
    bad(R"({"states":[{"cells":{"#map":[[[0,0],{"label":"F"}]]}}]})", 0,
        "state 0: a cell position in a trace is {\"#tup\"");
    bad(R"({"states":[{"cells":[]}]})", 0, "state 0: a state's \"cells\" is {\"#map\"");
    bad(R"({"states":[{"cells":{"#map":[[{"#tup":[0,0]},{"label":"Q"}]]}}]})", 0,
        "state 0: cell [0,0]: 'Q' is not a state of field 'label'");
    bad(R"({"states":[{"cells":{"#map":[]},"inputs":{"target":[]}}]})", 0, "input 'target' is {\"#set\"");
}

TEST_CASE("ASCII: a state without a one-character name gets a character the legend explains") {
    auto c = checkFromJson(test::brokenSystem("planner_general1_no_guard"), "square:4x1",
                           std::string(HOLON_TEST_DIR) + "/cli/general1_no_guard_start.json");
    const auto& safety = c.property("safety");
    REQUIRE(safety.trace);
    const std::string text = checker::drawTraceAscii(*safety.trace, *c.kept.engine);
    // Every state shown has a line "x = NAME" in the legend, each with its own character.
    std::vector<const std::vector<rules::CellValue>*> all;
    for (const auto& s : safety.trace->steps) all.push_back(&s.cells);
    const auto key = checker::asciiKey(*c.kept.engine, all);
    std::set<char> used;
    for (const auto& [v, ch] : key.chars) {
        CHECK(used.insert(ch).second);
        CHECK(text.find(std::string(1, ch) + " = " + c.world.model->alphabet().name(v)) != std::string::npos);
    }
    CHECK(key.chars.size() >= 3);  // D&F, D&U and a D&P with its pointer at least
    CHECK(text.find("-- input target:") != std::string::npos);
    // States that have one-character names need no legend, and keep their names.
    auto g = test::checkAll(test::brokenSystem("general1_leaky"), "square:3x1");
    const auto& m = g.property("mass_conservation");
    REQUIRE(m.trace);
    const std::string plain = checker::drawTraceAscii(*m.trace, *g.kept.engine);
    CHECK(plain.find("legend") == std::string::npos);
    CHECK(plain.find('C') != std::string::npos);
}

TEST_CASE("SVG: every field, every input, arrows with heads, one colour per value, titles that fit") {
    auto c = checkFromJson(test::brokenSystem("planner_general1_no_guard"), "square:4x1",
                           std::string(HOLON_TEST_DIR) + "/cli/general1_no_guard_start.json");
    const auto& safety = c.property("safety");
    REQUIRE(safety.trace);
    const std::string title(300, 'x');
    const std::string svg =
        checker::drawTraceSvg(*safety.trace, *c.kept.engine, "planner_general1 " + title + " end");
    // Both fields of a cell are in its text ("D F", "D P"), the pointer is an arrow with a head.
    CHECK(svg.find(">D F</text>") != std::string::npos);
    CHECK(svg.find(">D P</text>") != std::string::npos);
    CHECK(svg.find("marker-end=\"url(#head0)\"") != std::string::npos);
    CHECK(svg.find("<marker id=\"head0\"") != std::string::npos);
    // The legend names each field's values and the input; the input is drawn as its own pattern.
    for (const char* s :
         {">res (fill, text):</text>", ">label (text):</text>", ">input target</text>", "url(#hatch0)"}) {
        CAPTURE(s);
        CHECK(svg.find(s) != std::string::npos);
    }
    // The long title is wrapped: no title line is wider than the picture.
    const std::regex widthRe("width=\"([0-9.]+)\"");
    std::smatch m;
    REQUIRE(std::regex_search(svg, m, widthRe));
    const double width = std::stod(m[1]);
    const std::regex titleRe("font-size=\"14\" font-weight=\"bold\">([^<]*)</text>");
    int titleLines = 0;
    for (auto it = std::sregex_iterator(svg.begin(), svg.end(), titleRe); it != std::sregex_iterator();
         ++it) {
        ++titleLines;
        CHECK(9.0 * static_cast<double>((*it)[1].length()) <= width - 20);
    }
    CHECK(titleLines >= 2);
    // A value's colour depends on its name and its field, not on the picture: F is the same
    // colour in planner_intermediate and planner_general1, and the values of a field differ.
    test::World a = test::World::library("planner_intermediate", "square:2x2"),
                b = test::World::library("planner_general1", "square:2x2");
    const auto& la = a.system.fields[a.system.fieldIndex("label")];
    const auto& lb = b.system.fields[b.system.fieldIndex("label")];
    for (int v = 0; v < 3; ++v) CHECK(checker::valueColour(la, v) == checker::valueColour(lb, v));
    CHECK(checker::valueColour(la, 0) != checker::valueColour(la, 1));
    CHECK(checker::valueColour(la, 1) != checker::valueColour(la, 2));
    CHECK(checker::valueColour(la, 0) != checker::valueColour(la, 2));
}

TEST_CASE("SVG and ASCII on hex and cubic regions: every cell drawn, pointers along z as symbols") {
    auto hex = test::checkFrom(test::brokenSystem("hex_delete_shared"), "hex:r5", kTwoHoles, "");
    const auto& holes = hex.property("holes");
    REQUIRE(holes.trace);
    const std::string svg = checker::drawTraceSvg(*holes.trace, *hex.kept.engine, "holes");
    CHECK(svg.find("<polygon") != std::string::npos);
    CHECK(svg.find(">M</text>") != std::string::npos);
    // A lock pointing along z in a cubic region: a circle with a dot (+z) or a cross (-z).
    test::World w(test::brokenSystem("general_lock2_ranked"), "cubic:1x1x2");
    checker::Trace t;
    auto cfg = w.in->empty();
    cfg.cells[w.region.indexOf({0, 0, 0})] = static_cast<rules::CellValue>(w.value("D&lock=+z"));
    cfg.cells[w.region.indexOf({0, 0, 1})] = static_cast<rules::CellValue>(w.value("B1&lock=-z"));
    t.steps.push_back({cfg.cells, -1});
    rules::Engine engine(*w.model, w.region, cfg.inputs);
    const std::string cubic = checker::drawTraceSvg(t, engine, "lock along z");
    CHECK(cubic.find("r=\"1.2\"") != std::string::npos);  // the dot of +z
    CHECK(cubic.find(">z=1</text>") != std::string::npos);
    const std::string ascii = checker::drawTraceAscii(t, engine);
    CHECK(ascii.find("z=0") != std::string::npos);
    CHECK(ascii.find("= D&lock=+z") != std::string::npos);
    CHECK(ascii.find("= B1&lock=-z") != std::string::npos);
}
