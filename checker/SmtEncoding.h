#pragma once
// The one translation from the rule IR (through the engine's compiled tables) to Z3 expressions.
// Z3's limits and failures are in Solver.h.

#include "checker/Budget.h"
#include "rules/Engine.h"

#include <functional>
#include <map>
#include <optional>
#include <string>
#include <vector>
#include <z3++.h>

namespace holon::checker {

class SmtEncoding {
public:
    /// What the formulas are for. Spacer (Horn clauses) is sensitive to how a formula is written,
    /// and the helpers that speed up ordinary queries slow it down: for Horn clauses,
    /// pointer-reachability witnesses do not name their lowest and highest rank, and comparisons of
    /// counts and masses stay two sums instead of one sum of per-cell differences (see the .cpp).
    enum class Use { Queries, HornClauses };
    /// `engine` must cover every input combination (Engine(..., true)) when inputs are left open.
    /// Building formulas throws OutOfTime once `budget` is spent: on a large region encoding alone
    /// can take longer than the solver is given.
    SmtEncoding(z3::context& ctx, const rules::Engine& engine, Use use = Use::Queries, Budget budget = Budget());
    const Budget& budget() const { return budget_; }

    /// A configuration, one-hot: is[i][v] says cell i holds state v; exactly one per cell (the
    /// domain constraints go to `facts()`).
    struct State {
        std::vector<std::vector<z3::expr>> is;
    };
    State state(const std::string& name);
    /// Facts every query asserts: domains of all states made so far.
    const std::vector<z3::expr>& facts() const { return facts_; }
    /// Fixes the inputs to the problem's (otherwise each cell's inputs are free booleans).
    z3::expr inputsAre(const std::vector<std::uint32_t>& inputs) const;
    /// Each cell's input bits, in the system's input order.
    const std::vector<std::vector<z3::expr>>& inputBits() const { return inputBits_; }
    z3::expr configurationIs(const State& s, const std::vector<rules::CellValue>& cells) const;

    /// A non-local expression of the system. `positive`: the expression occurs under an even number
    /// of negations; connectivity and pointer reachability are then encoded by existential
    /// witnesses (ranks), and under odd negations by refutations (a cut, a pointer-closed set).
    z3::expr holds(const rules::Expr& e, const State& s, bool positive = true);
    z3::expr number(const rules::Expr& e, const State& s);
    /// Every constraint holds; `positive` as for holds() (false where the result is negated).
    z3::expr legal(const State& s, bool positive = true);
    /// The configuration placed instance p leads s to, as expressions over s (no new variables):
    /// its pattern cells rewritten, every other cell as in s. Meaningful where p matches.
    State successor(int placed, const State& s) const;
    /// Placed instance p fires from `from` to `to` (left side, guard, rewrite, and frame).
    z3::expr fires(int placed, const State& from, const State& to);
    /// Left side and guard of placed instance p hold (locally enabled).
    z3::expr matches(int placed, const State& s);
    /// One step: `selector` picks the instance; the successor must be legal.
    z3::expr step(const State& from, const State& to, const z3::expr& selector);
    /// (rank of a) <lex (rank of b) when b steps to a by placed instance p: numbers are linear in counts and mass, so
    /// with the frame condition their change is a sum over the instance's own cells.
    z3::expr lexLessAfter(const std::vector<rules::Expr>& ranking, int placed, const State& after, const State& before);
    /// Every component of the ranking is the same after the step as before.
    z3::expr keptAfter(const std::vector<rules::Expr>& ranking, int placed, const State& after, const State& before);
    z3::expr massUnits(const State& s);
    /// Cell `cell`'s mass in units of the mass denominator (an integer term).
    z3::expr cellMassUnits(const State& s, int cell) const;
    /// Lemmas for the solver: every connectivity or reachability hypothesis made since the last
    /// call, restated for the cut and stray sets the refutations made since then, or without
    /// refutations for the predicates named in its state (see the .cpp). Implied by the
    /// hypotheses; assert one of the two with the query.
    struct Lemmas {
        z3::expr all;
        /// Without the restatements of reachability hypotheses for named predicates, which help
        /// some queries and drown others (see the .cpp); `all` when there are none.
        z3::expr lean;
        bool differ = false;
    };
    Lemmas instantiate();
    /// Records, for the lemmas, the cells of s each distinct left-side test of the rules accepts
    /// (Progress: in a connected ensemble holding both a C and a D, some C is next to some D).
    void leftSideSets(const State& s);

    /// A number that is a constant plus the same function of (inputs, state) summed over cells:
    /// counts without cell guards, mass, and their sums and differences.
    struct PerCell {
        rules::Rational constant;
        std::vector<rules::Rational> term;  // [combo * alphabet + state]
    };

    /// Decodes a configuration from a model.
    std::vector<rules::CellValue> decode(const z3::model& m, const State& s) const;

private:
    z3::expr member(const State& s, int cell, const std::function<bool(int combo, rules::CellValue v)>& accepts);
    z3::expr memberPred(const State& s, int cell, const rules::CellPredicate& pred);
    z3::expr inputCombo(int cell, int combo) const;
    /// Per state some input combination lets `accepts` take: the condition on the cell's input
    /// bits under which it does (true when every combination does).
    std::vector<std::pair<int, z3::expr>> acceptance(int cell, const std::function<bool(int, rules::CellValue)>& accepts);
    /// The cell is in one of the accepted states under its condition.
    z3::expr inStateWhen(const State& s, int cell, const std::vector<std::pair<int, z3::expr>>& accepted) const;
    std::map<std::pair<const rules::CellPredicate*, int>, std::vector<std::pair<int, z3::expr>>> predicateAcceptance_;
    std::vector<int> comboOfBits_;  // when every input combination is covered: [input bits] -> combination
    /// A compiled guard; `cells` are the region indices of the pattern cells it names.
    z3::expr guard(const rules::Engine::GuardNode& g, const std::int32_t* cells, const State& s);
    z3::expr guardNumber(const rules::Engine::GuardNode& g, const std::int32_t* cells, const State& s);
    /// Per site of a guard quantifier (a neighbour of its pattern cell, or a pattern cell): it is accepted.
    std::vector<z3::expr> acceptedSites(const rules::Engine::GuardNode& g, const std::int32_t* cells, const State& s);
    /// The cell counts for a region quantifier: it satisfies the predicate (and the cell guard).
    z3::expr memberCounted(const State& s, std::int32_t cell, const rules::Expr& quantifier);
    /// reaches(from, field, to) at one state: the cells, and per cell and direction whether a step
    /// goes that way.
    struct Reachability {
        std::vector<z3::expr> from, to;
        std::vector<std::vector<z3::expr>> steps;
    };
    /// A connectivity (no `reach`) or reachability hypothesis: what its witness says.
    struct Hypothesis {
        std::vector<z3::expr> members;  // the cells it is about (for reaches: the `from` cells)
        std::optional<Reachability> reach;
        z3::expr witness;
        unsigned state;  // id of the state's first variable
    };
    std::optional<PerCell> perCell(const rules::Expr& e) const;
    /// A comparison of such numbers as one integer sum over cells, with its sign lemmas recorded.
    std::optional<z3::expr> cellwise(const rules::Expr& e, const State& s);
    z3::expr isCut(const std::vector<z3::expr>& members, const std::vector<z3::expr>& in) const;
    z3::expr isStray(const Reachability& r, const std::vector<z3::expr>& in) const;
    /// Free set variables for a refutation; they and their complement among `members` are recorded.
    std::vector<z3::expr> freshSet(const std::string& prefix, const std::vector<z3::expr>& members);
    /// Records the cells of a predicate in state s as a set to instantiate hypotheses on.
    void candidate(const State& s, const std::vector<z3::expr>& members);
    /// Records `witness` (returned) as a hypothesis with what it means.
    z3::expr hypothesis(const z3::expr& witness, Hypothesis h);
    z3::expr connected(const rules::CellPredicate& pred, const State& s, bool positive);
    z3::expr reaches(const rules::Expr& e, const State& s, bool positive);
    /// Cell `to` of the successor takes the rewrite of cell `from` of the predecessor.
    z3::expr rewritten(int placed, int k, const State& before, int fromCell, const State& after, int toCell) const;
    z3::expr sameCell(const State& a, int i, const State& b, int j) const;
    z3::expr fresh(const std::string& prefix, const z3::sort& sort);
    z3::expr delta(const rules::Expr& e, int placed, const State& after, const State& before);

    z3::context& ctx_;
    const rules::Engine& engine_;
    int alphabet_;
    Use use_;
    Budget budget_;
    std::vector<std::vector<z3::expr>> inputBits_;  // [cell][input]
    std::vector<z3::expr> facts_;
    int counter_ = 0;
    std::vector<Hypothesis> hypotheses_;
    std::vector<std::vector<z3::expr>> refutationSets_;
    std::vector<z3::expr> signLemmas_;
    std::vector<std::pair<unsigned, std::vector<z3::expr>>> predicateSets_;  // by state
};

}  // namespace holon::checker
