// The per-instance record of a sculpting run (SculptSteps.h). The recording hook hears an instance
// before it is applied, so each line is written when the next instance starts (or the timestep
// ends), when the cells hold its after-states.

#include "planner/hex/SculptSteps.h"

#include "rules/ConfigIo.h"

#include <nlohmann/json.hpp>

namespace holon::planner::hex {

SculptSteps::SculptSteps(std::ostream& out, const HoleSculptor& sculptor)
    : out_(&out), recorder_([this](const Applied& a) {
          flush();
          if (a.engine) pending_ = a;
      }) {
    const HexArray& array = sculptor.array();
    const rules::Model& model = sculptor.rules().holeEngine().tables().model();
    const rules::Lattice& lattice = array.board().lattice();
    nlohmann::json points = nlohmann::json::array(), cells = nlohmann::json::array(), target = nlohmann::json::array();
    for (std::int64_t i : array.points()) {
        const nlohmann::json at = rules::pointJson(lattice, array.board().point(i));
        points.push_back(at);
        if (sculptor.cell(i)) {
            nlohmann::json cell = rules::stateFields(model, sculptor.cell(i));
            cell["at"] = at;
            cells.push_back(cell);
        }
        if (sculptor.target()[i]) target.push_back(at);
    }
    *out_ << nlohmann::json{{"run", "hex"}, {"system", model.system().name}, {"source", model.system().sourceName}, {"start", {{"lattice", lattice.name()}, {"points", points}, {"cells", cells}, {"inputs", {{"target", target}}}}}}
                 .dump()
          << '\n';
}

void SculptSteps::timestepEnded() {
    flush();
    ++timestep_;
}

void SculptSteps::flush() {
    if (!pending_) return;
    const BoxEngine& engine = *pending_->engine;
    const rules::Model& model = engine.tables().model();
    nlohmann::json cells = nlohmann::json::array(), after = nlohmann::json::array();
    for (std::int64_t s : engine.cellSteps(pending_->shape)) {
        cells.push_back(rules::pointJson(engine.board().lattice(), engine.board().point(pending_->anchor + s)));
        after.push_back(rules::stateFields(model, pending_->cells[pending_->anchor + s]));
    }
    *out_ << nlohmann::json{{"round", timestep_}, {"system", model.system().name}, {"rule", model.rules()[engine.ruleOf(pending_->shape)].name}, {"cells", cells}, {"after", after}}.dump() << '\n';
    pending_.reset();
}

}  // namespace holon::planner::hex
