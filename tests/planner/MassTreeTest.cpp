// MassTree, the connectivity test behind --keep-connected, against a plain search of the whole
// mass: on random blobs, random changes (cells emptied, cells filled) must be accepted exactly when
// the mass stays connected, and after every accepted change every filled cell but the root must
// have a neighbour one hop nearer the root.

#include "planner/Random.h"
#include "planner/hex/HexShapes.h"
#include "planner/hex/MassTree.h"

#include <doctest/doctest.h>

#include <algorithm>

using namespace holon::planner::hex;

namespace {

void requireParents(const HexArray& a, const MassTree& tree, const std::vector<std::uint8_t>& filled) {
    for (std::int64_t i : a.points()) {
        if (!filled[i]) {
            REQUIRE(tree.distance(i) == -1);
            continue;
        }
        REQUIRE(tree.distance(i) >= 0);
        if (i == tree.root()) continue;
        bool parent = false;
        for (int k = 0; k < 6; ++k) parent |= filled[i + a.step(k)] && tree.distance(i + a.step(k)) == tree.distance(i) - 1;
        REQUIRE(parent);
    }
}

}  // namespace

TEST_CASE("MassTree accepts a change exactly when the mass stays connected") {
    const HexArray a(16);
    holon::planner::Random random(11);
    std::int64_t accepted = 0, refused = 0;
    for (int blob = 0; blob < 40; ++blob) {
        std::vector<std::uint8_t> filled(a.size(), 0);
        const std::int64_t root = a.points()[a.points().size() / 2 + 8];
        filled[root] = 1;
        std::vector<std::int64_t> cells{root};
        for (int grow = 0; grow < 70; ++grow) {  // a random connected blob, often thin and looped
            const std::int64_t c = cells[random.below(cells.size())], n = c + a.step(static_cast<int>(random.below(6)));
            if (a.inside(n) && !filled[n]) filled[n] = 1, cells.push_back(n);
        }
        MassTree tree(a, [&](std::int64_t i) { return filled[i] != 0; });
        tree.rebuild(root);
        requireParents(a, tree, filled);
        for (int t = 0; t < 300; ++t) {
            std::vector<std::int64_t> full, empty;
            for (std::int64_t i : a.points()) (filled[i] ? full : empty).push_back(i);
            std::vector<std::int64_t> emptied, filledNow;
            const int e = static_cast<int>(random.below(4)), f = static_cast<int>(random.below(3));
            for (int k = 0; k < e; ++k) {
                const std::int64_t c = full[random.below(full.size())];
                if (c != root && std::find(emptied.begin(), emptied.end(), c) == emptied.end()) emptied.push_back(c);
            }
            for (int k = 0; k < f; ++k) {  // next to the mass, mostly
                const std::int64_t c = full[random.below(full.size())] + a.step(static_cast<int>(random.below(6)));
                if (a.inside(c) && !filled[c] && std::find(filledNow.begin(), filledNow.end(), c) == filledNow.end()) filledNow.push_back(c);
            }
            std::vector<std::uint8_t> after = filled;
            for (std::int64_t c : emptied) after[c] = 0;
            for (std::int64_t c : filledNow) after[c] = 1;
            const bool expected = connected(a, after);  // HexShapes: a search of the whole mass
            REQUIRE(tree.change(emptied, filledNow) == expected);
            if (expected) filled = after, ++accepted;
            else ++refused;
            requireParents(a, tree, filled);
        }
    }
    CHECK(accepted > 1000);
    CHECK(refused > 1000);
}

TEST_CASE("MassTree never lets the root go, and rebuild refuses a mass in pieces") {
    const HexArray a(12);
    std::vector<std::uint8_t> filled(a.size(), 0);
    const std::int64_t root = a.points()[50];
    filled[root] = filled[root + a.step(0)] = 1;
    MassTree tree(a, [&](std::int64_t i) { return filled[i] != 0; });
    tree.rebuild(root);
    CHECK_FALSE(tree.change({root}, {}));
    CHECK(tree.change({root + a.step(0)}, {root + a.step(3)}));
    filled[root + a.step(0)] = 0, filled[root + a.step(3)] = 1;
    filled[root + 3 * a.step(0)] = 1;
    CHECK_THROWS_AS(tree.rebuild(root), std::logic_error);
}
