// The checks of holon check on the library and on deliberately broken systems: holonomy (pixel
// and intermediate holonomic, the hex pivot not, seed 000 Fig. 2; general_n holonomic modulo
// resource moves), the planner's safety, termination and progress, and the counterexamples the
// broken variants must produce. Every trace replays through the reference interpreter.

#include "CheckSupport.h"
#include "checker/Draw.h"
#include "checker/Holonomy.h"
#include "checker/Obligations.h"
#include "rules/TextFile.h"

#include <regex>

using namespace holon;
using checker::Verdict;

TEST_CASE("pixel and intermediate are holonomic, the hex pivot is not (seed 000 Fig. 2)") {
    for (const char* spec : {"square:3x3", "hex:r1", "cubic:2x2x2"}) {
        CAPTURE(spec);
        CHECK(test::checkAll(rules::librarySystem("pixel"), spec).property("holonomy").verdict == Verdict::Holds);
        CHECK(test::checkAll(rules::librarySystem("intermediate"), spec).property("holonomy").verdict == Verdict::Holds);
    }
    auto pivot = test::checkAll(rules::librarySystem("hex_pivot"), "hex:r2");
    const auto& h = pivot.property("holonomy");
    REQUIRE(h.verdict == Verdict::Violated);
    CHECK(h.witness["distance"].get<int>() >= 4);  // Fig. 2 needs four pivots; hex:r2 holds worse
    REQUIRE(h.trace);
    // The witness pair is one module move apart.
    const auto& first = h.trace->steps.front().cells;
    const auto& last = h.trace->steps.back().cells;
    int differ = 0;
    for (std::size_t i = 0; i < first.size(); ++i) differ += first[i] != last[i];
    CHECK(differ == 2);
    CHECK(static_cast<int>(h.trace->steps.size()) - 1 == h.witness["distance"].get<int>());
    pivot.replayAll();
    CHECK(checker::drawTraceSvg(*h.trace, *pivot.kept.engine, "pivot").find("<polygon") != std::string::npos);
}

TEST_CASE("general_n and general-lock_n are holonomic modulo resource moves") {
    for (const char* stem : {"general1", "general2", "general3"}) {
        CAPTURE(stem);
        CHECK(test::checkAll(rules::librarySystem(stem), "square:3x2").property("holonomy").verdict == Verdict::Holds);
    }
    // Without transfers, general1 loses the reduction to pixel: a creator cannot reach the cell
    // where a metamodule should appear.
    auto noTransfer = test::parse("system g\nstates D | C\nmass D = 1, C = 2\nrule create / destroy: C _ <=> D D\nconstraint connected\nconstraint count(#) >= 1\nholonomic by occupancy\n");
    auto c = test::checkAll(noTransfer, "square:3x2");
    CHECK(c.property("holonomy").verdict == Verdict::Violated);
    c.replayAll();
}

TEST_CASE("the U/P/F planner keeps its spanning tree, terminates and progresses (seed 000 §IV-C)") {
    auto c = test::checkFrom(rules::librarySystem("planner_intermediate"), "square:4x3", "UFU.\nUUU.\nUUU.", ".###\n.###\n.###");
    CHECK(c.report.stats.states > 1000);
    for (const char* p : {"safety", "termination", "progress", "deadlock"}) CHECK(c.property(p).verdict == Verdict::Holds);
}

TEST_CASE("deletion without its guard breaks the tree: a shortest counterexample") {
    auto c = test::checkFrom(test::brokenSystem("planner_no_guard"), "square:4x3", "UFU.\nUUU.\nUUU.", ".###\n.###\n.###");
    const auto& safety = c.property("safety");
    REQUIRE(safety.verdict == Verdict::Violated);
    CHECK(safety.trace->steps.size() == 4);  // path_create, path_propagate, delete
    c.replayAll();
    CHECK(checker::drawTraceAscii(*safety.trace, *c.kept.engine).find("delete") != std::string::npos);
}

TEST_CASE("a create that does not conserve mass is caught on its first use") {
    auto c = test::checkAll(test::brokenSystem("general1_leaky"), "square:3x1");
    const auto& m = c.property("mass_conservation");
    REQUIRE(m.verdict == Verdict::Violated);
    CHECK(m.witness["rule"] == "create");
    c.replayAll();
    CHECK(test::checkAll(rules::librarySystem("general2"), "square:3x2").property("mass_conservation").verdict == Verdict::Holds);
}

TEST_CASE("livelock: transfers cycle without decreasing the ranking") {
    auto c = test::checkAll(test::brokenSystem("transfer_livelock"), "square:3x1");
    const auto& r = c.property("creators");
    REQUIRE(r.verdict == Verdict::Violated);
    CHECK(r.witness["livelock"] == true);
    REQUIRE(r.trace->loop.has_value());
    // The lasso closes: the last state steps back to the loop state by one enabled instance.
    const auto& last = r.trace->steps.back().cells;
    const auto& loopState = r.trace->steps[*r.trace->loop].cells;
    rules::Configuration config = c.world.in->empty();
    config.cells = last;
    bool closes = false;
    for (const auto& i : c.world.in->enabled(config)) closes |= c.world.in->successor(config, i)->cells == loopState;
    CHECK(closes);
    c.replayAll();
}

TEST_CASE("deadlocks are found and drawn") {
    auto stuck = test::parse("system stuck\nstates A | B\nrule spend: A _ => B B\nconstraint connected\ngoal count(A) == 2\n");
    auto c = test::checkFrom(stuck, "square:2x1", "A.", "");
    const auto& d = c.property("deadlock");
    REQUIRE(d.verdict == Verdict::Violated);
    CHECK(d.trace->steps.size() == 2);
    c.replayAll();
}

TEST_CASE("deadlock is relative to a goal, and a state stuck at the region's edge is no deadlock") {
    // Without a goal a state with no enabled rule is final, not a deadlock (a lone D of general1).
    auto g1 = test::checkAll(rules::librarySystem("general1"), "square:3x3");
    for (const auto& p : g1.report.properties) CHECK(p.name != "deadlock");
    CHECK(g1.report.overall() == Verdict::Holds);
    // Growth that fills the region is stuck only because the region ends: an edge effect.
    auto grow = test::parse("system grow\nstates M\nrule grow: M _ => M M\nconstraint connected\ngoal count(M) == 100\n");
    auto c = test::checkFrom(grow, "square:2x2", "M.\n..", "");
    const auto& d = c.property("deadlock");
    CHECK(d.verdict == Verdict::Holds);
    CHECK(d.witness["edge_effects"] == 1);
    CHECK(d.summary.find("region's edge") != std::string::npos);
    // The same growth with a move that only works inside: still an edge effect, not a flaw.
    auto stuck = test::parse("system stuck\nstates A | B\nrule grow: A _ => A B\nconstraint connected\ngoal count(B) == 9\n");
    auto s = test::checkFrom(stuck, "square:2x1", "A.", "");
    CHECK(s.property("deadlock").verdict == Verdict::Holds);
    CHECK(s.property("deadlock").witness["edge_effects"] == 1);
}

TEST_CASE("a rule with a far position leaves stuck states unclassified at once, instead of growing the region for minutes") {
    // Reach 2 * 1000: the grown region would hold millions of cells, and growing it outlasted
    // --timeout, --memory and SIGTERM.
    auto far = test::parse("system far\nlattice square2d\nstates M\nrule a: M@(0,0) _@(1000,1000) => _ @0\ngoal no(M)\nprogress\n");
    auto c = test::checkFrom(far, "square:3x1", "M..", "");
    const auto& d = c.property("deadlock");
    CHECK(d.verdict == Verdict::Unknown);
    CHECK(d.summary.find("the rules reach 4000 lattice steps") != std::string::npos);
    // A near position is still classified: the lone M is stuck only at the region's edge.
    auto near = test::parse("system near\nlattice square2d\nstates M\nrule a: M@(0,0) _@(3,3) => _ @0\ngoal no(M)\nprogress\n");
    auto n = test::checkFrom(near, "square:3x1", "M..", "");
    CHECK(n.property("deadlock").verdict == Verdict::Holds);
    CHECK(n.property("deadlock").witness["edge_effects"] == 1);
}

TEST_CASE("the budget bounds the holonomy check too, not only the exploration") {
    auto c = test::checkAll(rules::librarySystem("pixel"), "square:3x3");
    const auto& ex = *c.kept.explorer;
    const rules::Property& p = *c.world.system.property("holonomy");
    CHECK(checker::checkHolonomy(ex, checker::components(ex), p, Budget()).verdict == Verdict::Holds);
    const Budget spent(1e-9);
    const auto r = checker::checkHolonomy(ex, checker::components(ex), p, spent);
    CHECK(r.verdict == Verdict::Unknown);
    CHECK(r.summary.find("stopped by the timeout") != std::string::npos);
}

TEST_CASE("termination fails exactly when the reachable graph has a cycle, whatever steps it mixes") {
    // shrink undoes grow: grow increases the ranking, shrink decreases it; the cycle mixes both.
    auto undo = test::parse("system undo\nstates A\nrule grow: A _ => A A\nrule shrink: A A => A _\nconstraint connected\nranking size: count(A)\n");
    auto c = test::checkFrom(undo, "square:3x2", "A..\n...", "");
    const auto& r = c.property("size");
    REQUIRE(r.verdict == Verdict::Violated);
    CHECK(r.witness["cycle"] == true);
    REQUIRE(r.trace->loop.has_value());
    CHECK(r.summary.find("not terminating") != std::string::npos);
    c.replayAll();
    // A ranking that some step does not decrease, on an acyclic graph: violated, but runs terminate.
    auto acyclic = test::parse("system acyclic\nstates A | B | C\nrule ab: A => B\nrule bc: B => C\nranking r: count(A)\n");
    auto a = test::checkFrom(acyclic, "square:1x1", "A", "");
    CHECK(a.property("r").verdict == Verdict::Violated);
    CHECK(a.property("r").witness["cycle"] == false);
    CHECK(a.property("r").summary.find("no cycle") != std::string::npos);
}

TEST_CASE("a ranking judges a step by every rule that makes it, in either order of declaration") {
    // slide is excepted, move is covered, and they make the same steps: the graph keeps one edge
    // per step, and judging it by the first rule alone said "holds" when slide came first (audit 9).
    const std::string slide = "rule slide: A _ => _ A\n", move = "rule move: A _ => _ A if count nbr # >= 0\n";
    for (const std::string& rules : {slide + move, move + slide}) {
        CAPTURE(rules);
        auto c = test::checkFrom(test::parse("system paredge\nstates A\n" + rules + "ranking k: count(A) except slide\n"), "square:2x1", "A.", "");
        const auto& r = c.property("k");
        REQUIRE(r.verdict == Verdict::Violated);
        CHECK(r.witness["livelock"] == true);
        REQUIRE(r.trace->steps.size() == 2);
        CHECK(c.kept.engine->model().rules()[c.kept.engine->instances()[r.trace->steps[1].placed].rule].name == "move");
        c.replayAll();
    }
    // A covered rule that changes nothing, beside an excepted one that can make the same (empty) step.
    auto idle = test::parse("system idle\nstates A\nrule other: _ => *\nrule idle: A => A\nranking k: count(A) except other\n");
    CHECK(test::checkFrom(idle, "square:2x1", "A.", "").property("k").verdict == Verdict::Violated);
}

TEST_CASE("a rule that repeats another is still a rule: its steps are judged as its own (audit 10)") {
    // t has every instance of s, so the model keeps one shape for both; excepting s must not
    // except t, in check, in the bounded proof and in the proof for every size.
    for (const char* t : {"rule t: A _ => _ A\n", "rule t: _ A => A _\n"}) {
        CAPTURE(t);
        const rules::System dup = test::parse(std::string("system dup\nstates A\nrule s: A _ => _ A\n") + t + "ranking k: count(A) except s\n");
        auto c = test::checkFrom(dup, "square:2x1", "A.", "");
        const auto& r = c.property("k");
        REQUIRE(r.verdict == Verdict::Violated);
        CHECK(r.summary.find("through a step of rule 't'") != std::string::npos);
        CHECK(checker::drawTraceAscii(*r.trace, *c.kept.engine).find("s (also t) at") != std::string::npos);
        c.replayAll();
        const test::World w(dup, "square:2x1");
        checker::VerifyOptions o;
        o.timeoutSeconds = 60;
        CHECK(checker::verify(*w.model, w.region, o).overall() == Verdict::Violated);
    }
}

TEST_CASE("a livelock is a cycle of steps that keep the ranking, through a covered rule's step (audit 10)") {
    struct Case {
        const char *text, *start, *summary;
        bool cycle, livelock;
    };
    for (const Case& k : {
             // g is excepted and keeps count(#), and f keeps it too: a livelock.
             Case{"rule f: A => B\nrule g: B => A\nranking k: count(#) except g\n", "A", "never decreases", true, true},
             // mk decreases count(_) on the cycle: it is undone by rm, not a livelock.
             Case{"rule mk: _ => A\nrule rm: A => _\nranking k: count(_) except mk\n", ".", "undoes what it decreases", true, false},
             // Every rule excepted: the excepted steps break it, but a cycle of them alone is the allocator's.
             Case{"rule f: A => B\nrule g: B => A\nranking k: count(A) except f, g\n", "A", "no cycle", false, false},
         }) {
        CAPTURE(k.text);
        auto c = test::checkFrom(test::parse(std::string("system ll\nstates A | B\n") + k.text), "square:1x1", k.start, "");
        const auto& r = c.property("k");
        REQUIRE(r.verdict == Verdict::Violated);
        CHECK(r.summary.find(k.summary) != std::string::npos);
        CHECK(r.witness["cycle"] == k.cycle);
        CHECK(r.witness["livelock"] == k.livelock);
        c.replayAll();
    }
}

TEST_CASE("a trap without a deadlock: the goal is unreachable from a cycle") {
    // From A the goal G is one step away; from B and C only the cycle B <-> C remains.
    auto trap = test::parse("system trap\nstates A | B | C | G\nrule a2g: A => G\nrule a2b: A => B\nrule b2c: B => C\nrule c2b: C => B\ngoal count(G) == 1\n");
    auto c = test::checkFrom(trap, "square:1x1", "A", "");
    CHECK(c.property("deadlock").verdict == Verdict::Holds);
    const auto& g = c.property("goal_reachable");
    REQUIRE(g.verdict == Verdict::Violated);
    CHECK(g.witness["trapped"] == 2);
    CHECK(g.trace->steps.size() == 2);
    c.replayAll();
    // With a way out of the cycle the goal is reachable from everywhere.
    auto exit = test::parse("system exit\nstates A | B | C | G\nrule a2g: A => G\nrule a2b: A => B\nrule b2c: B => C\nrule c2b: C => B\nrule c2a: C => A\ngoal count(G) == 1\n");
    CHECK(test::checkFrom(exit, "square:1x1", "A", "").property("goal_reachable").verdict == Verdict::Holds);
}

TEST_CASE("general-lock2's planner: a deadlock from two creations started at once, and the goal out of reach") {
    test::Checked c{test::World::library("planner_general_lock2", "square:3x2"), {}, {}};
    checker::CheckOptions o;
    auto start = c.world.in->empty();
    c.world.set(start, 0, 0, "C&F"), c.world.set(start, 1, 0, "C&U"), c.world.set(start, 2, 0, "D&U");
    c.world.mark(start, "target", "##.\n##.");
    o.initial.push_back(start);
    o.properties = {"deadlock", "goal_reachable"};
    c.report = checker::check(*c.world.model, c.world.region, o, &c.kept);
    CHECK(c.property("deadlock").verdict == Verdict::Violated);
    CHECK(c.property("goal_reachable").verdict == Verdict::Violated);
    c.replayAll();
    // The same problem under planner_general2 (no locks): the goal stays reachable.
    test::Checked free{test::World::library("planner_general2", "square:3x2"), {}, {}};
    auto start2 = free.world.in->empty();
    free.world.set(start2, 0, 0, "C&F"), free.world.set(start2, 1, 0, "C&U"), free.world.set(start2, 2, 0, "D&U");
    free.world.mark(start2, "target", "##.\n##.");
    o.initial = {start2};
    free.report = checker::check(*free.world.model, free.world.region, o, &free.kept);
    CHECK(free.property("goal_reachable").verdict == Verdict::Holds);
}

TEST_CASE("an unknown property is bad input") {
    test::World w = test::World::library("pixel", "square:2x2");
    checker::CheckOptions o;
    o.all = true;
    o.properties = {"liveness"};
    CHECK_THROWS_WITH_AS(checker::check(*w.model, w.region, o), doctest::Contains("has no property 'liveness'"), holon::InputError);
}

TEST_CASE("general-lock_2: transfers can cycle with a creation half done, and a fair scheduler escapes") {
    const test::Checked c = test::checkLockedTransfers(test::brokenSystem("general_lock2_ranked"));
    const auto& r = c.property("partial");
    REQUIRE(r.verdict == Verdict::Violated);
    CHECK(r.witness["livelock"] == true);
    CHECK(r.witness["escapable"] == true);
    CHECK(c.report.properties.size() == 1);  // no goal, so no deadlock to check
    c.replayAll();
}

// Seed 003's hole moves as rules (rules/library/hex_holes.holon), explored with every interleaving.
namespace {
const char* kThreeHoles =
    "      M M M M M M M\n     M M M M M M M M\n    M M M M M M M M M\n   M M M M M H H M M M\n  M M M M M H C H M M M\n"
    " M M H H M M H H M M M M\nM M H C H M M M M M M M M\n M M H H M M M M M M M M\n  M M M M M M M H H M M\n"
    "   M M M M M M H C H M\n    M M M M M M H H M\n     M M M M M M M M\n      M M M M M M M\n";
const char* kTwoHoles =
    "     M M M M M M\n    M M M M M M M\n   M M M M M M M M\n  M M M M M H H M M\n M M H H M H C H M M\n"
    "M M H C H M H H M M M\n M M H H M M M M M M\n  M M M M M M M M M\n   M M M M M M M M\n    M M M M M M M\n     M M M M M M\n";
const char* kNeck =
    "    . . . . .\n   . . . . . .\n  . M M M M M M\n . M H H M M M .\n. M H C H M M . .\n . M H H M M . .\n"
    "  . M M M M . .\n   . . . . . .\n    . . . . .\n";
}  // namespace

TEST_CASE("hex holes: moves and deletions keep every hole whole and the module count (seed 003 §IV-D)") {
    auto c = test::checkFrom(rules::librarySystem("hex_holes"), "hex:r6", kThreeHoles, "");
    CHECK(c.report.stats.states > 100000);
    CHECK(c.property("holes").verdict == Verdict::Holds);
    CHECK(c.property("mass_conservation").verdict == Verdict::Holds);
    // A move into another hole's shepherds would break it: the rule's complete new shepherd group
    // rules that out, so with the guard removed the checker must find the break.
    std::string text = rules::readTextFile(rules::libraryDir() + "/hex_holes.holon");
    const auto at = text.find(" M@(2,0) M@(2,-1)");
    REQUIRE(at != std::string::npos);
    text.replace(at, 8, " *@(2,0)");  // the move no longer needs its new corner shepherd
    auto loose = test::checkFrom(test::parse(text), "hex:r5", kTwoHoles, "");
    CHECK(loose.property("holes").verdict == Verdict::Violated);
    loose.replayAll();
}

TEST_CASE("hex holes: deletion as the paper words it breaks a neighbouring hole, and pinches off modules (Fig. 6)") {
    auto shared = test::checkFrom(test::brokenSystem("hex_delete_shared"), "hex:r5", kTwoHoles, "");
    const auto& holes = shared.property("holes");
    REQUIRE(holes.verdict == Verdict::Violated);
    CHECK(holes.trace->steps.size() == 4);   // two moves toward the surface, one deletion
    CHECK(holes.trace->marked.size() == 1);  // the neighbouring hole's cell that lost its shepherd
    CHECK(holes.trace->description.find("crossed cells show where") != std::string::npos);
    shared.replayAll();

    auto neck = test::checkFrom(rules::librarySystem("hex_holes"), "hex:r4", kNeck, "");
    const auto& pinch = neck.property("one_mass");
    REQUIRE(pinch.verdict == Verdict::Violated);
    CHECK(pinch.trace->steps.size() == 3);  // the hole moves under the neck, then is deleted
    CHECK(neck.property("holes").verdict == Verdict::Holds);
    neck.replayAll();
    CHECK(pinch.trace->marked.size() == 3);  // the three modules of the knob, crossed in the picture
    CHECK(checker::drawTraceSvg(*pinch.trace, *neck.kept.engine, "pinch-off").find("<polygon") != std::string::npos);
}

TEST_CASE("hex delete: every choice of seven shepherds keeps the holes whole, and without the shared-shepherd guard it does not") {
    const std::string start = rules::readTextFile(std::string(HOLON_TEST_DIR) + "/../examples/hex/checker/surface_holes.txt");
    auto c = test::checkFrom(rules::librarySystem("hex_delete"), "hex:r5", start, "");
    CHECK(c.report.stats.states > 1000);  // both holes deleted, in many ways each
    CHECK(c.property("holes").verdict == Verdict::Holds);
    CHECK(c.property("mass_conservation").verdict == Verdict::Holds);
    // Without "count nbr@k H == n" a shepherd shared with the other hole may leave.
    const std::string text = rules::readTextFile(rules::libraryDir() + "/hex_delete.holon");
    const std::string loose = std::regex_replace(text, std::regex(" and\n    count nbr@\\d+ H == \\d( and count nbr@\\d+ H == \\d)*"), "");
    REQUIRE(loose != text);
    auto broken = test::checkFrom(test::parse(loose), "hex:r5", start, "");
    REQUIRE(broken.property("holes").verdict == Verdict::Violated);
    broken.replayAll();
}

TEST_CASE("hex growth (seed 003 §IV-E): one counting rule makes whole holes and keeps the module count, and without its guards it does not") {
    const char* blob =
        "    . . . . .\n   . . . . . .\n  . . . . . M .\n . . . . M M M .\n. . . . M M M M .\n . . M M M M M .\n"
        "  . . M M M M .\n   . M . . M .\n    . . . . .\n";
    const char* everywhere =
        "    x x x x x\n   x x x x x x\n  x x x x x x x\n x x x x x x x x\nx x x x x x x x x\n x x x x x x x x\n"
        "  x x x x x x x\n   x x x x x x\n    x x x x x\n";
    auto grown = test::checkFrom(rules::librarySystem("hex_growth"), "hex:r4", blob, everywhere, {}, {"holes", "mass_conservation"});
    CHECK(grown.report.stats.states == 4);  // three disks hold exactly 12 modules; each creation ends the others
    CHECK(grown.property("holes").verdict == Verdict::Holds);
    CHECK(grown.property("mass_conservation").verdict == Verdict::Holds);
    const std::string text = rules::readTextFile(rules::libraryDir() + "/hex_growth.holon");
    auto without = [&](const std::string& cut, const std::string& instead) {
        std::string t = text;
        const auto at = t.find(cut);
        REQUIRE(at != std::string::npos);
        return test::parse(t.replace(at, cut.size(), instead));
    };
    // Without "no pattern H | C" a creation overlaps a hole next to it.
    auto overlap = test::checkFrom(without(" and no pattern H | C", ""), "hex:r4", kNeck, everywhere, {}, {"holes"});
    REQUIRE(overlap.property("holes").verdict == Verdict::Violated);
    overlap.replayAll();
    // Counting 11 modules as enough makes a module out of nothing.
    auto eleven = test::checkFrom(without("count pattern M == 12", "count pattern M >= 11"), "hex:r4", blob, everywhere, {}, {"mass_conservation"});
    CHECK(eleven.property("mass_conservation").verdict == Verdict::Violated);
}

TEST_CASE("hex migration (holon's finishing move): a wall outside the target drains without cutting the mass, and without the constraint it cuts") {
    // A wall one module thick stands outside the target (the lower two rows); `constraint
    // connected` filters the moves that would cut the mass.
    const char* wall = "   . . . .\n  . . M . .\n . . M . . .\n. . M M . . .\n . M M . . .\n  M M M . .\n   M M . .\n";
    const char* lower = "   . . . .\n  . . . . .\n . . . . . .\n. . . . . . .\n x x x x x x\n  x x x x x\n   x x x x\n";
    const std::string file = rules::readTextFile(rules::libraryDir() + "/hex_migrate.holon");
    auto m = test::checkFrom(rules::librarySystem("hex_migrate"), "hex:r3", wall, lower);
    CHECK(m.property("holes").verdict == Verdict::Holds);
    CHECK(m.property("one_mass").verdict == Verdict::Holds);
    CHECK(m.property("mass_conservation").verdict == Verdict::Holds);
    // Migration alone: whatever has moved, every module can still end inside the target. (advance
    // moves voids either way; `holon hex` moves them only toward the surface, a non-local choice.)
    std::string text = file;
    text.erase(text.find("rule advance:"), text.find('\n', text.find("rule advance:")) + 1 - text.find("rule advance:"));
    CHECK(test::checkFrom(test::parse(text), "hex:r3", wall, lower).property("goal_reachable").verdict == Verdict::Holds);
    text = file;
    const std::string constraint = "constraint connected\n";
    const auto at = text.find(constraint);
    REQUIRE(at != std::string::npos);
    text.erase(at, constraint.size());
    auto cut = test::checkFrom(test::parse(text), "hex:r3", wall, lower, {}, {"one_mass"});
    const auto& split = cut.property("one_mass");
    REQUIRE(split.verdict == Verdict::Violated);
    CHECK(split.trace->steps.size() == 2);  // the first move already cuts
    cut.replayAll();
}

TEST_CASE("hex migration's advance: a channel one cell wide fills only if settled modules move deeper") {
    // A slot one cell wide runs down into a block of target modules; four modules wait above it.
    const char* start = "   M M M M\n  M . M M M\n M M . M M M\nM M M . M M M\n M M M . M M\n  M M M M M\n   M M M M\n";
    const char* below = "   . . . .\n  x x x x x\n x x x x x x\nx x x x x x x\n x x x x x x\n  x x x x x\n   x x x x\n";
    auto goalStates = [&](const rules::System& system) {
        auto c = test::checkFrom(system, "hex:r3", start, below);
        CHECK(c.property("holes").verdict == Verdict::Holds);
        CHECK(c.property("one_mass").verdict == Verdict::Holds);
        std::int64_t goals = 0;
        const rules::Expr& goal = *c.kept.engine->model().system().goal;
        for (checker::StateId s : c.kept.explorer->ids()) goals += c.kept.engine->holds(goal, c.kept.explorer->cells(s).data());
        return goals;
    };
    const rules::System withAdvance = rules::librarySystem("hex_migrate");
    CHECK(goalStates(withAdvance) > 0);
    // Without it the first module to settle plugs the slot's mouth.
    std::string text = rules::readTextFile(rules::libraryDir() + "/hex_migrate.holon");
    const auto at = text.find("rule advance:");
    REQUIRE(at != std::string::npos);
    text.erase(at, text.find('\n', at) + 1 - at);
    CHECK(goalStates(test::parse(text)) == 0);
}

TEST_CASE("hex collapse (seed 003 §IV-F): every collapse keeps the mass connected and the holes whole, and without the arc test it does not") {
    const char* blob = "   . . . .\n  . . . . .\n . . . M M .\nM M M M . . .\n . . M . . .\n  . M . . .\n   . . . .\n";
    auto c = test::checkFrom(rules::librarySystem("hex_collapse"), "hex:r3", blob, "");
    CHECK(c.report.stats.states > 100000);  // every gravity, every order
    CHECK(c.property("one_mass").verdict == Verdict::Holds);
    CHECK(c.property("mass_conservation").verdict == Verdict::Holds);
    const char* holeAndBlob =
        "    . . . . .\n   . . . . . .\n  . . M M M . .\n . . M H H M M .\n. . M H C H M M .\n . . M H H M M .\n"
        "  . M M M M . .\n   . . . . . .\n    . . . . .\n";
    auto h = test::checkFrom(rules::librarySystem("hex_collapse"), "hex:r4", holeAndBlob, "");
    CHECK(h.property("holes").verdict == Verdict::Holds);
    CHECK(h.property("one_mass").verdict == Verdict::Holds);
    // The arc test is what keeps the mass in one piece: drop it from one rule and a collapse cuts.
    std::string text = rules::readTextFile(rules::libraryDir() + "/hex_collapse.holon");
    const std::string arc = " and connected nbr # | @2";
    const auto at = text.find(arc);
    REQUIRE(at != std::string::npos);
    text.erase(at, arc.size());
    // Without the arc test the pieces wander apart and the graph is huge; asked only about
    // invariants, the checker stops once each has its shortest violation.
    auto cut = test::checkFrom(test::parse(text), "hex:r3", blob, "", {}, {"one_mass"});
    CHECK(cut.report.stats.stopped == StopReason::Decided);
    const auto& split = cut.property("one_mass");
    REQUIRE(split.verdict == Verdict::Violated);
    CHECK_FALSE(split.trace->marked.empty());  // the modules cut off
    cut.replayAll();
}
