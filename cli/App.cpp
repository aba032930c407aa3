// The `holon` application: every subcommand registered on one CLI11 app, the arguments parsed, the
// chosen subcommand run and every exception mapped to the exit-code contract (cli/Commands.h). Kept
// apart from main() so the argument fuzzer (fuzz/CliFuzz.cpp) runs exactly what the binary runs.

#include "cli/Commands.h"
#include "rules/Error.h"
#include "rules/Escape.h"

#include <csignal>
#include <iostream>
#include <map>

namespace holon::cli {

int runHolon(int argc, char** argv) {
    CLI::App app{"holon: check, verify and run rule systems for lattice modular robots"};
    app.require_subcommand(1);
    app.set_version_flag("--version", "holon 0.1.0");
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
    try {
        for (auto& [sub, run] : runs)
            if (sub->parsed()) return run();
    } catch (const holon::InputError& e) {
        std::cerr << "holon: error: " << rules::escapeText(e.what(), true) << '\n';
        return kExitBadInput;
    } catch (const Interrupted& e) {
        std::cerr << "holon: " << (e.signal() == SIGINT ? "interrupted (SIGINT)" : e.signal() == SIGTERM ? "terminated (SIGTERM)" : e.what()) << '\n';
        return 128 + e.signal();
    } catch (const LimitError& e) {
        std::cerr << "holon: limit: " << rules::escapeText(e.what(), true) << '\n';
        return kExitUndecided;
    } catch (const std::bad_alloc&) {
        std::cerr << "holon: error: out of memory before the job could finish; raise the machine's memory or lower --memory / --max-states\n";
        return kExitUndecided;
    } catch (const std::exception& e) {
        std::cerr << "holon: internal error: " << rules::escapeText(e.what(), true) << "\n  this is a bug in holon, not in your input; please report it with the command line\n";
        return kExitInternal;
    }
    return kExitInternal;
}

}  // namespace holon::cli
