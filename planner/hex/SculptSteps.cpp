// The per-instance record of a sculpting run (SculptSteps.h). The recording hook hears an instance
// before it is applied, so each line is written when the next instance starts (or the timestep
// ends), when the cells hold its after-states.

#include "planner/hex/SculptSteps.h"

#include "planner/Report.h"
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
    nlohmann::json line = planLine(engine, timestep_, pending_->anchor, pending_->shape, pending_->cells);
    line["system"] = engine.tables().model().system().name;
    *out_ << line.dump() << '\n';
    pending_.reset();
}

}  // namespace holon::planner::hex
