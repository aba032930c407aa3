#pragma once
// The limits of every subcommand that explores a reconfiguration graph (check, path, diff),
// registered once: the same names, validators and meanings everywhere, and the defaults taken from
// the library's checker::Limits, not restated here.

#include "checker/Explorer.h"
#include "cli/Commands.h"

#include <string>

namespace holon::cli {

struct ExploreLimitArgs {
    std::uint64_t maxStates = checker::Limits{}.maxStates;
    double timeout = checker::Limits{}.timeoutSeconds;
    std::uint64_t memoryMiB = checker::Limits{}.memoryBytes >> 20;
    int threads = checker::Limits{}.threads;
    /// `shares`: how many explorations split --memory (diff explores two designs).
    checker::Limits limits(int shares = 1) const {
        checker::Limits l;
        l.maxStates = maxStates, l.timeoutSeconds = timeout, l.memoryBytes = (memoryMiB << 20) / static_cast<std::uint64_t>(shares), l.threads = threads;
        return l;
    }
};

/// Registers --max-states, --timeout, --memory and --threads on `sub`; `each` qualifies what they
/// bound in the help ("each exploration").
inline void addExploreLimits(CLI::App* sub, ExploreLimitArgs& a, const std::string& each = "the exploration") {
    const checker::Limits defaults;
    sub->add_option("--max-states", a.maxStates, "stop " + each + " after this many states (default " + std::to_string(defaults.maxStates) + ")")
        ->check(CLI::Range(std::uint64_t{1}, std::uint64_t{1} << 40));
    sub->add_option("--timeout", a.timeout, "stop " + each + " after this many seconds (default: no limit)")->check(secondsValidator());
    sub->add_option("--memory", a.memoryMiB, "memory bound in MiB (default " + std::to_string(defaults.memoryBytes >> 20) + ")")->check(memoryValidator());
    sub->add_option("--threads", a.threads, "worker threads (default " + std::to_string(defaults.threads) + ")")->check(threadsValidator());
}

/// The option that raises the limit a search stopped at, for messages ("raise --memory").
inline std::string limitOption(checker::StopReason r) {
    switch (r) {
    case checker::StopReason::MaxStates: return "--max-states";
    case checker::StopReason::Timeout: return "--timeout";
    case checker::StopReason::Memory: return "--memory";
    case checker::StopReason::Finished:
    case checker::StopReason::Decided: break;
    }
    return "";
}

}  // namespace holon::cli
