// The planner's run-time monitor (issue: --check). Seed 000's Theorem 1 promises that the
// ensemble stays connected (Lemma 1, Safety) and, for general_n, the transfer and motion rules
// conserve mass (§III); the monitor checks both on the actual run, from scratch each time, so a
// bug in the incremental engine cannot hide a violation.

#include "planner/Monitor.h"

#include "rules/ConfigIo.h"

namespace holon::planner {

Monitor::Monitor(const Problem& problem, const Execution& execution) : problem_(&problem), execution_(&execution) {
    for (const rules::Property& p : problem.model->system().properties)
        if (p.kind == rules::Property::Kind::Conserves && p.quantity == rules::Property::Quantity::Mass) conservesMass_ = true;
    for (BoxEngine::Value v : execution.cells()) initialMass_ += problem.tables->massUnitsOf(v);
    if (!connected()) violation_ = "the start is not connected";
}

void Monitor::fired(std::int64_t anchor, int shape, const BoxEngine::Value* old) {
    lastFired_.push_back({anchor, shape});
    const auto& steps = problem_->engine->cellSteps(shape);
    for (std::size_t k = 0; k < steps.size(); ++k) before_.push_back(old[k]);
}

bool Monitor::connected() const {
    const Board& board = *problem_->board;
    const auto& cells = execution_->cells();
    std::vector<char> seen(cells.size(), 0);
    std::int64_t total = 0, start = -1;
    for (std::size_t i = 0; i < cells.size(); ++i)
        if (cells[i]) ++total, start = static_cast<std::int64_t>(i);
    if (total == 0) return true;
    std::vector<std::int64_t> stack{start};
    seen[start] = 1;
    std::int64_t reached = 0;
    const int degree = board.lattice().degree();
    while (!stack.empty()) {
        const std::int64_t i = stack.back();
        stack.pop_back();
        ++reached;
        for (int d = 0; d < degree; ++d) {
            const std::int64_t j = i + board.step(d);
            if (cells[j] && !seen[j]) seen[j] = 1, stack.push_back(j);
        }
    }
    return reached == total;
}

bool Monitor::roundEnd(const RunStats& stats) {
    ++checks_;
    std::int64_t mass = 0;
    for (BoxEngine::Value v : execution_->cells()) {
        if (v >= problem_->tables->alphabet()) violation_ = "a cell holds state " + std::to_string(v) + ", outside the alphabet";
        mass += problem_->tables->massUnitsOf(v < problem_->tables->alphabet() ? v : 0);
    }
    if (violation_.empty() && conservesMass_ && mass != initialMass_)
        violation_ = "mass changed from " + rules::Rational(initialMass_, problem_->tables->massDenominator()).str() + " to " +
                     rules::Rational(mass, problem_->tables->massDenominator()).str();
    if (violation_.empty() && !connected()) violation_ = "the ensemble is disconnected";
    if (!violation_.empty()) {
        violation_ += " after step " + std::to_string(stats.steps) + " (round " + std::to_string(stats.rounds) + ")";
        return false;
    }
    lastFired_.clear(), before_.clear();
    return true;
}

std::string Monitor::summary() const {
    if (!violation_.empty()) return "VIOLATED: " + violation_;
    return "connectivity" + std::string(conservesMass_ ? ", mass" : "") + " held at all " + std::to_string(checks_) + " checks";
}

void Monitor::writeTrace(const rules::OutputFile& file) const {
    const rules::Model& model = *problem_->model;
    const Board& board = *problem_->board;
    const rules::Lattice& lattice = board.lattice();
    std::vector<BoxEngine::Value> earlier = execution_->cells();
    std::size_t at = before_.size();
    for (std::size_t f = lastFired_.size(); f-- > 0;) {  // undo the last round, latest first
        const auto& steps = problem_->engine->cellSteps(lastFired_[f].second);
        at -= steps.size();
        for (std::size_t k = 0; k < steps.size(); ++k) earlier[lastFired_[f].first + steps[k]] = before_[at + k];
    }
    auto state = [&](const std::vector<BoxEngine::Value>& cells, nlohmann::json meta) {
        nlohmann::json map = nlohmann::json::array();
        for (std::size_t i = 0; i < cells.size(); ++i)
            if (cells[i]) map.push_back({{{"#tup", rules::pointJson(lattice, board.point(static_cast<std::int64_t>(i)))}}, rules::stateFields(model, cells[i])});
        return nlohmann::json{{"#meta", meta}, {"cells", {{"#map", map}}}};
    };
    nlohmann::json fired = nlohmann::json::array();
    for (const auto& [anchor, shape] : lastFired_) {
        nlohmann::json cells = nlohmann::json::array();
        for (std::int64_t s : problem_->engine->cellSteps(shape)) cells.push_back(rules::pointJson(lattice, board.point(anchor + s)));
        fired.push_back({{"rule", model.rules()[problem_->engine->ruleOf(shape)].name}, {"cells", cells}});
    }
    nlohmann::json itf{{"#meta", {{"format", "ITF"}, {"format-description", "https://apalache-mc.org/docs/adr/015adr-trace.html"},
                                  {"source", model.system().sourceName}, {"system", model.system().name}, {"property", "monitor"},
                                  {"description", violation_}}},
                       {"vars", {"cells"}},
                       {"states", {state(earlier, {{"index", 0}}), state(execution_->cells(), {{"index", 1}, {"fired", fired}})}}};
    file.write(itf.dump(1) + '\n');
}

}  // namespace holon::planner
