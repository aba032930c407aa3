// The one connected-set search (rules/Components.h) against an oracle that shares nothing with
// it: union-find over the region's neighbour pairs, on random cell sets of every lattice.

#include "rules/Components.h"
#include "rules/Lattice.h"
#include "rules/Region.h"

#include <doctest/doctest.h>

#include <algorithm>
#include <numeric>
#include <random>

using namespace holon::rules;

namespace {

/// The parts of `member` by union-find: each member cell's representative.
std::vector<int> unionFind(const Region& r, const std::vector<char>& member) {
    std::vector<int> parent(r.size());
    std::iota(parent.begin(), parent.end(), 0);
    auto find = [&](int a) {
        while (parent[a] != a) a = parent[a] = parent[parent[a]];
        return a;
    };
    for (int i = 0; i < r.size(); ++i)
        for (int d = 0; d < r.lattice().degree(); ++d)
            if (const int j = r.neighbour(i, d); j >= 0 && member[i] && member[j]) parent[find(i)] = find(j);
    std::vector<int> root(r.size(), -1);
    for (int i = 0; i < r.size(); ++i)
        if (member[i]) root[i] = find(i);
    return root;
}

}  // namespace

TEST_CASE("components and connected agree with union-find on every lattice, and the word form with both") {
    std::mt19937 random(27);
    Flood flood;  // one scratch for every search: the stamps must keep them apart
    for (const Lattice* l : Lattice::all()) {
        CAPTURE(l->name());
        const Region r = Region::box(*l, l->dimension() == 3 ? Vec{4, 4, 3} : Vec{6, 6, 1});
        REQUIRE(r.size() <= 64);
        std::vector<std::uint64_t> words(r.size(), 0);
        for (int i = 0; i < r.size(); ++i)
            for (int d = 0; d < l->degree(); ++d)
                if (const int j = r.neighbour(i, d); j >= 0) words[i] |= std::uint64_t{1} << j;
        int disconnected = 0, joined = 0;
        for (int trial = 0; trial < 300; ++trial) {
            const double density = std::uniform_real_distribution<double>(0.1, 0.9)(random);
            std::vector<char> member(r.size(), 0);
            std::uint64_t word = 0;
            for (int i = 0; i < r.size(); ++i)
                if (std::bernoulli_distribution(density)(random)) member[i] = 1, word |= std::uint64_t{1} << i;
            const auto isMember = [&](std::int64_t i) { return member[i] != 0; };
            const std::vector<int> root = unionFind(r, member);
            std::vector<int> part(r.size(), -1);
            const int count = components(flood, r.size(), verticesWhere(r.size(), isMember), regionEdges(r, isMember),
                                         [&](std::int64_t i, int k) { part[i] = k; });
            // Same partition: two members share a part exactly when they share a root.
            for (int i = 0; i < r.size(); ++i)
                for (int j = 0; j < r.size(); ++j)
                    if (member[i] && member[j]) CHECK((part[i] == part[j]) == (root[i] == root[j]));
            std::vector<int> roots;
            for (int i = 0; i < r.size(); ++i)
                if (member[i] && std::find(roots.begin(), roots.end(), root[i]) == roots.end()) roots.push_back(root[i]);
            CHECK(count == static_cast<int>(roots.size()));
            const bool one = roots.size() <= 1;
            CHECK(connected(flood, r.size(), verticesWhere(r.size(), isMember), regionEdges(r, isMember)) == one);
            CHECK(connectedWord(word, aroundByTable(words.data())) == one);
            (one ? joined : disconnected) += 1;
        }
        CHECK(joined > 0);  // the random sets must exercise both answers
        CHECK(disconnected > 0);
    }
}

TEST_CASE("a search stops where its visit says, and reachedWithin keeps to its set") {
    const Region r = Region::box(Lattice::get(LatticeKind::Square2D), Vec{8, 1, 1});  // a row of 8
    Flood flood;
    flood.begin(r.size());
    flood.add(0);
    const auto all = regionEdges(r, [](std::int64_t) { return true; });
    CHECK(flood.spread(all, [](std::int64_t v) { return v < 3; }) == 4);  // 0, 1, 2, then 3 stops it
    CHECK(flood.seen(3));
    CHECK(!flood.seen(4));  // 3 stopped the search before its neighbours were queued
    // A row's word: from cell 0 within {0, 1, 2, 4}: the gap at 3 stops it.
    const auto around = [](std::uint64_t s) { return (s << 1 | s >> 1) & 0xff; };
    CHECK(reachedWithin<std::uint64_t>(0b1, 0b10111, around) == 0b111);
    CHECK(!connectedWord<std::uint64_t>(0b10111, around));
    CHECK(connectedWord<std::uint64_t>(0, around));
}
