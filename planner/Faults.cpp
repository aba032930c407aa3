// Fault injection for plan runs (planner/Faults.h). The message layer is a filter on the
// scheduler, not a second copy of the state: an instance may fire once the latest state of every
// cell it reads has reached the others (a change made in round r arrives in round r + 1 .. r + D,
// drawn per change), and a relabel's message is lost with probability P each time the scheduler
// would fire it. Both only hold instances back, so every run is still an interleaving of enabled
// instances, the semantics the lemmas speak about. A loss is a write no rule makes: it is judged
// by the reference interpreter against the system's invariants and progress assumption.

#include "planner/Faults.h"

#include "planner/Replay.h"
#include "planner/Report.h"
#include "rules/ConfigIo.h"
#include "rules/Error.h"
#include "rules/Limits.h"
#include "rules/Parameter.h"

#include <charconv>
#include <sstream>

namespace holon::planner {

namespace {

std::string point(const Board& board, Vec p) { return showCell(p, board.lattice().dimension()); }

bool inside(const Board& board, Vec p) {
    const Vec lo = board.lower(), ext = board.extent();
    const bool z = board.lattice().dimension() != 3 || (p.z >= lo.z && p.z < lo.z + ext.z);
    return p.x >= lo.x && p.x < lo.x + ext.x && p.y >= lo.y && p.y < lo.y + ext.y && z;
}

}  // namespace

Loss parseLoss(const std::string& option, const std::string& text, int dimension, bool cell) {
    const std::string want = cell ? (dimension == 3 ? "ROUND:x,y,z" : "ROUND:x,y") : "ROUND";
    const auto fail = [&](const std::string& why) -> Loss { throw InputError(option + " '" + text + "': " + why + "; give " + want + " (ROUND >= 1: the loss comes after that round)"); };
    const std::size_t colon = text.find(':');
    if (cell != (colon != std::string::npos)) return fail(cell ? "no ':' between the round and the cell" : "a round alone, no cell");
    std::vector<std::int64_t> numbers;
    std::istringstream in(text.substr(0, colon) + (cell ? "," + text.substr(colon + 1) : ""));
    for (std::string part; std::getline(in, part, ',');) {
        std::int64_t v = 0;
        const auto [end, ec] = std::from_chars(part.data(), part.data() + part.size(), v);
        if (ec == std::errc::result_out_of_range) return fail("'" + part + "' is beyond the 64-bit range");
        if (part.empty() || ec != std::errc{} || end != part.data() + part.size()) return fail("'" + part + "' is not an integer");
        numbers.push_back(v);
    }
    if (text.back() == ',') return fail("ends with ','");
    if (numbers.size() != (cell ? 1u + static_cast<unsigned>(dimension) : 1u))
        return fail(cell ? std::to_string(numbers.size() - 1) + " coordinates, but the shapes are " + std::to_string(dimension) + "D" : "one number");
    if (numbers[0] < 1) return fail("round " + std::to_string(numbers[0]));
    Loss loss{numbers[0], std::nullopt};
    for (std::size_t k = 1; k < numbers.size(); ++k)
        if (numbers[k] < -rules::kMaxCoordinate || numbers[k] > rules::kMaxCoordinate) return fail("coordinate " + std::to_string(numbers[k]) + " is beyond +-" + std::to_string(rules::kMaxCoordinate));
    if (cell) loss.cell = Vec{static_cast<int>(numbers[1]), static_cast<int>(numbers[2]), dimension == 3 ? static_cast<int>(numbers[3]) : 0};
    return loss;
}

Faults::Faults(const Problem& problem, FaultOptions options)
    : problem_(&problem), options_(std::move(options)), random_(options_.seed), done_(options_.losses.size(), false), events_(options_.losses.size()) {
    const Board& board = *problem.board;
    for (const Loss& loss : options_.losses)
        if (loss.cell && !inside(board, *loss.cell))
            throw InputError(rules::parameterName(rules::Parameter::Lose) + " " + std::to_string(loss.round) + ":" + point(board, *loss.cell).substr(1, point(board, *loss.cell).size() - 2) + ": cell " +
                                 point(board, *loss.cell) + " lies outside start and target (the box from " + point(board, board.lower()) + " to " +
                                 point(board, board.lower() + board.extent() - Vec{1, 1, board.lattice().dimension() == 3 ? 1 : 0}) + "); name a metamodule of the start",
                             rules::Parameter::Lose);
    if (options_.delay > 0) arrives_.assign(static_cast<std::size_t>(board.size()), 0);
}

bool Faults::admit(const Execution& execution, std::int64_t anchor, int shape) {
    const BoxEngine& engine = execution.engine();
    if (!arrives_.empty()) {
        const std::int64_t now = execution.stats().rounds;
        for (std::int64_t r : engine.readSteps(shape))
            if (arrives_[anchor + r] > now) return ++delayed_, false;
    }
    if (options_.drop > 0 && engine.kind(shape) == ShapeKind::Relabel && static_cast<double>(random_.next() >> 11) * 0x1p-53 < options_.drop) return ++dropped_, false;
    return true;
}

void Faults::fired(const Execution& execution, std::int64_t anchor, int shape, const BoxEngine::Value* old) {
    if (arrives_.empty()) return;
    const std::int64_t now = execution.stats().rounds;
    const auto steps = execution.engine().cellSteps(shape);
    for (std::size_t k = 0; k < steps.size(); ++k)
        if (execution.cells()[anchor + steps[k]] != old[k])
            arrives_[anchor + steps[k]] = now + 1 + static_cast<std::int64_t>(random_.below(static_cast<std::uint64_t>(options_.delay)));
}

std::string Faults::describe(std::int64_t cell, BoxEngine::Value value) const {
    const rules::Model& model = *problem_->model;
    return point(*problem_->board, problem_->board->point(cell)) + " " + (value ? model.alphabet().name(value) : std::string("(empty)"));
}

void Faults::roundEnd(Execution& execution, const std::function<void(std::int64_t, BoxEngine::Value)>& lost) {
    const Board& board = *problem_->board;
    const std::int64_t round = execution.stats().rounds;
    roundsSeen_ = round;
    for (std::size_t k = 0; k < options_.losses.size() && broken_.empty(); ++k) {
        if (done_[k] || options_.losses[k].round > round) continue;
        // Each loss is judged by a pass over the board (0.4 s at 10^6 metamodules): 40 losses after
        // one round ran 17 s past --timeout 1. The rest wait, as "not reached", when the run stops.
        if (execution.budget().expired() || execution.budget().interrupted()) return;
        done_[k] = true;
        std::int64_t cell = -1;
        if (options_.losses[k].cell) {
            cell = board.index(*options_.losses[k].cell);
        } else {
            std::vector<std::int64_t> occupied;
            board.forEachInside([&](std::int64_t i, Vec) {
                if (execution.cells()[i]) occupied.push_back(i);
            });
            if (!occupied.empty()) cell = occupied[random_.below(occupied.size())];
        }
        const std::string when = "after round " + std::to_string(round);
        if (cell < 0 || execution.cells()[cell] == 0) {
            events_[k] = (cell < 0 ? std::string("no metamodule") : point(board, board.point(cell)) + " was empty") + " " + when + ": nothing lost";
            continue;
        }
        const BoxEngine::Value old = execution.lose(cell);
        lost(cell, old);
        events_[k] = "lost " + describe(cell, old) + " " + when;
        broken_ = judge(execution, cell, old, round);
        if (!broken_.empty()) execution.halt(StopReason::Fault);
    }
}

std::string Faults::judge(const Execution& execution, std::int64_t cell, BoxEngine::Value old, std::int64_t round) const {
    const std::string what = "losing " + describe(cell, old) + " after round " + std::to_string(round);
    // Connectivity first, in pieces: the one thing no rule can mend (rules move no metamodule
    // across a gap), and what --check must not blame on the planner.
    const Board& board = *problem_->board;
    const auto& cells = execution.cells();
    std::vector<char> seen(cells.size(), 0);
    std::vector<std::int64_t> sizes;
    board.forEachInside([&](std::int64_t start, Vec) {
        if (!cells[start] || seen[start]) return;
        std::vector<std::int64_t> stack{start};
        seen[start] = 1;
        std::int64_t size = 0;
        while (!stack.empty()) {
            const std::int64_t i = stack.back();
            stack.pop_back();
            ++size;
            for (int d = 0; d < board.lattice().degree(); ++d)
                if (const std::int64_t j = i + board.step(d); cells[j] && !seen[j]) seen[j] = 1, stack.push_back(j);
        }
        sizes.push_back(size);
    });
    if (sizes.empty()) return what + " left no metamodule";
    if (sizes.size() > 1) {
        std::string list;
        for (std::size_t k = 0; k < sizes.size() && k < 5; ++k) list += (k ? ", " : "") + std::to_string(sizes[k]);
        return what + " cut the ensemble into " + std::to_string(sizes.size()) + " pieces (" + list + (sizes.size() > 5 ? ", ..." : "") +
               " metamodules): the fault disconnected it, not the planner; no rule joins pieces";
    }
    // The lemmas' hypotheses, as the system states them: its invariants (Safety) and the
    // assumption of its progress property. One interpreter pass per loss.
    const BoardConfiguration configuration(*problem_, cells);
    if (const std::optional<std::string> broken = brokenHypothesis(configuration.interpreter(), configuration.configuration(), true))
        return what + " broke " + *broken + ", so seed 000's lemmas no longer cover the run";
    const rules::System& system = problem_->model->system();
    // Lemma 2's condition, as the planner knows it: the mass left must fill the target at its goal,
    // since no rule makes any (a loss only lowers it). The general_n systems state it as their
    // progress assumption, checked above; the lock planners state none.
    if (system.conservesMass() && problem_->schema.resource >= 0) {
        const rules::RuleTables& tables = *problem_->tables;
        std::int64_t units = 0;
        board.forEachInside([&](std::int64_t i, Vec) { units += cells[i] ? tables.massUnitsOf(cells[i]) : 0; });
        const rules::Rational mass(units, tables.massDenominator());
        const auto targetCells = static_cast<std::int64_t>(problem_->target.cells.size());
        const std::optional<GoalMass> atGoal = goalMass(*problem_, tables.comboIndex(1u << problem_->schema.target));
        const rules::Rational need = rules::Rational(targetCells) * rules::Rational(atGoal ? atGoal->least : 0, tables.massDenominator());
        if (mass < need)
            return what + " left mass " + mass.str() + ", and the target's " + std::to_string(targetCells) + " cells hold at least " + need.str() +
                   " at the goal: mass is conserved, so no plan can reach it";
    }
    return "";
}

std::string Faults::event(std::size_t k) const {
    if (done_[k]) return events_[k];
    const std::int64_t round = options_.losses[k].round;
    return "loss after round " + std::to_string(round) + (round > roundsSeen_ ? " not reached" : " not made: the run stopped first");
}

std::string Faults::summary() const {
    std::string s;
    for (std::size_t k = 0; k < options_.losses.size(); ++k)
        s += (s.empty() ? "" : "; ") + event(k);
    if (options_.delay > 0) s += (s.empty() ? "" : "; ") + std::to_string(delayed_) + " instances held back by late messages (delay 1-" + std::to_string(options_.delay) + " rounds)";
    if (options_.drop > 0) s += (s.empty() ? "" : "; ") + std::to_string(dropped_) + " relabel messages dropped";
    return s;
}

nlohmann::json Faults::json() const {
    nlohmann::json losses = nlohmann::json::array();
    for (std::size_t k = 0; k < options_.losses.size(); ++k)
        losses.push_back(event(k));
    return {{"losses", losses}, {"delayed", delayed_}, {"dropped", dropped_}, {"broken", broken_.empty() ? nlohmann::json() : nlohmann::json(broken_)}};
}

}  // namespace holon::planner
