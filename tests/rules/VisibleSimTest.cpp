// VisibleSim worlds (rules/VisibleSim.h), read back by a minimal XML reader of this test's own:
// every module inside gridSize, the lattice directions landing on VisibleSim's directions of the
// same name (the table of VisibleSim's lattice.h), world positions that keep holon's picture, and
// a round trip of positions and colours for each lattice; then holon's own reader: the same cells
// back from what the writer wrote, worlds written as VisibleSim's examples write them, and
// malformed worlds refused at their line and column.

#include "rules/Error.h"
#include "rules/VisibleSim.h"

#include <doctest/doctest.h>

#include <cmath>
#include <map>
#include <random>
#include <regex>
#include <set>

using holon::rules::Lattice;
using holon::rules::LatticeKind;
using holon::rules::Vec;
using holon::rules::VisibleSimCell;
using holon::rules::VisibleSimRobot;
namespace r = holon::rules;

namespace {

/// What a VisibleSim world says, read with regular expressions: gridSize, and each block's and
/// target cell's position and colour.
struct ParsedWorld {
    Vec grid;
    std::map<Vec, std::string> blocks, targets;  // position -> "r,g,b"
    std::string blockSize;
};

Vec triple(const std::string& text) {
    Vec v;
    REQUIRE(std::sscanf(text.c_str(), "%d,%d,%d", &v.x, &v.y, &v.z) == 3);
    return v;
}

ParsedWorld parseWorld(const std::string& xml) {
    ParsedWorld w;
    std::smatch m;
    REQUIRE(std::regex_search(xml, m, std::regex("<world gridSize=\"([-0-9,]+)\">")));
    w.grid = triple(m[1]);
    REQUIRE(std::regex_search(xml, m, std::regex("<blockList blockSize=\"([0-9.,]+)\">")));
    w.blockSize = m[1];
    const std::regex element("<(block|cell) position=\"([-0-9,]+)\"(?: orientation=\"0\")? color=\"([0-9,]+)\"/>");
    for (auto it = std::sregex_iterator(xml.begin(), xml.end(), element); it != std::sregex_iterator(); ++it) {
        auto& into = (*it)[1] == "block" ? w.blocks : w.targets;
        CHECK(into.emplace(triple((*it)[2]), (*it)[3]).second);  // each position once
    }
    CHECK(std::count(xml.begin(), xml.end(), '<') - std::count(xml.begin(), xml.end(), '>') == 0);
    return w;
}

std::string xmlOf(LatticeKind kind, VisibleSimRobot robot, const std::vector<VisibleSimCell>& blocks, const std::vector<VisibleSimCell>& targets = {}) {
    return r::visibleSimWorld(Lattice::get(kind), robot, blocks, targets, {"a test -- with dashes"});
}

/// VisibleSim's HHLattice directions (lattice.h, nCells): EAST, NORTH-EAST, NORTH-WEST, WEST,
/// SOUTH-WEST, SOUTH-EAST, in its axial (x, y).
const std::map<std::string, Vec> kHexDirections = {{"E", {1, 0, 0}}, {"NE", {0, 1, 0}}, {"NW", {-1, 1, 0}}, {"W", {-1, 0, 0}}, {"SW", {0, -1, 0}}, {"SE", {1, -1, 0}}};

}  // namespace

TEST_CASE("square2d: y flipped, shifted into the grid, slidingCubes' block size") {
    // Holon's picture (y down):  ##   VisibleSim's (y up) keeps it: row y=0 on top.
    //                            #.
    const std::string xml = xmlOf(LatticeKind::Square2D, VisibleSimRobot::SlidingCubes, {{{0, 0, 0}, "#4e79a7"}, {{1, 0, 0}, "#4e79a7"}, {{0, 1, 0}, "#ff0000"}});
    const ParsedWorld w = parseWorld(xml);
    CHECK(w.grid == Vec{2, 2, 1});
    CHECK(w.blockSize == "10,10,10");
    CHECK(w.blocks == std::map<Vec, std::string>{{{0, 1, 0}, "78,121,167"}, {{1, 1, 0}, "78,121,167"}, {{0, 0, 0}, "255,0,0"}});
    CHECK(xml.find("a test - - with dashes") != std::string::npos);  // no "--" inside a comment
    CHECK(xml.find("<targetList>") == std::string::npos);
    // A margin of 2: the grid grows by 2 on each side in the plane, the layer stays one cell thick.
    const ParsedWorld wide = parseWorld(r::visibleSimWorld(Lattice::get(LatticeKind::Square2D), VisibleSimRobot::SlidingCubes, {{{0, 0, 0}, "#000000"}}, {}, {}, 2));
    CHECK(wide.grid == Vec{5, 5, 1});
    CHECK(wide.blocks.count(Vec{2, 2, 0}) == 1);
    const ParsedWorld deep = parseWorld(r::visibleSimWorld(Lattice::get(LatticeKind::Cubic3D), VisibleSimRobot::SlidingCubes, {{{0, 0, 0}, "#000000"}}, {}, {}, 1));
    CHECK(deep.grid == Vec{3, 3, 3});
    CHECK(deep.blocks.count(Vec{1, 1, 1}) == 1);
}

TEST_CASE("hex2d: every direction lands on VisibleSim's direction of the same name, and the picture is kept") {
    const Lattice& hex = Lattice::get(LatticeKind::Hex2D);
    for (int d = 0; d < hex.degree(); ++d) {
        CAPTURE(hex.directionName(d));
        CHECK(r::toVisibleSimAxes(hex, hex.direction(d)) == kHexDirections.at(hex.directionName(d)));
    }
    // VisibleSim draws axial (x, y) at (x + y/2, y*sqrt(3)/2), y up; holon draws (q, r) with pointy
    // tops at (q + r/2, r*sqrt(3)/2), y down the page: the same picture.
    for (const Vec v : {Vec{0, 0, 0}, Vec{3, -2, 0}, Vec{-4, 5, 0}}) {
        const Vec p = r::toVisibleSimAxes(hex, v);
        CHECK(p.x + p.y / 2.0 == doctest::Approx(v.x + v.y / 2.0));
        CHECK(p.y == -v.y);
        CHECK(r::toVisibleSimAxes(hex, p) == v);  // its own inverse
    }
    const ParsedWorld w = parseWorld(xmlOf(LatticeKind::Hex2D, VisibleSimRobot::Hexanodes, {{{0, 0, 0}, "#000000"}, {{0, -1, 0}, "#000000"}, {{-1, 1, 0}, "#000000"}}));
    CHECK(w.blockSize == "50,50,12.5");
    // (0,0) -> (0,0), NW (0,-1) -> (-1,1), SW (-1,1) -> (0,-1); shifted by (-1,-1).
    CHECK(w.blocks == std::map<Vec, std::string>{{{1, 1, 0}, "0,0,0"}, {{0, 2, 0}, "0,0,0"}, {{1, 0, 0}, "0,0,0"}});
    CHECK(w.grid == Vec{2, 3, 1});
}

TEST_CASE("round trip: positions and colours come back, every one inside gridSize") {
    std::mt19937 random(11);
    const std::string palette[] = {"#4e79a7", "#59a14f", "#edc948", "#010203"};
    for (LatticeKind kind : {LatticeKind::Square2D, LatticeKind::Cubic3D, LatticeKind::Hex2D}) {
        const Lattice& lattice = Lattice::get(kind);
        const VisibleSimRobot robot = kind == LatticeKind::Hex2D ? VisibleSimRobot::Hexanodes : kind == LatticeKind::Cubic3D ? VisibleSimRobot::BlinkyBlocks
                                                                                                                             : VisibleSimRobot::SlidingCubes;
        for (int trial = 0; trial < 20; ++trial) {
            std::map<Vec, std::string> blocks, targets;
            const auto cell = [&] { return Vec{int(random() % 15) - 7, int(random() % 15) - 7, lattice.dimension() == 3 ? int(random() % 15) - 7 : 0}; };
            for (int k = 0; k < 40; ++k) blocks[cell()] = palette[random() % 4];
            for (int k = 0; k < 30; ++k) targets[cell()] = palette[random() % 4];
            std::vector<VisibleSimCell> b, t;
            for (const auto& [v, c] : blocks) b.push_back({v, c});
            for (const auto& [v, c] : targets) t.push_back({v, c});
            const ParsedWorld w = parseWorld(r::visibleSimWorld(lattice, robot, b, t, {}));
            REQUIRE(w.blocks.size() == blocks.size());
            REQUIRE(w.targets.size() == targets.size());
            // Back to holon's cells: undo the shift (the smallest coordinate of all is 0) and the axes.
            Vec lo{1 << 20, 1 << 20, 1 << 20};
            for (const auto* m : {&blocks, &targets})
                for (const auto& [v, c] : *m) {
                    const Vec p = r::toVisibleSimAxes(lattice, v);
                    lo = {std::min(lo.x, p.x), std::min(lo.y, p.y), std::min(lo.z, p.z)};
                }
            const auto back = [&](const std::map<Vec, std::string>& read) {
                std::map<Vec, std::string> out;
                for (const auto& [p, rgb] : read) {
                    CHECK((p.x >= 0 && p.y >= 0 && p.z >= 0 && p.x < w.grid.x && p.y < w.grid.y && p.z < w.grid.z));
                    int c[3];
                    REQUIRE(std::sscanf(rgb.c_str(), "%d,%d,%d", &c[0], &c[1], &c[2]) == 3);
                    char hexText[8];
                    std::snprintf(hexText, sizeof hexText, "#%02x%02x%02x", c[0], c[1], c[2]);
                    out[r::toVisibleSimAxes(lattice, p + lo)] = hexText;
                }
                return out;
            };
            CHECK(back(w.blocks) == blocks);
            CHECK(back(w.targets) == targets);
        }
    }
}

TEST_CASE("a robot on the wrong lattice, and an empty world, are refused") {
    CHECK_THROWS_AS(xmlOf(LatticeKind::Hex2D, VisibleSimRobot::SlidingCubes, {{{0, 0, 0}, "#000000"}}), holon::InputError);
    CHECK_THROWS_AS(xmlOf(LatticeKind::Cubic3D, VisibleSimRobot::Hexanodes, {{{0, 0, 0}, "#000000"}}), holon::InputError);
    CHECK_THROWS_AS(xmlOf(LatticeKind::Cubic3D, VisibleSimRobot::SlidingCubes, {}), holon::InputError);
}

namespace {

std::string readRefusal(const std::string& xml, std::size_t maxCells = 1000) {
    try {
        r::readVisibleSimWorld(xml, maxCells);
    } catch (const holon::InputError& e) {
        return e.what();
    }
    return "accepted";
}

}  // namespace

TEST_CASE("holon's reader gives back the cells the writer wrote, on every lattice, with a margin") {
    std::mt19937 random(5);
    for (LatticeKind kind : {LatticeKind::Square2D, LatticeKind::Cubic3D, LatticeKind::Hex2D}) {
        const Lattice& lattice = Lattice::get(kind);
        const VisibleSimRobot robot = kind == LatticeKind::Hex2D ? VisibleSimRobot::Hexanodes : VisibleSimRobot::SlidingCubes;
        for (int trial = 0; trial < 10; ++trial) {
            std::set<Vec> blocks, targets;
            const auto cell = [&] { return Vec{int(random() % 21) - 10, int(random() % 21) - 10, lattice.dimension() == 3 ? int(random() % 21) - 10 : 0}; };
            for (int k = 0; k < 50; ++k) blocks.insert(cell()), targets.insert(cell());
            std::vector<VisibleSimCell> b, t;
            for (Vec v : blocks) b.push_back({v, "#123456"});
            for (Vec v : targets) t.push_back({v, "#654321"});
            const r::VisibleSimCells back = r::readVisibleSimWorld(r::visibleSimWorld(lattice, robot, b, t, {"x"}, trial % 3), 1000);
            CHECK(back.lattice == &lattice);
            CHECK(back.blocks == std::vector<Vec>(blocks.begin(), blocks.end()));
            CHECK(back.targets == std::vector<Vec>(targets.begin(), targets.end()));
        }
    }
}

TEST_CASE("a world written as VisibleSim's examples write them") {
    // Tabs, stray ';' after an element, a default colour, blocksLine rows, a target of targetLines
    // and cells, a second target (not read), comments: as in VisibleSim's applicationsBin/*/config.xml.
    const std::string xml = R"(<?xml version="1.0" standalone="no" ?>
<world gridSize="6,4,2" windowSize="1800,900">
	<camera target="50,50,0" directionSpherical="30,30,100" angle="45"/>
	<blockList color="128,255,128" blockSize="10.0,10.0,10.0">
		<blocksLine plane="0" line=" 1" values="011100"/>
<!--		<blocksLine plane="1" line=" 4" values="000011"/>-->
		<block position="1,2,0" color="255,0,0" master="true"/>;
	</blockList>
	<targetList>
		<target format="grid">
			<targetLine plane="1" line="0" values="110000"/>
			<cell position="5,3,1"/>
		</target>
		<target format="grid"><cell position="0,0,0"/></target>
	</targetList>
</world>
)";
    const r::VisibleSimCells w = r::readVisibleSimWorld(xml, 1000);
    CHECK(w.lattice->kind() == LatticeKind::Cubic3D);
    CHECK(w.blocks == std::vector<Vec>{{1, 1, 0}, {1, 2, 0}, {2, 1, 0}, {3, 1, 0}});
    CHECK(w.targets == std::vector<Vec>{{0, 0, 1}, {1, 0, 1}, {5, 3, 1}});
    // One layer without holon's comment: square2d, y flipped within the grid (row 0 at the top).
    const r::VisibleSimCells flat = r::readVisibleSimWorld("<world gridSize=\"3,2,1\"><blockList><block position=\"2,0,0\"/></blockList></world>", 10);
    CHECK(flat.lattice->kind() == LatticeKind::Square2D);
    CHECK(flat.blocks == std::vector<Vec>{{2, 1, 0}});
}

TEST_CASE("malformed worlds are refused at their line and column") {
    const std::string head = "<world gridSize=\"3,3,1\">\n<blockList>\n";
    CHECK(readRefusal(head + "<block position=\"1,1,0\"/>\n</blockList>\n") == "line 1, column 1: <world> is never closed");
    CHECK(readRefusal(head + "<block position=\"1,1,0\"/>\n</world>\n") == "line 4, column 1: </world> closes <blockList> (opened at line 2, column 1)");
    CHECK(readRefusal(head + "  <block position=\"3,0,0\"/>\n</blockList></world>") ==
          "line 3, column 3: position 3,0,0 is outside the grid 3,3,1 (VisibleSim refuses it too)");
    CHECK(readRefusal(head + "<block position=\"1,1,0\"/>\n<block position=\"1,1,0\"/>\n</blockList></world>") ==
          "line 4, column 1: position 1,1,0 is given twice (also at line 3, column 1)");
    CHECK(readRefusal(head + "<block position=\"1,1\"/>\n</blockList></world>") == "line 3, column 1: position=\"1,1\" is not three whole numbers x,y,z");
    CHECK(readRefusal(head + "<block color=\"1,1,1\"/>\n</blockList></world>") == "line 3, column 1: <block> without a position=\"x,y,z\"");
    CHECK(readRefusal(head + "<block position=1,1,0/>\n</blockList></world>") == "line 3, column 17: the value of position must be in quotes");
    CHECK(readRefusal(head + "<blockBox boxOrigin=\"0,0,0\"/>\n</blockList></world>").find("line 3, column 1: <blockBox> is in world units") == 0);
    CHECK(readRefusal(head + "<blocksLine values=\"1x1\"/>\n</blockList></world>") == "line 3, column 1: values=\"...\" holds 'x'; a line of modules is 0s and 1s");
    CHECK(readRefusal(head + "<blocksLine values=\"111\"/>\n</blockList></world>", 2) == "line 3, column 1: more than 2 cells, the limit; give a smaller world");
    CHECK(readRefusal("<world><blockList/></world>") == "line 1, column 1: <world> needs gridSize=\"X,Y,Z\", three whole numbers from 1");
    CHECK(readRefusal("<robots gridSize=\"1,1,1\"/>") == "line 1, column 1: the root element is <robots>; a VisibleSim world's is <world>");
    CHECK(readRefusal("<!-- holon cubic3d cell (x, y, z) is at position (x, y, z) - (2147483000, 0, 0) -->\n<world gridSize=\"2147483000,1,1\"><blockList>"
                      "<block position=\"2147482000,0,0\"/></blockList></world>") ==
          "line 2, column 45: this position is beyond +-536870912 in holon's coordinates; give a smaller grid or offset");
    CHECK(readRefusal("<!-- only a comment") == "line 1, column 5: a comment is not closed ('-->' missing)");
    CHECK(readRefusal("") == "line 1, column 1: no element; a VisibleSim world is an XML file with a <world> element");
    // Nesting is bounded: every element's path names its ancestors, so 10^6 levels took minutes.
    std::string deep = head + "<block position=\"1,1,0\"/>\n";
    for (int k = 0; k < 100; ++k) deep += "<a>";
    CHECK(readRefusal(deep) == "line 4, column 187: <a> is nested 65 elements deep; a VisibleSim world nests at most a few");
}
