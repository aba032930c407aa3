// What a plan leaves on disk: an interrupt stops the run at a round boundary and the files are
// committed whole (the CSV's last line complete, the summary marked interrupted); a run abandoned
// without finish() leaves no file behind; a file that cannot be written is reported, not lost.

#include "PlannerSupport.h"

#include "planner/Report.h"
#include "rules/Error.h"

#include <csignal>
#include <filesystem>
#include "rules/Parser.h"

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
    options.interrupt = &flag;
    planner::Execution ex(p, *allocator, options);
    planner::RunObserver observer;
    observer.roundEnd = [&](const planner::RunStats& stats) {
        if (stats.rounds == 3) flag = SIGINT;  // as the handler would, in the middle of the run
        return true;
    };
    const planner::RunStats stats = ex.run(observer);
    CHECK(stats.stopped == "interrupted");
    CHECK(stats.rounds == 3);
    CHECK_FALSE(stats.complete);
}

TEST_CASE("an interrupted plan's files are whole and the summary says so; an abandoned one leaves none") {
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
    options.interrupt = &flag;
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
