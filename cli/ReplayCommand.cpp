// `holon replay RULES PLAN.jsonl`: a plan written by `holon plan --plan-out` checked step by step by
// the reference interpreter, knowing nothing of the planner that made it (CaDiCaL's proofs checked
// by someone else). The first line gives the start configuration (target input included); each
// further line one fired instance, its rule, its pattern cells in order and their states after it
// (read by rules::PlanLineReader, holon view's reader too).
// A step is found as the shape of that rule whose pattern cells are exactly those cells, replayed
// with planner::replayStep (the conformance harness's judge: enabled, constraints kept) and its
// after-states compared with the interpreter's. Instances of one synchronous round are replayed in
// file order, one after another, as the harness replays them.

#include "cli/Commands.h"
#include "cli/Inputs.h"
#include "cli/Limits.h"

#include "planner/Replay.h"
#include "rules/ConfigIo.h"
#include "rules/Error.h"
#include "rules/Escape.h"
#include "rules/Library.h"
#include "rules/OutputFile.h"
#include "rules/PlanLines.h"
#include "rules/StopSignals.h"
#include "rules/TextFile.h"

#include <filesystem>
#include <fstream>
#include <iostream>
#include <memory>

namespace holon::cli {

namespace {

struct Args {
    std::string rules, plan;
    double timeout = 0;  // 0: none
};

int run(const Args& a) {
    // From the start: a plan read from a FIFO is waited for, and its start line can take seconds.
    const rules::StopSignals guard(true);
    // A signal or --timeout stops the replay between two lines: the steps so far are reported as
    // judged, and the exit is 128 + the signal or 3 (a plan of 10^8 steps takes minutes). It counts
    // from here: a 162 MB start line took 6 s to read, and a replay with --timeout 0.5 went on.
    const Budget budget = Budget(a.timeout) || Budget::onSignals();
    const std::optional<rules::System> system = loadRules(a.rules, {});
    if (!system) return kExitBadInput;
    // A folder opens as an empty stream, which read as a plan cut short.
    if (std::error_code error; std::filesystem::is_directory(a.plan, error)) throw InputError(a.plan + ": is a folder; give the plan's file (holon plan --plan-out FILE)");
    // Read as every input is: a FIFO with no writer is waited for within --timeout and signals.
    const std::unique_ptr<std::istream> file = rules::openInputStream(a.plan);
    rules::PlanLineReader plan(*file, a.plan);
    if (plan.kind() != "plan" || !plan.head().contains("start") || !plan.head()["start"].is_object())
        throw InputError(a.plan + ":1: not a holon plan: its first line must be {\"plan\":\"holon\",...,\"start\":CONFIGURATION} (holon plan --plan-out)");
    const nlohmann::json& of = plan.head().contains("system") ? plan.head()["system"] : nlohmann::json();
    if (of != system->name) throw InputError(a.plan + ":1: the plan is for system '" + (of.is_string() ? of.get<std::string>() : "") + "', not " + system->name + "; give its rule file");
    const nlohmann::json& start = plan.start();
    // The start names its system too (holon writes the same name twice): an edited start of another
    // system was replayed.
    if (start.contains("system") && start["system"] != system->name)
        throw InputError(a.plan + ":1: the start configuration is of system " + start["system"].dump() + ", and the plan of " + system->name + "; write the plan again");
    if (!start.contains("region") || !start["region"].is_string()) throw InputError(a.plan + ":1: the start configuration names no region");
    const rules::Region region = [&] {
        try {
            return rules::Region::parse(start["region"].get<std::string>());
        } catch (const InputError& e) {
            throw InputError(a.plan + ":1: " + e.what());
        }
    }();
    const rules::Model model(*system, region.lattice());
    const rules::Interpreter in(model, region);
    rules::Configuration now;
    std::uint32_t named = 0;
    try {
        now = rules::configFromJson(in, start, &named);
    } catch (const InputError& e) {
        throw InputError(a.plan + ":1: " + e.what());
    }
    // holon plan writes every input; one missing was read as false everywhere, and the first step
    // that reads it was reported as an illegal plan.
    for (std::size_t k = 0; k < system->inputs.size(); ++k)
        if (!(named >> k & 1u))
            throw InputError(a.plan + ":1: the start configuration does not set input '" + system->inputs[k] + "' of system " + system->name +
                             "; write the plan again with holon plan --plan-out");

    // The system's invariants (Safety's hypothesis, what a plan of the planner keeps): a plan that
    // starts outside them proves nothing (a tampered start was blamed on a later step, or passed).
    planner::InvariantWatch invariants(in);
    if (const std::optional<std::string> broken = invariants.start(now)) {
        std::cout << "replay " << a.plan << ": the start on line 1 breaks " << *broken << "; a plan must start where the system's invariants hold\n";
        return kExitViolated;
    }
    std::int64_t steps = 0, losses = 0;
    rules::PlanLine step;
    while (plan.next(step)) {
        if ((steps + losses) % 4096 == 0)
            if (const std::optional<StopReason> why = budget.reached()) {
                std::cout << "replay " << a.plan << ": stopped " << (*why == StopReason::Timeout ? "by --timeout" : "by a signal") << " at line " << plan.lineNumber()
                          << ", after " << steps << " steps, every one legal under " << system->name << "; the rest is not judged" << raiseAdvice(*why) << '\n';
                return *why == StopReason::Timeout ? kExitUndecided : 128 + caughtSignal();
            }
        for (std::size_t k = 0; k < step.cells.size(); ++k)
            if (!region.contains(step.cells[k]))
                throw InputError(plan.where() + ": cell " + rules::excerpt(step.json["cells"][k].dump()) + " lies outside the plan's region " + region.spec());
        // A metamodule lost to an injected fault (plan --lose): not a step to judge, the cell empties.
        if (step.fault) {
            rules::CellValue& lost = now.cells[region.indexOf(step.cells[0])];
            if (!lost) {
                std::cout << "replay " << a.plan << ": ILLEGAL line " << plan.lineNumber() << ": a loss at " << step.json["cells"][0].dump()
                          << ", which is empty there (holon plan writes a loss only of a metamodule)\n";
                return kExitViolated;
            }
            lost = 0;
            ++losses;
            invariants.afterLoss(now, "the loss at line " + std::to_string(plan.lineNumber()));
            continue;
        }
        const std::string& rule = step.rule;
        const std::vector<rules::Vec>& cells = step.cells;
        std::string named;
        for (const auto& c : step.json["cells"]) named += (named.empty() ? "" : " ") + c.dump();
        // Every shape of that rule on exactly those cells; the first that replays legally counts.
        std::string why = "the system has no rule '" + rules::excerpt(rule) + "' whose pattern lies on these cells";
        bool legal = false;
        for (int s = 0; s < static_cast<int>(model.shapes().size()) && !legal; ++s) {
            const rules::RuleShape& shape = model.shapes()[s];
            if (model.rules()[shape.rule].name != rule || shape.offsets.size() != cells.size()) continue;
            const rules::Instance instance{s, cells[0] - shape.offsets[0]};
            bool fits = true;
            for (std::size_t k = 0; k < cells.size(); ++k) fits &= shape.offsets[k] + instance.anchor == cells[k];
            if (!fits) continue;
            planner::StepUndo undo;
            if (const planner::StepFault f = planner::replayStep(in, now, instance, &undo); f != planner::StepFault::None) {
                why = planner::describe(f);
                continue;
            }
            legal = true;
            for (std::size_t k = 0; k < cells.size() && legal; ++k)
                if (const nlohmann::json is = rules::stateFields(model, now.cells[region.indexOf(cells[k])]); is != step.json["after"][k])
                    why = "the after-states differ: cell " + step.json["cells"][k].dump() + " becomes " + is.dump() + ", the plan says " + rules::excerpt(step.json["after"][k].dump(), 200),
                    legal = false;
            if (!legal) planner::undoStep(now, undo);
        }
        if (!legal) {
            std::cout << "replay " << a.plan << ": ILLEGAL step at line " << plan.lineNumber() << " (round " << step.round << ", rule " << rules::excerpt(rule) << ", cells " << rules::excerpt(named, 200)
                      << "): " << why << '\n';
            return kExitViolated;
        }
        ++steps;
        if (const std::optional<std::string> broken = invariants.afterStep(now)) {
            std::cout << "replay " << a.plan << ": the step at line " << plan.lineNumber() << " (round " << step.round << ", rule " << rules::excerpt(rule) << ", cells " << rules::excerpt(named, 200)
                      << ") is legal but breaks " << *broken << '\n';
            return kExitViolated;
        }
    }
    if (const std::optional<std::string> broken = invariants.end(now)) {
        std::cout << "replay " << a.plan << ": all " << steps << " steps legal, but the end breaks " << *broken << '\n';
        return kExitViolated;
    }
    std::cout << "replay " << a.plan << ": all " << steps << " steps legal under " << system->name
              << (losses ? " (with " + std::to_string(losses) + " injected " + (losses == 1 ? "loss" : "losses") + ")" : std::string()) << "; the end is "
              << (in.atGoal(now) ? "at the goal" : "NOT at the goal") << '\n';
    std::cout << "  " << invariants.summary() << '\n';
    return kExitOk;
}

}  // namespace

Run addReplayCommand(CLI::App& app) {
    auto a = std::make_shared<Args>();
    CLI::App* sub = app.add_subcommand("replay", "check a plan (holon plan --plan-out) step by step with the reference interpreter");
    addRulesFile(sub, "rules", a->rules, "the plan's rules, as plan --rules")->required();
    sub->add_option("plan", a->plan, "the plan, JSON Lines from holon plan --plan-out")->required();
    addTimeout(sub, a->timeout, "the steps judged so far are reported");
    return [a] { return run(*a); };
}

}  // namespace holon::cli
