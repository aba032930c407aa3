#pragma once
// Each subcommand registers itself on the app and returns the function that runs it; the function
// returns the process exit code (0 success, 1 a checked property does not hold, 2 bad input).

#include <CLI/CLI.hpp>
#include <functional>

namespace holon::cli {

using Run = std::function<int()>;

Run addRulesCommand(CLI::App& app);
Run addCheckCommand(CLI::App& app);
Run addVerifyCommand(CLI::App& app);
Run addPlanCommand(CLI::App& app);
Run addHexCommand(CLI::App& app);
Run addRoombotsCommand(CLI::App& app);

}  // namespace holon::cli
