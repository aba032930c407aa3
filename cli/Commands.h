#pragma once
// Each subcommand registers itself on the app and returns the function that runs it; the function
// returns the process exit code, the same contract for every subcommand (ExitCode below).

#include "checker/Verdict.h"
#include "rules/Budget.h"
#include "rules/Error.h"
#include "rules/Limits.h"

#include <CLI/CLI.hpp>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <functional>
#include <iomanip>
#include <iostream>
#include <new>
#include <sstream>
#include <string>

namespace holon::cli {

/// 0 every requested property holds / the job is done; 1 a property does not hold / the plan did
/// not complete; 2 bad input or usage; 3 undecided (a limit, a timeout, the solver's unknown);
/// 4 an internal error (a bug in holon: please report it). A run stopped by SIGINT or SIGTERM
/// (holon plan) exits 128 + the signal, 130 or 143, after writing what it has as complete files.
enum ExitCode : int { kExitOk = 0,
                      kExitViolated = 1,
                      kExitBadInput = 2,
                      kExitUndecided = 3,
                      kExitInternal = 4 };

/// Tells the user that holon itself went wrong (never their input), in one wording for every
/// subcommand: "holon COMMAND: internal error: WHAT" and what to do about it.
inline void reportInternalError(const std::string& command, const std::string& what) {
    std::cerr << "holon" << (command.empty() ? "" : " ") << command << ": internal error: " << what
              << "\n  this is a bug in holon, not in your input; please report it with the command line\n";
}

inline int exitCodeFor(checker::Verdict v) {
    switch (v) {
    case checker::Verdict::Holds: return kExitOk;
    case checker::Verdict::Violated: return kExitViolated;
    case checker::Verdict::Unknown: return kExitUndecided;
    }
    return kExitInternal;
}

/// Why a run stopped, as an exit code, the same for every subcommand: a run that did its job 0; one
/// that cannot go on (stuck, no progress, a monitor's or a fault's stop) 1; a limit the user set or
/// can raise 3; a signal 128 + `signal` (the one the budget caught).
inline int exitCodeFor(StopReason r, int signal) {
    switch (r) {
    case StopReason::Finished:
    case StopReason::Goal:
    case StopReason::Decided: return kExitOk;
    case StopReason::Stuck:
    case StopReason::NoProgress:
    case StopReason::Monitor:
    case StopReason::Fault: return kExitViolated;
    case StopReason::MaxStates:
    case StopReason::MaxSteps:
    case StopReason::MaxRounds:
    case StopReason::Memory:
    case StopReason::Timeout: return kExitUndecided;
    case StopReason::Interrupted: return 128 + signal;
    }
    return kExitInternal;
}

/// A finite number from `lo` to `hi` (CLI::Range lets NaN and inf through); `unit` names what it
/// counts in the message, as in "give seconds from 0.001 to 10000000, not nan".
inline CLI::Validator finiteValidator(double lo, double hi, const std::string& unit) {
    return CLI::Validator(
        [=](std::string& text) {
            const auto show = [](double x) {
                char buffer[32];
                std::snprintf(buffer, sizeof buffer, "%.10g", x);
                return std::string(buffer);
            };
            const auto range = [&] { return "give " + unit + " from " + show(lo) + " to " + show(hi) + ", not " + text; };
            double v = 0;
            try {
                std::size_t used = 0;
                v = std::stod(text, &used);
                if (used != text.size()) return range();
            } catch (const std::exception&) {
                return range();
            }
            return std::isfinite(v) && v >= lo && v <= hi ? std::string() : range();
        },
        "NUMBER");
}

/// --timeout values: a finite number of seconds from 0.001 to 10^7. No limit is the default (the
/// option left out); 0 is refused, as it is for every limit of every subcommand.
inline CLI::Validator secondsValidator() { return finiteValidator(1e-3, 1e7, "seconds"); }

/// A count that bounds work (--max-steps, --max-rounds): 1 to 2^62. No limit is the default (the
/// option left out); 0 is refused, not read as "no limit", as for every limit.
inline CLI::Validator countValidator() { return CLI::Range(std::int64_t{1}, std::int64_t{1} << 62); }

/// --threads: 1 to 64 (more than the machine has only costs memory; 1000 aborted on thread creation).
inline CLI::Validator threadsValidator() { return CLI::Range(1, 64); }
/// A random seed: 0 to 2^64 - 1 (CLI11 read -1 as 2^64 - 1).
inline CLI::Validator seedValidator() {
    return CLI::Validator([](std::string& s) { return !s.empty() && s[0] == '-' ? std::string("a seed is a whole number from 0 to 2^64 - 1") : std::string(); }, "0..2^64-1");
}

/// --memory in MiB, for every subcommand that allocates by its input: 16 MiB to 16 TiB; the
/// default is the library's (rules::kDefaultMemoryBytes).
constexpr std::uint64_t kDefaultMemoryMiB = rules::kDefaultMemoryBytes >> 20;
inline CLI::Validator memoryValidator() { return CLI::Range(std::uint64_t{16}, std::uint64_t{1} << 24); }

/// Runs a job under --memory: std::bad_alloc during it (the estimate fell short, or the machine
/// gives less than --memory) is a limit, exit 3, naming --memory, not a crash or a generic error.
inline int withinMemory(std::uint64_t memoryMiB, const std::function<int()>& job) {
    try {
        return job();
    } catch (const std::bad_alloc&) {
        throw LimitError("out of memory during the run, within --memory " + std::to_string(memoryMiB) +
                         " MiB: this machine gives less; lower --memory to what it has (then such jobs are refused before they start) or give a smaller job");
    }
}

using Run = std::function<int()>;

/// Parses the arguments, runs the subcommand they name and returns its exit code; every exception
/// becomes the exit code the contract gives it (2 bad input, 3 out of memory, 4 internal error).
int runHolon(int argc, char** argv);

Run addRulesCommand(CLI::App& app);
Run addCheckCommand(CLI::App& app);
Run addVerifyCommand(CLI::App& app);
Run addPlanCommand(CLI::App& app);
Run addHexCommand(CLI::App& app);
Run addRoombotsCommand(CLI::App& app);
Run addReplayCommand(CLI::App& app);
Run addPathCommand(CLI::App& app);
Run addDiffCommand(CLI::App& app);
Run addExportCommand(CLI::App& app);
Run addViewCommand(CLI::App& app);

}  // namespace holon::cli
