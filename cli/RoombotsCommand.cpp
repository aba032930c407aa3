// `holon roombots --structure cube|chair|FILE`: seed 001's furniture assembly from Roombots
// metamodules walking on a structured floor, for every chosen metamodule configuration and strategy,
// reported as the paper's Tables I and II (collisions per run, deadlocks starred) and Fig. 5 (moves
// per metamodule). `--make-clouds FILE` regenerates the collision-cloud look-up table. Output
// paths are checked before the runs; a file that cannot be written is reported after the tables.

#include "cli/Commands.h"
#include "cli/Limits.h"
#include "cli/Parallel.h"
#include "cli/WriteErrors.h"
#include "planner/roombots/Draw.h"
#include "rules/Budget.h"
#include "rules/Error.h"
#include "rules/Limits.h"
#include "rules/OutputFile.h"
#include "rules/StopSignals.h"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <atomic>
#include <filesystem>
#include <functional>
#include <iomanip>
#include <iostream>
#include <map>
#include <mutex>
#include <sstream>
#include <thread>
#include <unistd.h>

namespace holon::cli {
namespace {

namespace rb = planner::roombots;

struct RoombotsArgs {
    std::string structure = "cube", recipe = "given", clouds, makeClouds, out;
    std::vector<std::string> metamodules{"PAR", "PER", "SRS", "SRZ"}, strategies{"greedy", "slope", "step"};
    int runs = 0, threads = 0;  // 0: the option left out (the paper's runs, the machine's cores)
    int stall = planner::roombots::AssemblyOptions{}.stallSteps;
    double timeout = 0;  // 0: the option left out, no limit
    std::uint64_t memoryMiB = kDefaultMemoryMiB;
    std::uint64_t seed = 1;
    bool json = false, quiet = false;
};

struct Job {
    rb::Coupling coupling;
    rb::Strategy strategy;
    int run;
    rb::AssemblyResult result;
    bool ran = false;  // false: --timeout came first
};

std::string name(const Job& j) {
    return std::string(rb::couplingName(j.coupling)) + "_" + rb::strategyName(j.strategy) + "_" + std::to_string(j.run);
}

// What --out holds, per run.
const rules::OutputNames kTrace{"trace_", ".csv"}, kFeet{"feet_", ".svg"}, kAssembly{"assembly_", ".svg"}, kSteps{"steps_", ".jsonl"},
    kCoordination{"coordination_", ".json"};

/// One run's trace (CSV), foot traces and assembly (SVG), its actions for holon view (JSON Lines), and its coordination rule; a file that
/// cannot be written is added to `errors`.
void writeRun(const std::filesystem::path& dir, const Job& j, const rb::Setting& setting, WriteErrors& errors) {
    const auto write = [&](const std::string& file, const std::function<void(std::ostream&)>& fill) {
        errors.attempt([&] { rules::OutputFile("--out", (dir / file).string()).write(fill); });
    };
    write(kTrace.of(name(j)), [&](std::ostream& csv) {
        csv << "module,begin,end,from_x,from_y,to_x,to_y,force_x,force_y,seat\n";
        for (const rb::Action& a : j.result.actions)
            csv << a.module << ',' << a.begin << ',' << a.end << ',' << a.from.x << ',' << a.from.y << ',' << a.to.x << ',' << a.to.y << ','
                << a.forceX << ',' << a.forceY << ',' << a.seat << '\n';
    });
    write(kFeet.of(name(j)), [&](std::ostream& out) { out << rb::footTraceSvg(setting, j.result); });
    write(kAssembly.of(name(j)), [&](std::ostream& out) { out << rb::assemblySvg(setting, j.result); });
    write(kSteps.of(name(j)), [&](std::ostream& out) { out << rb::runSteps(setting, j.result, name(j)); });
    if (!j.result.coordination.empty()) write(kCoordination.of(name(j)), [&](std::ostream& out) { out << j.result.coordination; });
}

/// Collisions of the runs that did not deadlock, and of all runs.
std::pair<int, int> collisions(const std::vector<const Job*>& jobs) {
    int clean = 0, all = 0;
    for (const Job* j : jobs) all += j->result.collisions, clean += j->result.deadlocked ? 0 : j->result.collisions;
    return {clean, all};
}
int deadlocks(const std::vector<const Job*>& jobs) {
    return static_cast<int>(std::count_if(jobs.begin(), jobs.end(), [](const Job* j) { return j->result.deadlocked; }));
}
std::string collisionText(const std::vector<const Job*>& jobs) {
    const auto [clean, all] = collisions(jobs);
    return std::to_string(clean) + " (" + std::to_string(all) + ")";
}

void printTables(std::ostream& out, const std::vector<rb::Coupling>& couplings, const std::vector<rb::Strategy>& strategies,
                 const std::vector<Job>& jobs, int runs) {
    auto select = [&](auto keep) {
        std::vector<const Job*> s;
        for (const Job& j : jobs)
            if (keep(j)) s.push_back(&j);
        return s;
    };
    const int width = std::max(8, runs * 5 + 1);
    out << "collisions per run, * = deadlock (as Tables I and II)\n"
        << std::left << std::setw(6) << "";
    for (rb::Strategy s : strategies) out << "| " << std::setw(width) << rb::strategyName(s);
    out << "| DL | CL\n";
    for (rb::Coupling c : couplings) {
        out << std::setw(6) << rb::couplingName(c);
        for (rb::Strategy s : strategies) {
            std::ostringstream cell;
            for (const Job* j : select([&](const Job& j) { return j.coupling == c && j.strategy == s; }))
                cell << j->result.collisions << (j->result.deadlocked ? "* " : "  ");
            out << "| " << std::setw(width) << cell.str();
        }
        const auto row = select([&](const Job& j) { return j.coupling == c; });
        out << "| " << std::setw(3) << deadlocks(row) << "| " << collisionText(row) << '\n';
    }
    out << std::setw(6) << "DL";
    for (rb::Strategy s : strategies) out << "| " << std::setw(width) << deadlocks(select([&](const Job& j) { return j.strategy == s; }));
    out << "| " << deadlocks(select([](const Job&) { return true; })) << '\n'
        << std::setw(6) << "CL";
    for (rb::Strategy s : strategies) out << "| " << std::setw(width) << collisionText(select([&](const Job& j) { return j.strategy == s; }));
    out << "| " << collisionText(select([](const Job&) { return true; })) << "\n\nmoves per metamodule (as Fig. 5)\n"
        << std::setw(6) << "";
    for (rb::Strategy s : strategies) out << "| " << std::setw(width) << rb::strategyName(s);
    out << "| mean\n"
        << std::fixed << std::setprecision(1);
    for (rb::Coupling c : couplings) {
        out << std::setw(6) << rb::couplingName(c);
        double sum = 0;
        int n = 0;
        for (rb::Strategy s : strategies) {
            std::ostringstream cell;
            cell << std::fixed << std::setprecision(1);
            for (const Job* j : select([&](const Job& j) { return j.coupling == c && j.strategy == s; }))
                cell << j->result.meanMoves << ' ', sum += j->result.meanMoves, ++n;
            out << "| " << std::setw(width) << cell.str();
        }
        out << "| " << sum / std::max(1, n) << '\n';
    }
    out << std::right;
}

int run(const RoombotsArgs& a, const CLI::App& sub) {
    if (!a.makeClouds.empty()) {
        // It computes the table and stops: an option of the runs given with it was dropped in
        // silence (and --structure FILE --make-clouds FILE replaced the structure).
        // Every option but these is one of the runs', a new one included.
        std::string dropped;
        for (const CLI::Option* option : sub.get_options())
            if (option->count() > 0 && option->get_name() != "--make-clouds" && option->get_name() != "--timeout" && option->get_name() != "--quiet")
                dropped += (dropped.empty() ? "" : ", ") + option->get_name();
        if (!dropped.empty()) throw InputError("--make-clouds computes the collision-cloud table and stops, so " + dropped + " would do nothing; leave them out, or run without --make-clouds");
        const rules::OutputFile file("--make-clouds", a.makeClouds);  // checked before the table is computed
        const rules::StopSignals guard(true);
        rb::CloudTable table;
        try {
            table = rb::CloudTable::compute(Budget(a.timeout) || Budget::onSignals());
        } catch (const OutOfTime& e) {
            throw timeoutBeforeOutput(a.timeout, "while computing the collision-cloud table");
        }
        file.write([&](std::ostream& out) { out << table.json(); });
        std::cout << "wrote " << table.size() << " transitions to " << a.makeClouds << '\n';
        return 0;
    }
    // One budget for the recipes and every run: the deadline, and SIGINT or SIGTERM, which stop the
    // runs before their next action (a run cut short is dropped) so the tables hold whole runs.
    const Budget budget = Budget(a.timeout) || Budget::onSignals();
    const rules::StopSignals guard(true);  // one-shot: a second signal ends holon at once
    if (!a.out.empty()) rules::prepareOutputDir("--out", a.out);
    // A name that is neither built in nor a file: the message lists the names.
    const auto known = [](const char* option, const std::string& name, const std::string& first, const std::string& second) {
        if (name != first && name != second && !std::filesystem::is_regular_file(name))
            throw InputError(std::string(option) + " '" + name + "': not " + first + " or " + second + ", and no such file; give " + first + ", " + second + " or a recipe file");
    };
    known("--structure", a.structure, "cube", "chair");
    known("--recipe", a.recipe, "given", "auto");
    // A configuration or strategy named twice ran twice, and its runs were counted twice.
    std::vector<rb::Coupling> couplings;
    for (const std::string& m : a.metamodules) {
        couplings.push_back(rb::parseCoupling(m));
        if (std::count(couplings.begin(), couplings.end(), couplings.back()) > 1) throw InputError("--metamodule " + m + ": named twice; name each configuration once");
    }
    std::vector<rb::Strategy> strategies;
    for (const std::string& s : a.strategies) {
        strategies.push_back(rb::parseStrategy(s));
        if (std::count(strategies.begin(), strategies.end(), strategies.back()) > 1) throw InputError("--strategy " + s + ": named twice; name each strategy once");
    }
    const std::vector<rb::Setting> settings = rb::loadScenario(a.structure, a.seed, a.runs, budget);
    const rb::CloudTable table = rb::CloudTable::load(a.clouds.empty() ? rb::CloudTable::defaultPath() : a.clouds);
    // The seeding order per metamodule configuration and run: the structure's, or derived (--recipe auto).
    std::map<std::pair<rb::Coupling, int>, rb::Setting> runSettings;
    for (rb::Coupling c : couplings)
        for (int r = 0; r < static_cast<int>(settings.size()); ++r) runSettings[{c, r}] = settings[r];
    if (a.recipe != "given" && a.recipe != "auto") {
        const rb::Recipe recipe = rb::loadRecipe(a.recipe, settings.front().recipe, budget);
        for (auto& [key, setting] : runSettings) setting.recipe = recipe;
    }
    if (a.recipe == "auto") {
        std::vector<std::pair<rb::Coupling, int>> keys;
        for (const auto& [key, setting] : runSettings) keys.push_back(key);
        std::atomic<int> derived{0};
        runParallel(
            static_cast<int>(keys.size()), a.threads, false, "recipes", [&](int k) {
                rb::Setting& s = runSettings[keys[k]];
                try {
                    s.recipe = rb::automaticRecipe(table, keys[k].first, s, budget);
                    ++derived;
                } catch (const rb::AssemblyStopped&) {
                }
            },
            budget);
        if (derived < static_cast<int>(keys.size()) && budget.interrupted()) throw Interrupted(budget.signal());
        if (derived < static_cast<int>(keys.size()))
            throw timeoutBeforeOutput(a.timeout, "while deriving the recipes, before any run");
    }

    for (rb::Coupling c : couplings)  // a shape the configuration cannot take is the structure's fault, not the strategy's
        for (int s : rb::unfillableSeeds(table, c, settings.front())) {
            const auto& cells = settings.front().recipe.seeds[s].cells;
            std::cerr << "holon: warning: seed " << s << " (" << rb::shapeName(rb::classify(cells)) << " from " << cells[0].x << ','
                      << cells[0].y << ") is a posture no " << rb::couplingName(c) << " metamodule can take; its runs will deadlock\n";
        }
    std::vector<Job> jobs;
    for (rb::Coupling c : couplings)
        for (rb::Strategy s : strategies)
            for (int r = 0; r < static_cast<int>(settings.size()); ++r) jobs.push_back({c, s, r, {}});
    // Memory before the runs: each run's world (the floor around seeds and starts, its clouds),
    // about 1 MiB counted as 16 per thread, and its kept result (trace, snapshots: about 9 KiB
    // measured on the cube, counted as 64).
    const int parallel = std::min(static_cast<int>(jobs.size()), a.threads > 0 ? a.threads : std::max(1, static_cast<int>(std::thread::hardware_concurrency())));
    rules::requireMemory((std::uint64_t{16} << 20) * std::uint64_t(parallel) + (std::uint64_t{64} << 10) * jobs.size(), a.memoryMiB << 20,
                         std::to_string(jobs.size()) + " runs (" + std::to_string(parallel) + " at once)");
    if (!a.out.empty()) rules::removeEarlierOutputs(a.out, {kTrace.pattern(), kFeet.pattern(), kAssembly.pattern(), kSteps.pattern(), kCoordination.pattern()});
    rb::AssemblyOptions options;
    options.stallSteps = a.stall;
    options.budget = budget;  // a run the budget cuts short is dropped, not counted
    // Each run's files are written when it ends, one run at a time: written after the last run, 4
    // files a run took seconds past --timeout or a signal (2.4 s with --timeout 1; audit 7).
    WriteErrors errors;
    std::mutex writing;
    runParallel(
        static_cast<int>(jobs.size()), a.threads, !a.quiet && !a.json && isatty(STDERR_FILENO), "runs", [&](int k) {
            const rb::Setting& setting = runSettings.at({jobs[k].coupling, jobs[k].run});
            try {
                jobs[k].result = rb::assemble(table, jobs[k].coupling, jobs[k].strategy, setting, options);
                jobs[k].ran = true;
            } catch (const rb::AssemblyStopped&) {
                return;
            }
            if (a.out.empty()) return;
            const std::lock_guard lock(writing);
            writeRun(a.out, jobs[k], setting, errors);
        },
        budget);
    // Stopped by the budget: the tables and files hold the runs made, each whole.
    const std::size_t planned = jobs.size();
    jobs.erase(std::remove_if(jobs.begin(), jobs.end(), [](const Job& j) { return !j.ran; }), jobs.end());
    const StopReason stopped = jobs.size() < planned ? budget.reached().value_or(StopReason::Timeout) : StopReason::Finished;
    const std::string stoppedText = (stopped == StopReason::Interrupted ? "interrupted: " : "stopped by --timeout: ") + std::to_string(jobs.size()) + " of " + std::to_string(planned) + " runs made";

    int completed = 0, dl = 0, clean = 0, all = 0;
    double moves = 0;
    for (const Job& j : jobs) {
        completed += j.result.completed, dl += j.result.deadlocked, all += j.result.collisions;
        clean += j.result.deadlocked ? 0 : j.result.collisions;
        moves += j.result.meanMoves;
    }
    moves /= std::max<std::size_t>(1, jobs.size());
    if (a.json) {
        nlohmann::json runs = nlohmann::json::array();
        for (const Job& j : jobs)
            runs.push_back({{"metamodule", rb::couplingName(j.coupling)}, {"strategy", rb::strategyName(j.strategy)}, {"run", j.run}, {"recipe", runSettings.at({j.coupling, j.run}).recipe.name}, {"completed", j.result.completed}, {"deadlocked", j.result.deadlocked}, {"collisions", j.result.collisions}, {"moves", j.result.moves}, {"mean_moves", j.result.meanMoves}, {"seconds", j.result.seconds}, {"deadlock_reason", j.result.reason}});
        std::cout << nlohmann::json{{"structure", a.structure}, {"runs", runs}, {"completed", completed}, {"collisions", clean}, {"collisions_all_runs", all}, {"deadlocks", dl}, {"mean_moves", moves}, {"stopped", stopReasonName(stopped)}}.dump()
                  << '\n';
        errors.raise();
        return exitCodeFor(stopped, budget.signal());
    }
    std::cout << a.structure << ": " << settings.front().recipe.seeds.size() << " metamodules, " << settings.size() << (settings.size() == 1 ? " run" : " runs") << " per cell (";
    for (int r = 0; r < static_cast<int>(settings.size()); ++r) std::cout << (r ? ", " : "") << runSettings.at({couplings.front(), r}).recipe.name;
    std::cout << ")\n";
    if (a.recipe == "auto")
        for (rb::Coupling c : couplings) {
            std::cout << "  auto recipe, " << rb::couplingName(c) << ":";
            for (int r = 0; r < static_cast<int>(settings.size()); ++r) {
                std::cout << (r ? " |" : "");
                for (const rb::Seed& seed : runSettings.at({c, r}).recipe.seeds) {
                    int index = 0;
                    while (settings[r].recipe.seeds[index].cells != seed.cells) ++index;
                    std::cout << ' ' << index;
                }
            }
            std::cout << "  (" << runSettings.at({c, 0}).recipe.name << ")\n";
        }
    std::cout << '\n';
    printTables(std::cout, couplings, strategies, jobs, static_cast<int>(settings.size()));
    std::cout << "\n"
              << completed << " of " << jobs.size() << " runs completed, " << dl << " deadlocked; " << clean
              << " collisions in runs that did not deadlock (" << all << " in all); " << std::setprecision(1) << moves
              << " moves per metamodule\n";
    if (stopped != StopReason::Finished) std::cout << stoppedText << '\n';
    errors.raise();  // after the tables: the runs' results are printed even when their files are not written
    return exitCodeFor(stopped, budget.signal());
}

}  // namespace

Run addRoombotsCommand(CLI::App& app) {
    auto a = std::make_shared<RoombotsArgs>();
    CLI::App* sub = app.add_subcommand("roombots", "assemble furniture from Roombots metamodules walking on a structured floor (seed 001)");
    sub->add_option("--structure", a->structure, "cube (experiment I), chair (experiment II) or a recipe file");
    sub->add_option("--metamodule", a->metamodules, "metamodule configurations: PAR PER SRS SRZ (default all)")->delimiter(',');
    sub->add_option("--strategy", a->strategies, "greedy slope step (the paper's, default) and/or reserve (holon's)")->delimiter(',');
    sub->add_option("--recipe", a->recipe, "given (the structure's seeding order, default), auto (derived from the kinematics) or a recipe file");
    sub->add_option("--runs", a->runs, "runs per configuration and strategy, 1 to 1000 (default: the paper's 3 for cube, 4 for chair)")->check(CLI::Range(1, 1000));
    sub->add_option("--seed", a->seed, "random seed of the shifted starts")->check(seedValidator());
    sub->add_option("--stall", a->stall, "K: a deadlock is K steps in which no metamodule comes closer to an active seed (1 to 10000; default " + std::to_string(a->stall) + ")")->check(CLI::Range(1, 10000));
    sub->add_option("--clouds", a->clouds, "collision-cloud table (default: the one shipped with holon)");
    sub->add_option("--make-clouds", a->makeClouds, "compute the collision-cloud table from the kinematics, write it to FILE and stop");
    addThreads(sub, a->threads, "one run each");
    addTimeout(sub, a->timeout, "a run in progress is dropped and the tables hold the runs made");
    addMemory(sub, a->memoryMiB, "checked before the runs");
    sub->add_option("--out", a->out, "directory for per-run traces (CSV), foot-trace pictures and assembly snapshots (SVG), and each run action by action for holon view (steps_*.jsonl) (created if missing; its parent must exist)");
    sub->add_flag("--json", a->json, "print a JSON summary");
    sub->add_flag("--quiet", a->quiet, "no progress bar");
    return [a, sub] { return withinMemory(a->memoryMiB, [&] { return run(*a, *sub); }); };
}

}  // namespace holon::cli
