#pragma once
// The one translation from the rule IR (through the engine's compiled tables) to SMT terms (Smt.h).
// Z3's limits and failures are in SolverLimits.h.

#include "checker/Smt.h"
#include "rules/Budget.h"
#include "rules/Engine.h"

#include <functional>
#include <map>
#include <optional>
#include <string>
#include <vector>

namespace holon::checker {

class SmtEncoding {
public:
    /// What the formulas are for. Spacer (Horn clauses) is sensitive to how a formula is written,
    /// and the helpers that speed up ordinary queries slow it down: for Horn clauses,
    /// pointer-reachability witnesses do not name their lowest and highest rank, and comparisons of
    /// counts and masses stay two sums instead of one sum of per-cell differences (see the .cpp).
    enum class Use { Queries,
                     HornClauses };
    /// `engine` must cover every input combination (Engine(..., true)) when inputs are left open.
    /// Building formulas throws OutOfTime once `budget` is spent: on a large region encoding alone
    /// can take longer than the solver is given.
    SmtEncoding(smt::Context& ctx, const rules::Engine& engine, Use use = Use::Queries, Budget budget = Budget());
    const Budget& budget() const { return budget_; }
    const rules::Engine& engine() const { return engine_; }

    /// A configuration, one-hot: is[i][v] says cell i holds state v; exactly one per cell (the
    /// domain constraints go to `facts()`).
    struct State {
        std::vector<std::vector<smt::Term>> is;
    };
    State state(const std::string& name);
    /// Facts every query asserts: domains of all states made so far.
    const std::vector<smt::Term>& facts() const { return facts_; }
    /// Fixes the inputs to the problem's (otherwise each cell's inputs are free booleans).
    smt::Term inputsAre(const std::vector<std::uint32_t>& inputs) const;
    /// Each cell's input bits, in the system's input order.
    const std::vector<std::vector<smt::Term>>& inputBits() const { return inputBits_; }
    smt::Term configurationIs(const State& s, const std::vector<rules::CellValue>& cells) const;

    /// A non-local expression of the system. `positive`: the expression occurs under an even number
    /// of negations; connectivity and pointer reachability are then encoded by existential
    /// witnesses (ranks), and under odd negations by refutations (a cut, a pointer-closed set).
    smt::Term holds(const rules::Expr& e, const State& s, bool positive = true);
    smt::Term number(const rules::Expr& e, const State& s);
    /// What a region quantifier `all(T: G)`, `all(T)`, `no(T: G)` or `no(T)` asks of one cell: the
    /// conjunct of holds() for that cell (a local invariant on a window, checker/Window.h).
    smt::Term cellCondition(const rules::Expr& quantifier, const State& s, int cell);
    /// Every constraint holds; `positive` as for holds() (false where the result is negated).
    smt::Term legal(const State& s, bool positive = true);
    /// The configuration placed instance p leads s to, as expressions over s (no new variables):
    /// its pattern cells rewritten, every other cell as in s. Meaningful where p matches.
    State successor(int placed, const State& s) const;
    /// Placed instance p fires from `from` to `to` (left side, guard, rewrite, and frame).
    smt::Term fires(int placed, const State& from, const State& to);
    /// Left side and guard of placed instance p hold (locally enabled).
    smt::Term matches(int placed, const State& s);
    /// One step: `selector` picks the instance; the successor must be legal.
    smt::Term step(const State& from, const State& to, const smt::Term& selector);
    /// (rank of a) <lex (rank of b) when b steps to a by placed instance p: numbers are linear in counts and mass, so
    /// with the frame condition their change is a sum over the instance's own cells.
    smt::Term lexLessAfter(const std::vector<rules::Expr>& ranking, int placed, const State& after, const State& before);
    /// Every component of the ranking is the same after the step as before.
    smt::Term keptAfter(const std::vector<rules::Expr>& ranking, int placed, const State& after, const State& before);
    /// The step by placed instance p breaks ranking `r`: as a step of a rule `r` excepts it changes
    /// it, as a step of a rule it covers it does not decrease it (a shape kept once for several
    /// rules is a step of each: rules::RuleShape::rules).
    smt::Term rankingBroken(const rules::Property& r, int placed, const State& after, const State& before);
    smt::Term massUnits(const State& s);
    /// Cell `cell`'s mass in units of the mass denominator (an integer term).
    smt::Term cellMassUnits(const State& s, int cell) const;
    /// Lemmas for the solver: every connectivity or reachability hypothesis made since the last
    /// call, restated for the cut and stray sets the refutations made since then, or without
    /// refutations for the predicates named in its state (see the .cpp). Implied by the
    /// hypotheses; assert one of the two with the query.
    struct Lemmas {
        smt::Term all;
        /// Without the restatements of reachability hypotheses for named predicates, which help
        /// some queries and drown others (see the .cpp); `all` when there are none.
        smt::Term lean;
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
    std::vector<rules::CellValue> decode(const smt::Model& m, const State& s) const;

    /// Cell `cell` of s is accepted (its state and input combination); a cell < 0 lies outside the
    /// region: empty, without inputs.
    smt::Term member(const State& s, int cell, const std::function<bool(int combo, rules::CellValue v)>& accepts);
    /// Cell `cell` of s satisfies a predicate of the system's expressions.
    smt::Term memberPred(const State& s, int cell, const rules::CellPredicate& pred);

private:
    smt::Term inputCombo(int cell, int combo) const;
    /// Per state some input combination lets `accepts` take: the condition on the cell's input
    /// bits under which it does (true when every combination does).
    std::vector<std::pair<int, smt::Term>> acceptance(int cell, const std::function<bool(int, rules::CellValue)>& accepts);
    /// The cell is in one of the accepted states under its condition.
    smt::Term inStateWhen(const State& s, int cell, const std::vector<std::pair<int, smt::Term>>& accepted) const;
    std::map<std::pair<const rules::CellPredicate*, int>, std::vector<std::pair<int, smt::Term>>> predicateAcceptance_;
    std::vector<int> comboOfBits_;  // when every input combination is covered: [input bits] -> combination
    /// A compiled guard; `cells` are the region indices of the pattern cells it names.
    smt::Term guard(const rules::Engine::GuardNode& g, const std::int32_t* cells, const State& s);
    smt::Term guardNumber(const rules::Engine::GuardNode& g, const std::int32_t* cells, const State& s);
    /// Per site of a guard quantifier (a neighbour of its pattern cell, or a pattern cell): it is accepted.
    std::vector<smt::Term> acceptedSites(const rules::Engine::GuardNode& g, const std::int32_t* cells, const State& s);
    /// The cell counts for a region quantifier: it satisfies the predicate (and the cell guard).
    smt::Term memberCounted(const State& s, std::int32_t cell, const rules::Expr& quantifier);
    /// reaches(from, field, to) at one state: the cells, and per cell and direction whether a step
    /// goes that way.
    struct Reachability {
        std::vector<smt::Term> from, to;
        std::vector<std::vector<smt::Term>> steps;
    };
    /// A connectivity (no `reach`) or reachability hypothesis: what its witness says.
    struct Hypothesis {
        std::vector<smt::Term> members;  // the cells it is about (for reaches: the `from` cells)
        std::optional<Reachability> reach;
        smt::Term witness;
        unsigned state;  // id of the state's first variable
    };
    std::optional<PerCell> perCell(const rules::Expr& e) const;
    /// A comparison of such numbers as one integer sum over cells, with its sign lemmas recorded.
    std::optional<smt::Term> cellwise(const rules::Expr& e, const State& s);
    smt::Term isCut(const std::vector<smt::Term>& members, const std::vector<smt::Term>& in) const;
    smt::Term isStray(const Reachability& r, const std::vector<smt::Term>& in) const;
    /// Free set variables for a refutation; they and their complement among `members` are recorded.
    std::vector<smt::Term> freshSet(const std::string& prefix, const std::vector<smt::Term>& members);
    /// Records the cells of a predicate in state s as a set to instantiate hypotheses on.
    void candidate(const State& s, const std::vector<smt::Term>& members);
    /// Records `witness` (returned) as a hypothesis with what it means.
    smt::Term hypothesis(const smt::Term& witness, Hypothesis h);
    smt::Term connected(const rules::CellPredicate& pred, const State& s, bool positive);
    smt::Term reaches(const rules::Expr& e, const State& s, bool positive);
    /// Cell `to` of the successor takes the rewrite of cell `from` of the predecessor.
    smt::Term rewritten(int placed, int k, const State& before, int fromCell, const State& after, int toCell) const;
    smt::Term sameCell(const State& a, int i, const State& b, int j) const;
    smt::Term fresh(const std::string& prefix, smt::Sort sort);
    smt::Term delta(const rules::Expr& e, int placed, const State& after, const State& before);

    smt::Context& ctx_;
    const rules::Engine& engine_;
    int alphabet_;
    Use use_;
    Budget budget_;
    std::vector<std::vector<smt::Term>> inputBits_;  // [cell][input]
    std::vector<smt::Term> facts_;
    int counter_ = 0;
    std::vector<Hypothesis> hypotheses_;
    std::vector<std::vector<smt::Term>> refutationSets_;
    std::vector<smt::Term> signLemmas_;
    std::vector<std::pair<unsigned, std::vector<smt::Term>>> predicateSets_;  // by state
};

}  // namespace holon::checker
