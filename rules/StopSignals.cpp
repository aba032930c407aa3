// The SIGINT/SIGTERM catcher of rules/StopSignals.h: the handler only records the signal, the only
// thing a handler may safely do; the job polls it at its own safe points.

#include "rules/StopSignals.h"

namespace holon::rules {

namespace {

volatile std::sig_atomic_t caughtSignal = 0;

extern "C" void onStopSignal(int signal) { caughtSignal = signal; }

}  // namespace

StopSignals::StopSignals(bool oneShot) {
    caughtSignal = 0;
    struct sigaction action {};
    action.sa_handler = onStopSignal;
    sigemptyset(&action.sa_mask);
    action.sa_flags = oneShot ? SA_RESETHAND : 0;
    sigaction(SIGINT, &action, &oldInt_);
    sigaction(SIGTERM, &action, &oldTerm_);
    if (oldInt_.sa_handler == SIG_IGN) sigaction(SIGINT, &oldInt_, nullptr);
    if (oldTerm_.sa_handler == SIG_IGN) sigaction(SIGTERM, &oldTerm_, nullptr);
}

StopSignals::~StopSignals() {
    sigaction(SIGINT, &oldInt_, nullptr);
    sigaction(SIGTERM, &oldTerm_, nullptr);
}

const volatile std::sig_atomic_t* StopSignals::caught() { return &caughtSignal; }

}  // namespace holon::rules
