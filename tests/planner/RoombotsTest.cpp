// The Roombots back-end (seed 001): kinematics facts that follow from the geometry, the collision-cloud
// table against a fresh sweep, and assembly runs — holon's reservation strategy must finish every run
// without a collision or a deadlock, checked by the same geometric collision test the paper's
// strategies are measured with.

#include "planner/roombots/Assembly.h"
#include "rules/Error.h"

#include <doctest/doctest.h>

#include <algorithm>
#include <csignal>
#include <filesystem>
#include <fstream>
#include <map>
#include <set>

using namespace holon::planner::roombots;

namespace {

bool standsOnFloor(const Posture& p) {
    std::set<Cell> distinct(p.cells.begin(), p.cells.end());
    return distinct.size() == 4 && std::all_of(p.cells.begin(), p.cells.end(), [](const Cell& c) { return c.z >= 0; });
}

const CloudTable& shippedTable() {
    static const CloudTable table = CloudTable::load(CloudTable::defaultPath());
    return table;
}

}  // namespace

TEST_CASE("all joints at zero is the upright I for every coupling") {
    for (Coupling c : kCouplings) {
        const Posture p = Metamodule(c).posture(Joints{}, 0);
        for (int k = 0; k < 4; ++k) CHECK(p.cells[k] == Cell{0, 0, k});
        CHECK(classify(p.cells) == Shape::I);
    }
}

TEST_CASE("joint settings round-trip through their index") {
    for (int i = 0; i < kJointSettings; ++i) CHECK(Joints::fromIndex(i).index() == i);
}

TEST_CASE("the couplings differ as Fig. 3a says: PAR never folds into a U, PER never into an S, SRS and SRZ are mirror images") {
    std::map<Coupling, std::map<Shape, int>> shapes;
    for (Coupling c : kCouplings) {
        const Metamodule m(c);
        for (int i = 0; i < kJointSettings; ++i) {
            const Posture p = m.posture(Joints::fromIndex(i), 0);
            if (standsOnFloor(p)) ++shapes[c][classify(p.cells)];
        }
    }
    CHECK(shapes[Coupling::PAR][Shape::U] == 0);
    CHECK(shapes[Coupling::PAR][Shape::S] > 0);
    CHECK(shapes[Coupling::PER][Shape::S] == 0);
    CHECK(shapes[Coupling::PER][Shape::U] > 0);
    CHECK(shapes[Coupling::SRS] == shapes[Coupling::SRZ]);
    CHECK(shapes[Coupling::SRS] != shapes[Coupling::PAR]);
}

TEST_CASE("a stance read from the head is the same pose: reversed() and the head yaw agree with the kinematics") {
    for (Coupling c : kCouplings) {
        const Metamodule m(c);
        int stances = 0;
        for (int i = 0; i < kJointSettings; ++i) {
            const Joints j = Joints::fromIndex(i);
            const Posture p = m.posture(j, 0);
            if (!standsOnFloor(p) || !p.stance()) continue;
            ++stances;
            const Posture r = m.posture(reversed(j), p.headYaw);
            for (int k = 0; k < 4; ++k) CHECK(r.cells[k] == p.cells[3 - k] - p.cells[3]);
            CHECK(r.headFace == Cell{0, 0, -1});
            CHECK(reversed(reversed(j)) == j);
        }
        CHECK(stances > 0);
    }
}

TEST_CASE("a sweep covers where the motion starts and ends, standing still sweeps only the body") {
    const Metamodule m(Coupling::SRZ);
    const Joints zero{};
    CHECK(m.sweep(zero, zero, 0, 48, 0.45).size() == 4);
    int checked = 0;
    for (int i = 0; i < kJointSettings && checked < 50; i += 7) {
        const Joints to = Joints::fromIndex(i);
        const auto cloud = m.sweep(zero, to, 1, 48, 0.45);
        if (cloud.empty()) continue;  // self-collision or through the floor
        ++checked;
        for (const Joints* p : {&zero, &to})
            for (const Cell& c : m.posture(*p, 1).cells) CHECK(std::binary_search(cloud.begin(), cloud.end(), c));
    }
    CHECK(checked > 10);
}

TEST_CASE("the shipped collision-cloud table matches the kinematics") {
    const CloudTable& table = shippedTable();
    CHECK(table.size() > 10000);
    int checked = 0;
    for (Coupling c : kCouplings) {
        const Metamodule m(c);
        CHECK(!table.from(c, Joints{}).empty());
        const auto& row = table.from(c, Joints{});
        for (std::size_t k = 0; k < row.size(); k += 9, ++checked) {
            CHECK(row[k].cloud == m.sweep(Joints{}, row[k].to, 0, CloudTable::kSamples, CloudTable::kRadius));
            const Posture p = m.posture(row[k].to, 0);
            if (row[k].kind == Transition::Kind::Step) CHECK(p.stance());
            // every step's reversal has its own row: a walk never runs off the table
            if (row[k].kind == Transition::Kind::Step) CHECK(!table.from(c, reversed(row[k].to)).empty());
        }
    }
    CHECK(checked > 40);
}

TEST_CASE("reserve assembles the cube and the chair with no collision and no deadlock") {
    const CloudTable& table = shippedTable();
    for (const char* structure : {"cube", "chair"})
        for (Coupling c : {Coupling::PAR, Coupling::SRZ}) {
            const auto settings = loadScenario(structure, 1, 1);
            for (const Setting& s : settings) {
                CAPTURE(structure);
                CAPTURE(couplingName(c));
                const AssemblyResult r = assemble(table, c, Strategy::Reserve, s);
                CHECK(r.completed);
                CHECK(!r.deadlocked);
                CHECK(r.collisions == 0);
                REQUIRE(r.placed.size() == s.recipe.seeds.size());
                std::set<Cell> built, goal;
                for (const auto& cells : r.cells) built.insert(cells.begin(), cells.end());
                for (const Seed& seed : s.recipe.seeds) goal.insert(seed.cells.begin(), seed.cells.end());
                CHECK(built == goal);
            }
        }
}

TEST_CASE("the paper's strategies: a completed run has built the structure, and runs are reproducible") {
    const CloudTable& table = shippedTable();
    const auto settings = loadScenario("cube", 7);
    int completed = 0;
    for (Strategy strategy : kPaperStrategies) {
        const AssemblyResult a = assemble(table, Coupling::SRS, strategy, settings[0]);
        const AssemblyResult b = assemble(table, Coupling::SRS, strategy, settings[0]);
        CHECK(a.collisions == b.collisions);
        CHECK(a.moves == b.moves);
        CHECK(a.completed != a.deadlocked);
        if (!a.completed) continue;
        ++completed;
        std::set<Cell> built, goal;
        for (const auto& cells : a.cells) built.insert(cells.begin(), cells.end());
        for (const Seed& seed : settings[0].recipe.seeds) goal.insert(seed.cells.begin(), seed.cells.end());
        CHECK(built == goal);
    }
    CHECK(completed > 0);
}

TEST_CASE("bad Roombots input is refused with the place and the fix") {
    CHECK_THROWS_WITH_AS(parseCoupling("XYZ"), doctest::Contains("use PAR, PER, SRS or SRZ"), holon::InputError);
    CHECK_THROWS_WITH_AS(parseStrategy("fast"), doctest::Contains("greedy, slope, step or reserve"), holon::InputError);
    CHECK_THROWS_AS(loadScenario("/nonexistent/recipe.txt", 1), holon::InputError);
    CHECK_THROWS_WITH_AS(CloudTable::load("/nonexistent/clouds.json"), doctest::Contains("regenerate it with `CloudTable::compute /nonexistent/clouds.json`"), holon::InputError);
    // A table's every field is checked: an unknown kind was read as "seat", a negative duration
    // or a joint index past 2^32 was taken as it came, an empty table deadlocked every run.
    const std::string table = "{\"format\": \"holon-roombots-clouds-1\", \"couplings\": {";
    const std::string cloud = "\"" + std::string(49, '0') + "\"";
    auto tableWith = [&](const std::string& par) {
        const std::string path = (std::filesystem::temp_directory_path() / "holon_clouds_test.json").string();
        std::ofstream(path) << table << "\"PAR\": " << par << ", \"PER\": [[0, 1, \"seat\", 1, " << cloud << "]], \"SRS\": [[0, 1, \"seat\", 1, " << cloud
                            << "]], \"SRZ\": [[0, 1, \"seat\", 1, " << cloud << "]]}}";
        return path;
    };
    CHECK_NOTHROW(CloudTable::load(tableWith("[[0, 1, \"step\", 2.5, " + cloud + "]]")));
    CHECK_THROWS_WITH_AS(CloudTable::load(tableWith("[[0, 1, \"bogus\", 2.5, " + cloud + "]]")), doctest::Contains("transition kind 'bogus'"), holon::InputError);
    CHECK_THROWS_WITH_AS(CloudTable::load(tableWith("[[0, 1, \"step\", -1, " + cloud + "]]")), doctest::Contains("0 or more"), holon::InputError);
    CHECK_THROWS_WITH_AS(CloudTable::load(tableWith("[[0, 4294967297, \"step\", 1, " + cloud + "]]")), doctest::Contains("out of range"), holon::InputError);
    CHECK_THROWS_WITH_AS(CloudTable::load(tableWith("[[0, 1.5, \"step\", 1, " + cloud + "]]")), doctest::Contains("whole joint settings"), holon::InputError);
    CHECK_THROWS_WITH_AS(CloudTable::load(tableWith("[[0, 1, \"step\", 1, \"" + std::string(49, 'g') + "\"]]")), doctest::Contains("malformed cloud"), holon::InputError);
    CHECK_THROWS_WITH_AS(CloudTable::load(tableWith("[]")), doctest::Contains("no transitions in the PAR table"), holon::InputError);
    // Read like every other JSON input: a key given twice was read as its last value, and a NUL
    // ended the text.
    CHECK_THROWS_WITH_AS(CloudTable::load(tableWith("[], \"PAR\": [[0, 1, \"step\", 2.5, " + cloud + "]]")), doctest::Contains("appears twice"), holon::InputError);
    CHECK_THROWS_WITH_AS(CloudTable::load(tableWith(std::string("[[0, 1, \"step\", 2.5, ") + cloud + "]]" + std::string(1, '\0'))), doctest::Contains("NUL"), holon::InputError);
}

TEST_CASE("the automatic seeding order is a permutation of the seeds in which each can be filled in turn") {
    const CloudTable& table = shippedTable();
    const Setting given = loadScenario("cube", 1, 1).front();
    Setting automatic = given;
    automatic.recipe = automaticRecipe(table, Coupling::SRZ, given);
    CHECK(automatic.recipe.name == "auto");
    REQUIRE(automatic.recipe.seeds.size() == given.recipe.seeds.size());
    std::set<std::array<Cell, 4>> a, b;
    for (std::size_t k = 0; k < given.recipe.seeds.size(); ++k) {
        a.insert(automatic.recipe.seeds[k].cells), b.insert(given.recipe.seeds[k].cells);
        CHECK(automatic.recipe.seeds[k].group == static_cast<int>(k));
    }
    CHECK(a == b);
    const AssemblyResult r = assemble(table, Coupling::SRZ, Strategy::Reserve, automatic);
    CHECK(r.completed);
    CHECK(r.collisions == 0);
}

TEST_CASE("a bare voxel model is split into metamodules standing on the floor, or refused") {
    std::vector<Cell> chair;
    for (const Setting& s : loadScenario("chair", 1, 1))
        for (const Seed& seed : s.recipe.seeds) chair.insert(chair.end(), seed.cells.begin(), seed.cells.end());
    const std::vector<Seed> seeds = seedsFromVoxels(chair, "chair");
    REQUIRE(seeds.size() == 6);
    std::set<Cell> covered;
    for (const Seed& s : seeds) {
        CHECK(s.cells[0].z == 0);
        for (int k = 0; k < 4; ++k) {
            CHECK(covered.insert(s.cells[k]).second);
            if (k > 0) {
                const Cell d = s.cells[k] - s.cells[k - 1];
                CHECK(std::abs(d.x) + std::abs(d.y) + std::abs(d.z) == 1);
            }
        }
    }
    CHECK(covered == std::set<Cell>(chair.begin(), chair.end()));
    // A floating slab has no chain standing on the floor; five voxels cannot be metamodules.
    CHECK_THROWS_WITH_AS(seedsFromVoxels({{0, 0, 1}, {1, 0, 1}, {0, 1, 1}, {1, 1, 1}}, "slab"), doctest::Contains("cannot split the 4 voxels"), holon::InputError);
    CHECK_THROWS_WITH_AS(seedsFromVoxels({{0, 0, 0}, {0, 0, 1}, {0, 0, 2}, {0, 0, 3}, {1, 0, 0}}, "five"), doctest::Contains("multiple of 4"), holon::InputError);
}

TEST_CASE("a voxel model no split can cover is refused at once, and the search stops at the job's deadline or signal") {
    // An 8 x 8 slab without four cells of one colour: the search ran for minutes and ignored both
    // --timeout and SIGTERM. A chain covers two cells of each colour, so this is refused at once.
    std::vector<Cell> holes;
    for (int x = 0; x < 8; ++x)
        for (int y = 0; y < 8; ++y)
            if (!(x == y && (x == 1 || x == 3 || x == 4 || x == 6))) holes.push_back({x, y, 0});
    REQUIRE(holes.size() == 60);
    CHECK_THROWS_WITH_AS(seedsFromVoxels(holes, "holes"), doctest::Contains("28 of one colour and 32 of the other"), holon::InputError);
    // A 20 x 20 slab takes a hundred search steps: a deadline already past stops the first one, and
    // a caught signal too.
    std::vector<Cell> slab;
    for (int x = 0; x < 20; ++x)
        for (int y = 0; y < 20; ++y) slab.push_back({x, y, 0});
    CHECK(seedsFromVoxels(slab, "slab").size() == 100);
    const holon::Budget past(1e-9);
    while (!past.expired()) {
    }
    CHECK_THROWS_WITH_AS(seedsFromVoxels(slab, "slab", past), doctest::Contains("reached while splitting the voxels"), holon::LimitError);
    volatile std::sig_atomic_t caught = SIGTERM;
    CHECK_THROWS_AS(seedsFromVoxels(slab, "slab", holon::Budget::stopFlag(&caught)), holon::Interrupted);
}
