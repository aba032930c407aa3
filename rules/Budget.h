#pragma once
// One budget for every long run (check's exploration and later phases, verify, path, diff, plan,
// hex, roombots) and one status for why a run stopped. The budget is a value, like OMPL's
// PlannerTerminationCondition: a wall-clock deadline fixed when the job starts, optional caps on
// steps, states and rounds, and a stop flag (the SIGINT/SIGTERM catcher of rules/StopSignals),
// combined with ||. It never throws on its own; a run asks it where it can stop cleanly. It lives
// below checker/ and planner/ so that both take the same type.

#include <chrono>
#include <csignal>
#include <cstdint>
#include <optional>
#include <stdexcept>
#include <string>

namespace holon {

/// Why a run stopped, in one list for every subcommand. The first three are a run that did its job
/// (or found its answer), the next four one that cannot go on, the rest a limit or a signal.
enum class StopReason { Finished,       // explored everything / every run and timestep made
                        Goal,           // the plan reached its target
                        Decided,        // every question asked is answered before the end
                        Stuck,          // nothing is enabled and the goal is not reached
                        NoProgress,     // only transfers fired for too long
                        Monitor,        // the run-time monitor saw a violation
                        Fault,          // an injected fault broke what the rules assume
                        MaxStates,      // the state cap
                        MaxSteps,       // the step cap
                        MaxRounds,      // the round cap
                        Memory,         // the memory bound
                        Timeout,        // the deadline
                        Interrupted };  // SIGINT or SIGTERM

/// The name used in messages ("stopped by max-states") and JSON ("stopped": "no-progress").
std::string stopReasonName(StopReason r);

/// Work done so far, for the caps.
struct Progress {
    std::uint64_t states = 0, steps = 0, rounds = 0;
};

/// Thrown where a phase that cannot be stopped in the middle otherwise (verify building its
/// formulas) finds its budget spent; the caller makes the verdict unknown.
class OutOfTime : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

class Budget {
public:
    /// No limit at all.
    Budget() = default;
    /// A deadline `seconds` from now; `seconds` <= 0: none.
    explicit Budget(double seconds);
    /// Caps; 0: none.
    static Budget maxStates(std::uint64_t n);
    static Budget maxSteps(std::uint64_t n);
    static Budget maxRounds(std::uint64_t n);
    /// Stops once `*flag` is nonzero (set by a signal handler); null: never.
    static Budget stopFlag(const volatile std::sig_atomic_t* flag);
    /// Stops once rules::StopSignals has caught SIGINT or SIGTERM (while a catcher is installed).
    static Budget onSignals();
    /// The whole job's deadline (setJobDeadline), already passed or not; none when there is none.
    static Budget job();

    /// Whichever of the two stops first: the earlier deadline, the smaller caps, either flag.
    friend Budget operator||(Budget a, const Budget& b);

    /// Whether there is a deadline.
    bool limited() const { return seconds_ > 0; }
    double seconds() const { return seconds_; }
    double elapsed() const { return std::chrono::duration<double>(Clock::now() - start_).count(); }
    /// Seconds left (0 once expired); meaningful only when limited().
    double remaining() const { return seconds_ - elapsed() > 0 ? seconds_ - elapsed() : 0; }
    bool expired() const { return limited() && elapsed() >= seconds_; }
    /// The signal that set the stop flag, 0 for none.
    int signal() const { return stop_ ? static_cast<int>(*stop_) : 0; }
    /// Whether a signal can stop it (it has a stop flag).
    bool stoppable() const { return stop_ != nullptr; }
    bool interrupted() const { return signal() != 0; }

    /// The first limit reached by a run that has made `done` (a signal first, then the caps, then
    /// the deadline), or nothing. `readClock` false skips the deadline, for a caller that reads the
    /// clock only every so often because its steps are short.
    std::optional<StopReason> reached(const Progress& done = {}, bool readClock = true) const;

    /// Throws Interrupted once a signal is caught, OutOfTime once expired; `during` says what was
    /// cut short ("building the formulas").
    void check(const char* during) const;

private:
    using Clock = std::chrono::steady_clock;
    double seconds_ = 0;
    Clock::time_point start_ = Clock::now();
    std::uint64_t maxStates_ = 0, maxSteps_ = 0, maxRounds_ = 0;
    const volatile std::sig_atomic_t* stop_ = nullptr;
};

/// The whole job's deadline, for the waits no run's budget reaches: an input read from a pipe or
/// FIFO that nothing writes yet. The CLI sets it once at startup from --timeout, which counts from
/// the job's start; `seconds` <= 0: none.
void setJobDeadline(double seconds);
/// Seconds left before the job's deadline (0 once passed); infinity when there is none.
double jobSecondsLeft();
/// Throws LimitError about the timeout once the job's deadline has passed; `during` says what it
/// cut short ("building the page").
void checkJobDeadline(const std::string& during);

}  // namespace holon
