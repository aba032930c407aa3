// Parallel steps (checker/PathSchedule.h). Steps that interfere (one reads a cell the other
// writes) keep their order from the path; steps that do not commute as far as their own cells go,
// so any grouping that keeps the order of interfering steps ends where the path ends. What the
// footprints cannot see are the system's non-local constraints (a connectivity constraint may
// hold after two moves and not after either alone), so every placement is checked on the engine,
// and the whole schedule once more by the reference interpreter before it is shown.

#include "checker/PathSchedule.h"

#include <algorithm>

namespace holon::checker {

namespace {

/// Fires one round on `cells`: false unless each of its instances is enabled there with a legal
/// result on its own, and the round's result is legal.
bool fireRound(const std::vector<int>& round, const Trace& path, const rules::Engine& engine, std::vector<CellValue>& cells) {
    std::vector<CellValue> alone(cells);
    CellValue saved[rules::Engine::kMaxCells];
    for (int step : round) {
        const int placed = path.steps[step].placed;
        if (!engine.matches(cells.data(), placed)) return false;
        engine.apply(alone.data(), placed, saved);
        const bool legal = engine.legal(alone.data());
        engine.undo(alone.data(), placed, saved);
        if (!legal) return false;
    }
    for (int step : round) engine.apply(cells.data(), path.steps[step].placed, saved);
    return engine.legal(cells.data());
}

/// Rounds `from` onwards fire, the earlier ones being taken as they are.
bool validFrom(const Schedule& s, std::size_t from, const Trace& path, const rules::Engine& engine) {
    std::vector<CellValue> cells = path.steps.front().cells;
    CellValue saved[rules::Engine::kMaxCells];
    for (std::size_t r = 0; r < from; ++r)
        for (int step : s.rounds[r]) engine.apply(cells.data(), path.steps[step].placed, saved);
    for (std::size_t r = from; r < s.rounds.size(); ++r)
        if (!fireRound(s.rounds[r], path, engine, cells)) return false;
    return true;
}

std::string stepName(const Trace& path, const rules::Engine& engine, int step) {
    return "step " + std::to_string(step) + " (" + engine.model().rules()[engine.instances()[path.steps[step].placed].rule].name + ")";
}

}  // namespace

Schedule compactSteps(const Trace& path, const rules::Engine& engine, const Footprints& footprints) {
    Schedule s;
    std::vector<std::size_t> roundOf(path.steps.size(), 0);
    // Each step's footprint once: the pairs below are quadratic in the path's length.
    std::vector<Footprints::Footprint> prints(path.steps.size());
    for (std::size_t i = 1; i < path.steps.size(); ++i) prints[i] = footprints.of(path.steps[i].placed);
    for (std::size_t i = 1; i < path.steps.size(); ++i) {
        std::size_t earliest = 0;
        for (std::size_t j = 1; j < i; ++j)
            if (Footprints::interfere(prints[j], prints[i])) earliest = std::max(earliest, roundOf[j] + 1);
        std::size_t r = earliest;
        for (; r < s.rounds.size(); ++r) {
            s.rounds[r].push_back(static_cast<int>(i));
            if (validFrom(s, r, path, engine)) break;
            s.rounds[r].pop_back();
        }
        // A new last round starts where step i - 1 ended, since interfering steps kept their order.
        if (r == s.rounds.size()) s.rounds.push_back({static_cast<int>(i)});
        roundOf[i] = r;
    }
    return s;
}

bool replaySchedule(const Schedule& schedule, const Trace& path, const rules::Engine& engine, const rules::Interpreter& in, std::string* why) {
    const auto fail = [&](const std::string& text) {
        if (why) *why = text;
        return false;
    };
    std::vector<int> seen(path.steps.size(), 0);
    for (const auto& round : schedule.rounds)
        for (int step : round) {
            if (step < 1 || static_cast<std::size_t>(step) >= path.steps.size()) return fail("a round names step " + std::to_string(step) + ", which the path does not have");
            ++seen[step];
        }
    for (std::size_t k = 1; k < seen.size(); ++k)
        if (seen[k] != 1) return fail("step " + std::to_string(k) + " is in " + std::to_string(seen[k]) + " rounds");
    rules::Configuration at{path.steps.front().cells, engine.inputs()};
    for (std::size_t r = 0; r < schedule.rounds.size(); ++r) {
        const auto& round = schedule.rounds[r];
        const std::string where = "round " + std::to_string(r + 1) + ": ";
        for (int step : round)
            if (!in.successor(at, engine.instance(path.steps[step].placed))) return fail(where + stepName(path, engine, step) + " is not enabled at the round's start");
        std::vector<rules::Configuration> ends;
        for (bool reversed : {false, true}) {
            rules::Configuration c = at;
            for (std::size_t k = 0; k < round.size(); ++k) {
                const int step = round[reversed ? round.size() - 1 - k : k];
                const rules::Instance instance = engine.instance(path.steps[step].placed);
                if (!in.matches(c, instance)) return fail(where + stepName(path, engine, step) + " is disabled by the others of its round" + (reversed ? " fired in reverse order" : ""));
                c = in.apply(c, instance);
            }
            ends.push_back(std::move(c));
        }
        if (ends[0] != ends[1]) return fail(where + "its steps end in different configurations fired in path order and in reverse order");
        if (!in.legal(ends[0])) return fail(where + "it ends in a configuration a constraint rules out");
        at = std::move(ends[0]);
    }
    if (at.cells != path.steps.back().cells) return fail("the rounds do not end at the path's last configuration");
    return true;
}

}  // namespace holon::checker
