// Semantics of the standard library, checked with the reference interpreter against seed 000:
// general_n conserves mass on every step and builds a metamodule through B1..Bn-1 (§III-C); the
// U/P/F planner's six rules fire exactly as the table of §IV-A says; the hex pivot of Fig. 1a is
// blocked by a module in D.

#include "TestSupport.h"

#include <random>
#include <set>

using namespace holon;
using test::World;

namespace {

/// Random connected configurations of a system on a region (rejection sampling, fixed seed).
std::vector<rules::Configuration> randomLegal(const World& w, int count, double density, unsigned seed) {
    std::mt19937 rng(seed);
    std::uniform_real_distribution<double> coin(0, 1);
    std::uniform_int_distribution<int> state(1, w.model->alphabet().size() - 1);
    std::vector<rules::Configuration> out;
    for (int tries = 0; tries < count * 2000 && static_cast<int>(out.size()) < count; ++tries) {
        auto c = w.in->empty();
        for (auto& v : c.cells) v = coin(rng) < density ? static_cast<rules::CellValue>(state(rng)) : 0;
        if (w.in->legal(c)) out.push_back(c);
    }
    return out;
}

}  // namespace

TEST_CASE("every rule of general_n and general-lock_n conserves mass") {
    for (const char* stem : {"general1", "general2", "general3", "general_lock2", "general_lock3"}) {
        CAPTURE(stem);
        World w = World::library(stem, "square:4x4");
        auto configs = randomLegal(w, 60, 0.6, 7);
        REQUIRE(configs.size() == 60);
        int steps = 0;
        std::set<std::string> fired;
        for (const auto& c : configs)
            for (const auto& i : w.in->enabled(c)) {
                CHECK(w.in->mass(*w.in->successor(c, i)) == w.in->mass(c));
                fired.insert(w.model->rules()[w.model->shapes()[i.shape].rule].name);
                ++steps;
            }
        CHECK(steps > 100);
        CHECK(fired.count("transfer"));
        CHECK((fired.count("create") || fired.count("create1")));
    }
}

TEST_CASE("a broken create that does not conserve mass is caught") {
    World w(test::parse("system broken\nstates D | C\nmass D = 1, C = 2\nrule create: C _ => C D\nconstraint connected\n"), "square:3x1");
    auto c = w.ascii("C..");
    auto enabled = w.in->enabled(c);
    REQUIRE(enabled.size() == 1);
    CHECK(w.in->mass(*w.in->successor(c, enabled[0])) != w.in->mass(c));
}

TEST_CASE("general_n builds a new metamodule through B1 .. Bn-1") {
    // general3 on a 4x1 row starting "CCC.": explore everything reachable and watch cell 3.
    World w = World::library("general3", "square:4x1");
    const auto start = w.ascii("CCC.");
    std::vector<rules::Configuration> frontier{start};
    std::set<std::vector<rules::CellValue>> seen{start.cells};
    std::set<std::pair<std::string, std::string>> cell3;
    bool built = false;
    while (!frontier.empty()) {
        auto c = frontier.back();
        frontier.pop_back();
        for (const auto& i : w.in->enabled(c)) {
            auto next = *w.in->successor(c, i);
            if (w.at(c, 3, 0) != w.at(next, 3, 0)) cell3.insert({w.at(c, 3, 0), w.at(next, 3, 0)});
            built |= w.at(next, 3, 0) == "D" || w.at(next, 3, 0) == "C";
            if (seen.insert(next.cells).second) frontier.push_back(next);
        }
    }
    CHECK(built);
    // Cell 3 fills only through _ -> B1 -> B2 -> D (and back), plus transfers between D and C.
    const std::set<std::pair<std::string, std::string>> allowed{
        {"_", "B1"}, {"B1", "B2"}, {"B2", "D"}, {"B1", "_"}, {"B2", "B1"}, {"D", "B2"}, {"D", "C"}, {"C", "D"}};
    for (const auto& step : cell3) {
        CAPTURE(step.first + " -> " + step.second);
        CHECK(allowed.count(step));
    }
    CHECK(cell3.count({"_", "B1"}));
    CHECK(cell3.count({"B1", "B2"}));
    CHECK(cell3.count({"B2", "D"}));
}

TEST_CASE("general-lock_2: a locked pair builds only together") {
    World w = World::library("general_lock2", "square:3x2");
    auto c = w.in->empty();
    w.set(c, 0, 0, "C"), w.set(c, 1, 0, "C");
    // Start a creation from (1,0) into (2,0): the pair locks.
    rules::Configuration locked;
    for (const auto& i : w.in->enabled(c)) {
        auto next = *w.in->successor(c, i);
        if (w.at(next, 2, 0) == "B1&lock=-x") locked = next;
    }
    REQUIRE(!locked.cells.empty());
    CHECK(w.at(locked, 1, 0) == "D&lock=+x");
    // Only the partner may continue: give (1,1) a C next to the B1 and check it cannot use it.
    w.set(locked, 2, 1, "C");
    w.set(locked, 1, 1, "D");
    for (const auto& i : w.in->enabled(locked)) {
        auto next = *w.in->successor(locked, i);
        if (w.at(next, 2, 0) == "D") CHECK(w.at(locked, 1, 0).rfind("C", 0) == 0);
        CHECK(w.at(next, 2, 1) != "D&lock=-y");
    }
}

TEST_CASE("the U/P/F planner fires exactly as the table of seed 000 section IV-A") {
    World w = World::library("planner_intermediate", "square:3x2");
    auto fresh = [&](const std::string& target) {
        auto c = w.in->empty();
        w.mark(c, "target", target);
        return c;
    };
    auto only = [&](const rules::Configuration& c, const std::vector<std::string>& rules) { CHECK(w.enabledRules(c) == rules); };

    SUBCASE("finalization: F U^ => F F") {
        auto c = fresh("##.");
        w.set(c, 0, 0, "F"), w.set(c, 1, 0, "U");
        only(c, {"finalize"});
        CHECK(w.at(*w.in->successor(c, w.in->enabled(c)[0]), 1, 0) == "F");
    }
    SUBCASE("path creation: F Uv => F->P") {
        auto c = fresh("#..");
        w.set(c, 0, 0, "F"), w.set(c, 1, 0, "U");
        only(c, {"path_create"});
        CHECK(w.at(*w.in->successor(c, w.in->enabled(c)[0]), 1, 0) == "P&parent=-x");
    }
    SUBCASE("path propagation: P U => P->P") {
        auto c = fresh("#..");
        w.set(c, 0, 0, "F"), w.set(c, 1, 0, "P&parent=-x"), w.set(c, 2, 0, "U");
        only(c, {"path_propagate"});
        CHECK(w.at(*w.in->successor(c, w.in->enabled(c)[0]), 2, 0) == "P&parent=-x");
    }
    SUBCASE("path finalization: F P^ => F F") {
        auto c = fresh("##.");
        w.set(c, 0, 0, "F"), w.set(c, 1, 0, "P&parent=-x");
        only(c, {"delete", "path_finalize"});  // the paper deletes any P leaf, in T or not
    }
    SUBCASE("creation: F _^ => F F") {
        auto c = fresh("##.");
        w.set(c, 0, 0, "F");
        only(c, {"create"});
        CHECK(w.at(*w.in->successor(c, w.in->enabled(c)[0]), 1, 0) == "F");
    }
    SUBCASE("deletion: a P leaf with no U neighbour goes") {
        auto c = fresh("#..");
        w.set(c, 0, 0, "F"), w.set(c, 1, 0, "P&parent=-x"), w.set(c, 2, 0, "P&parent=-x");
        only(c, {"delete"});  // only the leaf at (2,0): (1,0) has a child
        CHECK(w.at(*w.in->successor(c, w.in->enabled(c)[0]), 2, 0) == "_");
    }
    SUBCASE("deletion does not fire on a P with a U neighbour") {
        auto c = fresh("#..");
        w.set(c, 0, 0, "F"), w.set(c, 1, 0, "P&parent=-x"), w.set(c, 1, 1, "U");
        only(c, {"path_propagate"});
    }
    SUBCASE("a neighbouring P that is not a child does not block deletion") {
        auto c = fresh("#..\n#..");
        w.set(c, 0, 0, "F"), w.set(c, 0, 1, "F");
        w.set(c, 1, 0, "P&parent=-x"), w.set(c, 1, 1, "P&parent=-x");
        only(c, {"delete", "delete"});
    }
    SUBCASE("the goal: every target cell F, nothing else") {
        auto c = fresh("##.");
        w.set(c, 0, 0, "F"), w.set(c, 1, 0, "F");
        CHECK(w.in->atGoal(c));
        only(c, {});
        w.set(c, 2, 0, "P&parent=-x");
        CHECK_FALSE(w.in->atGoal(c));
    }
}

TEST_CASE("planner over general1: deletion needs a destroyer, creation a creator") {
    World w = World::library("planner_general1", "square:3x1");
    auto c = w.in->empty();
    w.mark(c, "target", "##.");
    w.set(c, 0, 0, "D&F"), w.set(c, 1, 0, "D&F"), w.set(c, 2, 0, "D&P&parent=-x");
    CHECK(w.enabledRules(c) == std::vector<std::string>{"delete"});
    auto next = *w.in->successor(c, w.in->enabled(c)[0]);
    CHECK(w.at(next, 1, 0) == "C&F");
    CHECK(w.at(next, 2, 0) == "_");
    CHECK(w.in->mass(next) == w.in->mass(c));
    CHECK(w.in->atGoal(next));
}

TEST_CASE("hex pivot: A rolls about C into B only while D is empty (seed 000 Fig. 1a)") {
    World w = World::library("hex_pivot", "hex:r2");
    auto c = w.in->empty();
    auto put = [&](rules::Configuration& x, int q, int r) { x.cells[w.region.indexOf({q, r, 0})] = 1; };
    put(c, 0, 0), put(c, 1, 0);  // C and A
    auto moved = w.in->empty();
    put(moved, 0, 0), put(moved, 1, -1);  // A now at B
    auto reaches = [&](const rules::Configuration& from, const rules::Configuration& to) {
        for (const auto& i : w.in->enabled(from))
            if (*w.in->successor(from, i) == to) return true;
        return false;
    };
    CHECK(w.in->enabled(c).size() == 4);  // each module rolls about the other, both ways
    CHECK(reaches(c, moved));
    put(c, 2, -1), put(moved, 2, -1);  // a module in D blocks the pivot
    CHECK_FALSE(reaches(c, moved));
}
