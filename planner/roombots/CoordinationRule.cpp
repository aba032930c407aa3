// The reservation strategy's coordination, executed: rules/library/roombots_reserve.holon placed on
// the floor grid and run by the reference interpreter, the semantics `holon check` and `holon
// verify` are tested against (seed 001 §VI asks for a priority consensus; seed 000 §II-C for
// non-local constraints that every rule step respects). A metamodule is the column of its foot
// while it waits; a walk is the input bit set on every column its body or a collision cloud of the
// walk covers. The strategy never decides a start itself: the rule fires, or the metamodule waits.

#include "planner/roombots/CoordinationRule.h"

#include "planner/Recorder.h"
#include "rules/ConfigIo.h"
#include "rules/Error.h"
#include "rules/Library.h"
#include "rules/Parameter.h"

#include <nlohmann/json.hpp>
#include <stdexcept>

namespace holon::planner::roombots::detail {

struct CoordinationRule::System {
    rules::System system = rules::librarySystem("roombots_reserve");
    rules::Model model{system, rules::Lattice::get(rules::LatticeKind::Square2D)};
    rules::Region region;
    rules::Interpreter interpreter{model, region};
    explicit System(rules::Region r) : region(std::move(r)) {}
};

CoordinationRule::~CoordinationRule() = default;

CoordinationRule::CoordinationRule(const Floor& floor, int reach, const std::vector<Cell>& feet)
    : feet_(feet), x0_(floor.x0 - reach), y0_(floor.y0 - reach) {
    const int width = floor.x1 - floor.x0 + 1 + 2 * reach, depth = floor.y1 - floor.y0 + 1 + 2 * reach;
    system_ = std::make_unique<System>(rules::Region::box(rules::Lattice::get(rules::LatticeKind::Square2D), {width, depth, 1}));
    int walks = 0;
    while (system_->system.inputIndex("walk" + std::to_string(walks + 1)) >= 0) ++walks;
    if (static_cast<int>(feet_.size()) > walks)
        throw InputError("the reservation strategy coordinates at most " + std::to_string(walks) + " metamodules (roombots_reserve.holon has walk1..walk" +
                             std::to_string(walks) + "); this recipe has " + std::to_string(feet_.size()) +
                             " seeds: use a smaller structure or a " + rules::parameterName(rules::Parameter::Strategy) + " of the paper",
                         rules::Parameter::Strategy);
    nlohmann::json cells = nlohmann::json::array();
    for (std::size_t k = 0; k < feet_.size(); ++k) {
        const rules::Vec at = system_->region.cell(indexOf(feet_[k]));
        cells.push_back({{"at", {at.x, at.y}}, {"kind", "W"}, {"to", k + 1}});
    }
    waiting_ = now_ = rules::configFromJson(system_->interpreter, {{"cells", cells}});
}

int CoordinationRule::indexOf(const Cell& c) const {
    const int i = system_->region.indexOf({c.x - x0_, c.y - y0_, 0});
    if (i < 0) throw std::logic_error("a walk leaves the coordination rule's floor");
    return i;
}

bool CoordinationRule::start(int seed, const std::vector<Cell>& cells) {
    const std::uint32_t bit = 1u << system_->system.inputIndex("walk" + std::to_string(seed + 1));
    for (std::uint32_t& in : now_.inputs) in &= ~bit;
    for (const Cell& c : cells) now_.inputs[indexOf(c)] |= bit;
    return fire("start", seed);
}

void CoordinationRule::sit(int seed) {
    if (!fire("sit", seed)) throw std::logic_error("roombots_reserve.holon refused a metamodule its seat");
}

bool CoordinationRule::fire(const std::string& name, int seed) {
    const rules::Model& model = system_->model;
    const std::string rule = name + std::to_string(seed + 1);
    for (int s = 0; s < static_cast<int>(model.shapes().size()); ++s) {
        if (model.rules()[model.shapes()[s].rule].name != rule) continue;
        const rules::Instance instance{s, system_->region.cell(indexOf(feet_[seed])) - model.shapes()[s].offsets[0]};
        if (auto next = system_->interpreter.successor(now_, instance)) {
            Recorder::report({.engine = nullptr, .cells = nullptr, .anchor = 0, .shape = 0, .interpreter = &system_->interpreter, .configuration = &now_, .instance = instance});
            now_ = std::move(*next);
            return true;
        }
    }
    return false;
}

std::string CoordinationRule::configurationJson() const {
    rules::Configuration start = waiting_;
    start.inputs = now_.inputs;
    return rules::configToJson(system_->interpreter, start).dump() + "\n";
}

}  // namespace holon::planner::roombots::detail
