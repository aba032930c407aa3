// hex_holes.holon, hex_delete.holon, hex_growth.holon, hex_growth_flexible.holon, hex_collapse.holon
// and hex_migrate.holon placed on the hex array's board by the planner's compiled engine (seed 003
// §IV-D: a hole moves by shifting its three leading shepherds to the trailing edge; §IV-E: a
// deletion node fills a hole from seven shepherds, a growth node makes a hole; §IV-F: column
// collapse; holon's flexible growth and surface migration). The systems
// name the same cell states in the same order, so their engines share one cell array. An
// orientation is found by geometry: pattern cell 1 of a hole move is the new centre next to the
// old one at the anchor; pattern cell 1 of a collapse is the first cell of the column the module
// steps onto, at gravity + side.

#include "planner/hex/HoleRules.h"

#include "rules/Error.h"
#include "rules/Library.h"
#include "rules/Printer.h"

#include <algorithm>
#include <map>
#include <memory>
#include <mutex>

namespace holon::planner::hex {

namespace {

/// The column-collapse rules: name stem, and the side of the column relative to gravity.
struct CollapseRule {
    const char* stem;
    int side;
};
constexpr CollapseRule kCollapse[] = {{"fall", 0}, {"roll", 1}, {"collapse_up", 2}, {"collapse_down", 5}};

}  // namespace

/// A system compiled for the hex lattice: the same for every run of the process, so compiled once
/// (each rep compiled all six again: about 0.1 s a rep, 2.0 s for 20 reps of one timestep). Only
/// read once made, so the reps' threads share it.
struct CompiledHexSystem {
    rules::System system;
    std::unique_ptr<rules::Model> model;
    std::unique_ptr<rules::RuleTables> tables;
    std::uint32_t inTarget = 0;

    explicit CompiledHexSystem(const std::string& stem) : system(rules::librarySystem(stem)) {
        model = std::make_unique<rules::Model>(system, rules::Lattice::get(rules::LatticeKind::Hex2D));
        const int input = system.inputIndex("target");
        inTarget = input < 0 ? 0 : 1u << input;
        tables = std::make_unique<rules::RuleTables>(*model, std::vector<std::uint32_t>{inTarget});
        if (BoxEngine::reach(*tables) > HexArray::kPad) throw InputError(stem + ".holon reaches further than the hex array's padding");
    }

    static std::shared_ptr<const CompiledHexSystem> of(const std::string& stem) {
        static std::mutex mutex;
        static std::map<std::string, std::shared_ptr<const CompiledHexSystem>> made;
        const std::lock_guard lock(mutex);
        auto& slot = made[rules::libraryDir() + "/" + stem];  // HOLON_LIBRARY may name another library
        if (!slot) slot = std::make_shared<const CompiledHexSystem>(stem);
        return slot;
    }
};

struct HoleRules::Compiled {
    std::shared_ptr<const CompiledHexSystem> compiled;
    const rules::System& system;
    const rules::Model* model;
    std::unique_ptr<BoxEngine> engine;

    Compiled(const std::string& stem, const HexArray& array, const std::vector<std::uint8_t>& target)
        : compiled(CompiledHexSystem::of(stem)), system(compiled->system), model(compiled->model.get()) {
        const rules::RuleTables& tables = *compiled->tables;
        std::vector<std::uint8_t> combo(static_cast<std::size_t>(array.size()), BoxEngine::kOutside);
        for (std::int64_t i : array.points()) combo[i] = static_cast<std::uint8_t>(tables.comboIndex(target[i] ? compiled->inTarget : 0));
        engine = std::make_unique<BoxEngine>(tables, array.board(), std::move(combo));
    }
    const std::string& ruleName(int shape) const { return model->rules()[engine->ruleOf(shape)].name; }
};

HoleRules::~HoleRules() = default;

HoleRules::HoleRules(const HexArray& array, const std::vector<std::uint8_t>& target)
    : holeSystem_(std::make_unique<Compiled>("hex_holes", array, target)),
      collapseSystem_(std::make_unique<Compiled>("hex_collapse", array, target)),
      growthSystem_(std::make_unique<Compiled>("hex_growth", array, target)),
      migrateSystem_(std::make_unique<Compiled>("hex_migrate", array, target)),
      deleteSystem_(std::make_unique<Compiled>("hex_delete", array, target)),
      flexibleSystem_(std::make_unique<Compiled>("hex_growth_flexible", array, target)),
      holeEngine_(holeSystem_->engine.get()), collapseEngine_(collapseSystem_->engine.get()), growthEngine_(growthSystem_->engine.get()),
      migrateEngine_(migrateSystem_->engine.get()), deleteEngine_(deleteSystem_->engine.get()), flexibleEngine_(flexibleSystem_->engine.get()) {
    const rules::Alphabet& alphabet = holeSystem_->model->alphabet();
    for (const Compiled* c : {collapseSystem_.get(), growthSystem_.get(), migrateSystem_.get(), deleteSystem_.get(), flexibleSystem_.get()}) {
        const rules::Alphabet& other = c->model->alphabet();
        for (int v = 0; v < alphabet.size() || v < other.size(); ++v)
            if (v >= alphabet.size() || v >= other.size() || alphabet.name(static_cast<rules::CellValue>(v)) != other.name(static_cast<rules::CellValue>(v)))
                throw InputError("hex_holes.holon and " + c->system.name + ".holon must declare the same cell states in the same order");
    }
    module_ = static_cast<Value>(alphabet.byGlyph('M')), rim_ = static_cast<Value>(alphabet.byGlyph('H'));
    centre_ = static_cast<Value>(alphabet.byGlyph('C'));
    std::fill(std::begin(move_), std::end(move_), -1);
    std::fill(&collapse_[0][0][0], &collapse_[0][0][0] + 6 * 4 * 6, -1);
    auto direction = [&](const BoxEngine& engine, int shape) {
        const auto steps = engine.cellSteps(shape);
        for (int d = 0; d < 6; ++d)
            if (steps[1] - steps[0] == array.step(d)) return d;
        return -1;
    };
    // One orientation per slot: a second one (a mirror image, under `symmetry rotations+reflections`)
    // would silently replace the orientation the slot is for.
    auto place = [](int& slot, int s, const std::string& file, const std::string& rule) {
        if (slot >= 0)
            throw InputError(file + ".holon: two orientations of rule '" + rule +
                             "' point the same way; it is written for one side, so declare 'symmetry rotations'");
        slot = s;
    };
    for (int s = 0; s < holeEngine_->shapeCount(); ++s)
        if (holeSystem_->ruleName(s) == "hole_move") place(move_[direction(*holeEngine_, s)], s, "hex_holes", "hole_move");
    for (int s = 0; s < collapseEngine_->shapeCount(); ++s)
        for (const CollapseRule& c : kCollapse)
            for (int hops = 1; hops <= 3; ++hops)
                if (collapseSystem_->ruleName(s) == c.stem + std::to_string(hops))
                    place(collapse_[c.side][hops][(direction(*collapseEngine_, s) - c.side + 6) % 6], s, "hex_collapse",
                          collapseSystem_->ruleName(s));
    for (int d = 0; d < 6; ++d)
        if (move_[d] < 0) throw InputError("hex_holes.holon: no hole_move toward direction " + std::to_string(d));
    // The compiled engine does not evaluate non-local constraints; the sculptor enforces exactly
    // one, connectivity of the whole mass, with MassTree, so the file may declare no other.
    const rules::System& migrate = migrateSystem_->system;
    if (migrate.constraints.size() != 1 || rules::printExpr(migrate, migrate.constraints[0].expr) != "connected")
        throw InputError("hex_migrate.holon: `holon hex` enforces the one constraint `connected`; declare that and no other");
    std::fill(std::begin(migrate_), std::end(migrate_), -1);
    std::fill(std::begin(advance_), std::end(advance_), -1);
    for (int s = 0; s < migrateEngine_->shapeCount(); ++s) {
        const std::string& name = migrateSystem_->ruleName(s);
        if (name == "migrate") place(migrate_[direction(*migrateEngine_, s)], s, "hex_migrate", name);
        if (name == "advance") place(advance_[direction(*migrateEngine_, s)], s, "hex_migrate", name);
    }
    for (int d = 0; d < 6; ++d)
        if (migrate_[d] < 0 || advance_[d] < 0) throw InputError("hex_migrate.holon: needs rules migrate and advance in every direction");
    for (int s = 0; s < growthEngine_->shapeCount(); ++s)
        if (growthSystem_->ruleName(s) == "hole_create") create_ = s;
    if (create_ < 0) throw InputError("hex_growth.holon: no rule hole_create");
    // A deletion's shape is found by the shepherds it empties, a flexible creation's by its
    // third-ring cell (pattern cell 19), read off the rules' right sides.
    for (int s = 0; s < deleteEngine_->shapeCount(); ++s) {
        const rules::DirectedRule& rule = deleteSystem_->model->rules()[deleteEngine_->ruleOf(s)];
        const auto steps = deleteEngine_->cellSteps(s);
        std::vector<std::int64_t> emptied;
        for (std::size_t k = 0; k < steps.size(); ++k)
            if (rule.rhs()[k].base == rules::CellTerm::Base::Empty) emptied.push_back(steps[k] - steps[0]);
        std::sort(emptied.begin(), emptied.end());
        deletion_.emplace(emptied, s);  // a mirror-symmetric set gives two shapes doing the same
    }
    for (int s = 0; s < flexibleEngine_->shapeCount(); ++s) {
        const std::string& name = flexibleSystem_->ruleName(s);
        const auto steps = flexibleEngine_->cellSteps(s);
        if (steps.size() != 20) throw InputError("hex_growth_flexible.holon: rule '" + name + "' must have 20 pattern cells, the third-ring cell last");
        auto& slot = name.rfind("spill", 0) == 0 ? spill_ : borrow_;
        slot.emplace(steps[19] - steps[0], s);
    }
}

int HoleRules::deletion(std::vector<std::int64_t> emptied) const {
    std::sort(emptied.begin(), emptied.end());
    const auto it = deletion_.find(emptied);
    return it == deletion_.end() ? -1 : it->second;
}

int HoleRules::spill(std::int64_t step) const {
    const auto it = spill_.find(step);
    return it == spill_.end() ? -1 : it->second;
}

int HoleRules::borrow(std::int64_t step) const {
    const auto it = borrow_.find(step);
    return it == borrow_.end() ? -1 : it->second;
}

}  // namespace holon::planner::hex
