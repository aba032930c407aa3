// The `holon` application: every subcommand registered on one CLI11 app, the arguments parsed, the
// chosen subcommand run and every exception mapped to the exit-code contract (cli/Commands.h). Kept
// apart from main() so the argument fuzzer (fuzz/CliFuzz.cpp) runs exactly what the binary runs.

#include "cli/Commands.h"
#include "cli/ParameterNames.h"
#include "rules/Budget.h"
#include "rules/Error.h"
#include "rules/Escape.h"
#include "rules/OutputFile.h"

#include <csignal>
#include <iostream>
#include <map>
#include <string>

namespace holon::cli {

namespace {

/// What to change when a subcommand runs out of the machine's memory: the options that size its
/// work. The --memory bound of check, plan, hex, roombots and verify stops them cleanly first unless
/// it is set above what is free.
std::string memoryAdvice(const std::string& command) {
    if (command == "check") return "set --memory below the memory this machine has free (it bounds the exploration), lower --max-states, or choose a smaller --region";
    if (command == "verify") return "set --memory below the memory this machine has free, or choose a smaller --region or a lower --depth";
    if (command == "plan") return "set --memory below the memory this machine has free, or choose smaller --from/--to shapes or a lower --scale";
    if (command == "diff") return "set --memory below the memory this machine has free (both explorations share it), lower --max-states, or choose a smaller --region";
    if (command == "path") return "set --memory below the memory this machine has free (it bounds the search), lower --max-states, or choose a smaller --region";
    if (command == "hex") return "set --memory below the memory this machine has free, or choose a smaller --size or fewer --steps";
    if (command == "roombots") return "set --memory below the memory this machine has free, or choose a smaller structure or fewer --runs";
    return "give it fewer or smaller files";
}

}  // namespace

int runHolon(int argc, char** argv) {
    installOptionNames();
    CLI::App app{"holon: check, verify and run rule systems for lattice modular robots"};
    app.require_subcommand(1);
    app.set_version_flag("--version", "holon " HOLON_VERSION);
    std::map<CLI::App*, Run> runs;
    auto add = [&](Run (*factory)(CLI::App&)) {
        const std::size_t before = app.get_subcommands({}).size();
        Run run = factory(app);
        runs[app.get_subcommands({})[before]] = std::move(run);
    };
    add(addRulesCommand);
    add(addCheckCommand);
    add(addVerifyCommand);
    add(addPlanCommand);
    add(addHexCommand);
    add(addRoombotsCommand);
    add(addReplayCommand);
    add(addPathCommand);
    add(addDiffCommand);
    add(addExportCommand);
    add(addViewCommand);
    try {
        app.parse(argc, argv);
    } catch (const CLI::CallForHelp& e) {
        return app.exit(e);
    } catch (const CLI::CallForAllHelp& e) {
        return app.exit(e);
    } catch (const CLI::CallForVersion& e) {
        return app.exit(e);
    } catch (const CLI::ParseError& e) {
        app.exit(e);
        return kExitBadInput;
    }
    std::string command;
    try {
        for (auto& [sub, run] : runs)
            if (sub->parsed()) {
                command = sub->get_name();
                // An option that takes a value given an empty one ('--plan-out ""') was read as left
                // out: nothing written, nothing said.
                for (const CLI::Option* option : sub->get_options())
                    if (option->count() > 0 && option->get_expected_min() > 0)
                        for (const std::string& value : option->results()) {
                            if (value.empty()) throw InputError(option->get_name() + ": the value is empty; give one, or leave the option out");
                            // CLI11 reads integers in C's base 0: --seed 010 ran with seed 8, 0x10 was 16
                            // and 09 "not in range".
                            if (option->get_type_name().starts_with("INT") || option->get_type_name().starts_with("UINT"))
                                if (const std::size_t at = value.find_first_not_of("+- "); at != std::string::npos && value[at] == '0' && at + 1 < value.size())
                                    throw InputError(option->get_name() + " " + value + ": write the number in decimal, without a leading 0 or a 0x prefix");
                            // And fractions as C's strtod: --timeout 0x10 ran for 16 s (audit 7).
                            if (option->get_type_name().starts_with("FLOAT") && value.find_first_of("xX") != std::string::npos)
                                throw InputError(option->get_name() + " " + value + ": write the number in decimal, without a 0x prefix");
                        }
                // --timeout counts from the job's start, for the waits no run's budget reaches yet
                // (an input read from a FIFO that nothing writes).
                if (const CLI::Option* timeout = sub->get_option_no_throw("--timeout"); timeout && timeout->count() > 0)
                    setJobDeadline(timeout->as<double>());
                const rules::OutputClaims outputs;  // no two options write the same file
                return run();
            }
    } catch (const holon::InputError& e) {
        std::cerr << "holon: error: " << rules::escapeText(e.what(), true) << '\n';
        return kExitBadInput;
    } catch (const Interrupted& e) {
        std::cerr << "holon: " << (e.signal() == SIGINT ? "interrupted (SIGINT)" : e.signal() == SIGTERM ? "terminated (SIGTERM)"
                                                                                                         : e.what())
                  << '\n';
        return 128 + e.signal();
    } catch (const LimitError& e) {
        std::cerr << "holon: limit: " << rules::escapeText(e.what(), true) << '\n';
        return kExitUndecided;
    } catch (const std::bad_alloc&) {
        std::cerr << "holon " << command << ": stopped: the machine has no memory left for this job; " << memoryAdvice(command) << '\n';
        return kExitUndecided;
    } catch (const std::exception& e) {
        reportInternalError("", rules::escapeText(e.what(), true));
        return kExitInternal;
    }
    return kExitInternal;
}

}  // namespace holon::cli
