// The SIGINT/SIGTERM catcher of rules/StopSignals.h: the handler only records the signal, the only
// thing a handler may safely do; the job polls it at its own safe points.

#include "rules/StopSignals.h"

#include "rules/Budget.h"
#include "rules/Error.h"
#include "rules/OutputFile.h"

#include <cstdint>
#include <cstdlib>
#include <ctime>
#include <exception>

namespace holon::rules {

namespace {

volatile std::sig_atomic_t caughtSignal = 0, endOnSecond = 0;
std::int64_t firstAtNs = 0;  // when the first signal came; written before caughtSignal is set

std::int64_t nowNs() {
    timespec now{};
    clock_gettime(CLOCK_MONOTONIC, &now);  // async-signal-safe
    return std::int64_t{now.tv_sec} * 1'000'000'000 + now.tv_nsec;
}

/// Ends holon as the signal would, without the temporaries it was writing: the signal comes again
/// with its default action, at once or, where the handler blocks it, as the handler returns.
void endNow(int signal) {
    removeTemporaries();
    ::signal(signal, SIG_DFL);
    ::raise(signal);
}

extern "C" void onEndSignal(int signal) { endNow(signal); }

extern "C" void onStopSignal(int signal) {
    if (caughtSignal == 0) {
        firstAtNs = nowNs();
        caughtSignal = signal;
        return;
    }
    // A second signal ends holon at once, unless it repeats the first within a second: GNU timeout
    // signals the process and then its group, two deliveries of one request, and the second one
    // killed runs mid-write, leaving temporary files and no summary.
    if (endOnSecond && (signal != caughtSignal || nowNs() - firstAtNs >= 1'000'000'000)) endNow(signal);
}

// SIGPIPE too (a reader of holon's output that goes away ends holon at its next line), and SIGQUIT
// (Ctrl-\), which still dumps core; neither leaves FILE.tmp-XXXXXX behind.
constexpr int kEndSignals[] = {SIGINT, SIGTERM, SIGHUP, SIGQUIT, SIGPIPE};
std::terminate_handler previousTerminate = nullptr;
bool inForkedChild = false;

int depth = 0;  // catchers installed one inside another (verify's, then a solver race's)

}  // namespace

StopSignals::StopSignals(bool oneShot) : outerEndOnSecond_(endOnSecond) {
    // An inner catcher keeps what the outer one caught: resetting it let verify go on to exit 0.
    if (depth++ == 0) caughtSignal = 0;
    endOnSecond = oneShot ? 1 : 0;
    struct sigaction action {};
    action.sa_handler = onStopSignal;
    sigemptyset(&action.sa_mask);
    action.sa_flags = 0;
    sigaction(SIGINT, &action, &oldInt_);
    sigaction(SIGTERM, &action, &oldTerm_);
    // SIGHUP too (a closed terminal, a dropped ssh session): it ended a long plan at once, its
    // --out folder left partial with no summary.
    sigaction(SIGHUP, &action, &oldHup_);
    if (oldInt_.sa_handler == SIG_IGN) sigaction(SIGINT, &oldInt_, nullptr);
    if (oldTerm_.sa_handler == SIG_IGN) sigaction(SIGTERM, &oldTerm_, nullptr);
    if (oldHup_.sa_handler == SIG_IGN) sigaction(SIGHUP, &oldHup_, nullptr);
}

StopSignals::~StopSignals() {
    --depth;
    endOnSecond = outerEndOnSecond_;
    sigaction(SIGINT, &oldInt_, nullptr);
    sigaction(SIGTERM, &oldTerm_, nullptr);
    sigaction(SIGHUP, &oldHup_, nullptr);
}

const volatile std::sig_atomic_t* StopSignals::caught() { return &caughtSignal; }

void StopSignals::stopIfCaught() {
    // Outside any catcher a signal ends holon by itself; what an earlier catcher caught is done with.
    if (const int signal = caughtSignal; signal != 0 && depth > 0) throw Interrupted(signal);
}

void StopSignals::checkJob(const std::string& during) {
    stopIfCaught();
    checkJobDeadline(during);
}

void endOnSignalsCleanly() {
    struct sigaction action {
    }, old{};
    action.sa_handler = onEndSignal;
    sigemptyset(&action.sa_mask);
    action.sa_flags = SA_NODEFER;  // the re-raised signal is delivered at once, with its default action
    for (int signal : kEndSignals) {
        sigaction(signal, &action, &old);
        if (old.sa_handler == SIG_IGN) sigaction(signal, &old, nullptr);  // a shell's background job, nohup
    }
    // A file-size limit (ulimit -f) is a write that fails with EFBIG, reported as any failed write
    // (exit 2, the temporary removed); SIGXFSZ's default action killed holon mid-write (exit 153,
    // no word, FILE.tmp-XXXXXX left behind).
    ::signal(SIGXFSZ, SIG_IGN);
    // An exception no one catches (a thread's) ends holon through std::terminate: the same cleanup,
    // then the library's handler, which names the exception and aborts.
    static const bool once = [] {
        previousTerminate = std::set_terminate([] {
            if (!inForkedChild) removeTemporaries();
            if (previousTerminate) previousTerminate();
            std::abort();
        });
        return true;
    }();
    (void)once;
}

void leaveTemporariesToParent() {
    inForkedChild = true;
    for (int signal : kEndSignals) ::signal(signal, SIG_DFL);
}

}  // namespace holon::rules
