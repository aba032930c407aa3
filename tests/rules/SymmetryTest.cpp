// The `symmetry` declaration: which orientations of a rule exist (none, the rotations, or the
// rotations with the reflections, the default), what the reflections add to one-sided templates
// and what they leave alone: lines of cells, rule sets that are mirror-symmetric already, and the
// standard library, whose proofs and plans must not change.

#include "TestSupport.h"
#include "rules/Model.h"

#include <sstream>

using namespace holon;
using test::World;

namespace {

rules::System withSymmetry(rules::System s, rules::Symmetry symmetry) {
    s.symmetry = symmetry;
    return s;
}

int instances(const rules::System& s, rules::LatticeKind kind) {
    return static_cast<int>(rules::Model(s, rules::Lattice::get(kind)).shapes().size());
}

}  // namespace

TEST_CASE("a one-sided template has one orientation per symmetry: 1, the rotations, or twice as many") {
    // A module slides along +x with a wall below it: chiral on the square lattice.
    const rules::System s = test::parse(
        "system t\nlattice square2d\nstates M\nrule slide: M@(0,0) _@(1,0) #@(0,1) #@(1,1) => _ @0 * *\n");
    CHECK(s.symmetry == rules::Symmetry::RotationsReflections);
    CHECK(instances(s, rules::LatticeKind::Square2D) == 8);
    CHECK(instances(withSymmetry(s, rules::Symmetry::Rotations), rules::LatticeKind::Square2D) == 4);
    CHECK(instances(withSymmetry(s, rules::Symmetry::None), rules::LatticeKind::Square2D) == 1);
    // The same on hex2d (a step east along a wall to the north-west); on cubic3d the mirror image
    // of an L of three cells is a rotation of it.
    const rules::System h =
        test::parse("system t\nlattice hex2d\nstates M\nrule step: M@(0,0) _@(1,0) #@(0,-1) => _ @0 *\n");
    CHECK(instances(h, rules::LatticeKind::Hex2D) == 12);
    CHECK(instances(withSymmetry(h, rules::Symmetry::Rotations), rules::LatticeKind::Hex2D) == 6);
    const rules::System c = test::parse(
        "system t\nlattice cubic3d\nstates M\nrule step: M@(0,0,0) _@(1,0,0) #@(0,1,0) => _ @0 *\n");
    CHECK(instances(c, rules::LatticeKind::Cubic3D) == 24);
    CHECK(instances(withSymmetry(c, rules::Symmetry::Rotations), rules::LatticeKind::Cubic3D) == 24);
}

TEST_CASE("a positionless rule lies on a line its mirror maps onto itself: reflections add no instance") {
    const rules::System s = test::parse(R"(system t
field label: U | P | F
field parent: dir if P
rule grow: F U => F P&parent=@0 if no nbr U and count nbr@1 F >= 1
rule pair: F _ => F F
)");
    for (const rules::Lattice* l : rules::Lattice::all()) {
        CAPTURE(l->name());
        const rules::Model full(s, *l), rotations(withSymmetry(s, rules::Symmetry::Rotations), *l);
        REQUIRE(full.shapes().size() == rotations.shapes().size());
        CHECK(static_cast<int>(full.shapes().size()) == 2 * l->degree());
        for (std::size_t i = 0; i < full.shapes().size(); ++i)
            CHECK(full.shapes()[i].offsets == rotations.shapes()[i].offsets);
        // With the identity only, each rule keeps the orientation it was written in.
        CHECK(rules::Model(withSymmetry(s, rules::Symmetry::None), *l).shapes().size() == 2);
    }
}

TEST_CASE(
    "a guard that treats mirrored cells alike merges the mirrored orientation, whatever the conjuncts' "
    "order") {
    // Cells @2 and @3 are mirror images in the x axis; the guard asks the same of both, in index
    // order, which the mirror reverses.
    const rules::System s = test::parse(
        "system t\nlattice square2d\nstates M\n"
        "rule push: M@(0,0) _@(1,0) #@(0,1) #@(0,-1) => _ @0 * * if count "
        "nbr@2 # == 1 and count nbr@3 # == 1\n"
        "rule lean: M@(0,0) _@(1,0) #@(0,1) #@(0,-1) => _ @0 * * if count "
        "nbr@2 # == 1 and count nbr@3 # == 2\n");
    const rules::Model m(s, rules::Lattice::get(rules::LatticeKind::Square2D));
    CHECK(m.shapeCount(0) == 4);
    CHECK(m.shapeCount(1) == 8);  // asks different things of the two sides: chiral
}

TEST_CASE("sliding_cube slides with a wall on either side") {
    const std::string path = std::string(HOLON_TEST_DIR) + "/../examples/rules/sliding_cube.holon";
    std::ostringstream messages;
    auto system = rules::loadSystem(path, messages);
    INFO(messages.str());
    REQUIRE(system.has_value());
    World w(*system, "square:2x3");
    // A module with a wall above it (row 0) moves right; before reflections, only a wall below let
    // a module move right.
    for (const std::string art : {"MM\nM.\n..", "..\nM.\nMM"}) {
        CAPTURE(art);
        auto c = w.ascii(art);
        bool slidRight = false;
        for (const auto& i : w.in->enabled(c)) {
            if (w.model->rules()[w.model->shapes()[i.shape].rule].name != "slide") continue;
            auto next = w.in->successor(c, i);
            REQUIRE(next.has_value());
            slidRight |= w.at(*next, 1, 1) == "M&charge=0" && w.at(*next, 0, 1) == "_";
        }
        CHECK(slidRight);
    }
}

TEST_CASE("rotations claim their rewrites before reflections: a mirror-symmetric rule set keeps its split") {
    // hex_pivot's pivot_back is pivot mirrored; both keep their six rotations.
    const rules::System pivot = rules::librarySystem("hex_pivot");
    const rules::Model m(pivot, rules::Lattice::get(rules::LatticeKind::Hex2D));
    REQUIRE(m.rules().size() == 2);
    CHECK(m.shapeCount(0) == 6);
    CHECK(m.shapeCount(1) == 6);
    CHECK(m.duplicates().size() == 1);  // the reverse repeats the rule; validate() does not warn about that
}

TEST_CASE(
    "the default adds no instance to the standard library: proofs, checks and plans stay as they were") {
    for (const std::string& file : rules::libraryFiles()) {
        CAPTURE(file);
        std::ostringstream messages;
        auto system = rules::loadSystem(file, messages);
        REQUIRE(system.has_value());
        for (const rules::Lattice* l : rules::Lattice::all()) {
            if (system->lattice && *system->lattice != l->kind()) continue;
            CAPTURE(l->name());
            // As declared: by default rotations+reflections; hex_collapse keeps its gravity's handedness.
            const rules::Model full(*system, *l);
            const rules::Model rotations(withSymmetry(*system, rules::Symmetry::Rotations), *l);
            REQUIRE(full.shapes().size() == rotations.shapes().size());
            for (std::size_t i = 0; i < full.shapes().size(); ++i) {
                CHECK(full.shapes()[i].rule == rotations.shapes()[i].rule);
                CHECK(full.shapes()[i].offsets == rotations.shapes()[i].offsets);
            }
        }
    }
}
