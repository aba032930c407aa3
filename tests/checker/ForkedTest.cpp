// Forked jobs (checker/Forked.h): the race of solver jobs, and one job beside other work that is
// killed when the budget is spent; no child outlives either.

#include "checker/Forked.h"

#include <doctest/doctest.h>

#include <cerrno>
#include <chrono>
#include <csignal>
#include <new>
#include <stdexcept>
#include <sys/wait.h>
#include <thread>
#include <unistd.h>

using holon::Budget;
using holon::checker::ForkedJob;
using holon::checker::ForkedTask;

namespace {

/// Whether this process has no child left, running or unreaped.
bool noChildren() { return waitpid(-1, nullptr, WNOHANG) < 0 && errno == ECHILD; }

}  // namespace

TEST_CASE("a forked task answers from a child process while this one goes on") {
    ForkedTask task([](bool forked) { return nlohmann::json{{"pid", getpid()}, {"forked", forked}}; });
    const std::optional<nlohmann::json> answer = task.answer(Budget());
    REQUIRE(answer);
    CHECK(answer->at("pid").get<int>() != getpid());
    CHECK(answer->at("forked").get<bool>());
    CHECK(noChildren());
}

TEST_CASE("a forked task past its budget is killed and gives no answer") {
    const auto start = std::chrono::steady_clock::now();
    ForkedTask task([](bool) {
        std::this_thread::sleep_for(std::chrono::seconds(60));
        return nlohmann::json{{"late", true}};
    });
    CHECK_FALSE(task.answer(Budget(0.3)));
    CHECK(std::chrono::steady_clock::now() - start < std::chrono::seconds(10));
    CHECK(noChildren());
}

TEST_CASE("a forked task that is never asked is killed with the task") {
    {
        ForkedTask task([](bool) {
            std::this_thread::sleep_for(std::chrono::seconds(60));
            return nlohmann::json::object();
        });
    }
    CHECK(noChildren());
}

TEST_CASE("a forked job's exception comes back as an error answer") {
    ForkedTask task([](bool) -> nlohmann::json { throw std::runtime_error("no flow"); });
    const std::optional<nlohmann::json> answer = task.answer(Budget());
    REQUIRE(answer);
    CHECK(answer->value("error", "") == "no flow");
}

TEST_CASE("a forked job that runs out of memory or is killed says so: the caller may go on without it") {
    ForkedTask starved([](bool) -> nlohmann::json { throw std::bad_alloc(); });
    const std::optional<nlohmann::json> oom = starved.answer(Budget());
    REQUIRE(oom);
    CHECK(oom->value("resources", false));
    ForkedTask killed([](bool) -> nlohmann::json {
        raise(SIGKILL);
        return nlohmann::json::object();
    });
    const std::optional<nlohmann::json> died = killed.answer(Budget());
    REQUIRE(died);
    CHECK(died->value("error", "") == "the solver process died (signal 9)");
    CHECK(died->value("resources", false));
    ForkedTask failed([](bool) -> nlohmann::json { throw std::logic_error("a bug"); });
    CHECK_FALSE(failed.answer(Budget())->value("resources", false));
}

TEST_CASE("a race returns the first decisive answer and kills the other job") {
    const std::vector<ForkedJob> jobs = {[](bool) {
                                             std::this_thread::sleep_for(std::chrono::seconds(60));
                                             return nlohmann::json{{"verdict", "slow"}};
                                         },
                                         [](bool) { return nlohmann::json{{"verdict", "quick"}}; }};
    const auto result = holon::checker::firstDecisive(jobs, [](const nlohmann::json& a) { return a.value("verdict", "") == "quick"; });
    CHECK(result.job == 1);
    CHECK(result.answer.value("verdict", "") == "quick");
    CHECK(noChildren());
}
