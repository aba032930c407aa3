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
    // Streamed a point at a time, keys in the order the JSON library dumps them: the whole header
    // as one document took gigabytes on large arrays, and an allocation failing inside the
    // library ended holon.
    const HexArray& array = sculptor.array();
    const rules::Model& model = sculptor.rules().holeEngine().tables().model();
    const rules::Lattice& lattice = array.board().lattice();
    const auto list = [&](auto&& keep, auto&& item) {
        bool first = true;
        for (std::int64_t i : array.points())
            if (keep(i)) *out_ << (first ? "" : ",") << item(i).dump(), first = false;
    };
    const auto at = [&](std::int64_t i) { return rules::pointJson(lattice, array.board().point(i)); };
    *out_ << R"({"run":"hex","source":)" << nlohmann::json(model.system().sourceName).dump() << R"(,"start":{"cells":[)";
    list([&](std::int64_t i) { return sculptor.cell(i) != 0; },
         [&](std::int64_t i) {
             nlohmann::json cell = rules::stateFields(model, sculptor.cell(i));
             cell["at"] = at(i);
             return cell;
         });
    *out_ << R"(],"inputs":{"target":[)";
    list([&](std::int64_t i) { return sculptor.target()[i] != 0; }, at);
    *out_ << R"(]},"lattice":)" << nlohmann::json(lattice.name()).dump() << R"(,"points":[)";
    list([](std::int64_t) { return true; }, at);
    *out_ << R"(]},"system":)" << nlohmann::json(model.system().name).dump() << "}\n";
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
