#pragma once
// The system's constraints compiled for the explorer: trees whose predicates are numbered words
// (predicate k's word: the cells it accepts), evaluated from those words and the mass. On regions
// and alphabets of at most 64 the constraints are usually decided by their words alone, and then
// incrementally: a conjunct that is a linear comparison of counts and the mass is a sum a rule
// step changes by a fixed amount, and a connectivity conjunct is decided around the cells that
// changed (a cut cell of a connected set, a flood from the added cells). rules::Engine::legal is
// the reference these are tested against (tests/checker/WordsTest.cpp).

#include "checker/WordAdjacency.h"
#include "rules/Engine.h"

#include <cstdint>
#include <memory>
#include <optional>
#include <vector>

namespace holon::checker {

using rules::CellValue;

class WordConstraints {
    struct Tree;  // a constraint, compiled (below)

public:
    explicit WordConstraints(const rules::Engine& engine);
    WordConstraints(const WordConstraints&) = delete;  // conjuncts point into the trees
    WordConstraints& operator=(const WordConstraints&) = delete;
    const rules::Engine& engine() const { return *engine_; }

    // ---- any region: the constraints on predicate words, falling back to the cells ----
    /// The distinct predicates the constraints read; words are numbered by them.
    int predicates() const { return static_cast<int>(masks_.size()); }
    /// The states below 64 predicate k accepts under input combination `combo`.
    const std::uint64_t* acceptedStates(int combo) const { return &acceptedStates_[static_cast<std::size_t>(combo) * masks_.size()]; }
    bool accepts(int k, int combo, CellValue v) const { return engine_->tables().test(*masks_[k], combo, v); }
    /// Every constraint holds, on a region of at most 64 cells, given each predicate's word
    /// (`members[k]`), the mass, and the cells for the parts words cannot decide (a cell guard,
    /// a reaches).
    bool holdsOn(const std::uint64_t* members, std::int64_t mass, const CellValue* cells) const;

    // ---- small regions: the constraints decided by words alone ----
    /// Words decide every constraint: the region and the alphabet have at most 64 cells and
    /// states, no constraint needs a cell guard or a pointer walk, and they read at most
    /// Words::kMax predicates. The rest of this section needs it.
    bool onWords() const { return onWords_; }
    /// What the constraints read: per predicate the cells it accepts, and the mass. A rule step
    /// changes them by XOR (member bits) and a sum (mass) fixed by the states its cells go from
    /// and to.
    struct Words {
        static constexpr int kMax = 16;
        std::uint64_t members[kMax];
        std::int64_t mass;
    };
    /// The words of a configuration given the cells in each state (`occupied[v]`).
    void wordsOf(const std::uint64_t* occupied, Words& out) const;
    /// The predicate T of a constraint conjunct `connected(T)` (`connected` alone: the occupied
    /// cells), or null: every legal configuration's T cells are then one connected set.
    const rules::CellPredicate* connectedConjunct() const;
    /// The word of connectedConjunct()'s predicate, or -1.
    int connectedConjunctWord() const;
    const WordAdjacency& adjacency() const { return *adjacency_; }

    /// A legal configuration that configurations differing from it in a few cells are judged
    /// against (their parent in a search): its words, the sums of the constraints' linear
    /// comparisons, and, found once when first asked, the cells whose removal disconnects a word
    /// (cut cells).
    struct LegalBefore {
        static constexpr int kMaxSums = 8;
        Words words;
        std::int64_t sums[kMaxSums];
        mutable std::uint64_t cuts[Words::kMax];
        mutable std::uint32_t cutsKnown = 0;  // bit w: cuts[w] is computed
    };
    /// Fills everything of a LegalBefore but its words.
    void prepare(LegalBefore& before) const;
    /// The cut cells of word `word` of a legal configuration, found when first asked.
    std::uint64_t cutsOf(const LegalBefore& before, int word) const {
        if (!((before.cutsKnown >> word) & 1u)) before.cuts[word] = adjacency_->cutCells(before.words.members[word]), before.cutsKnown |= 1u << word;
        return before.cuts[word];
    }
    /// Every constraint holds. `before`, when given, is a legal configuration this one differs
    /// from in a few cells: a connectivity conjunct is then decided around the cells that changed.
    /// `connectedWord`: a word the caller knows is connected (its test is skipped).
    bool legalOn(const Words& now, const LegalBefore* before = nullptr, int connectedWord = -1) const;

    /// What a rewrite with fixed old and new states does to the words: the cells each word loses
    /// and gains, and the change of mass; built by addChange, one cell at a time.
    struct WordChange {
        std::uint64_t removed[Words::kMax] = {}, added[Words::kMax] = {};
        std::int64_t mass = 0;
    };
    void addChange(int cell, CellValue from, CellValue to, WordChange& change) const;
    /// A WordChange against the conjuncts: only what can fail after it. A conjunct the change
    /// leaves as it was needs no check (the configuration before was legal).
    struct Check {
        enum class Kind : std::uint8_t {
            Sum,        // sums[index] + delta  op  0
            Removed,    // word `index` loses one cell, `bits`: it must not be a cut cell
            Attached,   // word `index` gains the cells `bits`: they must join it
            Connected,  // word `index` loses `removed` and gains `bits`
            General,    // any other conjunct, on the words after the change
        };
        Kind kind;
        rules::CmpOp op = rules::CmpOp::Eq;
        int index = 0;
        std::int64_t delta = 0;
        std::uint64_t bits = 0, removed = 0;
        const Tree* expr = nullptr;
    };
    std::vector<Check> compileChange(const WordChange& change) const;
    /// Every constraint holds after a fixed change, compiled to `checks` (and described by
    /// `change` for general checks), made to the legal configuration `before`.
    bool legalAfter(const LegalBefore& before, const Check* checks, std::size_t count, const WordChange& change) const;

private:
    /// A constraint whose predicates are word numbers. A quantifier with a cell guard, and any
    /// kind words cannot decide, is evaluated on the cells by the engine (`source`).
    struct Tree {
        rules::Expr::Kind kind;
        rules::CmpOp op;
        rules::Rational value;
        int predicate = -1;
        const rules::Expr* source = nullptr;
        std::vector<Tree> kids;
        bool cellGuard = false;
    };
    Tree compile(const rules::Expr& e);
    bool holdsOn(const Tree& e, const std::uint64_t* members, std::int64_t mass, const CellValue* cells) const;
    rules::Rational numberOn(const Tree& e, const std::uint64_t* members, std::int64_t mass, const CellValue* cells) const;
    /// Whether word w of `before`, connected, stays connected when it loses the cells `removed`
    /// and gains `added`.
    bool stillConnected(const LegalBefore& before, int w, std::uint64_t removed, std::uint64_t added) const;

    /// A conjunct as legalOn evaluates it: a connectivity test, a linear comparison
    /// sum(coefficient x count of word) + massCoefficient x mass  op  0, or any other tree.
    struct Conjunct {
        const Tree* expr = nullptr;
        std::vector<std::pair<int, std::int64_t>> counts;  // (word, coefficient)
        std::int64_t massCoefficient = 0, constant = 0;
        int sum = -1;  // linear: its index in LegalBefore::sums, else -1
    };
    /// Adds sign x e to a conjunct's linear form; false when e is not a sum of counts, masses and integers.
    static bool addLinear(const Tree& e, std::int64_t sign, Conjunct& c);
    std::int64_t linearSum(const Conjunct& c, const Words& w) const;

    const rules::Engine* engine_;
    std::vector<const rules::RuleTables::Mask*> masks_;  // per word: its predicate's mask
    std::vector<std::uint64_t> acceptedStates_;          // [combo * words + k]: the states below 64 word k accepts
    std::vector<Tree> trees_;                            // per constraint
    bool onWords_ = false;
    std::vector<Conjunct> conjuncts_;           // on words: the constraints split at `and`
    std::vector<std::uint64_t> cellsInState_;   // on words: [word * alphabet + state]: cells whose inputs accept the state
    std::unique_ptr<WordAdjacency> adjacency_;  // regions of at most 64 cells
};

}  // namespace holon::checker
