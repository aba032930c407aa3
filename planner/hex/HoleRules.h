#pragma once
// The lattice rewrites of hole motion, rules/library/hex_holes.holon, compiled for one hex array:
// the sculptor's ensemble is the compiled engine's cell array, and a hole moves by applying the
// rule's instance (seed 003 §IV-D), the same rule `holon check` and `holon verify` examine.

#include "planner/BoxEngine.h"
#include "planner/hex/HexArray.h"
#include "rules/Model.h"

#include <memory>

namespace holon::planner::hex {

class HoleRules {
public:
    using Value = BoxEngine::Value;
    explicit HoleRules(const HexArray& array);
    HoleRules(const HoleRules&) = delete;  // the model points into system_
    HoleRules& operator=(const HoleRules&) = delete;

    const BoxEngine& engine() const { return *engine_; }
    /// The cell states: a module, a hole's rim cell, a hole's centre (empty is 0).
    Value module() const { return module_; }
    Value rim() const { return rim_; }
    Value centre() const { return centre_; }
    /// The hole_move instance that shifts the hole centred at the anchor one cell in direction d.
    int move(int d) const { return move_[d]; }

private:
    rules::System system_;
    std::unique_ptr<rules::Model> model_;
    std::unique_ptr<rules::RuleTables> tables_;
    std::unique_ptr<BoxEngine> engine_;
    Value module_ = 0, rim_ = 0, centre_ = 0;
    int move_[6] = {};
};

}  // namespace holon::planner::hex
