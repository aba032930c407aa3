#pragma once
// The lattice rewrites of hole motion, compiled for one hex array: rules/library/hex_holes.holon
// (hole move), hex_delete.holon (hole deletion), hex_growth.holon (hole creation),
// hex_growth_flexible.holon (creation spilling or borrowing a module), hex_collapse.holon (column
// collapse) and hex_migrate.holon (surface migration) placed on the array's board by the planner's
// compiled engine. The sculptor's ensemble is the engines' shared cell array, and every change to it
// applies one of these rules' instances (seed 003 §IV-D, §IV-E, §IV-F): the same rules `holon
// check` and `holon verify` examine (tests/planner/ConformanceTest.cpp replays runs to hold it so).

#include "planner/BoxEngine.h"
#include "planner/hex/HexArray.h"
#include "rules/Model.h"

#include <map>
#include <memory>
#include <vector>

namespace holon::planner::hex {

class HoleRules {
public:
    using Value = BoxEngine::Value;
    /// `target`: per board cell, whether it lies in the target (the rules' `target` input).
    HoleRules(const HexArray& array, const std::vector<std::uint8_t>& target);
    HoleRules(const HoleRules&) = delete;  // the models point into their systems
    HoleRules& operator=(const HoleRules&) = delete;
    ~HoleRules();

    const BoxEngine& holeEngine() const { return *holeEngine_; }
    const BoxEngine& collapseEngine() const { return *collapseEngine_; }
    const BoxEngine& growthEngine() const { return *growthEngine_; }
    const BoxEngine& deleteEngine() const { return *deleteEngine_; }
    const BoxEngine& flexibleEngine() const { return *flexibleEngine_; }
    /// hex_migrate's rules; their constraint `connected` is the caller's to enforce (MassTree).
    const BoxEngine& migrateEngine() const { return *migrateEngine_; }
    /// The hole_create shape, anchored at the growth node.
    int create() const { return create_; }
    /// The hex_delete shape, anchored at the hole's centre, whose shepherds leaving are exactly the
    /// cells `emptied` steps away from it; -1 if none is.
    int deletion(std::vector<std::int64_t> emptied) const;
    /// The hex_growth_flexible shape, anchored at the growth node, that moves the disk's extra
    /// module onto (spill) or takes the missing one from (borrow) the cell `step` away; -1 if none.
    int spill(std::int64_t step) const;
    int borrow(std::int64_t step) const;
    /// The cell states: a module, a hole's rim cell, a hole's centre (empty is 0).
    Value module() const { return module_; }
    Value rim() const { return rim_; }
    Value centre() const { return centre_; }
    /// The hole_move shape that shifts the hole centred at the anchor one cell in direction d.
    int move(int d) const { return move_[d]; }
    /// The column-collapse shape (anchored at the moving module) for gravity direction `gravity`
    /// that steps onto the column in direction gravity + `side` (0 fall, 1 roll, 2 up, 5 down)
    /// whose head lies `hops` below; the landing cell is pattern cell `hops`. -1 if none.
    int collapse(int side, int hops, int gravity) const { return collapse_[side][hops][gravity]; }
    /// The migration shape (anchored at the moving module) that moves it one cell in direction d.
    int migrate(int d) const { return migrate_[d]; }
    /// The advance shape (anchored at the module inside the target) that moves it one cell in direction d.
    int advance(int d) const { return advance_[d]; }

private:
    struct Compiled;
    std::unique_ptr<Compiled> holeSystem_, collapseSystem_, growthSystem_, migrateSystem_, deleteSystem_, flexibleSystem_;
    const BoxEngine *holeEngine_ = nullptr, *collapseEngine_ = nullptr, *growthEngine_ = nullptr, *migrateEngine_ = nullptr,
                    *deleteEngine_ = nullptr, *flexibleEngine_ = nullptr;
    int create_ = -1;
    std::map<std::vector<std::int64_t>, int> deletion_;  // sorted steps of the shepherds that leave -> shape
    std::map<std::int64_t, int> spill_, borrow_;         // step of the third-ring cell -> shape
    Value module_ = 0, rim_ = 0, centre_ = 0;
    int move_[6] = {};
    int collapse_[6][4][6] = {};
    int migrate_[6] = {}, advance_[6] = {};
};

}  // namespace holon::planner::hex
