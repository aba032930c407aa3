// The viewer's run: the state table and sampling. Sampling merges consecutive steps rather than
// dropping them, so every configuration shown is one the run went through and every cell that
// changed between two shown steps is highlighted as changed.

#include "viewer/Run.h"

#include <algorithm>
#include <map>

namespace holon::viewer {

int Run::state(const std::string& key, const std::string& colour, const std::string& text) {
    for (std::size_t s = 0; s < states.size(); ++s)
        if (states[s].key == key) return static_cast<int>(s);
    states.push_back({key, colour, text});
    return static_cast<int>(states.size()) - 1;
}

namespace {

std::int64_t changesOf(const Run& run) {
    std::int64_t n = 0;
    for (const Run::Step& s : run.steps) n += static_cast<std::int64_t>(s.changes.size());
    return n;
}

/// The steps merged in groups of g: each group's net changes, its cells looked at, its marks.
std::vector<Run::Step> merged(const Run& run, int g) {
    std::vector<Run::Step> out{run.steps[0]};
    std::vector<int> now = run.start, before(run.cells.size(), -1);
    for (std::size_t first = 1; first < run.steps.size(); first += static_cast<std::size_t>(g)) {
        const std::size_t last = std::min(run.steps.size() - 1, first + static_cast<std::size_t>(g) - 1);
        Run::Step step;
        step.label = run.steps[first].label + (last > first ? " ... " + run.steps[last].label : "");
        std::vector<int> touched, looked;
        for (std::size_t k = first; k <= last; ++k) {
            for (const auto& [cell, state] : run.steps[k].changes) {
                if (before[cell] < 0) before[cell] = now[cell], touched.push_back(cell);
                now[cell] = state;
            }
            looked.insert(looked.end(), run.steps[k].context.begin(), run.steps[k].context.end());
            step.marked.insert(step.marked.end(), run.steps[k].marked.begin(), run.steps[k].marked.end());
        }
        for (int cell : touched) {
            if (now[cell] != before[cell]) step.changes.push_back({cell, now[cell]});
            before[cell] = -1;
        }
        std::sort(looked.begin(), looked.end());
        looked.erase(std::unique(looked.begin(), looked.end()), looked.end());
        for (const auto& change : step.changes) before[change.first] = -2;  // changed: not context
        for (int cell : looked)
            if (before[cell] != -2) step.context.push_back(cell);
        for (const auto& change : step.changes) before[change.first] = -1;
        out.push_back(std::move(step));
    }
    return out;
}

}  // namespace

void sample(Run& run, std::int64_t maxChanges) {
    if (run.sampled == 1) run.runSteps = static_cast<std::int64_t>(run.steps.size()) - 1;
    if (changesOf(run) <= maxChanges) return;  // also when sampled before
    for (int g = 2;; g *= 2) {
        Run candidate = run;
        candidate.steps = merged(run, g);
        if (changesOf(candidate) <= maxChanges || candidate.steps.size() <= 2) {
            if (run.violation > 0) candidate.violation = (run.violation - 1) / g + 1;
            candidate.sampled = g;
            run = std::move(candidate);
            return;
        }
    }
}

std::vector<int> configurationAt(const Run& run, std::size_t k) {
    std::vector<int> now = run.start;
    for (std::size_t s = 1; s <= k && s < run.steps.size(); ++s)
        for (const auto& [cell, state] : run.steps[s].changes) now[cell] = state;
    return now;
}

}  // namespace holon::viewer
