// The Z3 adapter (Smt.h): the only file that includes Z3's API. Terms are built by z3++'s own
// operators, so the formulas are exactly what z3++ makes. A Term holds the Z3_ast itself, with
// z3++'s reference counting, including its one quirk: 4.8.12's move assignment of z3::expr never
// releases the term it overwrites (ast::operator=(ast&&)), so each `q = q && x` keeps the old q
// referenced until the context goes. The exported obligations depend on it: Z3's SMT-LIB2 printer
// let-binds every subterm with more than one reference, and with the old q released all 34 files
// of proofs/smt came out different (fewer let-bindings). So do the solver's timings: with Z3's
// term ids reused, safety of planner_general1 on square:4x4 took 105 s instead of 16 (once, on a
// loaded machine). But where z3++ leaves those references to Z3, which frees them with the context
// one chain link per sweep of its whole term table (6 minutes after a 1.5 s progress proof on
// hex:r1), ours keeps them in the Context and releases them newest first, a chain in one pass.
// z3++ throws through Z3_THROW, defined here so that every Z3 error leaves this file as
// smt::Failure.

#include "checker/Smt.h"

#include "checker/SolverLimits.h"

#define Z3_THROW(x) throw ::holon::checker::smt::Failure((x).msg())
#include <z3++.h>

#include <algorithm>
#include <chrono>
#include <condition_variable>
#include <exception>
#include <limits>
#include <mutex>
#include <system_error>
#include <thread>
#include <unordered_set>

namespace holon::checker::smt {

struct Context::Native : z3::context {};
struct Relation::Native {
    z3::func_decl decl;
};
struct Model::Native {
    z3::model model;
};
struct Solver::Native {
    z3::solver solver;
};

namespace {

Z3_ast ast(const Term& t) { return reinterpret_cast<Z3_ast>(t.node()); }
z3::expr z(const Term& t) { return z3::expr(t.context().native(), ast(t)); }
Term wrap(Context& ctx, const z3::expr& e) { return Term(ctx, reinterpret_cast<Term::Node*>(static_cast<Z3_ast>(e))); }
Term wrap(const Term& like, const z3::expr& e) { return wrap(like.context(), e); }
z3::expr_vector vector(Context& ctx, const std::vector<Term>& terms) {
    z3::expr_vector v(ctx.native());
    for (const Term& t : terms) v.push_back(z(t));
    return v;
}

}  // namespace

/// One thread per context, for the context's whole life: it interrupts Z3 once the budget's
/// deadline passes or a signal is caught, whatever Z3 is doing. A watcher around each check only
/// missed the rest: asserting square:45x45's formulas (Z3 preprocesses them as they come) ran 18 s
/// past a 3 s deadline. Z3's own SIGINT catcher is off (ctrl_c, set with each solver's parameters):
/// it took the signal for itself, and the job went on as if nothing had been asked.
struct Context::Watcher {
    std::mutex mutex;
    std::condition_variable ended;
    bool done = false;
    std::thread thread;

    explicit Watcher(const Context& ctx)
        : thread([this, &ctx] {
              // Wakes every 20 ms, and at once when the context goes.
              std::unique_lock lock(mutex);
              while (!ended.wait_for(lock, std::chrono::milliseconds(20), [&] { return done; }))
                  if (ctx.budget_.expired() || ctx.budget_.interrupted()) {
                      Z3_interrupt(ctx.native());
                      return;
                  }
          }) {}
    ~Watcher() {
        {
            const std::lock_guard lock(mutex);
            done = true;
        }
        ended.notify_one();
        thread.join();
    }
};

Context::Context(const Budget& budget) : budget_(budget) {
    // None after the deadline or a signal: a context made then is kept, not freed (below), and
    // verify with 3,000 properties kept one for each obligation left, gigabytes, past --timeout.
    budget_.check("starting the solver");
    // z3++ 4.8.12 would use the null context Z3 returns past its memory limit, and crash.
    const Z3_config config = Z3_mk_config();
    const Z3_context probe = config ? Z3_mk_context_rc(config) : nullptr;
    if (config) Z3_del_config(config);
    if (!probe) throw Failure("out of memory");
    Z3_del_context(probe);
    native_ = new Native;
    try {
        if (budget_.limited() || budget_.stoppable()) watcher_ = std::make_unique<Watcher>(*this);
    } catch (const std::system_error&) {  // no thread to be had (ulimit -u): as out of memory
        delete native_;
        throw Failure("out of memory");
    }
}

Context::~Context() {
    watcher_.reset();
    // Interrupted too: freeing took minutes after a SIGINT on square:30x30. And on the way out of
    // a failure (Z3 out of memory) when the job has a deadline: freeing square:60x60's formulas
    // after the process hit its ulimit ran 10 minutes past a 30 s deadline. Without a deadline it
    // is freed: kept, its memory made every later obligation run out at once.
    // Nor after a check that answered unknown for want of memory: Z3 took 50 s to several minutes
    // to free such a context (square:20x20 with a memory bound), deaf to the deadline and signals.
    const bool failing = std::uncaught_exceptions() > 0 && budget_.limited();
    if (!budget_.expired() && !budget_.interrupted() && !failing && !exhausted_) {
        for (auto t = retained_.rbegin(); t != retained_.rend(); ++t) Z3_dec_ref(*native_, static_cast<Z3_ast>(const_cast<void*>(*t)));
        delete native_;
        return;
    }
    // Kept reachable, not dropped: it is memory the process holds on purpose, not a leak. The list
    // itself is never destroyed, so it still holds them when the leak check runs at exit.
    static auto* const kept = new std::vector<Native*>;
    kept->push_back(native_);
}

void Context::checkStopped(const char* during) const {
    // The budget, not whether the watcher has fired yet: Z3's own timer, set to the time left,
    // often cancels first (the watcher looks every 20 ms).
    budget_.check(during);
}

namespace {
/// Runs a Z3 call; a failure after the deadline or a signal (Z3_interrupt cancels the context for
/// good, and every later call that reads its limits fails) is the budget's stop, not Z3's error.
template <class F>
auto guarded(const Context& ctx, const char* during, F&& call) {
    try {
        return call();
    } catch (const Failure&) {
        ctx.checkStopped(during);
        throw;
    }
}
}  // namespace

Term Context::boolVal(bool b) { return wrap(*this, native_->bool_val(b)); }
Term Context::intVal(std::int64_t n) { return wrap(*this, native_->int_val(n)); }
Term Context::realVal(std::int64_t n) { return wrap(*this, native_->real_val(n)); }
Term Context::realVal(std::int64_t num, std::int64_t den) {
    constexpr std::int64_t lo = std::numeric_limits<int>::min(), hi = std::numeric_limits<int>::max();
    if (num >= lo && num <= hi && den >= lo && den <= hi) return wrap(*this, native_->real_val(static_cast<int>(num), static_cast<int>(den)));
    // A mass denominator may pass 2^31 (up to 2^32): narrowing it to int wrapped the value.
    return wrap(*this, native_->real_val((std::to_string(num) + "/" + std::to_string(den)).c_str()));
}
Term Context::constant(const std::string& name, Sort sort) {
    switch (sort) {
    case Sort::Bool: return wrap(*this, native_->bool_const(name.c_str()));
    case Sort::Int: return wrap(*this, native_->int_const(name.c_str()));
    }
    throw Failure("a constant of no sort");
}
Term Context::boolConst(const std::string& name) { return constant(name, Sort::Bool); }
Term Context::intConst(const std::string& name) { return constant(name, Sort::Int); }

Relation Context::relation(const std::string& name, unsigned arity) {
    z3::sort_vector sorts(*native_);
    for (unsigned k = 0; k < arity; ++k) sorts.push_back(native_->bool_sort());
    return Relation(*this, std::make_shared<const Relation::Native>(Relation::Native{native_->function(name.c_str(), sorts, native_->bool_sort())}));
}

Term::Term(Context& ctx, Node* node) : ctx_(&ctx), node_(node) { Z3_inc_ref(ctx.native(), ast(*this)); }
Term::Term(const Term& o) : ctx_(o.ctx_), node_(o.node_) {
    if (node_) Z3_inc_ref(ctx_->native(), ast(*this));
}
Term& Term::operator=(const Term& o) {
    if (o.node_) Z3_inc_ref(o.ctx_->native(), ast(o));
    if (node_) Z3_dec_ref(ctx_->native(), ast(*this));
    ctx_ = o.ctx_, node_ = o.node_;
    return *this;
}
Term& Term::operator=(Term&& o) {
    // The overwritten term keeps its reference, as with z3++ (see the top of this file).
    if (this == &o) return *this;
    if (node_) ctx_->retained_.push_back(node_);
    ctx_ = o.ctx_, node_ = o.node_;
    o.node_ = nullptr;
    return *this;
}
Term::~Term() {
    if (node_) Z3_dec_ref(ctx_->native(), ast(*this));
}

unsigned Term::id() const { return z(*this).id(); }
Term Term::simplify() const {
    return guarded(*ctx_, "simplifying a formula", [&] { return wrap(*this, z(*this).simplify()); });
}
Term Term::substituteVars(const std::vector<Term>& values) const {
    z3::expr_vector v = vector(*ctx_, values);
    return guarded(*ctx_, "building the formulas", [&] { return wrap(*this, z(*this).substitute(v)); });
}
Term::Op Term::op() const {
    const z3::expr e = z(*this);
    if (e.is_var()) return Op::Var;
    if (!e.is_app()) return Op::Other;
    switch (e.decl().decl_kind()) {
    case Z3_OP_TRUE: return Op::True;
    case Z3_OP_FALSE: return Op::False;
    case Z3_OP_NOT: return Op::Not;
    case Z3_OP_AND: return Op::And;
    case Z3_OP_OR: return Op::Or;
    case Z3_OP_IMPLIES: return Op::Implies;
    case Z3_OP_EQ:
    case Z3_OP_IFF: return Op::Eq;
    case Z3_OP_XOR: return Op::Xor;
    default: return Op::Other;  // Z3's operators are hundreds
    }
}
unsigned Term::arity() const { return z(*this).num_args(); }
Term Term::arg(unsigned k) const { return wrap(*this, z(*this).arg(k)); }
unsigned Term::varIndex() const { return Z3_get_index_value(ctx_->native(), ast(*this)); }
std::string Term::str() const { return z(*this).to_string(); }

Term operator!(const Term& a) { return wrap(a, !z(a)); }
Term operator&&(const Term& a, const Term& b) { return wrap(a, z(a) && z(b)); }
Term operator||(const Term& a, const Term& b) { return wrap(a, z(a) || z(b)); }
Term operator==(const Term& a, const Term& b) { return wrap(a, z(a) == z(b)); }
Term operator!=(const Term& a, const Term& b) { return wrap(a, z(a) != z(b)); }
Term operator<(const Term& a, const Term& b) { return wrap(a, z(a) < z(b)); }
Term operator<=(const Term& a, const Term& b) { return wrap(a, z(a) <= z(b)); }
Term operator>(const Term& a, const Term& b) { return wrap(a, z(a) > z(b)); }
Term operator>=(const Term& a, const Term& b) { return wrap(a, z(a) >= z(b)); }
Term operator==(const Term& a, int b) { return wrap(a, z(a) == b); }
Term operator<(const Term& a, int b) { return wrap(a, z(a) < b); }
Term operator<=(const Term& a, int b) { return wrap(a, z(a) <= b); }
Term operator>(const Term& a, int b) { return wrap(a, z(a) > b); }
Term operator>=(const Term& a, int b) { return wrap(a, z(a) >= b); }
Term operator+(const Term& a, const Term& b) { return wrap(a, z(a) + z(b)); }
Term operator-(const Term& a, const Term& b) { return wrap(a, z(a) - z(b)); }
Term operator-(const Term& a) { return wrap(a, -z(a)); }
Term operator/(const Term& a, const Term& b) { return wrap(a, z(a) / z(b)); }
Term implies(const Term& a, const Term& b) { return wrap(a, z3::implies(z(a), z(b))); }
Term ite(const Term& c, const Term& t, const Term& e) { return wrap(c, z3::ite(z(c), z(t), z(e))); }
Term toReal(const Term& a) { return wrap(a, z3::to_real(z(a))); }
Term anyOf(Context& ctx, const std::vector<Term>& terms) { return wrap(ctx, z3::mk_or(vector(ctx, terms))); }
bool same(const Term& a, const Term& b) { return z3::eq(z(a), z(b)); }

Term universalClosure(const Term& sentence) {
    // Its uninterpreted constants in depth-first preorder, each once. Iterative: formulas built
    // as chains (`q = q && x`) are thousands deep, past the stack of a sanitizer build.
    const z3::expr root = z(sentence);
    z3::expr_vector vars(root.ctx());
    std::unordered_set<unsigned> seen;
    std::vector<z3::expr> stack{root};
    while (!stack.empty()) {
        const z3::expr e = stack.back();
        stack.pop_back();
        if (!seen.insert(e.id()).second) continue;
        if (e.is_quantifier()) {
            stack.push_back(e.body());
            continue;
        }
        if (!e.is_app()) continue;
        if (e.num_args() == 0 && e.decl().decl_kind() == Z3_OP_UNINTERPRETED) {
            vars.push_back(e);
            continue;
        }
        for (unsigned k = e.num_args(); k-- > 0;) stack.push_back(e.arg(k));  // the first argument on top
    }
    return vars.empty() ? sentence : wrap(sentence, z3::forall(vars, root));
}

Term Relation::operator()(const std::vector<Term>& args) const { return wrap(*ctx_, native_->decl(vector(*ctx_, args))); }

namespace {
z3::expr evaluated(const Context& ctx, const z3::model& model, const Term& e) {
    return guarded(ctx, "reading the solver's model", [&] { return model.eval(z(e), true); });
}
}  // namespace

bool Model::isTrue(const Term& e) const { return evaluated(*ctx_, native_->model, e).is_true(); }
int Model::intValue(const Term& e) const { return evaluated(*ctx_, native_->model, e).get_numeral_int(); }
std::optional<Term> Model::definition(const Relation& r) const {
    return guarded(*ctx_, "reading the solver's model", [&]() -> std::optional<Term> {
        if (!native_->model.has_interp(r.native().decl)) return std::nullopt;
        return wrap(*ctx_, native_->model.get_func_interp(r.native().decl).else_value());
    });
}

Solver::Solver(Context& ctx, Logic logic)
    : ctx_(&ctx),
      native_(std::make_shared<Native>(Native{logic == Logic::Horn ? z3::solver(ctx.native(), "HORN") : z3::solver(ctx.native())})) {
    z3::params params(ctx.native());
    params.set("ctrl_c", false);  // the context's watcher stops the check: Z3's catcher took SIGINT for itself
    native_->solver.set(params);
}
void Solver::add(const Term& e) {
    guarded(*ctx_, "building the formulas", [&] { native_->solver.add(z(e)); });
}
void Solver::addFile(const std::string& path) {
    guarded(*ctx_, "reading the formulas", [&] { native_->solver.from_file(path.c_str()); });
}

namespace {
Result result(z3::check_result r) {
    switch (r) {
    case z3::sat: return Result::Sat;
    case z3::unsat: return Result::Unsat;
    case z3::unknown: return Result::Unknown;
    }
    return Result::Unknown;
}
}  // namespace

Result Solver::check() {
    return noteExhaustion(guarded(*ctx_, "solving", [&] { return result(native_->solver.check()); }));
}
Result Solver::check(const std::vector<Term>& assumptions) {
    z3::expr_vector v = vector(*ctx_, assumptions);
    return noteExhaustion(guarded(*ctx_, "solving", [&] { return result(native_->solver.check(v)); }));
}
Result Solver::noteExhaustion(Result r) {
    if (r == Result::Unknown && outOfMemory(reasonUnknown())) ctx_->markExhausted();
    return r;
}
void Solver::push() {
    guarded(*ctx_, "solving", [&] { native_->solver.push(); });
}
void Solver::pop() {
    guarded(*ctx_, "solving", [&] { native_->solver.pop(); });
}
void Solver::setTimeout(unsigned milliseconds) {
    z3::params params(ctx_->native());
    params.set("timeout", milliseconds);  // added to the solver's parameters: ctrl_c stays off
    native_->solver.set(params);
}
void Solver::limitTime(const Budget& budget, double capSeconds) {
    if (!budget.limited()) return;
    const double seconds = std::min(capSeconds, budget.remaining() + 0.05);
    setTimeout(std::max(1u, static_cast<unsigned>(seconds * 1000)));
}
Model Solver::model() const {
    return guarded(*ctx_, "reading the solver's model", [&] { return Model(*ctx_, std::make_shared<const Model::Native>(Model::Native{native_->solver.get_model()})); });
}
std::string Solver::reasonUnknown() const { return native_->solver.reason_unknown(); }
std::string Solver::toSmt2() const { return native_->solver.to_smt2(); }

void setMemoryLimit(std::uint64_t mib) { z3::set_param("memory_max_size", std::to_string(mib).c_str()); }
std::uint64_t allocatedMiB() { return Z3_get_estimated_alloc_size() >> 20; }
void resetMemory() { Z3_reset_memory(); }

}  // namespace holon::checker::smt
