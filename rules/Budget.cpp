// The budget and stop status of rules/Budget.h: how two budgets combine, which limit a run has
// reached, and the names the messages and JSON use for why a run stopped.

#include "rules/Budget.h"

#include "rules/Error.h"
#include "rules/StopSignals.h"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <limits>
#include <sstream>

namespace holon {

std::string stopReasonName(StopReason r) {
    switch (r) {
    case StopReason::Finished: return "finished";
    case StopReason::Goal: return "goal";
    case StopReason::Decided: return "decided";
    case StopReason::Stuck: return "stuck";
    case StopReason::NoProgress: return "no-progress";
    case StopReason::Monitor: return "monitor";
    case StopReason::Fault: return "fault";
    case StopReason::MaxStates: return "max-states";
    case StopReason::MaxSteps: return "max-steps";
    case StopReason::MaxRounds: return "max-rounds";
    case StopReason::Memory: return "memory";
    case StopReason::Timeout: return "timeout";
    case StopReason::Interrupted: return "interrupted";
    }
    throw InternalError("stopReasonName: a StopReason out of range");
}

namespace {
// Nanoseconds of the steady clock; 0: no deadline. Atomic: read from worker threads too.
std::atomic<std::int64_t> jobDeadline{0};
}  // namespace

void setJobDeadline(double seconds) {
    const auto now = std::chrono::steady_clock::now().time_since_epoch();
    jobDeadline = seconds > 0 ? std::chrono::duration_cast<std::chrono::nanoseconds>(now + std::chrono::duration<double>(seconds)).count() : 0;
}

double jobSecondsLeft() {
    const std::int64_t deadline = jobDeadline;
    if (deadline == 0) return std::numeric_limits<double>::infinity();
    const std::int64_t now = std::chrono::duration_cast<std::chrono::nanoseconds>(std::chrono::steady_clock::now().time_since_epoch()).count();
    return deadline > now ? static_cast<double>(deadline - now) * 1e-9 : 0;
}

void checkJobDeadline(const std::string& during) {
    if (jobSecondsLeft() <= 0)
        throw LimitError("the job's " + rules::parameterName(rules::Parameter::Timeout) + " ran out while " + during, rules::Parameter::Timeout);
}

Budget::Budget(double seconds) : seconds_(seconds > 0 ? seconds : 0) {}

Budget Budget::maxStates(std::uint64_t n) {
    Budget b;
    b.maxStates_ = n;
    return b;
}

Budget Budget::maxSteps(std::uint64_t n) {
    Budget b;
    b.maxSteps_ = n;
    return b;
}

Budget Budget::maxRounds(std::uint64_t n) {
    Budget b;
    b.maxRounds_ = n;
    return b;
}

Budget Budget::stopFlag(const volatile std::sig_atomic_t* flag) {
    Budget b;
    b.stop_ = flag;
    return b;
}

Budget Budget::onSignals() { return stopFlag(rules::StopSignals::caught()); }

Budget Budget::job() {
    const double left = jobSecondsLeft();
    if (std::isinf(left)) return {};
    Budget b;
    b.seconds_ = std::max(left, 1e-9);  // passed: expired at once, not "no deadline"
    return b;
}

Budget operator||(Budget a, const Budget& b) {
    // The smaller of two caps, 0 meaning none.
    const auto cap = [](std::uint64_t x, std::uint64_t y) { return x == 0 ? y : y == 0 ? x
                                                                                       : std::min(x, y); };
    if (b.limited() && (!a.limited() || b.start_ + std::chrono::duration_cast<Budget::Clock::duration>(std::chrono::duration<double>(b.seconds_)) <
                                            a.start_ + std::chrono::duration_cast<Budget::Clock::duration>(std::chrono::duration<double>(a.seconds_))))
        a.seconds_ = b.seconds_, a.start_ = b.start_;
    a.maxStates_ = cap(a.maxStates_, b.maxStates_);
    a.maxSteps_ = cap(a.maxSteps_, b.maxSteps_);
    a.maxRounds_ = cap(a.maxRounds_, b.maxRounds_);
    // holon has one stop flag (rules::StopSignals'); two different ones would need a list.
    if (a.stop_ && b.stop_ && a.stop_ != b.stop_) throw InternalError("Budget: two different stop flags combined");
    if (!a.stop_) a.stop_ = b.stop_;
    return a;
}

std::optional<StopReason> Budget::reached(const Progress& done, bool readClock) const {
    if (interrupted()) return StopReason::Interrupted;
    if (maxStates_ && done.states >= maxStates_) return StopReason::MaxStates;
    if (maxRounds_ && done.rounds >= maxRounds_) return StopReason::MaxRounds;
    if (maxSteps_ && done.steps >= maxSteps_) return StopReason::MaxSteps;
    if (readClock && expired()) return StopReason::Timeout;
    return std::nullopt;
}

void Budget::check(const char* during) const {
    if (interrupted()) throw Interrupted(signal());  // a signal stops the phase as it stops the job
    if (!expired()) return;
    std::ostringstream text;
    text << "timeout (" << seconds_ << " s) while " << during;
    throw OutOfTime(text.str());
}

}  // namespace holon
