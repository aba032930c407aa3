// holon diff against transition sets computed independently: the reference interpreter's BFS from
// the same start in both designs, configurations and transitions written by state names, and the
// set differences counted. A design compared with itself has no difference.

#include "TestSupport.h"
#include "checker/Diff.h"
#include "rules/Engine.h"
#include "rules/TextFile.h"

#include <set>

using namespace holon;
using test::World;

namespace {

using Named = std::vector<std::string>;

struct ReferenceGraph {
    std::set<Named> states;
    std::set<std::pair<Named, Named>> transitions;
};

Named named(const World& w, const rules::Configuration& c) {
    Named n;
    for (rules::CellValue v : c.cells) n.push_back(w.model->alphabet().name(v));
    return n;
}

ReferenceGraph referenceGraph(const World& w, const rules::Configuration& start) {
    ReferenceGraph g;
    std::vector<rules::Configuration> todo{start};
    g.states.insert(named(w, start));
    while (!todo.empty()) {
        const rules::Configuration c = todo.back();
        todo.pop_back();
        for (const auto& i : w.in->enabled(c)) {
            const auto s = *w.in->successor(c, i);
            g.transitions.insert({named(w, c), named(w, s)});
            if (g.states.insert(named(w, s)).second) todo.push_back(s);
        }
    }
    return g;
}

template <class T>
std::uint64_t onlyIn(const std::set<T>& a, const std::set<T>& b) {
    std::uint64_t n = 0;
    for (const T& x : a) n += !b.count(x);
    return n;
}

struct Design {
    World world;
    std::unique_ptr<rules::Engine> engine;
    std::unique_ptr<checker::Explorer> explorer;
    Design(rules::System system, const std::string& spec, const rules::Configuration& start) : world(std::move(system), spec) {
        engine = std::make_unique<rules::Engine>(*world.model, world.region, start.inputs);
        explorer = std::make_unique<checker::Explorer>(*engine, checker::Explorer::Options());
        explorer->addInitial(start.cells.data());
        explorer->explore();
    }
};

/// planner_intermediate and a variant whose deletion ignores its guard, from one start on
/// square:4x2, with their graphs computed by the reference interpreter.
struct GuardedAndNot {
    World a = World::library("planner_intermediate", "square:4x2");
    World b{test::parse(rules::readTextFile(std::string(HOLON_TEST_DIR) + "/checker/broken/planner_no_guard.holon")), "square:4x2"};
    rules::Configuration startA = a.ascii("UFU.\nUUU.\n"), startB = b.ascii("UFU.\nUUU.\n");
    ReferenceGraph ga, gb;
    GuardedAndNot() {
        a.mark(startA, "target", ".###\n.###\n"), b.mark(startB, "target", ".###\n.###\n");
        ga = referenceGraph(a, startA), gb = referenceGraph(b, startB);
    }
};

}  // namespace

TEST_CASE("diff counts equal the set differences of independently computed transitions") {
    const GuardedAndNot g;
    const World &a = g.a, &b = g.b;
    const rules::Configuration &startA = g.startA, &startB = g.startB;
    const ReferenceGraph &ga = g.ga, &gb = g.gb;
    Design da(a.system, "square:4x2", startA), db(b.system, "square:4x2", startB);
    const auto compared = checker::compareDesigns({da.engine.get(), da.explorer.get()}, {db.engine.get(), db.explorer.get()}, Budget());
    REQUIRE(std::holds_alternative<checker::DesignDifference>(compared));
    const auto& d = std::get<checker::DesignDifference>(compared);
    CHECK(d.states[0] == ga.states.size());
    CHECK(d.states[1] == gb.states.size());
    CHECK(d.transitions[0] == ga.transitions.size());
    CHECK(d.transitions[1] == gb.transitions.size());
    CHECK(d.onlyStates[0] == onlyIn(ga.states, gb.states));
    CHECK(d.onlyStates[1] == onlyIn(gb.states, ga.states));
    CHECK(d.onlyTransitions[0] == onlyIn(ga.transitions, gb.transitions));
    CHECK(d.onlyTransitions[1] == onlyIn(gb.transitions, ga.transitions));
    CHECK(d.onlyTransitions[1] > 0);  // the unguarded deletion is a move the planner does not have
    CHECK_FALSE(d.same());
    REQUIRE(d.transitionWitness[1]);
    // The witness's last step is a transition of B that A lacks.
    const auto& w = *d.transitionWitness[1];
    const Named from = named(b, {w.steps[w.steps.size() - 2].cells, startB.inputs}), to = named(b, {w.steps.back().cells, startB.inputs});
    CHECK(gb.transitions.count({from, to}));
    CHECK_FALSE(ga.transitions.count({from, to}));
    std::string why;
    CHECK_MESSAGE(checker::replay(w, *db.engine, *b.in, &why), why);
}

TEST_CASE("a design compared with itself has no difference") {
    World a = World::library("pixel", "square:3x3");
    const auto start = a.ascii("M..\nMM.\n...\n");
    Design d1(a.system, "square:3x3", start), d2(a.system, "square:3x3", start);
    const auto compared = checker::compareDesigns({d1.engine.get(), d1.explorer.get()}, {d2.engine.get(), d2.explorer.get()}, Budget());
    REQUIRE(std::holds_alternative<checker::DesignDifference>(compared));
    const auto& d = std::get<checker::DesignDifference>(compared);
    CHECK(d.same());
    CHECK(d.transitions[0] == d.transitions[1]);
    CHECK(d.transitions[0] > 0);
    CHECK_FALSE(d.transitionWitness[0]);
}

TEST_CASE("the comparison reads the budget: a deadline that passes while it runs makes it undecided") {
    // The comparison once ran 50 s past --timeout 10 (pixel on square:5x5, every configuration).
    World a = World::library("pixel", "square:4x4");
    const auto start = a.ascii("M...\n....\n....\n....\n");
    Design d1(a.system, "square:4x4", start), d2(a.system, "square:4x4", start);
    REQUIRE(d1.explorer->stats().states > 4096);  // the comparison reads the clock every 4,096 states
    const auto stopped = checker::compareDesigns({d1.engine.get(), d1.explorer.get()}, {d2.engine.get(), d2.explorer.get()}, Budget(1e-9));
    REQUIRE(std::holds_alternative<StopReason>(stopped));
    CHECK(std::get<StopReason>(stopped) == StopReason::Timeout);
    const auto whole = checker::compareDesigns({d1.engine.get(), d1.explorer.get()}, {d2.engine.get(), d2.explorer.get()}, Budget(3600));
    REQUIRE(std::holds_alternative<checker::DesignDifference>(whole));
    CHECK(std::get<checker::DesignDifference>(whole).same());
}

TEST_CASE("a library caller diffs two designs without the CLI: checker::diff explores both and compares") {
    const GuardedAndNot g;
    const World &a = g.a, &b = g.b;
    const rules::Configuration &startA = g.startA, &startB = g.startB;
    const ReferenceGraph &ga = g.ga, &gb = g.gb;
    checker::DiffOptions options;
    options.initial[0] = {startA}, options.initial[1] = {startB};
    const checker::DiffReport report = checker::diff(*a.model, *b.model, a.region, options);
    CHECK(report.stopped() == -1);
    REQUIRE(report.difference);
    const checker::DesignDifference& d = *report.difference;
    CHECK(d.states[0] == ga.states.size());
    CHECK(d.states[1] == gb.states.size());
    CHECK(d.onlyTransitions[0] == onlyIn(ga.transitions, gb.transitions));
    CHECK(d.onlyTransitions[1] == onlyIn(gb.transitions, ga.transitions));
    REQUIRE(d.transitionWitness[1]);
    CHECK(report.witnessText(1).starts_with(b.system.name + " fires 'delete' after "));
    const nlohmann::json j = report.toJson();
    CHECK(j["in_b"]["only_transitions"] == d.onlyTransitions[1]);
    CHECK(j["in_b"]["witness"]["trace"]["states"].size() == d.transitionWitness[1]->steps.size());

    // A limit on either exploration leaves the comparison undecided, naming the design it stopped.
    options.limits.maxStates = 2;
    const checker::DiffReport stopped = checker::diff(*a.model, *b.model, a.region, options);
    CHECK(stopped.stopped() == 0);
    CHECK(stopped.explored[0].explorer->stats().stopped == StopReason::MaxStates);
    CHECK_FALSE(stopped.difference);
}
