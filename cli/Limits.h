#pragma once
// The limits of every subcommand, registered once: --timeout, --memory, --threads and the caps
// (--max-states, --max-steps, --max-rounds) have the same names, validators and meaning everywhere,
// and their help states the defaults the library holds (checker::Limits, rules::kDefaultMemoryBytes,
// checker::VerifyOptions), not restated here. What differs between subcommands is only what a
// limit cuts short, which each one says in `what`.
//
// --timeout always means: wall-clock seconds for the whole job from its start, setup included;
// when they run out the job stops where its outputs are whole, reports what it has, and exits 3.
// verify's per-obligation limit is --obligation-timeout. --threads always means worker threads.

#include "checker/Explorer.h"
#include "cli/Commands.h"
#include "rules/Error.h"
#include "rules/Limits.h"
#include "rules/Region.h"
#include "rules/StopSignals.h"

#include <sstream>
#include <string>

namespace holon::cli {

/// A default for help text: "no limit" for 0, else the number.
inline std::string defaultText(double value, const std::string& none = "no limit") {
    if (value == 0) return none;
    std::ostringstream text;
    text << value;
    return text.str();
}

/// --timeout: `what` says what is kept when it runs out ("the runs made so far").
inline CLI::Option* addTimeout(CLI::App* sub, double& seconds, const std::string& what) {
    return sub->add_option("--timeout", seconds, "stop the whole job after this many seconds, setup included; " + what + " (exit 3; default: " + defaultText(seconds) + ")")
        ->check(secondsValidator());
}

/// --memory in MiB; `checked` says when the job compares its estimate with it.
inline CLI::Option* addMemory(CLI::App* sub, std::uint64_t& mib, const std::string& checked) {
    return sub->add_option("--memory", mib, "memory bound in MiB, " + checked + " (default " + std::to_string(mib) + ")")->check(memoryValidator());
}

/// --threads; `what` says what runs in parallel; 0 as the default means the machine's cores.
inline CLI::Option* addThreads(CLI::App* sub, int& threads, const std::string& what) {
    return sub->add_option("--threads", threads, "worker threads, " + what + ", 1 to 64 (default " + defaultText(threads, "the machine's cores") + ")")->check(threadsValidator());
}

/// A cap on work (--max-steps, --max-rounds, --max-states) counted in `unit`.
inline CLI::Option* addCap(CLI::App* sub, const std::string& name, std::uint64_t& cap, const std::string& unit) {
    return sub->add_option(name, cap, "stop after this many " + unit + " (exit 3; default " + defaultText(static_cast<double>(cap)) + ")")
        ->check(CLI::Range(std::uint64_t{1}, std::uint64_t{1} << 62));
}

/// The limits of a subcommand that explores a reconfiguration graph (check, path, diff).
struct ExploreLimitArgs {
    std::uint64_t maxStates = checker::Limits{}.maxStates;
    double timeout = checker::Limits{}.timeoutSeconds;
    std::uint64_t memoryMiB = checker::Limits{}.memoryBytes >> 20;
    int threads = checker::Limits{}.threads;
    /// `shares`: how many explorations split --memory (diff explores two designs). The search
    /// stops as interrupted on SIGINT or SIGTERM while a rules::StopSignals is installed.
    checker::Limits limits(int shares = 1) const {
        checker::Limits l;
        l.maxStates = maxStates, l.timeoutSeconds = timeout, l.memoryBytes = (memoryMiB << 20) / static_cast<std::uint64_t>(shares), l.threads = threads;
        l.stopFlag = rules::StopSignals::caught();
        return l;
    }
};

/// The region of an exploration (check, path, diff): refused before it is built (LimitError, exit
/// 3) when its own tables (rules::Region::kBytesPerCell a cell, 190 MiB at the largest region)
/// are over --memory, which they were by 12 times under --memory 16.
inline rules::Region exploreRegion(const std::string& spec, const ExploreLimitArgs& limits) {
    return rules::Region::parse(spec, 1u << 22, [&](std::uint64_t cells) {
        rules::requireMemory(rules::checkedProduct({cells, rules::Region::kBytesPerCell}), limits.memoryMiB << 20,
                             "region " + spec + " (" + rules::countText(cells) + " cells)");
    });
}

/// Registers --max-states, --timeout, --memory and --threads on `sub`; `each` qualifies what they
/// bound in the help ("each exploration").
inline void addExploreLimits(CLI::App* sub, ExploreLimitArgs& a, const std::string& each = "the exploration") {
    sub->add_option("--max-states", a.maxStates, "stop " + each + " after this many states (default " + std::to_string(a.maxStates) + ")")
        ->check(CLI::Range(std::uint64_t{1}, std::uint64_t{1} << 40));
    addTimeout(sub, a.timeout, "the states explored so far are reported");
    addMemory(sub, a.memoryMiB, "for " + each);
    addThreads(sub, a.threads, "for " + each);
}

/// The option that raises the limit a run stopped at, for messages ("raise --memory"); empty when
/// no option does (a signal, or a reason that is not a limit).
inline std::string limitOption(StopReason r) {
    switch (r) {
    case StopReason::MaxStates: return "--max-states";
    case StopReason::MaxSteps: return "--max-steps";
    case StopReason::MaxRounds: return "--max-rounds";
    case StopReason::Timeout: return "--timeout";
    case StopReason::Memory: return "--memory";
    case StopReason::Finished:
    case StopReason::Goal:
    case StopReason::Decided:
    case StopReason::Stuck:
    case StopReason::NoProgress:
    case StopReason::Monitor:
    case StopReason::Fault:
    case StopReason::Interrupted: break;
    }
    return "";
}

/// The signal rules::StopSignals caught (SIGINT, SIGTERM), 0 for none.
inline int caughtSignal() { return *rules::StopSignals::caught(); }

/// --timeout run out before a job wrote anything: `when` says where ("while laying out the
/// board").
inline LimitError timeoutBeforeOutput(double seconds, const std::string& when) {
    return LimitError("--timeout " + (std::ostringstream() << seconds).str() + " s: reached " + when + "; nothing was written; raise --timeout");
}

/// "; raise --timeout" after a message of a run stopped by `r`, or nothing.
inline std::string raiseAdvice(StopReason r, const std::string& then = "") {
    const std::string option = limitOption(r);
    return option.empty() ? "" : "; raise " + option + then;
}

}  // namespace holon::cli
