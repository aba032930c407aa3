// The reservation strategy's coordination, executed: rules/library/roombots_reserve.holon placed on
// the floor grid and run by rules::Engine, the engine `holon check` explores (seed 001 §VI asks
// for a priority consensus; seed 000 §II-C for non-local constraints that every rule step
// respects). A metamodule is the column of its foot while it waits; a walk is the input bit set
// on every column its body or a collision cloud of the walk covers. The strategy never decides a
// start itself: the rule fires, or the metamodule waits.

#include "planner/roombots/CoordinationRule.h"

#include "rules/ConfigIo.h"
#include "rules/Error.h"
#include "rules/Library.h"

#include <stdexcept>

namespace holon::planner::roombots::detail {

struct CoordinationRule::Compiled {
    rules::System system = rules::librarySystem("roombots_reserve");
    rules::Model model{system, rules::Lattice::get(rules::LatticeKind::Square2D)};
    rules::Region region;
    std::unique_ptr<rules::Engine> engine;
    explicit Compiled(rules::Region r) : region(std::move(r)) {}
};

CoordinationRule::~CoordinationRule() = default;

CoordinationRule::CoordinationRule(const Floor& floor, int reach, const std::vector<Cell>& feet)
    : feet_(feet), x0_(floor.x0 - reach), y0_(floor.y0 - reach) {
    const int width = floor.x1 - floor.x0 + 1 + 2 * reach, depth = floor.y1 - floor.y0 + 1 + 2 * reach;
    compiled_ = std::make_unique<Compiled>(rules::Region::box(rules::Lattice::get(rules::LatticeKind::Square2D), {width, depth, 1}));
    int walks = 0;
    while (compiled_->system.inputIndex("walk" + std::to_string(walks + 1)) >= 0) ++walks;
    if (seeds() > walks)
        throw InputError("the reservation strategy coordinates at most " + std::to_string(walks) + " metamodules (roombots_reserve.holon has walk1..walk" +
                         std::to_string(walks) + "); this recipe has " + std::to_string(seeds()) +
                         " seeds: use a smaller structure or a --strategy of the paper");
    inputs_.assign(static_cast<std::size_t>(compiled_->region.size()), 0);
    cells_.assign(inputs_.size(), 0);
    const rules::Alphabet& alphabet = compiled_->model.alphabet();
    for (int k = 0; k < seeds(); ++k) {
        const std::string waiting = "W&to=" + std::to_string(k + 1);
        for (int v = 1; v < alphabet.size(); ++v)
            if (alphabet.name(static_cast<rules::CellValue>(v)) == waiting) cells_[indexOf(feet_[k])] = static_cast<rules::CellValue>(v);
        if (cells_[indexOf(feet_[k])] == 0) throw InputError("roombots_reserve.holon has no state " + waiting);
    }
    waiting_ = cells_;
}

std::string CoordinationRule::configurationJson() const {
    const rules::Region& region = compiled_->region;
    nlohmann::json cells = nlohmann::json::array(), inputs = nlohmann::json::object();
    for (int i = 0; i < region.size(); ++i)
        if (waiting_[i] != 0) {
            nlohmann::json cell = rules::stateFields(compiled_->model, waiting_[i]);
            cell["at"] = rules::pointJson(region.lattice(), region.cell(i));
            cells.push_back(cell);
        }
    for (std::size_t k = 0; k < compiled_->system.inputs.size(); ++k) {
        nlohmann::json marked = nlohmann::json::array();
        for (int i = 0; i < region.size(); ++i)
            if ((inputs_[i] >> k) & 1u) marked.push_back(rules::pointJson(region.lattice(), region.cell(i)));
        if (!marked.empty()) inputs[compiled_->system.inputs[k]] = marked;
    }
    return nlohmann::json{{"system", compiled_->system.name}, {"region", region.spec()}, {"cells", cells}, {"inputs", inputs}}.dump() + "\n";
}

int CoordinationRule::indexOf(const Cell& c) const {
    const int i = compiled_->region.indexOf({c.x - x0_, c.y - y0_, 0});
    if (i < 0) throw std::logic_error("a walk leaves the coordination rule's floor");
    return i;
}

bool CoordinationRule::start(int seed, const std::vector<Cell>& cells) {
    const std::uint32_t bit = 1u << compiled_->system.inputIndex("walk" + std::to_string(seed + 1));
    for (std::uint32_t& in : inputs_) in &= ~bit;
    for (const Cell& c : cells) inputs_[indexOf(c)] |= bit;
    compiled_->engine = std::make_unique<rules::Engine>(compiled_->model, compiled_->region, inputs_);
    return fire("start", seed);
}

void CoordinationRule::sit(int seed) {
    if (!fire("sit", seed)) throw std::logic_error("roombots_reserve.holon refused a metamodule its seat");
}

bool CoordinationRule::fire(const std::string& name, int seed) {
    const rules::Engine& engine = *compiled_->engine;
    const std::string rule = name + std::to_string(seed + 1);
    for (std::int32_t p : engine.instancesAt(indexOf(feet_[seed]))) {
        if (compiled_->model.rules()[engine.instances()[p].rule].name != rule || !engine.matches(cells_.data(), p)) continue;
        rules::CellValue saved[rules::Engine::kMaxCells];
        engine.apply(cells_.data(), p, saved);
        if (engine.legal(cells_.data())) return true;
        engine.undo(cells_.data(), p, saved);
        return false;
    }
    return false;
}

}  // namespace holon::planner::roombots::detail
