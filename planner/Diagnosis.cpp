// The rule a stuck cell waits on (planner/Diagnosis.h). Every orientation of every rule that would
// write the cell is placed over it, in each position the cell could take; the interpreter says
// which pattern cells reject their states and which guard conjunct is false. The instance with the
// fewest failures is the nearest to firing, and what fails there is what the cell waits for;
// transfers come last, since moving a resource alone never brings a cell to the goal.

#include "planner/Diagnosis.h"
#include "planner/Transport.h"

#include "rules/Printer.h"

#include <algorithm>
#include <limits>

namespace holon::planner {

std::string waitingOn(const Problem& problem, const BoardConfiguration& board, std::int64_t cell) {
    const rules::Model& model = *problem.model;
    const rules::Interpreter& in = board.interpreter();
    const rules::Configuration& c = board.configuration();
    const BoxEngine& engine = *problem.engine;
    const Vec at = board.position(problem.board->point(cell));
    const auto boardPoint = [&](Vec regionPoint) { return showCell(regionPoint - board.shift(), model.lattice().dimension()); };
    const auto stateAt = [&](Vec regionPoint) {
        const rules::CellValue v = c.cells[static_cast<std::size_t>(in.region().indexOf(regionPoint))];
        return v ? model.alphabet().name(v) : std::string("empty");
    };
    std::optional<rules::Instance> best;
    rules::Blocked bestWhy;
    std::size_t bestScore = std::numeric_limits<std::size_t>::max();
    for (int s = 0; s < static_cast<int>(model.shapes().size()); ++s) {
        const rules::RuleShape& shape = model.shapes()[s];
        const auto steps = engine.cellSteps(s);
        const auto writes = engine.writeSteps(s);
        for (std::size_t k = 0; k < shape.offsets.size(); ++k) {
            if (std::find(writes.begin(), writes.end(), steps[k]) == writes.end()) continue;
            const rules::Instance instance{s, at - shape.offsets[k]};
            if (!in.cellsOf(instance)) continue;
            rules::Blocked why = in.blocked(c, instance);
            if (std::find(why.cells.begin(), why.cells.end(), static_cast<int>(k)) != why.cells.end()) continue;  // not a rule for this state
            // A transfer only moves resources, never a cell toward the goal: planner rules first.
            const std::size_t score = (engine.kind(s) == ShapeKind::Transfer ? 1000 : 0) + why.cells.size() + (why.conjunct >= 0);
            if (score < bestScore) bestScore = score, best = instance, bestWhy = std::move(why);
        }
    }
    if (!best) return "no rule changes a cell in this state here";
    const rules::RuleShape& shape = model.shapes()[best->shape];
    const rules::DirectedRule& rule = model.rules()[shape.rule];
    std::string cells;
    for (Vec o : shape.offsets) cells += (cells.empty() ? "" : " ") + boardPoint(best->anchor + o);
    std::string text = "waits on rule " + rule.name + " at " + cells;
    // Only a system that moves resources has an allocator to hold anything back.
    if (bestWhy.enabled()) return text + ": enabled, not fired: held back by " + (movesResources(problem) ? "the allocator, " : "") + "a fault or a constraint, or the run stopped first";
    const rules::RefPrinter ref = [&](int k) { return "@" + boardPoint(best->anchor + shape.offsets[static_cast<std::size_t>(k)]); };
    std::vector<std::string> fails;
    for (int k : bestWhy.cells) {
        const Vec p = best->anchor + shape.offsets[static_cast<std::size_t>(k)];
        fails.push_back(boardPoint(p) + " is " + stateAt(p) + ", the rule needs " + rules::printTerm(model.system(), rule.lhs()[static_cast<std::size_t>(k)], ref));
    }
    if (bestWhy.conjunct >= 0) {
        const rules::Expr& e = *rules::conjuncts(*rule.guard())[static_cast<std::size_t>(bestWhy.conjunct)];
        std::string blame = "guard `" + rules::printExpr(model.system(), e, ref) + "` is false";
        for (std::size_t w = 0; w < bestWhy.witnesses.size(); ++w)
            blame += (w ? ", " : ": blocked by ") + boardPoint(bestWhy.witnesses[w]) + " " + stateAt(bestWhy.witnesses[w]);
        fails.push_back(blame);
    }
    for (std::size_t f = 0; f < fails.size(); ++f) text += (f ? "; " : ": ") + fails[f];
    return text;
}

}  // namespace holon::planner
