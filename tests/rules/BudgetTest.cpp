// The one budget type (rules/Budget.h): each limit alone, their composition with ||, the order in
// which a spent budget names its reason, and the names messages and JSON use.

#include "rules/Budget.h"

#include <doctest/doctest.h>

#include <chrono>
#include <set>
#include <string>
#include <thread>

using namespace holon;

TEST_CASE("an empty budget never stops") {
    const Budget none;
    CHECK(!none.limited());
    CHECK(!none.expired());
    CHECK(!none.interrupted());
    CHECK(!none.reached({1u << 30, 1u << 30, 1u << 30}));
    CHECK_NOTHROW(none.check("anything"));
}

TEST_CASE("each cap stops at its count, not before") {
    CHECK(!Budget::maxSteps(5).reached({0, 4, 0}));
    CHECK(Budget::maxSteps(5).reached({0, 5, 0}) == StopReason::MaxSteps);
    CHECK(!Budget::maxRounds(3).reached({0, 100, 2}));
    CHECK(Budget::maxRounds(3).reached({0, 0, 3}) == StopReason::MaxRounds);
    CHECK(Budget::maxStates(7).reached({7, 0, 0}) == StopReason::MaxStates);
    CHECK(!Budget::maxSteps(0).reached({0, 1u << 30, 0}));  // 0: no cap
}

TEST_CASE("a deadline expires, says how long it was, and is skipped when the clock is not read") {
    const Budget spent(1e-9);
    std::this_thread::sleep_for(std::chrono::milliseconds(1));
    CHECK(spent.limited());
    CHECK(spent.expired());
    CHECK(spent.remaining() == 0);
    CHECK(spent.reached() == StopReason::Timeout);
    CHECK(!spent.reached({}, false));
    CHECK_THROWS_WITH_AS(spent.check("building the formulas"), "timeout (1e-09 s) while building the formulas", OutOfTime);
    const Budget far(1000);
    CHECK(!far.expired());
    CHECK(far.remaining() > 999);
    CHECK(!Budget(0).limited());
    CHECK(!Budget(-1).limited());
}

TEST_CASE("the stop flag stops the run as interrupted and names the signal") {
    volatile std::sig_atomic_t flag = 0;
    const Budget b = Budget::stopFlag(&flag);
    CHECK(!b.reached());
    flag = SIGTERM;
    CHECK(b.interrupted());
    CHECK(b.signal() == SIGTERM);
    CHECK(b.reached() == StopReason::Interrupted);
}

TEST_CASE("|| stops at whichever limit comes first") {
    volatile std::sig_atomic_t flag = 0;
    const Budget both = Budget(1000) || Budget::maxSteps(10) || Budget::maxRounds(4) || Budget::stopFlag(&flag);
    CHECK(both.limited());
    CHECK(both.seconds() == 1000);
    CHECK(!both.reached({0, 9, 3}));
    CHECK(both.reached({0, 10, 0}) == StopReason::MaxSteps);
    CHECK(both.reached({0, 0, 4}) == StopReason::MaxRounds);
    // The smaller of two caps, the earlier of two deadlines, whatever the order.
    CHECK((Budget::maxSteps(10) || Budget::maxSteps(3)).reached({0, 3, 0}) == StopReason::MaxSteps);
    CHECK((Budget::maxSteps(3) || Budget::maxSteps(10)).reached({0, 3, 0}) == StopReason::MaxSteps);
    CHECK((Budget(1000) || Budget(5)).seconds() == 5);
    CHECK((Budget(5) || Budget(1000)).seconds() == 5);
    CHECK((Budget() || Budget(5)).seconds() == 5);
    // A signal outranks every other reason: the user asked to stop.
    flag = SIGINT;
    CHECK(both.reached({0, 10, 4}) == StopReason::Interrupted);
    CHECK((Budget(1e-9) || Budget::stopFlag(&flag)).reached() == StopReason::Interrupted);
}

TEST_CASE("a budget combined with a later one keeps its own deadline") {
    const Budget early(0.05);
    std::this_thread::sleep_for(std::chrono::milliseconds(60));
    const Budget later(0.05);  // starts now: its deadline is after early's
    CHECK((later || early).expired());
    CHECK((early || later).expired());
}

TEST_CASE("every stop reason has its own name, the ones messages and JSON have always used") {
    const StopReason all[] = {StopReason::Finished, StopReason::Goal, StopReason::Decided, StopReason::Stuck, StopReason::NoProgress,
                              StopReason::Monitor, StopReason::Fault, StopReason::MaxStates, StopReason::MaxSteps, StopReason::MaxRounds,
                              StopReason::Memory, StopReason::Timeout, StopReason::Interrupted};
    std::set<std::string> names;
    for (StopReason r : all) names.insert(stopReasonName(r));
    CHECK(names.size() == std::size(all));
    CHECK(stopReasonName(StopReason::Finished) == "finished");
    CHECK(stopReasonName(StopReason::Goal) == "goal");
    CHECK(stopReasonName(StopReason::NoProgress) == "no-progress");
    CHECK(stopReasonName(StopReason::MaxStates) == "max-states");
    CHECK(stopReasonName(StopReason::MaxSteps) == "max-steps");
    CHECK(stopReasonName(StopReason::MaxRounds) == "max-rounds");
    CHECK(stopReasonName(StopReason::Timeout) == "timeout");
    CHECK(stopReasonName(StopReason::Interrupted) == "interrupted");
}

TEST_CASE("Budget::job is the job's deadline: none, ahead, or passed (expired, not unlimited)") {
    setJobDeadline(0);
    CHECK_FALSE(Budget::job().limited());
    setJobDeadline(100);
    CHECK(Budget::job().limited());
    CHECK_FALSE(Budget::job().expired());
    CHECK((Budget(1000) || Budget::job()).remaining() <= 100);  // the earlier deadline of the two
    setJobDeadline(1e-6);
    std::this_thread::sleep_for(std::chrono::milliseconds(2));
    CHECK(Budget::job().expired());
    setJobDeadline(0);
}
