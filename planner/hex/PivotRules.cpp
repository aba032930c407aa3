// hex_pivot.holon compiled on a box of disk cells (PivotRules.h). Each shape of the system is
// classified by its pattern cells' two sides: the cell whose disk leaves (occupied, then empty),
// the one it lands on (empty, then occupied), the pivot (occupied on both) and the swept cell
// (empty on both). The twelve rolls (six directions, two pivots each) must all be there, else the
// bundled rule file is broken; a second shape doing the same roll (a mirror image) is redundant.

#include "planner/hex/PivotRules.h"

#include "rules/Error.h"
#include "rules/Library.h"
#include "rules/RuleTables.h"

namespace holon::planner::hex {

struct PivotRules::Compiled {
    rules::System system = rules::librarySystem("hex_pivot");
    rules::Model model{system, rules::Lattice::get(rules::LatticeKind::Hex2D)};
    rules::RuleTables tables{model, std::vector<std::uint32_t>{0}};
};

PivotRules::~PivotRules() = default;

PivotRules::PivotRules(Vec lower, Vec extent) : compiled_(std::make_unique<Compiled>()) {
    const rules::Model& model = compiled_->model;
    const rules::Lattice& lattice = model.lattice();
    board_ = std::make_unique<Board>(lattice, lower, extent, BoxEngine::reach(compiled_->tables));
    std::vector<std::uint8_t> combo(static_cast<std::size_t>(board_->size()), BoxEngine::kOutside);
    const auto inside = static_cast<std::uint8_t>(compiled_->tables.comboIndex(0));
    board_->forEachInside([&](std::int64_t i, Vec) { combo[i] = inside; });
    engine_ = std::make_unique<BoxEngine>(compiled_->tables, *board_, std::move(combo));
    const int glyph = model.alphabet().byGlyph('M');
    if (glyph <= 0) throw InternalError("hex_pivot.holon: no state M for a disk");
    disk_ = static_cast<Value>(glyph);

    for (int d = 0; d < 6; ++d) roll_[d][0] = roll_[d][1] = Instance{};
    for (int s = 0; s < engine_->shapeCount(); ++s) {
        const rules::RuleShape& shape = model.shapes()[s];
        const rules::DirectedRule& rule = model.rules()[shape.rule];
        const auto empty = [](const rules::CellTerm& t) { return t.base == rules::CellTerm::Base::Empty && t.copyFrom < 0; };
        std::vector<int> leaves, lands, pivot, swept;
        for (std::size_t k = 0; k < shape.offsets.size(); ++k) {
            const bool before = !empty(rule.lhs()[k]), after = !empty(rule.rhs()[k]);
            (before ? (after ? pivot : leaves) : (after ? lands : swept)).push_back(static_cast<int>(k));
        }
        if (leaves.size() != 1 || lands.size() != 1 || pivot.size() != 1 || swept.size() != 1) continue;
        const Vec from = shape.offsets[leaves[0]];
        const int d = lattice.directionOf(shape.offsets[lands[0]] - from);
        if (d < 0) continue;
        const Vec p = shape.offsets[pivot[0]] - from;
        const int side = p == lattice.direction((d + 1) % 6) ? 0 : p == lattice.direction((d + 5) % 6) ? 1
                                                                                                       : -1;
        const Vec other = lattice.direction(side == 0 ? (d + 5) % 6 : (d + 1) % 6);
        if (side < 0 || shape.offsets[swept[0]] - from != other || roll_[d][side].shape >= 0) continue;
        roll_[d][side] = {s, board_->offset(shape.offsets[0] - from)};
    }
    for (int d = 0; d < 6; ++d)
        for (int side = 0; side < 2; ++side)
            if (roll_[d][side].shape < 0)
                throw InternalError("hex_pivot.holon has no rule rolling a disk toward " + lattice.directionName(d) + " about its " +
                                    (side ? "clockwise" : "counterclockwise") + " neighbour");
}

PivotRules::Instance PivotRules::find(Vec from, Vec to, Vec pivot) const {
    const rules::Lattice& lattice = board_->lattice();
    const int d = lattice.directionOf(to - from);
    if (d < 0) return {};
    const Vec p = pivot - from;
    const int side = p == lattice.direction((d + 1) % 6) ? 0 : p == lattice.direction((d + 5) % 6) ? 1
                                                                                                   : -1;
    if (side < 0) return {};
    return roll(board_->index(from), d, side);
}

}  // namespace holon::planner::hex
