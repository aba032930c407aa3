// Failure cells for pictures (see FailureCells.h): what a person should look at in the last
// configuration of a violated invariant's trace. Only the quantifiers whose failure has cells
// contribute; the parts of a disconnected set are found by a flood fill over the region.

#include "checker/FailureCells.h"

#include "rules/Components.h"

#include <algorithm>

namespace holon::checker {

using rules::Expr;

namespace {

void collect(const rules::Engine& engine, const Expr& e, const rules::CellValue* cells, std::vector<int>& out) {
    if (engine.holds(e, cells)) return;
    const rules::Region& region = engine.region();
    const int n = region.size();
    auto where = [&](const rules::CellPredicate& pred, auto&& also) {
        for (std::int32_t i = 0; i < n; ++i)
            if (engine.cellMatches(pred, i, cells[i]) && also(i)) out.push_back(i);
    };
    switch (e.kind) {
    case Expr::Kind::And:
    case Expr::Kind::Or:  // a false `or`: every disjunct is false
        for (const Expr& k : e.kids) collect(engine, k, cells, out);
        break;
    case Expr::Kind::No:
        if (e.around == -1 && e.kids.empty()) where(e.pred, [](int) { return true; });
        break;
    case Expr::Kind::All:
        if (rules::hasCellGuard(e)) where(e.pred, [&](std::int32_t i) { return !engine.cellGuardHolds(e, cells, i); });
        break;
    case Expr::Kind::Connected: {
        if (e.around != -1) break;
        // The parts of the T cells; every part but the largest is cut off.
        const auto member = [&](std::int64_t i) { return engine.cellMatches(e.pred, static_cast<int>(i), cells[i]); };
        std::vector<int> part(n, -1), sizes;
        rules::Flood flood;
        rules::components(flood, n, rules::verticesWhere(n, member), rules::regionEdges(region, member), [&](std::int64_t i, int k) {
            if (k == static_cast<int>(sizes.size())) sizes.push_back(0);
            part[i] = k, ++sizes[k];
        });
        const int largest = static_cast<int>(std::max_element(sizes.begin(), sizes.end()) - sizes.begin());
        where(e.pred, [&](int i) { return part[i] != largest; });
        break;
    }
    case Expr::Kind::Bool:
    case Expr::Kind::Number:
    case Expr::Kind::Mass:
    case Expr::Kind::Not:
    case Expr::Kind::Implies:
    case Expr::Kind::Compare:
    case Expr::Kind::Add:
    case Expr::Kind::Sub:
    case Expr::Kind::Neg:
    case Expr::Kind::Count:
    case Expr::Kind::Some:
    case Expr::Kind::Reaches:
        break;  // no cells to show
    }
}

}  // namespace

std::vector<int> failureCells(const rules::Engine& engine, const Expr& e, const rules::CellValue* cells) {
    std::vector<int> out;
    collect(engine, e, cells, out);
    std::sort(out.begin(), out.end());
    out.erase(std::unique(out.begin(), out.end()), out.end());
    return out;
}

}  // namespace holon::checker
