// The shape bench's generator (bench/ShapeGenerator): every drawn problem is one the planner can
// take (face-connected start and target, both holding the seed at the origin), the same seed draws
// the same problems, and the families reach the sizes asked for.

#include "ShapeGenerator.h"

#include <doctest/doctest.h>

#include <algorithm>

using namespace holon;

TEST_CASE("shape bench pairs: connected, seeded at the origin, reproducible") {
    int differ = 0;
    for (int dimension : {2, 3})
        for (int index = 0; index < 24; ++index) {
            CAPTURE(dimension);
            CAPTURE(index);
            const bench::ShapePair p = bench::shapePair(dimension, 7, index, 0, 120, 1.9);
            CAPTURE(p.family);
            for (const planner::Shape* s : {&p.start, &p.target}) {
                CHECK(s->dimension == dimension);
                CHECK(std::binary_search(s->cells.begin(), s->cells.end(), rules::Vec{}));
                CHECK(planner::components(s->cells, dimension).size() == 1);
                CHECK(std::adjacent_find(s->cells.begin(), s->cells.end()) == s->cells.end());
            }
            const bench::ShapePair again = bench::shapePair(dimension, 7, index, 0, 120, 1.9);
            CHECK(again.start.cells == p.start.cells);
            CHECK(again.target.cells == p.target.cells);
            const bench::ShapePair other = bench::shapePair(dimension, 8, index, 0, 120, 1.9);
            differ += other.start.cells != p.start.cells || other.target.cells != p.target.cells;
        }
    CHECK(differ >= 40);  // another seed draws other problems (a solid of the same size may repeat)
}

TEST_CASE("every shape family comes close to the size asked for") {
    for (int dimension : {2, 3})
        for (const std::string& family : bench::shapeFamilies(dimension)) {
            CAPTURE(dimension);
            CAPTURE(family);
            std::mt19937_64 random(3);
            const planner::Shape s = bench::shapeOf(family, dimension, 400, random);
            CHECK(s.cells.size() >= 150);
            CHECK(s.cells.size() <= 1000);
        }
}
