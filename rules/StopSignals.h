#pragma once
// SIGINT, SIGTERM and SIGHUP caught while a long job runs, so it stops at a point where its outputs are
// whole (a plan at a round boundary, verify after killing its solver processes) instead of dying
// mid-write. One mechanism for every subcommand that needs it.

#include <csignal>
#include <string>

namespace holon::rules {

/// Installs the catcher for its lifetime and restores the previous handlers after. A signal the
/// caller ignores (a shell's background job, nohup) stays ignored. With `oneShot`, a second signal
/// ends the process at once (the first one's orderly stop is taking too long for the user), unless
/// it is the first one again within a second (one request delivered twice, as GNU timeout does).
class StopSignals {
public:
    explicit StopSignals(bool oneShot);
    ~StopSignals();
    StopSignals(const StopSignals&) = delete;
    StopSignals& operator=(const StopSignals&) = delete;

    /// The signal caught since the catcher was installed (SIGINT, SIGTERM or SIGHUP), 0 for none; the
    /// address is what a run polls (planner::RunOptions::interrupt).
    static const volatile std::sig_atomic_t* caught();

    /// Throws Interrupted once the catcher installed now has caught a signal: for work that polls no
    /// budget (reading an input, building a page) but must stop as a run would.
    static void stopIfCaught();
    /// stopIfCaught, then checkJobDeadline(during): the poll of every input reader and of work
    /// outside a run's budget.
    static void checkJob(const std::string& during);

private:
    struct sigaction oldInt_ {
    }, oldTerm_{}, oldHup_{};
    int outerEndOnSecond_;
};

/// For the whole process, outside any StopSignals: SIGINT, SIGTERM, SIGHUP, SIGQUIT and SIGPIPE
/// end holon as they would, and so does std::terminate, after removing the temporaries being
/// written (rules::removeTemporaries). A signal the caller ignores stays ignored. SIGXFSZ is
/// ignored: a write past a file-size limit fails (EFBIG) and is reported as a failed write.
void endOnSignalsCleanly();

/// In a forked child: signals end it with their default actions and std::terminate removes
/// nothing, since the temporaries it inherited are its parent's to finish or remove.
void leaveTemporariesToParent();

}  // namespace holon::rules
