// `holon hex --from SHAPE --to SHAPE --size N`: seed 003's hole-motion sculpting on an N x N hex
// array, repeated --reps times with different seeds (in parallel on the machine's cores), reported
// as the paper's Table I row: modules, maximum compliance (mean, std), islands. The --out folder
// is checked before the runs; a file that cannot be written is reported after the table.

#include "cli/Commands.h"
#include "cli/Limits.h"
#include "cli/Parallel.h"
#include "cli/WriteErrors.h"
#include "planner/hex/HexShapes.h"
#include "planner/hex/SculptRun.h"
#include "planner/hex/SculptSteps.h"
#include "rules/Budget.h"
#include "rules/Error.h"
#include "rules/Limits.h"
#include "rules/OutputFile.h"
#include "rules/StopSignals.h"
#include "rules/Svg.h"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <functional>
#include <iomanip>
#include <iostream>
#include <optional>
#include <sstream>
#include <thread>
#include <unistd.h>

namespace holon::cli {

namespace {

struct HexArgs {
    planner::hex::SculptSetup setup;
    int reps = 1, threads = 0;  // threads 0: the option left out, the machine's cores
    double timeout = 0;         // 0: the option left out, no limit
    std::uint64_t memoryMiB = kDefaultMemoryMiB;
    std::uint64_t seed = 1;
    std::string out, stepsOut;
    bool json = false, quiet = false;
};

struct Stat {
    double mean = 0, std = 0;
};

Stat stat(const std::vector<planner::hex::SculptResult>& runs, double (*field)(const planner::hex::SculptResult&)) {
    Stat s;
    for (const auto& r : runs) s.mean += field(r);
    s.mean /= runs.size();
    for (const auto& r : runs) s.std += (field(r) - s.mean) * (field(r) - s.mean);
    s.std = runs.size() > 1 ? std::sqrt(s.std / (runs.size() - 1)) : 0.0;
    return s;
}

/// The mean over repetitions of each metric against time, as seed 003 Figs. 9, 11 and 12.
std::string seriesSvg(const std::vector<planner::hex::SculptResult>& runs, int steps) {
    if (steps == 0) return rules::Svg().document(1, 1);
    const double w = 640, h = 320, left = 40, bottom = 20;
    rules::Svg svg;
    for (int pct = 0; pct <= 100; pct += 20) {
        svg.text(2, 5 + h * (1 - pct / 100.0) + 4, std::to_string(pct) + "%");
        svg.line(left, 5 + h * (1 - pct / 100.0), left + w, 5 + h * (1 - pct / 100.0), {{"stroke", "#ddd"}});
    }
    svg.text(left + w - 80, h + bottom + 5, std::to_string(steps) + " timesteps");
    const struct {
        const char* name;
        const char* colour;
        float planner::hex::SculptSample::*field;
    } metrics[] = {
        {"completeness", "#1f6fd0", &planner::hex::SculptSample::completeness},
        {"stability", "#2a9d3a", &planner::hex::SculptSample::stability},
        {"compliance", "#111", &planner::hex::SculptSample::compliance}};
    int row = 0;
    for (const auto& m : metrics) {
        std::vector<std::pair<double, double>> points;
        const int stride = std::max(1, steps / 640);
        for (int t = 0; t < steps; t += stride) {
            double mean = 0;
            for (const auto& r : runs) mean += r.series[t].*m.field;
            mean /= runs.size();
            points.push_back({left + w * t / steps, 5 + h * (1 - mean)});
        }
        svg.polyline(points, {{"fill", "none"}, {"stroke", m.colour}});
        svg.text(left + 10, h - 40 + 14 * row++, m.name, {{"fill", m.colour}});
    }
    return svg.document(w + left + 10, h + bottom + 10, {{"font-size", 11}});
}

// What --out holds.
const rules::OutputNames kFrame{"frame_", ".svg"};
const std::string kSeriesSvg = "series.svg", kSeriesCsv = "series.csv";

/// series.svg and series.csv; a file that cannot be written is added to `errors`.
void writeOutputs(const HexArgs& a, const std::vector<planner::hex::SculptResult>& runs, int steps, WriteErrors& errors) {
    const auto attempt = [&](const std::string& name, const std::function<void(std::ostream&)>& fill) {
        errors.attempt([&] { rules::OutputFile("--out", (std::filesystem::path(a.out) / name).string()).write(fill); });
    };
    attempt(kSeriesSvg, [&](std::ostream& svg) { svg << seriesSvg(runs, steps); });
    attempt(kSeriesCsv, [&](std::ostream& csv) {
        csv << "step";
        for (std::size_t r = 0; r < runs.size(); ++r) csv << ",completeness" << r << ",stability" << r << ",compliance" << r << ",holes" << r;
        csv << '\n';
        for (int t = 0; t < steps; ++t) {
            csv << t + 1;
            for (const auto& run : runs)
                csv << ',' << run.series[t].completeness << ',' << run.series[t].stability << ',' << run.series[t].compliance << ',' << run.series[t].holes;
            csv << '\n';
        }
    });
}

/// The improvements over seed 003 a run uses, by flag name.
std::vector<std::string> improvements(const planner::hex::SculptOptions& o) {
    std::vector<std::string> on;
    const std::pair<bool, const char*> flags[] = {{o.dropOverhangs, "drop-overhangs"}, {o.flexibleGrowth, "flexible-growth"}, {o.roll, "roll"}, {o.deleteOverflow, "delete-overflow"}, {o.growInside, "grow-inside"}, {o.keepConnected, "keep-connected"}, {o.migrate, "migrate"}, {o.balance, "balance"}};
    for (const auto& [set, name] : flags)
        if (set) on.push_back(name);
    return on;
}

int run(HexArgs a) {
    // One budget for every run and every timestep: the deadline, and SIGINT or SIGTERM, which stop
    // the runs at a timestep boundary so that the table and the files hold whole timesteps.
    const Budget budget = Budget(a.timeout) || Budget::onSignals();
    const rules::StopSignals guard(true);  // one-shot: a second signal ends holon at once
    // The pictures are inputs before --out is prepared and its earlier files removed: a picture
    // saved in the folder as series.csv was deleted as an earlier output, then reported missing.
    for (const auto& [option, spec] : {std::pair{"--from", a.setup.from}, std::pair{"--to", a.setup.to}})
        if (planner::hex::isPictureFile(spec)) rules::OutputClaims::reading(option, spec);
    if (!a.out.empty()) rules::prepareOutputDir("--out", a.out);
    std::optional<rules::OutputStream> stepsFile;  // the first run, instance by instance
    if (!a.stepsOut.empty()) stepsFile.emplace(rules::OutputFile("--steps-out", a.stepsOut).open());
    // Memory before any array is made: the runs that go at once, and every run's series.
    const std::uint64_t perRun = planner::hex::sculptBytes(a.setup), series = static_cast<std::uint64_t>(a.setup.steps) * sizeof(planner::hex::SculptSample);
    const int parallel = std::min(a.reps, a.threads > 0 ? a.threads : std::max(1, static_cast<int>(std::thread::hardware_concurrency())));
    rules::requireMemory(rules::checkedProduct({perRun, std::uint64_t(parallel)}) + rules::checkedProduct({series, std::uint64_t(a.reps)}), a.memoryMiB << 20,
                         std::to_string(a.reps) + (a.reps == 1 ? " run of " : " runs of ") + std::to_string(a.setup.steps) + " timesteps on " + std::to_string(a.setup.size) + "x" +
                             std::to_string(a.setup.size) + " (" + std::to_string(parallel) + " at once)");
    if (!a.out.empty()) rules::removeEarlierOutputs(a.out, {kFrame.pattern(), kSeriesSvg, kSeriesCsv});
    std::vector<planner::hex::SculptResult> runs(a.reps);
    std::vector<char> ran(a.reps, 0);
    WriteErrors errors;  // written only by run 0 (the frames), read after every run has ended
    runParallel(
        a.reps, a.threads, !a.quiet && !a.json && isatty(STDERR_FILENO), "runs", [&](int r) {
            planner::hex::SculptSetup setup = a.setup;
            setup.options.seed = a.seed + r;
            const int last = setup.steps;
            std::optional<planner::hex::SculptSteps> steps;
            runs[r] = planner::hex::runSculpt(
                setup, [&](const planner::hex::HoleSculptor& s) {
                    if (steps) steps->timestepEnded();
                    if (!a.out.empty() && r == 0 && (s.time() == 1 || s.time() == last / 10 || s.time() == last)) {
                        errors.attempt([&] {
                            rules::OutputFile("--out", (std::filesystem::path(a.out) / kFrame.of(std::to_string(s.time()))).string()).write(planner::hex::sculptSvg(s));
                        });
                    } },
                budget,
                [&](const planner::hex::HoleSculptor& s) {
                    if (stepsFile && r == 0) steps.emplace(stepsFile->stream(), s);
                });
            ran[r] = runs[r].steps > 0;
        },
        budget);
    // Stopped by the budget: the runs that made at least one timestep, compared over the timesteps
    // all of them made; the files written are whole, and say so by their length.
    std::vector<planner::hex::SculptResult> kept;
    for (int r = 0; r < a.reps; ++r)
        if (ran[r]) kept.push_back(std::move(runs[r]));
    if (kept.empty() && budget.interrupted()) throw Interrupted(budget.signal());
    if (kept.empty()) throw timeoutBeforeOutput(a.timeout, "before the first timestep");
    runs = std::move(kept);
    int steps = a.setup.steps;
    for (const auto& r : runs) steps = std::min(steps, r.steps);
    const bool cut = steps < a.setup.steps || static_cast<int>(runs.size()) < a.reps;
    // Why: the first kept run's own reason, else (every kept run finished, others never started)
    // the budget's.
    StopReason stopped = StopReason::Finished;
    if (cut) {
        const auto short_ = std::find_if(runs.begin(), runs.end(), [](const auto& r) { return r.stopped != StopReason::Finished; });
        stopped = short_ != runs.end() ? short_->stopped : budget.reached().value_or(StopReason::Timeout);
    }

    const Stat compliance = stat(runs, [](const auto& r) { return r.maxCompliance; });
    const Stat completeness = stat(runs, [](const auto& r) { return r.maxCompleteness; });
    const Stat stability = stat(runs, [](const auto& r) { return r.maxStability; });
    const Stat islands = stat(runs, [](const auto& r) { return static_cast<double>(r.islands); });
    const Stat seconds = stat(runs, [](const auto& r) { return r.seconds; });
    const Stat modules = stat(runs, [](const auto& r) { return static_cast<double>(r.modules); });
    if (!a.out.empty()) writeOutputs(a, runs, steps, errors);
    if (stepsFile) errors.attempt([&] { stepsFile->commit(); });
    if (a.json) {
        auto js = [](Stat s) { return nlohmann::json{{"mean", s.mean}, {"std", s.std}}; };
        nlohmann::json j{{"from", a.setup.from}, {"to", a.setup.to}, {"size", a.setup.size}, {"reps", runs.size()}, {"modules", js(modules)}, {"steps", steps}, {"stopped", stopReasonName(stopped)}, {"tri_regions", runs[0].triRegions}, {"completeness", js(completeness)}, {"stability", js(stability)}, {"compliance", js(compliance)}, {"islands", js(islands)}, {"seconds", js(seconds)}, {"improvements", improvements(a.setup.options)}};
        std::cout << j.dump() << '\n';
    } else {
        std::cout << std::fixed << std::setprecision(2) << a.setup.from << " -> " << a.setup.to << " on " << a.setup.size << "x" << a.setup.size
                  << ", " << runs.size() << " reps of " << steps << " timesteps" << (stopped == StopReason::Timeout ? " (stopped by --timeout)" : stopped == StopReason::Interrupted ? " (interrupted)"
                                                                                                                                                                                     : "")
                  << ", " << runs[0].triRegions << " tri-regions"
                  << (improvements(a.setup.options).empty() ? "" : ", holon's improvements:");
        for (const std::string& i : improvements(a.setup.options)) std::cout << " --" << i;
        std::cout << '\n'
                  << "  modules " << std::setprecision(0) << modules.mean << std::setprecision(2) << "\n  max compliance " << 100 * compliance.mean
                  << "% (std " << 100 * compliance.std << ")\n  max completeness " << 100 * completeness.mean << "% (std " << 100 * completeness.std
                  << ")\n  max stability " << 100 * stability.mean << "% (std " << 100 * stability.std << ")\n  islands " << islands.mean
                  << " modules (std " << islands.std << ")\n  seconds per run " << seconds.mean << '\n'
                  << "  first run: " << runs[0].counts.created << " holes created, " << runs[0].counts.deleted << " deleted ("
                  << runs[0].counts.surplusDeleted << " as surplus), " << runs[0].startHoles
                  << " at start, " << runs[0].endHoles << " at end (" << runs[0].holeBudget << " fill the target exactly); " << runs[0].counts.collapsed << " collapses, " << runs[0].counts.steered << " steered, " << runs[0].counts.migrated << " migrations\n"
                  << "  first run's last timestep: " << runs[0].residue.outside << " modules outside the target, " << runs[0].residue.emptyInside
                  << " target points empty (" << runs[0].residue.walledIn << " walled in), " << runs[0].residue.holeCellsOutside << " hole cells outside\n";
    }
    errors.raise();  // after the table: the runs' results are printed even when their files are not written
    return exitCodeFor(stopped, budget.signal());
}

}  // namespace

Run addHexCommand(CLI::App& app) {
    auto a = std::make_shared<HexArgs>();
    CLI::App* sub = app.add_subcommand("hex", "sculpt a hex-lattice ensemble by hole motion (seed 003)");
    sub->add_option("--from", a->setup.from, "source geometry: square, T, rectangle, circle, or a picture file")->required();
    sub->add_option("--to", a->setup.to, "target geometry: square, T, rectangle, circle, or a picture file")->required();
    sub->add_option("--size", a->setup.size, "lattice points per side of the array")->required();
    sub->add_option("--reps", a->reps, "repetitions with seeds seed, seed+1, ... (1 to 1000)")->check(CLI::Range(1, 1000));
    sub->add_option("--steps", a->setup.steps, "timesteps per run (1 to 10^9)")->check(CLI::Range(1, 1000000000));
    sub->add_option("--seed", a->seed, "random seed of the first repetition")->check(seedValidator());
    sub->add_option("--tri", a->setup.triFraction, "tri-region edge as a fraction of the array side (0.001 to 1)")->check(finiteValidator(1e-3, 1, "a fraction"));
    sub->add_option("--decay", a->setup.options.decay, "c_decay of the temperature test, timesteps per diameter (0.001 to 10^9)")->check(finiteValidator(1e-3, 1e9, "timesteps per diameter"));
    sub->add_option("--hole-density", a->setup.options.holeDensity, "initial holes per source lattice point (0 to 1)")->check(finiteValidator(0, 1, "holes per point"));
    sub->add_flag_callback(
        "--improved", [a] {
            auto& o = a->setup.options;
            o.dropOverhangs = o.flexibleGrowth = o.roll = o.deleteOverflow = o.growInside = o.keepConnected = o.migrate = o.balance = true;
        },
        "all of holon's improvements: --drop-overhangs --flexible-growth --roll --delete-overflow --grow-inside --keep-connected --migrate --balance");
    sub->add_flag("--drop-overhangs", a->setup.options.dropOverhangs, "a column head with a gap below it falls into the gap");
    sub->add_flag("--flexible-growth", a->setup.options.flexibleGrowth, "growth nodes also start with one module more or fewer in their disk");
    sub->add_flag("--roll", a->setup.options.roll, "outside the target, surface modules roll down one-hop slopes (with --migrate, migration moves them instead)");
    sub->add_flag("--delete-overflow", a->setup.options.deleteOverflow, "modules outside the target delete holes in growth regions too");
    sub->add_flag("--grow-inside", a->setup.options.growInside, "growth only where the new shepherd group lies inside the target");
    sub->add_flag("--keep-connected", a->setup.options.keepConnected, "refuse every deletion and collapse that would cut the mass apart");
    sub->add_flag("--migrate", a->setup.options.migrate, "modules outside the target move along the surface toward empty target points");
    sub->add_flag("--balance", a->setup.options.balance, "hold the live holes at (target area - modules) / 7: creation stops there, deletion below it only as growth asks, surplus holes deleted at the surface");
    addThreads(sub, a->threads, "one run each");
    addTimeout(sub, a->timeout, "every run keeps the timesteps made so far");
    addMemory(sub, a->memoryMiB, "checked before the arrays are made");
    sub->add_option("--out", a->out, "directory for series.csv, series.svg (metrics over time) and SVG frames of the first run (created if missing; its parent must exist)");
    sub->add_option("--steps-out", a->stepsOut, "write the first run as JSON Lines, one rule instance a line, for holon view (large: keep --size and --steps small)");
    sub->add_flag("--json", a->json, "print a JSON summary");
    sub->add_flag("--quiet", a->quiet, "no progress bar");
    return [a] { return withinMemory(a->memoryMiB, [&] { return run(*a); }); };
}

}  // namespace holon::cli
