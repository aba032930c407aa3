// `holon plan --rules FILE --from SHAPE --to SHAPE`: run seed 000's U/P/F planner, compiled from
// a verified rule file, on a start and a target shape, with a resource allocator for general_n.
// Every output path is checked before the run; SIGINT or SIGTERM stops the run at the next round,
// writes what it has as complete files (the summary marked interrupted) and exits 128 + signal.

#include "checker/Forked.h"
#include "cli/Commands.h"
#include "cli/Inputs.h"
#include "cli/Limits.h"
#include "cli/PlanProof.h"
#include "cli/WriteErrors.h"
#include "planner/Diagnosis.h"
#include "planner/Execution.h"
#include "planner/Faults.h"
#include "planner/Monitor.h"
#include "planner/Report.h"
#include "planner/hex/DiskMetamodules.h"
#include "rules/Budget.h"
#include "rules/ConfigIo.h"
#include "rules/Error.h"
#include "rules/Library.h"
#include "rules/Limits.h"
#include "rules/OutputFile.h"
#include "rules/StopSignals.h"
#include "viewer/Page.h"
#include "viewer/Readers.h"

#include <nlohmann/json.hpp>

#include <charconv>
#include <csignal>
#include <filesystem>
#include <functional>
#include <iomanip>
#include <iostream>
#include <optional>
#include <signal.h>
#include <unistd.h>

namespace holon::cli {

namespace {

/// Where a run that stopped short is stuck: how many cells the goal does not accept yet, and the
/// first few with their states and the rule each waits on.
void printShortOfGoal(const planner::Problem& problem, const planner::Execution& execution) {
    const auto [cells, count] = planner::cellsShortOfGoal(execution, 5);
    if (count == 0) return;
    std::cout << "  " << count << (count == 1 ? " cell is" : " cells are") << " short of the goal" << (count > 5 ? ", the first 5:\n" : ":\n");
    const planner::BoardConfiguration board(problem, execution.cells());
    for (std::int64_t i : cells)
        std::cout << "    " << planner::showCell(problem.board->point(i), problem.board->lattice().dimension()) << ' '
                  << rules::stateFields(*problem.model, execution.cells()[i]).dump() << ' ' << planner::waitingOn(problem, board, i) << '\n';
}

/// The transfer bound the child computed; -1 when the run was stopped short and it did not wait,
/// or when the child ran out of memory or was killed (said on standard error: the plan stands).
std::int64_t lowerBoundOf(checker::ForkedTask& task, const Budget& budget) {
    const std::optional<nlohmann::json> answer = task.answer(budget);
    if (!answer) return -1;
    if (answer->contains("bound")) return answer->at("bound").get<std::int64_t>();
    const std::string why = answer->value("error", answer->dump());
    if (!answer->value("resources", false)) throw InternalError("the transfer lower bound: " + why);
    std::cerr << "holon plan: warning: no transfer lower bound: its process failed (" << why << ")\n";
    return -1;
}

struct PlanArgs {
    std::string rules = "planner_intermediate", from, to, allocator = "random", scheduler = "sync", out, planOut, seedCell, traceOut, hexDisks, html;
    std::string requireProof;  // --require-proof's list; every declared property when given bare
    const CLI::Option* requireProofOption = nullptr;
    const CLI::Option* allocatorOption = nullptr;
    std::vector<std::string> noWarnings, lose, loseRandom;
    std::int64_t delay = 0;
    double drop = 0;
    std::optional<std::uint64_t> faultSeed;
    int scale = 1;
    std::uint64_t seed = planner::RunOptions{}.seed;
    int threads = planner::RunOptions{}.threads;
    std::uint64_t maxSteps = 0, maxRounds = 0;
    double timeout = 0;  // 0: the option left out, no limit
    std::uint64_t memoryMiB = kDefaultMemoryMiB;
    bool check = false, json = false, quiet = false;
};

/// --seed-cell x,y (2D shapes) or x,y,z (3D): as many coordinates as the shapes have dimensions.
std::optional<planner::Vec> parseCell(const std::string& text, int dimension) {
    if (text.empty()) return std::nullopt;
    const std::string want = dimension == 3 ? "x,y,z" : "x,y";
    std::vector<int> v;
    std::istringstream in(text);
    for (std::string part; std::getline(in, part, ',');) {
        int value = 0;
        const auto [end, ec] = std::from_chars(part.data(), part.data() + part.size(), value);
        if (part.empty() || ec != std::errc{} || end != part.data() + part.size())
            throw InputError("--seed-cell '" + text + "': '" + part + "' is not an integer; give " + want);
        v.push_back(value);
    }
    if (text.back() == ',') throw InputError("--seed-cell '" + text + "': ends with ','; give " + want);
    if (static_cast<int>(v.size()) != dimension)
        throw InputError("--seed-cell '" + text + "': " + std::to_string(v.size()) + " coordinates, but the shapes are " + std::to_string(dimension) + "D; give " + want);
    return planner::Vec{v[0], v[1], dimension == 3 ? v[2] : 0};
}

constexpr std::size_t kMaxDiskMetamodules = 500;  // every move is written out, about 2,300 per template (80 bytes each), and replayed

/// --hex-disks: the plan's disk moves (JSON Lines), start and end pictures, and an independent
/// replay of every move. Returns false when a template had no disk motion or the replay failed; a
/// file that cannot be written is added to `errors`. An interrupted plan's moves are written, not
/// judged: the last templates are unfinished. What it did is said on `out`.
bool writeDisks(const std::string& dir, const planner::hex::DiskMetamodules& disks, const planner::Execution& execution, bool failed,
                bool interrupted, WriteErrors& errors, std::ostream& out) {
    errors.attempt([&] {
        // Millions of lines for a few dozen metamodules: streamed (rule names are identifiers).
        rules::OutputStream moves = rules::OutputFile("--hex-disks", dir + "/disk_moves.jsonl").open();
        std::string line;
        for (const planner::hex::DiskMove& m : disks.moves()) {
            const auto pair = [&](planner::Vec v) { line += '[' + std::to_string(v.x) + ',' + std::to_string(v.y) + ']'; };
            line = "{\"instance\":" + std::to_string(m.instance) + ",\"rule\":\"" + m.rule + "\",\"from\":";
            pair(m.from), line += ",\"to\":", pair(m.to), line += ",\"pivot\":", pair(m.pivot), line += "}\n";
            moves.stream() << line;
        }
        moves.commit();
    });
    errors.attempt([&] { rules::OutputFile("--hex-disks", dir + "/disks.svg").write(planner::hex::disksSvg({{"start", disks.startDisks()}, {"end", disks.disks()}})); });
    errors.attempt([&] { rules::OutputFile("--hex-disks", dir + "/creation.svg").write(planner::hex::sequenceSvg(disks.design(), 0, 6)); });
    out << "  hex disks: " << disks.side() << "x" << disks.side() << " disks per metamodule slot, " << disks.disksPerUnit()
        << " per unit of mass (the ring); creation " << disks.design().base(0).size() << " pivot moves; " << disks.moves().size() << " pivot moves in all, in "
        << dir << "/disk_moves.jsonl, disks.svg and creation.svg\n";
    if (interrupted) {
        out << "  hex disks: the plan was interrupted; the moves so far are written, not replayed\n";
        return true;
    }
    if (failed) {
        out << "  hex disks FAILED: " << disks.failure() << '\n';
        return false;
    }
    std::string why;
    if (!disks.slotsMatch(execution.cells(), why)) {
        out << "  hex disks FAILED: " << why << '\n';
        return false;
    }
    const std::string fault = planner::hex::replayDiskMoves(disks.startDisks(), disks.moves());
    out << "  hex disks replayed: " << (fault.empty() ? "every move a pivot into an empty cell, all disks connected after each" : "FAILED at " + fault) << '\n';
    return fault.empty();
}

/// --drop P: a probability strictly between 0 and 1 (0 injects nothing; 1 would never deliver a
/// relabel, so no run could complete).
CLI::Validator probabilityValidator() {
    return CLI::Validator(
        [](std::string& text) {
            std::size_t used = 0;
            double p = 0;
            try {
                p = std::stod(text, &used);
            } catch (const std::exception&) {
                used = 0;
            }
            return used == text.size() && p > 0 && p < 1 ? std::string() : "'" + text + "' is not a probability strictly between 0 and 1 (1 would never deliver a relabel)";
        },
        "P");
}

/// A system fixed to a lattice plan does not run on: plan picks the lattice from the shapes
/// (square2d for 2D, cubic3d for 3D), so the fix is the rule file or the shapes, not a region.
void requirePlanLattice(const rules::System& system, const rules::Lattice& lattice) {
    if (!system.lattice || *system.lattice == lattice.kind()) return;
    const rules::Lattice& fixed = rules::Lattice::get(*system.lattice);
    const bool otherDimension = fixed.kind() != rules::LatticeKind::Hex2D;  // square2d or cubic3d: the shapes' dimension decides
    throw InputError("--rules: system '" + system.name + "' is written for the " + fixed.name() + " lattice, but plan runs on " + lattice.name() +
                     " for these " + std::to_string(lattice.dimension()) + "D shapes (square2d for 2D shapes, cubic3d for 3D ones); give --rules a planner system for " +
                     lattice.name() + " (planner_intermediate, planner_general1, ...)" +
                     (otherDimension ? ", or --from and --to as " + std::to_string(fixed.dimension()) + "D shapes" : std::string()));
}

int run(const PlanArgs& a) {
    // One budget for every phase: setup (shapes, board) and the run share the deadline and the
    // stop flag of the signal catcher below.
    const Budget budget = Budget(a.timeout) || Budget::onSignals();
    // From here on a signal stops the job: during setup at the next phase (exit 128 + it, nothing
    // written), during the run at a round boundary with the files still written. Without the
    // catcher a signal during a long setup killed holon without a word.
    const rules::StopSignals guard(true);  // one-shot: a second signal ends holon at once
    const auto during = [&](const std::string& phase) {
        if (budget.interrupted()) throw Interrupted(budget.signal());
        if (budget.expired()) throw timeoutBeforeOutput(a.timeout, "while " + phase + ", before the plan ran");
    };
    // Names and output paths are checked before any work: a finished plan is never lost to a
    // typo, and a misspelt name does not wait for a large board to be laid out.
    const planner::AllocatorKind allocatorKind = planner::allocatorKind(a.allocator);
    planner::RunOptions options;
    if (a.scheduler == "sync") options.scheduler = planner::Scheduler::Sync;
    else if (a.scheduler == "async") options.scheduler = planner::Scheduler::Async;
    else if (a.scheduler == "adversarial") options.scheduler = planner::Scheduler::Adversarial;
    else throw InputError("--scheduler '" + a.scheduler + "': choose sync, async or adversarial");
    if (!a.out.empty()) rules::prepareOutputDir("--out", a.out, planner::Report::outDirFiles());
    if (!a.planOut.empty()) rules::OutputFile("--plan-out", a.planOut);
    // The viewer reads the plan back from its file once it is complete.
    if (!a.html.empty() && a.planOut.empty()) throw InputError("--html needs --plan-out FILE: the viewer plays the plan written there");
    if (!a.html.empty()) rules::OutputFile("--html", a.html);
    if (!a.hexDisks.empty()) rules::prepareOutputDir("--hex-disks", a.hexDisks);
    std::optional<rules::OutputFile> traceFile;
    if (!a.traceOut.empty() && !a.check) throw InputError("--trace-out writes the round the monitor finds violating, and without --check nothing monitors the plan; add --check");
    if (!a.traceOut.empty()) traceFile.emplace("--trace-out", a.traceOut);
    else if (!a.out.empty()) traceFile.emplace("--out", a.out + "/violation.itf.json");

    auto system = loadRules(a.rules, a.noWarnings, "--rules");
    if (!system) return 2;
    const std::uint64_t memory = a.memoryMiB << 20;
    planner::Shape from = planner::parseShape(a.from, a.scale, memory);
    during("making the shapes");  // between the two: each of box:7000x7000's took 1.5 s
    planner::Shape to = planner::parseShape(a.to, a.scale, memory - std::min(memory, from.cells.size() * sizeof(planner::Vec)));
    during("making the shapes");
    const rules::Lattice& lattice = rules::Lattice::get(from.dimension == 3 ? rules::LatticeKind::Cubic3D : rules::LatticeKind::Square2D);
    requirePlanLattice(*system, lattice);
    // Before any work: a plan --require-proof refuses is refused at once.
    const PlanProof proof = planProof(a.rules, *system, lattice.name());
    if (a.requireProofOption->count() > 0) requireProof(proof, requiredProperties(a.requireProof, *system));
    rules::Model model(*system, lattice);
    const std::optional<planner::Vec> seedCell = parseCell(a.seedCell, from.dimension);
    planner::Problem problem = planner::makeProblem(model, std::move(from), std::move(to), seedCell, a.seed, memory, [&] { during("laying out the board"); });
    // An option that cannot act is refused, not passed over in silence.
    if (a.allocatorOption->count() > 0 && !planner::movesResources(problem))
        throw InputError("--allocator " + a.allocator + ": " + system->name + " has no transfers, so there is nothing to allocate; leave --allocator out");
    std::unique_ptr<planner::Allocator> allocator = planner::makeAllocator(allocatorKind, problem, a.seed);
    during("laying out the board");

    options.seed = a.seed;
    options.threads = a.threads;
    options.budget = budget || Budget::maxSteps(a.maxSteps) || Budget::maxRounds(a.maxRounds);

    planner::FaultOptions faultOptions;
    for (const std::string& text : a.lose) faultOptions.losses.push_back(planner::parseLoss("--lose", text, lattice.dimension(), true));
    for (const std::string& text : a.loseRandom) faultOptions.losses.push_back(planner::parseLoss("--lose-random", text, lattice.dimension(), false));
    faultOptions.delay = a.delay, faultOptions.drop = a.drop, faultOptions.seed = a.faultSeed.value_or(a.seed);
    options.messageDelay = a.delay;
    if (a.faultSeed && a.loseRandom.empty() && a.delay == 0 && a.drop == 0)
        throw InputError("--fault-seed draws the random faults, and none is given; add --lose-random, --delay or --drop, or leave --fault-seed out");
    std::unique_ptr<planner::Faults> faults = faultOptions.any() ? std::make_unique<planner::Faults>(problem, faultOptions) : nullptr;
    const planner::Execution* running = nullptr;  // the admit hook is called only while it runs
    if (faults) options.admit = [&](std::int64_t anchor, int shape) { return faults->admit(*running, anchor, shape); };

    std::unique_ptr<planner::hex::DiskMetamodules> disks;
    if (!a.hexDisks.empty()) {
        if (!faultOptions.losses.empty()) throw InputError("--hex-disks: a lost metamodule has no disk motion to realise; leave out --lose and --lose-random, or --hex-disks");
        if (problem.start.cells.size() + problem.target.cells.size() > kMaxDiskMetamodules)
            throw InputError("--hex-disks: at most " + std::to_string(kMaxDiskMetamodules) + " metamodules in start and target together (every disk move, about 2,300 a template, is written out and replayed); use a smaller --scale");
        disks = std::make_unique<planner::hex::DiskMetamodules>(problem);
    }
    during("preparing the run");
    planner::Execution execution(problem, *allocator, options);
    running = &execution;
    planner::Report report(problem, execution, {a.out, a.planOut, "--out", "--plan-out", !a.quiet && isatty(STDERR_FILENO) != 0});
    std::unique_ptr<planner::Monitor> monitor = a.check ? std::make_unique<planner::Monitor>(problem, execution) : nullptr;
    bool disksFailed = false;
    planner::RunObserver observer;
    observer.fired = [&](std::int64_t anchor, int shape, const planner::BoxEngine::Value* old) {
        report.fired(anchor, shape, old);
        if (monitor) monitor->fired(anchor, shape, old);
        if (disks && !disksFailed) disksFailed = !disks->fired(anchor, shape, old, execution.cells());
        if (faults) faults->fired(execution, anchor, shape, old);
    };
    observer.roundEnd = [&](const planner::RunStats& stats) {
        report.roundEnd(stats);
        if (monitor && !monitor->roundEnd(stats)) return false;
        if (faults)
            faults->roundEnd(execution, [&](std::int64_t cell, planner::BoxEngine::Value old) {
                report.lost(cell);
                if (monitor) monitor->lost(cell, old);
            });
        return true;
    };
    // The transfer bound, a min-cost flow over the board, takes minutes at 10^6 metamodules (118 s
    // on the block at K = 31): a child process solves it on the other core while the plan runs.
    std::optional<checker::ForkedTask> bound;
    if (planner::movesResources(problem)) bound.emplace([&](bool) { return nlohmann::json{{"bound", planner::transferLowerBound(problem)}}; });
    const planner::RunStats stats = execution.run(observer);
    // After a loss that broke the lemmas' hypotheses the end is the fault's configuration, not the
    // planner's: the monitor's last word is the round before it.
    if (monitor && !(faults && !faults->broken().empty())) monitor->finish(stats);
    const bool interrupted = stats.stopped == StopReason::Interrupted;
    // A plan stopped by --timeout or a signal does not wait for the bound (the child is killed).
    const std::int64_t lowerBound = bound ? lowerBoundOf(*bound, budget) : -1;
    // What produced the run: summary.json and --json say the same.
    nlohmann::json about = {{"system", system->name}, {"allocator", allocator->name()}, {"scheduler", a.scheduler}, {"seed", a.seed}, {"proof", proof.json()}};
    if (faults) about["faults"] = faults->json();
    for (const auto& [key, value] : about.items()) report.addSummary(key, value);
    report.finish(stats, lowerBound);
    WriteErrors errors;
    for (const std::string& e : report.writeErrors()) errors.add(e);
    // A signal while the page is built (seconds at 10^6 metamodules) stops it: the page is not
    // written, the summary is still printed, and the exit says the signal.
    int pageSignal = 0;
    bool pageTimedOut = false;
    if (!a.html.empty() && report.writeErrors().empty()) {
        try {
            errors.attempt([&] { rules::OutputFile("--html", a.html).write(viewer::page(viewer::readRun(a.planOut, "", a.memoryMiB << 20))); });
        } catch (const Interrupted& e) {
            pageSignal = e.signal();
            std::cerr << "holon plan: --html " << a.html << " not written: " << e.what() << " while the page was built\n";
        } catch (const LimitError& e) {
            pageTimedOut = true;  // the deadline, or the page over --memory (whose message says to raise it)
            const bool timeout = e.parameter() == rules::Parameter::Timeout;
            std::cerr << "holon plan: --html " << a.html << " not written: " << e.what() << (timeout ? "; raise --timeout" : "") << '\n';
        }
    }

    if (a.json) {
        nlohmann::json j = planner::runSummary(problem, execution, stats, lowerBound);
        j.update(about);
        std::cout << j.dump(2) << '\n';
    } else {
        std::cout << "plan " << problem.start.name << " -> " << problem.target.name << " with " << system->name << " (" << a.scheduler
                  << ", allocator " << allocator->name() << ", seed " << a.seed << ")\n"
                  << "  proof: " << proof.line() << '\n'
                  << "  start " << problem.start.cells.size() << " metamodules, target " << problem.target.cells.size() << ", seed cell ("
                  << problem.seed.x << "," << problem.seed.y << (lattice.dimension() == 3 ? "," + std::to_string(problem.seed.z) : "") << ")\n"
                  << "  creations " << stats.creations << ", deletions " << stats.deletions << ", transfers " << stats.transfers;
        if (lowerBound >= 0) std::cout << " (lower bound " << lowerBound << ")";
        std::cout << ", relabels " << stats.relabels << "\n  " << stats.rounds << " rounds, " << stats.steps << " steps, " << stats.evaluations
                  << " rule evaluations, " << std::fixed << std::setprecision(3) << stats.seconds << " s\n  ";
        if (stats.complete) std::cout << "complete: the target is reached\n";
        else if (interrupted) std::cout << "NOT complete: interrupted by " << Interrupted::signalName(budget.signal()) << " after round " << stats.rounds << "\n";
        else if (faults && !faults->broken().empty()) std::cout << "NOT complete: stopped by a fault: " << faults->broken() << '\n';
        else std::cout << "NOT complete: stopped by " << stopReasonName(stats.stopped) << '\n';
        if (faults) std::cout << "  faults: " << faults->summary() << '\n';
        if (!stats.complete) printShortOfGoal(problem, execution);
        if (monitor) std::cout << "  monitor: " << monitor->summary() << '\n';
        if (!a.out.empty() && errors.empty())
            std::cout << "  wrote " << a.out << "/ (summary.json" << (interrupted ? ", marked interrupted" : "") << ", completion.csv, snapshots"
                      << (stats.complete ? "" : ", end.json: the end configuration, for holon check --from") << ")\n";
    }
    // Under --json, stdout holds the JSON alone: the disks' lines go to stderr.
    const bool disksOk = !disks || writeDisks(a.hexDisks, *disks, execution, disksFailed, interrupted, errors, a.json ? std::cerr : std::cout);
    const bool violated = monitor && monitor->violated();
    if (violated && traceFile) {
        errors.attempt([&] {
            monitor->writeTrace(*traceFile);
            std::cout << "  the violating step is in " << traceFile->path() << '\n';
        });
    }
    // A file that could not be written outranks the verdict: the summary above is all there is.
    errors.raise();
    if (pageSignal != 0) return exitCodeFor(StopReason::Interrupted, pageSignal);
    if (pageTimedOut) return exitCodeFor(StopReason::Timeout, 0);
    if (!interrupted && (!disksOk || violated)) return kExitViolated;
    return exitCodeFor(stats.stopped, budget.signal());
}

}  // namespace

Run addPlanCommand(CLI::App& app) {
    auto a = std::make_shared<PlanArgs>();
    CLI::App* sub = app.add_subcommand("plan", "run the U/P/F planner compiled from a rule file, from a start shape to a target shape");
    std::string shapes;
    for (const auto& [name, what] : planner::shapeGenerators()) shapes += "\n    " + name + ": " + what;
    sub->footer("SHAPE is a generator or a file (.json cell list, .xyz voxels, .binvox, a VisibleSim world .xml or its target WORLD.xml#target, ASCII art):" + shapes);
    addRulesFile(sub, "--rules", a->rules, "the planner");
    sub->add_option("--from", a->from, "start shape")->required();
    sub->add_option("--to", a->to, "target shape")->required();
    sub->add_option("--scale", a->scale, "every cell becomes a KxK (3D: KxKxK) block (1 to 2^29: beyond it no cell fits the coordinate range)")->check(CLI::Range(1, rules::kMaxCoordinate));
    a->allocatorOption = sub->add_option("--allocator", a->allocator, "resource allocator for general_n: " + planner::allocatorChoices() + " (default " + a->allocator + ")");
    sub->add_option("--scheduler", a->scheduler, "sync (rounds, default), async (one instance at a time) or adversarial");
    sub->add_option("--seed", a->seed, "random seed (default " + std::to_string(a->seed) + ")")->check(seedValidator());
    sub->add_option("--seed-cell", a->seedCell, "the seed metamodule x,y[,z] (default: the overlap cell nearest its centre)");
    sub->add_flag("--check", a->check, "monitor after every step or round that the ensemble stays connected, conserves mass (where the system says so) and holds only states of its alphabet");
    sub->add_flag("--json", a->json, "print the summary as JSON");
    sub->add_option("--out", a->out, "write summary.json, completion.csv and SVG snapshots into this folder (created if missing; its parent must exist)");
    sub->add_option("--hex-disks", a->hexDisks, "2D general_n plans: realise every template as pivot moves of hex-lattice disks (seed 000 Fig. 4a); write disk_moves.jsonl and disks.svg into this folder");
    sub->add_option("--plan-out", a->planOut, "write the plan as JSON Lines (one fired instance per line)");
    sub->add_option("--html", a->html, "with --plan-out: write the plan as a self-contained HTML viewer (docs/viewer.md)");
    addCap(sub, "--max-steps", a->maxSteps, "steps");
    addCap(sub, "--max-rounds", a->maxRounds, "rounds");
    addTimeout(sub, a->timeout, "the plan so far is written");
    addMemory(sub, a->memoryMiB, "checked before the shapes and the board are made");
    addThreads(sub, a->threads, "for a round's independent work on boards of 2^17 cells or more (at most 2 are used; the plan is the same for any number)");
    sub->add_option("--trace-out", a->traceOut, "with --check: write the violating round as an ITF JSON trace (default DIR/violation.itf.json with --out)");
    sub->add_option("--lose", a->lose, "fault: lose the metamodule at x,y[,z] after round ROUND (ROUND:x,y[,z]; repeatable); the run goes on when seed 000's lemmas still cover it, else stops and names what the loss broke (exit 1)");
    sub->add_option("--lose-random", a->loseRandom, "fault: lose a metamodule drawn at random (--fault-seed) after round ROUND (repeatable)");
    sub->add_option("--delay", a->delay, "fault: every state change reaches the neighbours 1 to D rounds later, drawn at random; an instance waits for the states it reads (1 to 10^6)")->check(CLI::Range(std::int64_t{1}, std::int64_t{1000000}));
    sub->add_option("--drop", a->drop, "fault: each time a relabel would fire, its message is lost with probability P and sent again later (0 < P < 1)")->check(probabilityValidator());
    sub->add_option("--fault-seed", a->faultSeed, "random seed of the faults: random losses, delays, drops (default: --seed)")->check(seedValidator());
    a->requireProofOption = sub->add_option("--require-proof", a->requireProof,
                                            "refuse to run (exit 2) unless the rules' certificate (holon verify --every-size) is valid and proves these properties "
                                            "for every region: --require-proof alone requires every declared property, --require-proof=termination,mass_conservation those")
                                ->expected(0, 1);
    sub->add_flag("--quiet", a->quiet, "no progress bar");
    sub->add_option("-W", a->noWarnings, "silence a warning: -W no-NAME");
    return [a] { return withinMemory(a->memoryMiB, [&] { return run(*a); }); };
}

}  // namespace holon::cli
