#pragma once
// The one adapter between holon and Z3 (Smt.cpp is the only file that sees Z3's API): terms
// (`Term`) in a `Context`, a `Solver` with a `Result` enum, the `Model` of a satisfiable answer,
// and Z3's process-wide memory accounting. Every Z3 error surfaces as `smt::Failure`. What a
// failure or an unknown answer means for an obligation is in SolverLimits.h.

#include "rules/Budget.h"

#include <cstdint>
#include <memory>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

namespace holon::checker::smt {

/// A Z3 error: running out of its memory limit, an invalid call (a bug in holon), a bad file.
class Failure : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

class Term;
class Relation;
enum class Sort { Bool,
                  Int };

/// Owns a Z3 context; every Term, Relation, Solver and Model made in it must go before it does.
class Context {
public:
    /// Throws Failure("out of memory") where Z3 cannot make a context within its memory limit.
    /// Freed with the Context unless `budget` is spent or interrupted by then (see the destructor).
    explicit Context(const Budget& budget = Budget());
    /// Releases the terms move assignments kept (see Term), newest first, then the context.
    /// Past the deadline or a signal it stays allocated, and reachable, until the process ends.
    ~Context();
    Context(const Context&) = delete;
    Context& operator=(const Context&) = delete;

    Term boolVal(bool b);
    Term intVal(std::int64_t n);
    Term realVal(std::int64_t n);
    /// num/den, exactly (Z3's C++ API takes ints: larger ones go through the numeral's text).
    Term realVal(std::int64_t num, std::int64_t den);
    Term constant(const std::string& name, Sort sort);
    Term boolConst(const std::string& name);
    Term intConst(const std::string& name);
    /// An uninterpreted predicate over `arity` Booleans (a Horn clause relation).
    Relation relation(const std::string& name, unsigned arity);

    struct Native;  // the Z3 context, in Smt.cpp
    Native& native() const { return *native_; }
    const Budget& budget() const { return budget_; }
    /// Throws the budget's OutOfTime or Interrupted once it is spent or a signal is caught (the
    /// watcher has then interrupted Z3, or is about to); `during` says what was cut short.
    void checkStopped(const char* during) const;
    /// A check in this context answered unknown for want of memory: it is not freed then (below).
    void markExhausted() { exhausted_ = true; }

private:
    friend class Term;
    struct Watcher;  // interrupts Z3 at the deadline or on a signal, in Smt.cpp
    Budget budget_;
    Native* native_;
    /// The Z3 terms move assignments overwrote, in order (Term::Node*, declared below): each still
    /// holds the reference Z3's C++ API would have kept.
    std::vector<const void*> retained_;
    bool exhausted_ = false;
    std::unique_ptr<Watcher> watcher_;
};

/// A Z3 term, reference-counted; copies share the term. A move assignment keeps the term it
/// overwrites referenced until the context goes, as Z3 4.8.12's C++ API does: the SMT-LIB2 files
/// written from the terms, and the solver's timings, depend on it (see Smt.cpp).
class Term {
public:
    /// What the inspection of a solved formula needs (Reach's invariant printer); anything else is Other.
    enum class Op { Var,
                    True,
                    False,
                    Not,
                    And,
                    Or,
                    Implies,
                    Eq,
                    Xor,
                    Other };

    Term(const Term& o);
    Term(Term&& o) noexcept : ctx_(o.ctx_), node_(o.node_) { o.node_ = nullptr; }
    Term& operator=(const Term& o);
    Term& operator=(Term&& o);
    ~Term();

    Context& context() const { return *ctx_; }
    /// Z3's id of the term: equal for structurally equal terms of one context.
    unsigned id() const;
    Term simplify() const;
    /// The term with bound variable k replaced by `values[k]`.
    Term substituteVars(const std::vector<Term>& values) const;
    Op op() const;
    unsigned arity() const;
    Term arg(unsigned k) const;
    /// The de Bruijn index of a bound variable (op() == Var).
    unsigned varIndex() const;
    std::string str() const;

    struct Node;                     // a Z3_ast, in Smt.cpp
    Term(Context& ctx, Node* node);  // takes a reference to `node`
    Node* node() const { return node_; }

private:
    Context* ctx_;
    Node* node_;
};

Term operator!(const Term& a);
Term operator&&(const Term& a, const Term& b);
Term operator||(const Term& a, const Term& b);
Term operator==(const Term& a, const Term& b);
Term operator!=(const Term& a, const Term& b);
Term operator<(const Term& a, const Term& b);
Term operator<=(const Term& a, const Term& b);
Term operator>(const Term& a, const Term& b);
Term operator>=(const Term& a, const Term& b);
/// Against a numeral of a's sort.
Term operator==(const Term& a, int b);
Term operator<(const Term& a, int b);
Term operator<=(const Term& a, int b);
Term operator>(const Term& a, int b);
Term operator>=(const Term& a, int b);
Term operator+(const Term& a, const Term& b);
Term operator-(const Term& a, const Term& b);
Term operator-(const Term& a);
Term operator/(const Term& a, const Term& b);
Term implies(const Term& a, const Term& b);
Term ite(const Term& c, const Term& t, const Term& e);
Term toReal(const Term& a);
/// The disjunction of `terms` as one n-ary or (a nullary one, false, when there are none).
Term anyOf(Context& ctx, const std::vector<Term>& terms);
/// Structural identity (Z3 shares equal terms).
bool same(const Term& a, const Term& b);
/// The sentence universally closed over its uninterpreted constants (a Horn clause).
Term universalClosure(const Term& sentence);

/// An uninterpreted predicate over Booleans, made by Context::relation.
class Relation {
public:
    struct Native;  // the Z3 declaration, in Smt.cpp
    Relation(Context& ctx, std::shared_ptr<const Native> native) : ctx_(&ctx), native_(std::move(native)) {}
    Term operator()(const std::vector<Term>& args) const;
    const Native& native() const { return *native_; }

private:
    Context* ctx_;
    std::shared_ptr<const Native> native_;
};

enum class Result { Sat,
                    Unsat,
                    Unknown };

/// The model of a satisfiable answer, completed: every term has a value.
class Model {
public:
    bool isTrue(const Term& e) const;
    int intValue(const Term& e) const;
    /// The relation's interpretation over its bound variables, if the model has one.
    std::optional<Term> definition(const Relation& r) const;
    struct Native;  // the Z3 model, in Smt.cpp
    Model(Context& ctx, std::shared_ptr<const Native> native) : ctx_(&ctx), native_(std::move(native)) {}

private:
    Context* ctx_;
    std::shared_ptr<const Native> native_;
};

/// An incremental solver; copies share it.
class Solver {
public:
    /// Horn: Spacer, for constrained Horn clauses.
    enum class Logic { Any,
                       Horn };
    explicit Solver(Context& ctx, Logic logic = Logic::Any);
    void add(const Term& e);
    /// Asserts the SMT-LIB2 file's assertions.
    void addFile(const std::string& path);
    Result check();
    /// Under the assumptions, which hold for this check only.
    Result check(const std::vector<Term>& assumptions);
    void push();
    void pop();
    void setTimeout(unsigned milliseconds);
    /// Z3's own timer for the checks to come: the time `budget` has left, at most `capSeconds`;
    /// none without a deadline. It runs a little past the deadline, so that the context's watcher
    /// stops the check at the deadline as the budget's stop (Z3's timer, ending it a moment
    /// before, read as the solver giving up).
    void limitTime(const Budget& budget, double capSeconds = 1e9);
    /// Of the last check, when it was Sat.
    Model model() const;
    /// Of the last check, when it was Unknown.
    std::string reasonUnknown() const;
    /// The assertions as an SMT-LIB2 benchmark (declarations, then one assert each).
    std::string toSmt2() const;
    struct Native;  // the Z3 solver, in Smt.cpp

private:
    Result noteExhaustion(Result r);
    Context* ctx_;
    std::shared_ptr<Native> native_;
};

/// Z3's memory accounting, for the whole process: its limit (memory_max_size, in MiB), what it
/// has allocated, and a reset after running out (Z3 makes no new context until then).
void setMemoryLimit(std::uint64_t mib);
std::uint64_t allocatedMiB();
void resetMemory();

}  // namespace holon::checker::smt
