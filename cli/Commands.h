#pragma once
// Each subcommand registers itself on the app and returns the function that runs it; the function
// returns the process exit code, the same contract for every subcommand (ExitCode below).

#include "checker/Verdict.h"

#include <CLI/CLI.hpp>
#include <cmath>
#include <functional>

namespace holon::cli {

/// 0 every requested property holds / the job is done; 1 a property does not hold / the plan did
/// not complete; 2 bad input or usage; 3 undecided (a limit, a timeout, the solver's unknown);
/// 4 an internal error (a bug in holon: please report it). A run stopped by SIGINT or SIGTERM
/// (holon plan) exits 128 + the signal, 130 or 143, after writing what it has as complete files.
enum ExitCode : int { kExitOk = 0, kExitViolated = 1, kExitBadInput = 2, kExitUndecided = 3, kExitInternal = 4 };

inline int exitCodeFor(checker::Verdict v) {
    switch (v) {
    case checker::Verdict::Holds: return kExitOk;
    case checker::Verdict::Violated: return kExitViolated;
    case checker::Verdict::Unknown: return kExitUndecided;
    }
    return kExitInternal;
}

/// --timeout values: a finite number of seconds from 0.001 to 10^7 (CLI::Range lets NaN through).
inline CLI::Validator secondsValidator() {
    return CLI::Validator(
        [](std::string& text) {
            double v = 0;
            try {
                std::size_t used = 0;
                v = std::stod(text, &used);
                if (used != text.size()) return std::string("'" + text + "' is not a number of seconds");
            } catch (const std::exception&) {
                return std::string("'" + text + "' is not a number of seconds");
            }
            return std::isfinite(v) && v >= 1e-3 && v <= 1e7 ? std::string() : std::string("give seconds from 0.001 to 10000000, not " + text);
        },
        "SECONDS");
}

/// --memory values in MiB: from 16 MiB to 16 TiB.
inline CLI::Range memoryRange() { return CLI::Range(std::uint64_t{16}, std::uint64_t{1} << 24); }

using Run = std::function<int()>;

Run addRulesCommand(CLI::App& app);
Run addCheckCommand(CLI::App& app);
Run addVerifyCommand(CLI::App& app);
Run addPlanCommand(CLI::App& app);
Run addHexCommand(CLI::App& app);
Run addRoombotsCommand(CLI::App& app);

}  // namespace holon::cli
