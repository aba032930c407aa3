// Conformance every lattice passes: neighbour symmetry, opposites, a closed point group (rotations
// first, then reflections) that maps the direction set onto itself, and the cell counts of bounded
// regions.

#include "rules/Error.h"
#include "rules/Lattice.h"
#include "rules/Region.h"

#include <algorithm>
#include <doctest/doctest.h>

using namespace holon::rules;

TEST_CASE("every lattice passes the conformance checks") {
    for (const Lattice* l : Lattice::all()) {
        CAPTURE(l->name());
        for (int d = 0; d < l->degree(); ++d) {
            CHECK(l->opposite(l->opposite(d)) == d);
            CHECK(l->direction(l->opposite(d)) == Vec{} - l->direction(d));
            CHECK(l->directionOf(l->direction(d)) == d);
            CHECK(l->directionByName(l->directionName(d)) == d);
        }
        const auto& rotations = l->rotations();
        const auto& group = l->pointGroup();
        // The proper rotations come first, in the order of rotations(), then as many reflections.
        REQUIRE(group.size() == 2 * rotations.size());
        for (std::size_t i = 0; i < group.size(); ++i) {
            CHECK(group[i].determinant() == (i < rotations.size() ? 1 : -1));
            if (i < rotations.size()) CHECK(group[i] == rotations[i]);
            CHECK(std::count(group.begin(), group.end(), group[i]) == 1);
        }
        for (const LinearMap& a : group) {
            // Closure: the product of two symmetries is a symmetry of the group.
            for (const LinearMap& b : group) CHECK(std::find(group.begin(), group.end(), a.then(b)) != group.end());
            // Each symmetry permutes the directions.
            std::vector<int> image;
            for (Vec d : l->directions()) image.push_back(l->directionOf(a.apply(d)));
            std::sort(image.begin(), image.end());
            for (int d = 0; d < l->degree(); ++d) CHECK(image[d] == d);
        }
        // The first reflection fixes direction 0, so a line of cells along it maps onto itself.
        CHECK(group[rotations.size()].apply(l->direction(0)) == l->direction(0));
        CHECK(l->symmetries(Symmetry::None).size() == 1);
        CHECK(l->symmetries(Symmetry::Rotations).size() == rotations.size());
        CHECK(l->symmetries(Symmetry::RotationsReflections).size() == group.size());
        // The rotations act transitively on directions, so a rule written along one direction
        // closes to all of them.
        std::vector<int> orbit;
        for (const LinearMap& r : rotations) orbit.push_back(l->directionOf(r.apply(l->direction(0))));
        std::sort(orbit.begin(), orbit.end());
        orbit.erase(std::unique(orbit.begin(), orbit.end()), orbit.end());
        CHECK(static_cast<int>(orbit.size()) == l->degree());
    }
    CHECK(Lattice::get(LatticeKind::Square2D).rotations().size() == 4);
    CHECK(Lattice::get(LatticeKind::Cubic3D).rotations().size() == 24);
    CHECK(Lattice::get(LatticeKind::Hex2D).rotations().size() == 6);
    CHECK(Lattice::get(LatticeKind::Square2D).pointGroup().size() == 8);
    CHECK(Lattice::get(LatticeKind::Cubic3D).pointGroup().size() == 48);
    CHECK(Lattice::get(LatticeKind::Hex2D).pointGroup().size() == 12);
}

TEST_CASE("region cell counts and neighbour symmetry") {
    CHECK(Region::parse("square:5x3").size() == 15);
    CHECK(Region::parse("cubic:3x3x3").size() == 27);
    for (int r = 1; r <= 6; ++r) CHECK(Region::parse("hex:r" + std::to_string(r)).size() == 3 * r * (r + 1) + 1);
    for (const char* spec : {"square:4x3", "cubic:3x2x2", "hex:r3"}) {
        Region region = Region::parse(spec);
        CAPTURE(spec);
        const Lattice& l = region.lattice();
        int edges = 0;
        for (int i = 0; i < region.size(); ++i) {
            CHECK(region.indexOf(region.cell(i)) == i);
            for (int d = 0; d < l.degree(); ++d) {
                const int j = region.neighbour(i, d);
                if (j < 0) continue;
                ++edges;
                CHECK(region.neighbour(j, l.opposite(d)) == i);
            }
        }
        CHECK(edges % 2 == 0);
    }
    // Interior edges: a 4x3 grid has 3*3 + 4*2 = 17 undirected edges; hex:r1 has 12.
    auto undirected = [](const Region& region) {
        int edges = 0;
        for (int i = 0; i < region.size(); ++i)
            for (int d = 0; d < region.lattice().degree(); ++d) edges += region.neighbour(i, d) >= 0;
        return edges / 2;
    };
    CHECK(undirected(Region::parse("square:4x3")) == 17);
    CHECK(undirected(Region::parse("hex:r1")) == 12);
    CHECK(undirected(Region::parse("cubic:2x2x2")) == 12);
}

TEST_CASE("bad region specifications are rejected with a message") {
    for (const char* spec : {"square:5", "square:0x3", "cube:3x3x3", "hex:2", "hex:r", "square:axb", "cubic:2x2", ""})
        CHECK_THROWS_AS(Region::parse(spec), holon::InputError);
    CHECK_THROWS_WITH_AS(Region::parse("square:100000x100000"), doctest::Contains("choose a smaller region"), holon::InputError);
    CHECK_THROWS_WITH_AS(Region::parse("tri:3x3"), doctest::Contains("unknown lattice 'tri'"), holon::InputError);
}
