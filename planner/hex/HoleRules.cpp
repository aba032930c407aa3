// hex_holes.holon placed on the hex array's board by the planner's compiled engine (seed 003
// §IV-D: a hole moves by shifting its three leading shepherds to the trailing edge). The move's
// six orientations are found by where each puts the new centre: pattern cell 1, next to the old
// centre at the anchor.

#include "planner/hex/HoleRules.h"

#include "rules/Error.h"
#include "rules/Library.h"

namespace holon::planner::hex {

HoleRules::HoleRules(const HexArray& array) : system_(rules::librarySystem("hex_holes")) {
    model_ = std::make_unique<rules::Model>(system_, rules::Lattice::get(rules::LatticeKind::Hex2D));
    tables_ = std::make_unique<rules::RuleTables>(*model_, std::vector<std::uint32_t>{});
    if (BoxEngine::reach(*tables_) > HexArray::kPad) throw InputError("hex_holes.holon reaches further than the hex array's padding");
    std::vector<std::uint8_t> combo(static_cast<std::size_t>(array.size()), BoxEngine::kOutside);
    for (std::int64_t i : array.points()) combo[i] = 0;
    engine_ = std::make_unique<BoxEngine>(*tables_, array.board(), std::move(combo));
    const rules::Alphabet& alphabet = model_->alphabet();
    module_ = static_cast<Value>(alphabet.byGlyph('M')), rim_ = static_cast<Value>(alphabet.byGlyph('H'));
    centre_ = static_cast<Value>(alphabet.byGlyph('C'));
    std::fill(std::begin(move_), std::end(move_), -1);
    for (int s = 0; s < engine_->shapeCount(); ++s) {
        if (model_->rules()[engine_->ruleOf(s)].name != "hole_move") continue;
        const auto steps = engine_->cellSteps(s);
        for (int d = 0; d < 6; ++d)
            if (steps[1] - steps[0] == array.step(d)) move_[d] = s;
    }
    for (int d = 0; d < 6; ++d)
        if (move_[d] < 0) throw InputError("hex_holes.holon: no hole_move toward direction " + std::to_string(d));
}

}  // namespace holon::planner::hex
