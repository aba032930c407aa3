// Word-parallel matching for regions of at most 64 cells (see WordMatcher.h). Each pattern cell
// of each shape is a left-side mask over (input combination, state); equal masks are one test,
// evaluated once per configuration as a word of accepting cells. The anchors of a shape's
// instances are grouped by how far each pattern cell sits from its anchor in region indices: one
// group per pattern cell in a box region, a few more where rows differ in length (hex disks).

#include "checker/WordMatcher.h"

#include <algorithm>

namespace holon::checker {

using rules::RuleTables;

WordMatcher::WordMatcher(const rules::Engine& engine)
    : engine_(&engine), regionSize_(engine.region().size()), alphabet_(engine.tables().alphabet()) {
    const RuleTables& tables = engine.tables();
    for (int s = 0; s < tables.shapeCount(); ++s) {
        const RuleTables::Shape& shape = tables.shape(s);
        shapes_.push_back({});
        firstCell_.push_back(static_cast<int>(cellTest_.size()));
        for (const RuleTables::Mask& m : shape.lhs) {
            auto it = std::find_if(tests_.begin(), tests_.end(), [&](const RuleTables::Mask& t) { return t.bits == m.bits; });
            if (it == tests_.end()) it = tests_.insert(tests_.end(), m);
            cellTest_.push_back(static_cast<int>(it - tests_.begin()));
        }
    }
    testCells_.assign(tests_.size() * alphabet_, 0);
    for (std::size_t t = 0; t < tests_.size(); ++t)
        for (int c = 0; c < regionSize_; ++c)
            for (int v = 0; v < alphabet_; ++v)
                if (tables.test(tests_[t], engine.comboOfCell(c), static_cast<CellValue>(v))) testCells_[t * alphabet_ + v] |= std::uint64_t{1} << c;
    pending_.resize(cellTest_.size());
    for (const rules::Engine::Placed& p : engine.instances()) addInstance(p.shape, p.cells, p.size);
}

void WordMatcher::addInstance(int shape, const std::int32_t* cells, int size) {
    Shape& sh = shapes_[shape];
    const int anchor = cells[0];
    sh.anchors |= std::uint64_t{1} << anchor;
    for (int k = 0; k < size; ++k) {
        auto& group = pending_[firstCell_[shape] + k];
        const int delta = cells[k] - anchor;
        auto it = std::find_if(group.begin(), group.end(), [&](const Pending& a) { return a.delta == delta; });
        if (it == group.end()) it = group.insert(group.end(), {delta, 0});
        it->anchors |= std::uint64_t{1} << anchor;
    }
}

void WordMatcher::finish() {
    firstCell_.push_back(static_cast<int>(pending_.size()));
    auto stepsOf = [&](int cell, int test) {
        for (const Pending& g : pending_[cell])
            steps_.push_back({~g.anchors, test, static_cast<std::uint8_t>(std::max(0, g.delta)), static_cast<std::uint8_t>(std::max(0, -g.delta))});
    };
    for (std::size_t s = 0; s < shapes_.size(); ++s) {
        shapes_[s].first = static_cast<int>(steps_.size());
        for (int k = firstCell_[s]; k < firstCell_[s + 1]; ++k) stepsOf(k, cellTest_[k]);
        for (const Filter& f : filters_)
            if (f.shape == static_cast<int>(s)) stepsOf(firstCell_[s] + f.k, static_cast<int>(tests_.size()) + f.test);
        shapes_[s].last = static_cast<int>(steps_.size());
    }
    filters_.clear();
    pending_.clear();
    pending_.shrink_to_fit();
    firstCell_.clear();
    cellTest_.clear();
}

}  // namespace holon::checker
