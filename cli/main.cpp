// The `holon` command: one binary, a subcommand per job. Exit codes are the same for every
// subcommand (cli/Commands.h): 0 success, 1 a checked property does not hold, 2 bad input or
// usage, 3 undecided, 4 an internal error.

#include "cli/Commands.h"
#include "rules/Error.h"

#include <iostream>
#include <map>

int main(int argc, char** argv) {
    CLI::App app{"holon: check, verify and run rule systems for lattice modular robots"};
    app.require_subcommand(1);
    app.set_version_flag("--version", "holon 0.1.0");
    std::map<CLI::App*, holon::cli::Run> runs;
    auto add = [&](holon::cli::Run (*factory)(CLI::App&)) {
        const std::size_t before = app.get_subcommands({}).size();
        holon::cli::Run run = factory(app);
        runs[app.get_subcommands({})[before]] = std::move(run);
    };
    add(holon::cli::addRulesCommand);
    add(holon::cli::addCheckCommand);
    add(holon::cli::addVerifyCommand);
    add(holon::cli::addPlanCommand);
    add(holon::cli::addHexCommand);
    add(holon::cli::addRoombotsCommand);
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
        return holon::cli::kExitBadInput;
    }
    try {
        for (auto& [sub, run] : runs)
            if (sub->parsed()) return run();
    } catch (const holon::InputError& e) {
        std::cerr << "holon: error: " << e.what() << '\n';
        return holon::cli::kExitBadInput;
    } catch (const std::bad_alloc&) {
        std::cerr << "holon: error: out of memory before the job could finish; raise the machine's memory or lower --memory / --max-states\n";
        return holon::cli::kExitUndecided;
    } catch (const std::exception& e) {
        std::cerr << "holon: internal error: " << e.what() << "\n  this is a bug in holon, not in your input; please report it with the command line\n";
        return holon::cli::kExitInternal;
    }
    return holon::cli::kExitInternal;
}
