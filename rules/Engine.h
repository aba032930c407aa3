#pragma once
// The compiled rule engine: a system on a region with fixed inputs, compiled into decision tables at
// load time. Every engine that needs speed (the explorer, the planner) runs rules through this one;
// tests hold it to the reference interpreter's semantics.

#include "rules/Interpreter.h"
#include "rules/RuleTables.h"
#include "rules/WordMatcher.h"

#include <bit>
#include <cstdint>
#include <memory>
#include <unordered_map>
#include <vector>

namespace holon::rules {

class Engine {
    struct CompiledExpr;  // a constraint's expression, compiled (below)

public:
    static constexpr int kMaxCells = RuleTables::kMaxCells;
    using GuardNode = RuleTables::GuardNode;

    /// One rule shape anchored in the region, with the region indices of its cells.
    struct Placed {
        int shape = 0, rule = 0;
        Vec anchor;
        std::uint8_t size = 0;
        const std::int32_t* cells = nullptr;  // region indices of the pattern cells (in the engine's pool)
    };

    /// `inputs`: per region cell, the input bits of the problem. With `everyInputCombination`, the
    /// tables cover all 2^k combinations of the k inputs, for encodings where inputs are unknown.
    Engine(const Model& model, const Region& region, const std::vector<std::uint32_t>& inputs, bool everyInputCombination = false);
    ~Engine();
    Engine(Engine&&) noexcept;
    const Model& model() const { return *model_; }
    const Region& region() const { return *region_; }
    const std::vector<Placed>& instances() const { return placed_; }
    /// Placed instances whose pattern includes region cell i (for incremental re-checking).
    const std::vector<std::int32_t>& instancesAt(int cell) const { return byCell_[cell]; }
    Instance instance(int placed) const { return {placed_[placed].shape, placed_[placed].anchor}; }

    /// Left side and guard hold.
    bool matches(const CellValue* cells, int placed) const;
    /// Calls f(placed) once for every instance whose left side and guard hold. On small regions
    /// every shape is matched at all its anchors at once (WordMatcher), in instance order;
    /// otherwise cell by cell, trying only the shapes whose first cell accepts that cell's state.
    template <class F>
    void forEachMatch(const CellValue* cells, F&& f) const {
        const int shapes = static_cast<int>(model_->shapes().size());
        if (words_) {
            words_->forEachShape(cells, [&](int s, std::uint64_t anchors) {
                const bool guarded = tables_.shape(s).hasGuard;
                for (; anchors; anchors &= anchors - 1) {
                    const std::int32_t p = placedIndex_[static_cast<std::size_t>(std::countr_zero(anchors)) * shapes + s];
                    if (!guarded || guardHolds(cells, placed_[p])) f(p);
                }
            });
            return;
        }
        for (int c = 0; c < region_->size(); ++c) {
            for (std::int32_t s : tables_.shapesByFirst(combo_[c], cells[c])) {
                const std::int32_t p = placedIndex_[static_cast<std::size_t>(c) * shapes + s];
                if (p >= 0 && matchesAfterFirst(cells, p)) f(p);
            }
        }
    }
    /// Small regions: f(placed) for every instance whose left side and guard hold, given the cells
    /// in each state as words (`occupied[v]`), by a matcher of the caller's (newWordMatcher, with
    /// tests of its own whose words are `extra`); `cells` is read only by guards.
    template <class F>
    void forEachMatchIn(const WordMatcher& matcher, const std::uint64_t* occupied, const std::uint64_t* extra, const CellValue* cells,
                        F&& f) const {
        const int shapes = static_cast<int>(model_->shapes().size());
        matcher.forEachShapeIn(
            occupied,
            [&](int s, std::uint64_t anchors) {
                const bool guarded = tables_.shape(s).hasGuard;
                for (; anchors; anchors &= anchors - 1) {
                    const std::int32_t p = placedIndex_[static_cast<std::size_t>(std::countr_zero(anchors)) * shapes + s];
                    if (!guarded || guardHolds(cells, placed_[p])) f(p);
                }
            },
            extra);
    }
    /// A word matcher for this engine's instances, not yet finished: the caller may add tests
    /// (WordMatcher::addWordTest, require) before WordMatcher::finish.
    std::unique_ptr<WordMatcher> newWordMatcher() const;
    bool matchesOnWords() const { return words_ != nullptr; }
    /// The predicate T of a constraint conjunct `connected(T)` (`connected` alone: the occupied
    /// cells), or null: every legal configuration's T cells are then one connected set.
    const CellPredicate* connectedConjunct() const;
    /// The constraint word of connectedConjunct()'s predicate, or -1 (constraints not on words).
    int connectedConjunctWord() const;
    /// Small regions: the cells adjacent to each cell, as words.
    const std::vector<std::uint64_t>& neighbourWords() const { return neighbourBits_; }
    bool hasGuards() const;
    /// Small regions: what the constraints read, as words: for each predicate they name, the
    /// cells it accepts, and the mass. A rule step changes them by XOR (member bits) and a sum
    /// (mass) fixed by the states its cells go from and to.
    struct ConstraintWords {
        static constexpr int kMax = 16;
        std::uint64_t members[kMax];  // one per predicate the constraints read
        std::int64_t mass;
    };
    /// The constraints are decided by their words alone (legalOn); false when one needs more,
    /// such as a cell guard or a pointer walk, or they name more than ConstraintWords::kMax
    /// predicates.
    bool constraintsOnWords() const { return constraintsOnWords_; }
    /// The constraint words of a configuration given the cells in each state (`occupied[v]`).
    void constraintWords(const std::uint64_t* occupied, ConstraintWords& out) const;
    /// What a rewrite with fixed old and new states does to the constraint words: the cells each
    /// word loses and gains, and the change of mass; built by addChange, one cell at a time.
    struct WordChange {
        std::uint64_t removed[ConstraintWords::kMax] = {}, added[ConstraintWords::kMax] = {};
        std::int64_t mass = 0;
    };
    void addChange(int cell, CellValue from, CellValue to, WordChange& change) const;
    /// A legal configuration that configurations differing from it in a few cells are judged
    /// against (their parent in a search): its words, the sums of the constraints' linear
    /// comparisons, and, found once when first asked, the cells whose removal disconnects a set
    /// (cut cells).
    struct LegalBefore {
        static constexpr int kMaxSums = 8;
        ConstraintWords words;
        std::int64_t sums[kMaxSums];
        mutable std::uint64_t cuts[ConstraintWords::kMax];
        mutable std::uint32_t cutsKnown = 0;  // bit w: cuts[w] is computed
    };
    /// Fills everything of a LegalBefore but its words.
    void prepare(LegalBefore& before) const;
    /// The cut cells of constraint word `word` of a legal configuration, found when first asked.
    std::uint64_t cutsOf(const LegalBefore& before, int word) const {
        if (!((before.cutsKnown >> word) & 1u)) before.cuts[word] = cutCells(before.words.members[word]), before.cutsKnown |= 1u << word;
        return before.cuts[word];
    }
    /// Every constraint holds. `before`, when given, is a legal configuration this one differs
    /// from in a few cells: a connectivity conjunct is then decided around the cells that changed.
    /// `connectedWord`: a constraint word the caller knows is connected (its test is skipped).
    bool legalOn(const ConstraintWords& now, const LegalBefore* before = nullptr, int connectedWord = -1) const;
    /// A WordChange against the constraint conjuncts: only what can fail after it. A conjunct
    /// the change leaves as it was needs no check (the configuration before was legal).
    struct Check {
        enum class Kind : std::uint8_t {
            Sum,       // sums[index] + delta  op  0
            Removed,   // word `index` loses one cell, `bits`: it must not be a cut cell
            Attached,  // word `index` gains the cells `bits`: they must join it
            Connected, // word `index` loses `removed` and gains `bits`
            General,   // any other conjunct, on the words after the change
        };
        Kind kind;
        CmpOp op = CmpOp::Eq;
        int index = 0;
        std::int64_t delta = 0;
        std::uint64_t bits = 0, removed = 0;
        const CompiledExpr* expr = nullptr;
    };
    std::vector<Check> compileChange(const WordChange& change) const;
    /// Every constraint holds after a fixed change, compiled to `checks` (and described by
    /// `change` for general checks), made to the legal configuration `before`.
    bool legalAfter(const LegalBefore& before, const Check* checks, std::size_t count, const WordChange& change) const;
    /// The state pattern cell k of an instance takes when the instance fires; `old[j]` is the
    /// state of its pattern cell j before.
    CellValue rewritten(const Placed& p, int k, const CellValue* old) const {
        const RuleTables::Shape& t = tables_.shape(p.shape);
        return t.copyFrom[k] >= 0 ? old[t.copyFrom[k]] : t.rhs[k][old[k]];
    }
    /// Rewrites the instance's cells in place; `saved` receives their old values for undo().
    void apply(CellValue* cells, int placed, CellValue* saved) const;
    void undo(CellValue* cells, int placed, const CellValue* saved) const;
    /// Every constraint holds.
    bool legal(const CellValue* cells) const;
    /// Mass of a configuration in units of 1/massDenominator().
    std::int64_t massUnits(const CellValue* cells) const;
    std::int64_t massDenominator() const { return tables_.massDenominator(); }
    const RuleTables& tables() const { return tables_; }

    const std::vector<std::uint32_t>& inputs() const { return inputs_; }

    // ---- read access to the compiled tables, per (input combination, state), for encoders ----
    int comboCount() const { return tables_.comboCount(); }
    std::uint32_t comboInputs(int combo) const { return tables_.comboInputs(combo); }
    int comboOfCell(int cell) const { return combo_[cell]; }
    bool lhsAccepts(int placed, int k, int combo, CellValue v) const;
    /// The pattern cell whose old state cell k takes (a move), or -1.
    int rhsCopyFrom(int placed, int k) const;
    CellValue rhsValue(int placed, int k, CellValue v) const;
    const GuardNode* guardOf(int placed) const;
    /// The compiled cell guard of a region quantifier of this system (`all(H: no nbr _)`).
    const GuardNode& cellGuardOf(const Expr& quantifier) const { return cellGuards_.at(&quantifier); }
    bool guardAccepts(const GuardNode& node, int site, int combo, CellValue v) const;
    bool predicateAccepts(const CellPredicate& pred, int combo, CellValue v) const { return tables_.test(predicateMask(pred), combo, v); }
    std::int64_t massUnitsOf(CellValue v) const { return tables_.massUnitsOf(v); }

    /// Evaluate a non-local expression of this system (a constraint, the goal, a property) on a
    /// configuration. Thread-safe: every predicate is compiled in the constructor.
    bool holds(const Expr& e, const CellValue* cells) const;
    /// The cells that show why a condition of this system is false, for a picture: for each false
    /// conjunct (and every disjunct of a false `or`), the T cells of a false `no(T)`, the T cells
    /// outside the largest connected part of a false `connected(T)`, the T cells where G fails in
    /// `all(T: G)`. Empty where the condition is true or its failure has no cells (a comparison).
    std::vector<int> failureCells(const Expr& e, const CellValue* cells) const;
    /// Whether one cell in state v satisfies a predicate of this system's expressions.
    bool cellMatches(const CellPredicate& pred, int cell, CellValue v) const { return predicateAccepts(pred, combo_[cell], v); }
    Rational number(const Expr& e, const CellValue* cells) const;

public:
    /// Incremental evaluation of the non-local constraints while one thread walks through
    /// configurations that differ in a few cells. On regions of at most 64 cells every predicate of
    /// the system is kept as a 64-bit membership mask, updated per changed cell, and connectivity
    /// is a flood fill over neighbour masks; larger regions fall back to the general evaluation.
    class Evaluator {
    public:
        explicit Evaluator(const Engine& engine);
        void load(const CellValue* cells);
        const CellValue* cells() const { return cells_.data(); }
        void apply(int placed, CellValue* saved);
        void undo(int placed, const CellValue* saved);
        void set(int cell, CellValue value);
        /// The next configuration in candidate order (cell 0 the fastest digit), wrapping to all
        /// zeros after the last; the few cells that change are followed incrementally.
        void advance();
        bool legal() const;

    private:
        /// Cell `cell` now holds `value`: its bit in every predicate word follows.
        void updateMembers(int cell, CellValue value);
        const Engine* engine_;
        std::vector<CellValue> cells_;
        std::vector<std::uint64_t> members_;  // per predicate index
        std::int64_t mass_ = 0;
        bool small_;
    };

private:
    using Mask = RuleTables::Mask;
    /// Left side and guard hold, the first pattern cell known to match. Most cells are decided by
    /// the states their pattern cell accepts under some and under every input combination.
    bool matchesAfterFirst(const CellValue* cells, int placed) const {
        const Placed& p = placed_[placed];
        const RuleTables::Shape& t = tables_.shape(p.shape);
        const CellTest* tests = &cellTests_[firstCellTest_[p.shape]];
        for (int k = 1; k < p.size; ++k) {
            const CellValue v = cells[p.cells[k]];
            if (v < 64) {
                if (!((tests[k].any >> v) & 1u)) return false;
                if ((tests[k].all >> v) & 1u) continue;
            }
            if (!test(t.lhs[k], combo_[p.cells[k]], v)) return false;
        }
        return !t.hasGuard || guardHolds(cells, p);
    }
    bool guardHolds(const CellValue* cells, const Placed& p) const;
    struct CellTest {
        std::uint64_t any, all;  // states below 64 accepted under some / every input combination
    };
    std::vector<CellTest> cellTests_;   // per shape, per pattern cell
    std::vector<int> firstCellTest_;    // per shape: its first entry in cellTests_
    bool test(const Mask& m, int combo, CellValue v) const { return tables_.test(m, combo, v); }
    const Mask& predicateMask(const CellPredicate& pred) const;
    bool connected(const Mask& m, const CellValue* cells) const;
    /// reaches(from, nbr, to): every `from` cell has a path through `from` cells to a `to` cell.
    bool reachesAlongAdjacency(const Mask& from, const Mask& to, const CellValue* cells) const;
    /// Cells satisfying a region quantifier's predicate (and, if asked, its cell guard).
    int countCells(const Expr& e, const CellValue* cells, bool withCellGuard) const;

    const Model* model_;
    const Region* region_;
    std::vector<std::uint32_t> inputs_;
    RuleTables tables_;
    std::vector<int> combo_;  // per cell: index of its input combination in tables_
    std::vector<Placed> placed_;
    std::vector<std::int32_t> cellPool_;  // Placed::cells point here
    std::vector<std::int32_t> placedIndex_;                // [cell * shapes + shape]: the instance anchored there, or -1
    std::vector<std::vector<std::int32_t>> byCell_;
    std::unique_ptr<WordMatcher> words_;  // small regions and alphabets only
    std::unordered_map<const CellPredicate*, int> predicateIndex_;
    std::vector<Mask> predicateMasks_;  // distinct predicates only: equal text, one mask
    std::vector<std::uint64_t> predicateStates_;  // [combo * predicates + k]: the states below 64 predicate k accepts
    std::unordered_map<const Expr*, GuardNode> cellGuards_;  // per quantifier with a cell guard

    /// The constraints as trees whose predicates are already indices (the Evaluator's input).
    struct CompiledExpr {
        Expr::Kind kind;
        CmpOp op;
        Rational value;
        int predicate = -1;
        const Expr* source = nullptr;
        std::vector<CompiledExpr> kids;
        bool cellGuard = false;  // a quantifier with a cell guard: evaluated by the general path
    };
    std::vector<CompiledExpr> compiledConstraints_;
    CompiledExpr compileExpr(const Expr& e) const;
    /// A compiled expression on predicate words (`members[k]`: the cells predicate k accepts) and
    /// the mass; `cells` (null when absent) serves the parts words cannot decide.
    bool holdsOn(const CompiledExpr& e, const std::uint64_t* members, std::int64_t mass, const CellValue* cells) const;
    Rational numberOn(const CompiledExpr& e, const std::uint64_t* members, std::int64_t mass, const CellValue* cells) const;

    /// Small regions: whether a set of cells is connected (a flood fill on words).
    bool connectedCells(std::uint64_t cells) const;
    /// Whether word w of `before`, connected, stays connected when it loses the cells `removed`
    /// and gains `added`.
    bool stillConnected(const LegalBefore& before, int w, std::uint64_t removed, std::uint64_t added) const;
    /// The general case of stillConnected, out of line: `now` is connected when the targets are.
    [[gnu::noinline]] bool reconnected(std::uint64_t now, std::uint64_t targets) const;
    /// The cut cells of a connected, non-empty set (Tarjan's depth-first search on words).
    std::uint64_t cutCells(std::uint64_t set) const;
    bool constraintsOnWords_ = false;
    // The constraints again, their predicates numbered by position in constraintPredicates_
    // (the index into ConstraintWords::members), split at `and`.
    std::vector<CompiledExpr> wordConstraints_;
    /// A conjunct as legalOn evaluates it: a connectivity test, a linear comparison
    /// sum(coefficient x count of word) + massCoefficient x mass  op  0, or any other expression.
    struct Conjunct {
        const CompiledExpr* expr = nullptr;
        std::vector<std::pair<int, std::int64_t>> counts;  // (word, coefficient)
        std::int64_t massCoefficient = 0, constant = 0;
        int sum = -1;  // linear: its index in LegalBefore::sums, else -1
    };
    std::int64_t linearSum(const Conjunct& c, const ConstraintWords& w) const;
    std::vector<Conjunct> conjuncts_;
    /// Adds sign x e to a conjunct's linear form; false when e is not a sum of counts, masses and integers.
    static bool addLinear(const CompiledExpr& e, std::int64_t sign, Conjunct& c);
    std::vector<int> constraintPredicates_;      // predicate indices the constraints read
    std::vector<std::uint64_t> predicateCells_;  // [word * alphabet + state]: cells whose inputs accept the state
    std::vector<std::uint64_t> neighbourBits_;  // small regions: per cell, its neighbours as a mask
    /// Small regions: the neighbours of a set of cells as a few word shifts. Cells whose neighbour
    /// sits `delta` indices away form one mask (in a box, one per direction), so the neighbours of
    /// every cell in r are the union over steps of (r & from) shifted by delta.
    struct Shift {
        std::uint64_t from;
        std::uint8_t left, right;  // delta = left - right; one of them is 0 (branch-free)
    };
    std::vector<Shift> shifts_;
    template <std::size_t N>
    std::uint64_t neighboursBy(std::uint64_t r) const {  // unrolled for boxes: 4 shifts on square2d, 6 on cubic3d
        std::uint64_t out = 0;
        for (std::size_t i = 0; i < N; ++i) out |= ((r & shifts_[i].from) << shifts_[i].left) >> shifts_[i].right;
        return out;
    }
    std::uint64_t neighboursOf(std::uint64_t r) const {
        switch (shifts_.size()) {
        case 4: return neighboursBy<4>(r);
        case 6: return neighboursBy<6>(r);
        }
        std::uint64_t out = 0;
        for (const Shift& s : shifts_) out |= ((r & s.from) << s.left) >> s.right;
        return out;
    }
    /// The same on any small region: by shifts where the region has them, else cell by cell.
    std::uint64_t around(std::uint64_t r) const {
        if (!shifts_.empty()) return neighboursOf(r);
        std::uint64_t out = 0;
        for (; r; r &= r - 1) out |= neighbourBits_[std::countr_zero(r)];
        return out;
    }
};

}  // namespace holon::rules
