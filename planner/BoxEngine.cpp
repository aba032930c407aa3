// The compiled rule engine of the planner (issue: compiled rules). It runs the same decision
// tables as the explorer's Engine (rules/RuleTables), placed by index steps on a padded box
// instead of per-instance lists, which is what lets seed 000's U/P/F planner (§IV-A) run on 10^6
// metamodules in a few bytes per cell. tests/planner/CompiledVsInterpreterTest.cpp holds it to
// the reference interpreter step for step.

#include "planner/BoxEngine.h"

#include "planner/Recorder.h"

#include <algorithm>
#include <cstdlib>
#include <set>

namespace holon::planner {

namespace {

/// Cells of the board as seen by a compiled guard.
struct BoardCells {
    const BoxEngine::Value* cells;
    const std::uint8_t* combos;
    const Board* board;
    std::int64_t overridden, overridden2;
    BoxEngine::Value replacement, replacement2;
    BoxEngine::Value value(std::int64_t i) const {
        if (i == overridden) return replacement;
        return i == overridden2 ? replacement2 : cells[i];
    }
    // Padding cells are empty; as combination 0 they are exactly what a guard sees outside the
    // region, so neighbours need no bounds test (and no load of their combination first).
    int combo(std::int64_t i) const { return combos[i] == BoxEngine::kOutside ? 0 : combos[i]; }
    std::int64_t neighbour(std::int64_t i, int d) const { return i + board->step(d); }
};

ShapeKind classify(const rules::RuleTables& tables, int shape) {
    const rules::RuleTables::Shape& t = tables.shape(shape);
    // Per cell, the masses it may have before and after; a transfer exchanges resources between
    // cells, so each cell has one mass before and one after and the cells' masses are a
    // permutation of what they were (C D => D C). A step that moves mass otherwise (C B1 => D D,
    // the second creator completing a general_2 partial) is a stage of a creation or deletion.
    std::vector<std::int64_t> before, after;
    bool massMoves = false, exchange = true;
    for (std::size_t k = 0; k < t.lhs.size(); ++k) {
        if (t.copyFrom[k] >= 0) return ShapeKind::Motion;
        std::set<std::int64_t> massBefore, massAfter;
        for (int c = 0; c < tables.comboCount(); ++c)
            for (int v = 0; v < tables.alphabet(); ++v) {
                const auto value = static_cast<rules::CellValue>(v);
                if (!tables.test(t.lhs[k], c, value)) continue;
                const rules::CellValue w = t.rhs[k][value];
                if ((v == 0) != (w == 0)) return ShapeKind::Motion;
                if (tables.massUnitsOf(value) != tables.massUnitsOf(w)) massMoves = true;
                massBefore.insert(tables.massUnitsOf(value)), massAfter.insert(tables.massUnitsOf(w));
            }
        exchange = exchange && massBefore.size() == 1 && massAfter.size() == 1;
        if (exchange) before.push_back(*massBefore.begin()), after.push_back(*massAfter.begin());
    }
    if (!massMoves) return ShapeKind::Relabel;
    std::sort(before.begin(), before.end()), std::sort(after.begin(), after.end());
    return exchange && before == after ? ShapeKind::Transfer : ShapeKind::Motion;
}

}  // namespace

int BoxEngine::reach(const rules::RuleTables& tables) {
    int r = 0;
    const auto& shapes = tables.model().shapes();
    for (int s = 0; s < tables.shapeCount(); ++s) {
        const int extra = tables.shape(s).hasGuard ? 1 : 0;
        for (Vec w : shapes[s].offsets) {
            const Vec v = w - shapes[s].offsets[0];
            r = std::max({r, std::abs(v.x) + extra, std::abs(v.y) + extra, std::abs(v.z) + extra});
        }
    }
    return std::max(r, 1);
}

BoxEngine::BoxEngine(const rules::RuleTables& tables, const Board& board, std::vector<std::uint8_t> combo)
    : tables_(&tables), board_(&board), combo_(std::move(combo)), alphabet_(static_cast<std::size_t>(tables.alphabet())) {
    if (tables.alphabet() > 255)
        throw InputError("system '" + tables.model().system().name + "' has " + std::to_string(tables.alphabet()) +
                         " cell states; the planner stores at most 255 per cell");
    const rules::Lattice& lattice = board.lattice();
    for (int s = 0; s < tables.shapeCount(); ++s) {
        const rules::RuleShape& shape = tables.model().shapes()[s];
        ruleOf_.push_back(shape.rule);
        kinds_.push_back(classify(tables, s));
        std::vector<std::int64_t> cells, writes, reads;
        // Steps are taken from pattern cell 0, the anchor: the first-cell index then applies.
        const Vec origin = shape.offsets[0];
        for (Vec v : shape.offsets) cells.push_back(board.offset(v - origin));
        const rules::RuleTables::Shape& t = tables.shape(s);
        for (std::size_t k = 0; k < shape.offsets.size(); ++k)
            if (tables.mayWrite(s, static_cast<int>(k))) writes.push_back(cells[k]);
        for (const rules::RuleTables::Site site : tables.readSites(s))
            reads.push_back(board.offset(shape.offsets[site.cell] - origin + (site.direction < 0 ? Vec{} : lattice.direction(site.direction))));
        std::sort(reads.begin(), reads.end());
        reads.erase(std::unique(reads.begin(), reads.end()), reads.end());
        influence_.insert(influence_.end(), reads.begin(), reads.end());
        Program program;
        program.cells = static_cast<int>(cells.size());
        program.at = static_cast<std::uint32_t>(steps_.size());
        for (std::size_t k = 0; k < cells.size(); ++k) {
            steps_.push_back(cells[k]);
            copyFrom_.push_back(t.copyFrom[k]), rhs_.push_back(t.copyFrom[k] >= 0 ? nullptr : t.rhs[k].data());
            if (k == 0) continue;
            bool needsCombo = tables.test(t.lhs[k], 0, 0);
            for (int c = 1; c < tables.comboCount() && !needsCombo; ++c)
                for (int v = 0; v < tables.alphabet() && !needsCombo; ++v)
                    needsCombo = tables.test(t.lhs[k], c, static_cast<rules::CellValue>(v)) != tables.test(t.lhs[k], 0, static_cast<rules::CellValue>(v));
            tests_.push_back({cells[k], t.lhs[k].bits.data(), needsCombo, tables.acceptedStates(t.lhs[k].bits).first});
        }
        hot_.push_back({static_cast<std::uint32_t>(tests_.size() - (cells.size() - 1)), static_cast<std::uint32_t>(cells.size() - 1), t.hasGuard});
        for (int c = 0; c < tables.comboCount(); ++c) emptyAnchors_ = emptyAnchors_ || tables.test(t.lhs[0], c, 0);
        program.readAt = static_cast<std::uint32_t>(readPool_.size()), program.reads = reads.size();
        program.writeAt = static_cast<std::uint32_t>(writePool_.size()), program.writes = writes.size();
        readPool_.insert(readPool_.end(), reads.begin(), reads.end());
        writePool_.insert(writePool_.end(), writes.begin(), writes.end());
        programs_.push_back(program);
    }
    std::sort(influence_.begin(), influence_.end());
    influence_.erase(std::unique(influence_.begin(), influence_.end()), influence_.end());
}

bool BoxEngine::matches(const Value* cells, std::int64_t anchor, int shape, std::int64_t cell, Value value, std::int64_t cell2, Value value2) const {
    const rules::RuleTables::Shape& t = tables_->shape(shape);
    const std::span<const std::int64_t> steps = cellSteps(shape);
    std::int32_t at[rules::RuleTables::kMaxCells];
    for (std::size_t k = 0; k < steps.size(); ++k) {
        const std::int64_t i = anchor + steps[k];
        if (combo_[i] == kOutside) return false;
        Value now = cells[i];
        if (i == cell) now = value;
        else if (i == cell2) now = value2;
        if (!tables_->test(t.lhs[k], combo_[i], now)) return false;
        at[k] = static_cast<std::int32_t>(i);
    }
    return !t.hasGuard || tables_->guard(t.guard, BoardCells{cells, combo_.data(), board_, cell, cell2, value, value2}, at);
}

bool BoxEngine::guardHolds(const Value* cells, std::int64_t anchor, int shape) const {
    const Program& p = programs_[shape];
    const std::int64_t* step = steps_.data() + p.at;
    std::int32_t at[rules::RuleTables::kMaxCells];
    for (int k = 0; k < p.cells; ++k) at[k] = static_cast<std::int32_t>(anchor + step[k]);
    return tables_->guard(tables_->shape(shape).guard, BoardCells{cells, combo_.data(), board_, -1, -1, 0, 0}, at);
}

void BoxEngine::apply(Value* cells, std::int64_t anchor, int shape, Value* old) const {
    if (Recorder::active()) Recorder::report({.engine = this, .cells = cells, .anchor = anchor, .shape = shape, .interpreter = nullptr, .configuration = nullptr, .instance = {}});
    const Program& p = programs_[shape];
    const std::int64_t* step = steps_.data() + p.at;
    const int* copyFrom = copyFrom_.data() + p.at;
    const rules::CellValue* const* rhs = rhs_.data() + p.at;
    for (int k = 0; k < p.cells; ++k) old[k] = cells[anchor + step[k]];
    for (int k = 0; k < p.cells; ++k) cells[anchor + step[k]] = static_cast<Value>(copyFrom[k] >= 0 ? old[copyFrom[k]] : rhs[k][old[k]]);
}

}  // namespace holon::planner
