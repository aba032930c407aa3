// Shapes: generators, files, scaling, and the messages for bad shape arguments.

#include "planner/Shape.h"
#include "rules/Error.h"

#include <algorithm>
#include <doctest/doctest.h>
#include <filesystem>
#include <fstream>

namespace holon::test {

using planner::parseShape;

TEST_CASE("shape generators have the sizes their names say") {
    CHECK(parseShape("box:6x3x2").cells.size() == 36);
    CHECK(parseShape("box:6x3x2").dimension == 3);
    CHECK(parseShape("box:40x20").cells.size() == 800);
    CHECK(parseShape("box:6x3x2", 4).cells.size() == 36 * 64);
    CHECK(parseShape("box:40x20", 3).cells.size() == 800 * 9);
    const planner::Shape t = parseShape("T:9");
    CHECK(t.cells.size() == 9 * 3 + 3 * 9);
    CHECK(planner::components(t.cells, 2).size() == 1);
    CHECK(parseShape("disc:1").cells.size() == 5);
    CHECK(parseShape("ring:2,4").cells.size() < parseShape("disc:4").cells.size());
    CHECK(planner::components(parseShape("ring:2,4").cells, 2).size() == 1);
    const planner::Shape chair = parseShape("chair:3");
    CHECK(chair.dimension == 3);
    CHECK(planner::components(chair.cells, 3).size() == 1);
}

TEST_CASE("shape files: JSON, ASCII art and voxels") {
    const auto dir = std::filesystem::temp_directory_path() / "holon_shape_test";
    std::filesystem::create_directories(dir);
    std::ofstream(dir / "l.txt") << "#..\n#..\n###\n";
    std::ofstream(dir / "c.json") << R"({"cells": [[0,0,0],[1,0,0],[1,1,0]]})";
    std::ofstream(dir / "v.xyz") << "# two voxels\n0 0 0\n0 0 1\n";
    std::ofstream(dir / "bad.txt") << "#?\n";
    const planner::Shape l = parseShape((dir / "l.txt").string());
    CHECK(l.cells.size() == 5);
    // The first line is row y = 0, at the top as in the checker's pictures: y runs down the page.
    CHECK(std::binary_search(l.cells.begin(), l.cells.end(), planner::Vec{0, 0, 0}));
    CHECK(std::binary_search(l.cells.begin(), l.cells.end(), planner::Vec{2, 2, 0}));
    CHECK_FALSE(std::binary_search(l.cells.begin(), l.cells.end(), planner::Vec{2, 0, 0}));
    CHECK(parseShape((dir / "c.json").string()).dimension == 3);
    CHECK(parseShape((dir / "v.xyz").string()).cells.size() == 2);
    CHECK_THROWS_WITH_AS(parseShape((dir / "bad.txt").string()), doctest::Contains("line 1, column 2"), InputError);
}

TEST_CASE("bad shape arguments name the fix") {
    CHECK_THROWS_WITH_AS(parseShape("box:0x3"), doctest::Contains("not a size"), InputError);
    CHECK_THROWS_WITH_AS(parseShape("box:3"), doctest::Contains("expected 2 or 3 numbers"), InputError);
    CHECK_THROWS_WITH_AS(parseShape("ring:5,2"), doctest::Contains("inner radius"), InputError);
    CHECK_THROWS_WITH_AS(parseShape("blob:3"), doctest::Contains("neither a shape generator"), InputError);
    CHECK_THROWS_WITH_AS(parseShape("box:100000x100000"), doctest::Contains("more than the limit"), InputError);
}

}  // namespace holon::test
