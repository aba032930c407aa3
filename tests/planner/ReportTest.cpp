// What a plan leaves on disk: an interrupt stops the run at a round boundary and the files are
// committed whole (the CSV's last line complete, the summary marked interrupted); a run abandoned
// without finish() leaves no file behind; a file that cannot be written is reported, not lost.

#include "PlannerSupport.h"

#include "planner/Report.h"
#include "rules/ConfigIo.h"
#include "rules/Error.h"

#include "rules/TextFile.h"
#include <csignal>
#include <filesystem>

#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>

namespace holon::test {

namespace {
namespace fs = std::filesystem;
bool anyTemporary(const fs::path& dir) {
    for (const auto& e : fs::directory_iterator(dir))
        if (e.path().filename().string().find(".tmp-") != std::string::npos) return true;
    return false;
}
}  // namespace

TEST_CASE("an interrupt stops the run at the next round boundary") {
    PlannerSystem sys("planner_intermediate", 2);
    const planner::Problem p = planner::makeProblem(*sys.model, planner::parseShape("box:12x3"), planner::parseShape("box:3x12"), std::nullopt, 1);
    auto allocator = planner::makeAllocator("random", p, 1);
    volatile std::sig_atomic_t flag = 0;
    planner::RunOptions options;
    options.budget = Budget::stopFlag(&flag);
    planner::Execution ex(p, *allocator, options);
    planner::RunObserver observer;
    observer.roundEnd = [&](const planner::RunStats& stats) {
        if (stats.rounds == 3) flag = SIGINT;  // as the handler would, in the middle of the run
        return true;
    };
    const planner::RunStats stats = ex.run(observer);
    CHECK(stats.stopped == StopReason::Interrupted);
    CHECK(stats.rounds == 3);
    CHECK_FALSE(stats.complete);
}

TEST_CASE("an interrupted plan's files are whole and the summary says so, an abandoned one leaves none") {
    const fs::path dir = fs::temp_directory_path() / "holon_report_test";
    fs::remove_all(dir);
    fs::create_directories(dir);
    PlannerSystem sys("planner_intermediate", 2);
    const planner::Problem p = planner::makeProblem(*sys.model, planner::parseShape("box:12x3"), planner::parseShape("box:3x12"), std::nullopt, 1);
    const planner::ReportOptions ro{(dir / "out").string(), (dir / "plan.jsonl").string(), "--out", "--plan-out", false};
    {
        auto allocator = planner::makeAllocator("random", p, 1);
        planner::Execution ex(p, *allocator, {});
        planner::Report report(p, ex, ro);
        CHECK(fs::is_directory(dir / "out"));
        planner::RunObserver observer;
        observer.fired = [&](std::int64_t a, int s, const planner::BoxEngine::Value* old) { report.fired(a, s, old); };
        observer.roundEnd = [&](const planner::RunStats& stats) {
            report.roundEnd(stats);
            return stats.rounds < 2;  // abandoned: the report is destroyed without finish()
        };
        ex.run(observer);
    }
    CHECK_FALSE(fs::exists(dir / "plan.jsonl"));
    CHECK_FALSE(fs::exists(dir / "out" / "completion.csv"));
    CHECK_FALSE(anyTemporary(dir));
    CHECK_FALSE(anyTemporary(dir / "out"));

    auto allocator = planner::makeAllocator("random", p, 1);
    volatile std::sig_atomic_t flag = 0;
    planner::RunOptions options;
    options.budget = Budget::stopFlag(&flag);
    planner::Execution ex(p, *allocator, options);
    planner::Report report(p, ex, ro);
    planner::RunObserver observer;
    observer.fired = [&](std::int64_t a, int s, const planner::BoxEngine::Value* old) { report.fired(a, s, old); };
    observer.roundEnd = [&](const planner::RunStats& stats) {
        report.roundEnd(stats);
        if (stats.rounds == 4) flag = SIGTERM;
        return true;
    };
    const planner::RunStats stats = ex.run(observer);
    report.finish(stats, -1);
    CHECK(report.writeErrors().empty());
    const nlohmann::json summary = nlohmann::json::parse(rules::readTextFile((dir / "out" / "summary.json").string()));
    CHECK(summary["interrupted"] == true);
    CHECK(summary["stopped"] == "interrupted");
    CHECK(summary["rounds"] == 4);
    const std::string csv = rules::readTextFile((dir / "out" / "completion.csv").string());
    REQUIRE_FALSE(csv.empty());
    CHECK(csv.back() == '\n');
    CHECK(std::count(csv.begin(), csv.end(), '\n') == 5);  // the header and one line per round that fired
    const std::string plan = rules::readTextFile((dir / "plan.jsonl").string());
    REQUIRE_FALSE(plan.empty());
    CHECK(plan.back() == '\n');
    CHECK(plan.find("\"round\":4") != std::string::npos);
    CHECK(plan.find("\"round\":5") == std::string::npos);
    CHECK(fs::exists(dir / "out" / "snapshot-end.svg"));
    CHECK_FALSE(anyTemporary(dir));
    CHECK_FALSE(anyTemporary(dir / "out"));
    fs::remove_all(dir);
}

TEST_CASE("completion.csv says where the plan waits: the planner instances enabled and those the allocator holds back") {
    const fs::path dir = fs::temp_directory_path() / "holon_report_waiting_test";
    fs::remove_all(dir);
    fs::create_directories(dir);
    // general1 under eager, whose deletion order holds deletions back, and the intermediate
    // planner under the random allocator, which holds nothing back.
    for (const auto& [system, allocatorName] : {std::pair<std::string, std::string>{"planner_general1", "eager"}, {"planner_intermediate", "random"}}) {
        CAPTURE(system);
        PlannerSystem sys(system, 3);
        const planner::Problem p = planner::makeProblem(*sys.model, planner::parseShape("box:6x3x2", 2), planner::parseShape("box:3x3x4", 2), std::nullopt, 1);
        auto allocator = planner::makeAllocator(allocatorName, p, 1);
        planner::Execution ex(p, *allocator, {});
        planner::Report report(p, ex, {(dir / system).string(), "", "--out", "--plan-out", false});
        const planner::BoxEngine& engine = *p.engine;
        std::int64_t mismatches = 0;
        planner::RunObserver observer;
        observer.roundEnd = [&](const planner::RunStats& stats) {
            report.roundEnd(stats);
            // The same count, instance by instance over the whole board.
            planner::Execution::Waiting all;
            for (std::int64_t a = 0; a < static_cast<std::int64_t>(p.cells.size()); ++a)
                for (int s = 0; s < engine.shapeCount(); ++s)
                    if (engine.kind(s) != planner::ShapeKind::Transfer && ex.enabled(a, s)) ++all.enabled, all.held += !allocator->releases(ex, a, s);
            const planner::Execution::Waiting listed = ex.waiting();
            mismatches += listed.enabled != all.enabled || listed.held != all.held;
            return true;
        };
        const planner::RunStats stats = ex.run(observer);
        report.finish(stats, -1);
        REQUIRE(stats.complete);
        CHECK(mismatches == 0);
        std::istringstream csv(rules::readTextFile((dir / system / "completion.csv").string()));
        std::string line;
        std::getline(csv, line);
        CHECK(line.ends_with(",planner_enabled,planner_held"));
        std::int64_t rows = 0, heldRows = 0;
        while (std::getline(csv, line)) {
            const auto comma = line.rfind(',');
            const std::int64_t held = std::stoll(line.substr(comma + 1)), enabled = std::stoll(line.substr(line.rfind(',', comma - 1) + 1));
            CHECK(held <= enabled);
            ++rows, heldRows += held > 0;
        }
        CHECK(rows > 10);
        if (allocatorName == "random") CHECK(heldRows == 0);
        else CHECK(heldRows > rows / 4);
    }
    fs::remove_all(dir);
}

TEST_CASE("plan outputs that cannot be written: refused before the run, or reported after it") {
    PlannerSystem sys("planner_intermediate", 2);
    const planner::Problem p = planner::makeProblem(*sys.model, planner::parseShape("box:4x2"), planner::parseShape("box:2x4"), std::nullopt, 1);
    auto allocator = planner::makeAllocator("random", p, 1);
    planner::Execution ex(p, *allocator, {});
    CHECK_THROWS_WITH_AS(planner::Report(p, ex, {"/nonexistent/out", "", "--out", "--plan-out", false}), doctest::Contains("--out"), InputError);
    CHECK_THROWS_WITH_AS(planner::Report(p, ex, {"", "/nonexistent/plan.jsonl", "--out", "--plan-out", false}), doctest::Contains("--plan-out"), InputError);
    if (!fs::exists("/dev/full")) return;
    planner::Report report(p, ex, {"", "/dev/full", "--out", "--plan-out", false});
    planner::RunObserver observer;
    observer.fired = [&](std::int64_t a, int s, const planner::BoxEngine::Value* old) { report.fired(a, s, old); };
    const planner::RunStats stats = ex.run(observer);
    CHECK(stats.complete);
    report.finish(stats, -1);
    REQUIRE(report.writeErrors().size() == 1);
    CHECK(report.writeErrors()[0].find("--plan-out /dev/full: cannot write: No space left") != std::string::npos);
}

}  // namespace holon::test

namespace holon::test {

TEST_CASE("a plan that stops short can be diagnosed: its start in the plan, its end and stuck cells on disk") {
    const fs::path dir = fs::temp_directory_path() / "holon_report_diagnose_test";
    fs::remove_all(dir);
    fs::create_directories(dir);
    PlannerSystem sys("planner_general1", 2);
    const planner::Problem p = planner::makeProblem(*sys.model, planner::parseShape("box:6x3"), planner::parseShape("box:3x6"), std::nullopt, 1);
    auto allocator = planner::makeAllocator("random", p, 1);
    planner::RunOptions options;
    options.budget = Budget::maxSteps(30);
    planner::Execution ex(p, *allocator, options);
    const std::vector<planner::BoxEngine::Value> start = ex.cells();
    {
        planner::Report report(p, ex, {(dir / "out").string(), (dir / "plan.jsonl").string(), "--out", "--plan-out", false});
        planner::RunObserver observer;
        observer.fired = [&](std::int64_t a, int s, const planner::BoxEngine::Value* old) { report.fired(a, s, old); };
        observer.roundEnd = [&](const planner::RunStats& st) { return report.roundEnd(st), true; };
        const planner::RunStats stats = ex.run(observer);
        REQUIRE_FALSE(stats.complete);
        report.finish(stats, -1);
    }
    // Both configurations read back through the reference interpreter's reader, target included.
    const rules::Region region = rules::Region::parse("square:6x6");
    const rules::Interpreter in(*sys.model, region);
    auto boardOf = [&](const rules::Configuration& c) {
        std::vector<planner::BoxEngine::Value> cells(ex.cells().size(), 0);
        int targets = 0;
        for (int i = 0; i < region.size(); ++i) {
            cells[p.board->index(region.cell(i))] = c.cells[i];
            targets += c.inputs[i] != 0;
        }
        CHECK(targets == 18);
        return cells;
    };
    std::istringstream plan(rules::readTextFile((dir / "plan.jsonl").string()));
    std::string header;
    std::getline(plan, header);
    const nlohmann::json h = nlohmann::json::parse(header);
    CHECK(h["system"] == "planner_general1");
    CHECK(boardOf(rules::configFromJson(in, h["start"])) == start);
    CHECK(boardOf(rules::readConfigFile(in, (dir / "out" / "end.json").string())) == ex.cells());
    const nlohmann::json summary = nlohmann::json::parse(rules::readTextFile((dir / "out" / "summary.json").string()));
    const auto [some, count] = planner::cellsShortOfGoal(ex, 100);
    CHECK(count > 0);
    CHECK(summary["cells_short_of_goal"] == count);
    CHECK(summary["short_of_goal"].size() == std::min<std::size_t>(20, some.size()));
    fs::remove_all(dir);
}

}  // namespace holon::test
