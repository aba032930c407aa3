// `holon replay RULES PLAN.jsonl`: a plan written by `holon plan --plan-out` checked step by step by
// the reference interpreter, knowing nothing of the planner that made it (CaDiCaL's proofs checked
// by someone else). The first line gives the start configuration (target input included); each
// further line one fired instance, its rule, its pattern cells in order and their states after it.
// A step is found as the shape of that rule whose pattern cells are exactly those cells, replayed
// with planner::replayStep (the conformance harness's judge: enabled, constraints kept) and its
// after-states compared with the interpreter's. Instances of one synchronous round are replayed in
// file order, one after another, as the harness replays them.

#include "cli/Commands.h"
#include "cli/Inputs.h"

#include "planner/Replay.h"
#include "rules/ConfigIo.h"
#include "rules/Error.h"
#include "rules/Library.h"

#include <filesystem>
#include <fstream>
#include <iostream>
#include <memory>

namespace holon::cli {

namespace {

struct Args {
    std::string rules, plan;
};

/// A lattice point given as [x, y] or [x, y, z].
rules::Vec pointOf(const nlohmann::json& j, const std::string& where) {
    if (!j.is_array() || j.size() < 2 || j.size() > 3) throw InputError(where + ": a cell must be [x, y] or [x, y, z]");
    for (const auto& c : j)
        if (!c.is_number_integer()) throw InputError(where + ": a cell must be [x, y] or [x, y, z] of integers");
    return {j[0].get<int>(), j[1].get<int>(), j.size() == 3 ? j[2].get<int>() : 0};
}

/// The string field `key` of `j`, or "" when it is missing or no string.
std::string text(const nlohmann::json& j, const char* key) { return j.contains(key) && j[key].is_string() ? j[key].get<std::string>() : ""; }

int run(const Args& a) {
    const std::optional<rules::System> system = loadRules(a.rules, {});
    if (!system) return kExitBadInput;
    std::ifstream file(a.plan);
    if (!file) throw InputError(a.plan + ": cannot open the plan");
    std::string line;
    int lineNo = 0;
    const auto where = [&] { return a.plan + ":" + std::to_string(lineNo); };
    const auto next = [&](nlohmann::json& j) {
        if (!std::getline(file, line)) return false;
        ++lineNo;
        try {
            j = nlohmann::json::parse(line);
        } catch (const nlohmann::json::exception& e) {  // parse_error, and out_of_range for a number past a double
            throw InputError(where() + ": not a JSON line (" + e.what() + ")");
        }
        if (!j.is_object()) throw InputError(where() + ": expected a JSON object");
        return true;
    };

    nlohmann::json head;
    if (!next(head) || text(head, "plan") != "holon" || !head.contains("start") || !head["start"].is_object())
        throw InputError(a.plan + ":1: not a holon plan: its first line must be {\"plan\":\"holon\",...,\"start\":CONFIGURATION} (holon plan --plan-out)");
    if (text(head, "system") != system->name)
        throw InputError(a.plan + ":1: the plan is for system '" + text(head, "system") + "', not " + system->name + "; give its rule file");
    const nlohmann::json& start = head["start"];
    if (!start.contains("region") || !start["region"].is_string()) throw InputError(a.plan + ":1: the start configuration names no region");
    const rules::Region region = rules::Region::parse(start["region"].get<std::string>());
    const rules::Model model(*system, region.lattice());
    const rules::Interpreter in(model, region);
    rules::Configuration now;
    try {
        now = rules::configFromJson(in, start);
    } catch (const InputError& e) {
        throw InputError(a.plan + ":1: " + e.what());
    }
    const rules::Vec offset = start.contains("offset") ? pointOf(start["offset"], a.plan + ":1") : rules::Vec{};

    std::int64_t steps = 0, losses = 0;
    nlohmann::json step;
    while (next(step)) {
        // A metamodule lost to an injected fault (plan --lose): not a step to judge, the cell empties.
        if (step.contains("fault")) {
            if (text(step, "fault") != "lose" || !step.contains("cells") || !step["cells"].is_array() || step["cells"].size() != 1)
                throw InputError(where() + ": a fault must be {\"round\":R,\"fault\":\"lose\",\"cells\":[[x,y]]}");
            const rules::Vec p = pointOf(step["cells"][0], where()) + offset;
            if (!region.contains(p)) throw InputError(where() + ": cell " + step["cells"][0].dump() + " lies outside the plan's region " + region.spec());
            now.cells[region.indexOf(p)] = 0;
            ++losses;
            continue;
        }
        if (!step.contains("round") || !step["round"].is_number_integer() || !step.contains("rule") || !step["rule"].is_string() || !step.contains("cells") || !step["cells"].is_array() || !step.contains("after") ||
            !step["after"].is_array() || step["after"].size() != step["cells"].size())
            throw InputError(where() + ": a step must be {\"round\":R,\"rule\":NAME,\"cells\":[[x,y],...],\"after\":[{...},...]}, one state after per cell");
        const std::string rule = step["rule"];
        std::vector<rules::Vec> cells;
        std::string named;
        for (const auto& c : step["cells"]) {
            const rules::Vec p = pointOf(c, where());
            named += (named.empty() ? "" : " ") + c.dump();
            if (!region.contains(p + offset)) throw InputError(where() + ": cell " + c.dump() + " lies outside the plan's region " + region.spec());
            cells.push_back(p + offset);
        }
        // Every shape of that rule on exactly those cells; the first that replays legally counts.
        std::string why = "the system has no rule '" + rule + "' whose pattern lies on these cells";
        bool legal = false;
        for (int s = 0; s < static_cast<int>(model.shapes().size()) && !legal; ++s) {
            const rules::RuleShape& shape = model.shapes()[s];
            if (model.rules()[shape.rule].name != rule || shape.offsets.size() != cells.size()) continue;
            const rules::Instance instance{s, cells[0] - shape.offsets[0]};
            bool fits = true;
            for (std::size_t k = 0; k < cells.size(); ++k) fits &= shape.offsets[k] + instance.anchor == cells[k];
            if (!fits) continue;
            rules::Configuration after;
            if (const planner::StepFault f = planner::replayStep(in, now, instance, after); f != planner::StepFault::None) {
                why = planner::describe(f);
                continue;
            }
            legal = true;
            for (std::size_t k = 0; k < cells.size() && legal; ++k)
                if (const nlohmann::json is = rules::stateFields(model, after.cells[region.indexOf(cells[k])]); is != step["after"][k])
                    why = "the after-states differ: cell " + step["cells"][k].dump() + " becomes " + is.dump() + ", the plan says " + step["after"][k].dump(),
                    legal = false;
            if (legal) now = std::move(after);
        }
        if (!legal) {
            std::cout << "replay " << a.plan << ": ILLEGAL step at line " << lineNo << " (round " << step["round"].get<std::int64_t>() << ", rule " << rule << ", cells " << named
                      << "): " << why << '\n';
            return kExitViolated;
        }
        ++steps;
    }
    std::cout << "replay " << a.plan << ": all " << steps << " steps legal under " << system->name
              << (losses ? " (with " + std::to_string(losses) + " injected " + (losses == 1 ? "loss" : "losses") + ")" : std::string()) << "; the end is "
              << (in.atGoal(now) ? "at the goal" : "NOT at the goal") << '\n';
    return kExitOk;
}

}  // namespace

Run addReplayCommand(CLI::App& app) {
    auto a = std::make_shared<Args>();
    CLI::App* sub = app.add_subcommand("replay", "check a plan (holon plan --plan-out) step by step with the reference interpreter");
    addRulesFile(sub, "rules", a->rules, "the plan's rules, as plan --rules")->required();
    sub->add_option("plan", a->plan, "the plan, JSON Lines from holon plan --plan-out")->required();
    return [a] { return run(*a); };
}

}  // namespace holon::cli
