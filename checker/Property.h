#pragma once
// One type per property kind of the rule IR (rules::Property::Kind), holding the three things holon
// does with a property: (a) its explicit-state check over an explored graph (`holon check`), (b) its
// proof obligation for Z3 (`holon verify`), and (c) the confirmation of its counterexamples by the
// reference interpreter. propertyType() builds one by a switch over the kind, so a new kind does not
// compile until each of the three is written. The built-in properties of a system with a goal
// (deadlock freedom, goal reachability) are types of the same interface.

#include "checker/Explorer.h"
#include "checker/Graph.h"
#include "checker/Obligations.h"
#include "checker/SmtEncoding.h"
#include "checker/Verdict.h"
#include "rules/Budget.h"
#include "rules/Engine.h"
#include "rules/Interpreter.h"

#include <functional>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace holon::checker {

class ProofRunner;

/// What a phase after the exploration needs beside the explored graph, per state and per edge,
/// from its containers (a BGL compressed-sparse-row copy of the graph is 8 bytes a state and 4
/// an edge; its algorithms' maps a few words a state).
struct PhaseCost {
    double perState = 0, perEdge = 0;
};
/// The weak components of the whole graph (Graph.h), which check() counts and holonomy reads.
inline constexpr PhaseCost kComponentsCost{16, 0};

/// The terminal states outside the goal (and where an assumption holds), split into deadlocks and
/// edge effects of the bounded region (checker/properties/Progress.cpp).
struct Stuck {
    std::vector<StateId> deadlocks, edgeEffects;
    std::uint64_t unclassified = 0;
    std::string unclassifiedWhy;  // why some stuck states were not classified: the budget, or the grown region's size
};

/// What an explicit-state check reads: the explored graph and whether it is whole.
struct ExploredGraph {
    const rules::Model& model;
    const rules::Region& region;
    const rules::Engine& engine;
    const Explorer& explorer;
    const Components& components;  // weak components of the whole graph; empty when not computed
    const Budget& budget;
    bool complete;  // the search finished: every reachable state is in the graph
    /// Stuck states by progress assumption (none: deadlock freedom), classified once for every
    /// property that judges them.
    std::map<const rules::Expr*, Stuck>& stuck;
};

/// What an obligation is proved with: the runner (solver, SMT-LIB2 export), the obligation's
/// budget, and the system's invariants (progress is asked where they hold).
struct ProofContext {
    ProofRunner& run;
    const Budget& budget;
    const std::vector<const rules::Property*>& invariants;
};

/// States a run must never reach, for `verify --depth` and `--reach`: symbolically and as a test
/// on a concrete state (which cuts a decoded path at its first bad state).
struct BadTarget {
    std::function<smt::Term(SmtEncoding&, const SmtEncoding::State&)> bad;
    std::function<bool(const std::vector<CellValue>&, const rules::Engine&)> isBad;
    std::string failure;   // "invariant 'safety' fails", "a deadlock outside the goal"
    bool atDepth = false;  // --depth checks it too (the invariants); --reach checks every target
};

/// What a counterexample claims: a path of rule steps (check's traces, verify's --depth and
/// --reach), or what the property's own obligation asked for (a stuck state, an unjoined pair).
enum class Evidence { Path,
                      Obligation };

class PropertyType {
public:
    PropertyType(std::string name, std::string kind) : name_(std::move(name)), kind_(std::move(kind)) {}
    virtual ~PropertyType() = default;
    const std::string& name() const { return name_; }
    const std::string& kind() const { return kind_; }
    /// An empty result with this property's name and kind.
    PropertyResult named() const {
        PropertyResult r;
        r.name = name_;
        r.kind = kind_;
        return r;
    }

    // (a) The explicit-state check.
    /// Called on every state as the explorer stores it (from several threads), for the kinds that
    /// judge single states; the others leave watchesStates() false.
    virtual bool watchesStates() const { return false; }
    virtual void onState(const rules::Engine&, StateId, const CellValue*) {}
    /// Decided during the search (an invariant once violated: the states of the next level are
    /// checked as they are stored, so the shortest violations are known).
    virtual bool decided() const { return false; }
    /// What the check holds beside the explored graph; none: it works on the stored states.
    virtual std::optional<PhaseCost> cost(bool /*complete*/) const { return std::nullopt; }
    virtual PropertyResult check(const ExploredGraph& g) const = 0;

    // (b) The proof obligation.
    virtual Obligation prove(const ProofContext& c) const = 0;
    /// The bad states of --depth and --reach; none for the kinds not about single states.
    virtual std::optional<BadTarget> target(const rules::Engine&) const { return std::nullopt; }

    // (c) The confirmation.
    /// Whether the reference interpreter confirms `r`'s evidence, under the inputs of `engine`: by
    /// default its trace replays step by step.
    virtual bool confirm(const PropertyResult& r, Evidence evidence, const rules::Interpreter& in, const rules::Engine& engine, std::string* why) const;
    /// What a confirmed counterexample of verify adds to its summary (an invariant: the conjunct
    /// that is false).
    virtual void explain(PropertyResult&, const rules::Interpreter&, const rules::Engine&) const {}

protected:
    /// An obligation's counterexample of one step (conservation, rankings, inductive invariants):
    /// its trace replays, and the step breaks the property, as `broken(before, after, instance)`
    /// judges on the interpreter's configurations; `keeps` says what the step did instead.
    bool confirmBrokenStep(const PropertyResult& r, const rules::Interpreter& in, const rules::Engine& engine, std::string* why, const char* keeps,
                           const std::function<bool(const CellValue* before, const CellValue* after, int instance)>& broken) const;

private:
    std::string name_, kind_;
};

/// The type of a declared property.
std::unique_ptr<PropertyType> propertyType(const rules::Property& p);
/// Every property `holon check` knows for a system, in report order: the declared ones, then, with
/// a goal, "deadlock" and "goal_reachable" (relative to a goal: without one, a state with no
/// enabled rule is merely final).
std::vector<std::unique_ptr<PropertyType>> checkablePropertyTypes(const rules::System& system);

/// Confirms r's evidence with `type` and records it: r.confirmation, witness[`flag`] and, with a
/// trace, witness["trace"] (its configurations, for --json). `engine` has the inputs r holds under.
void confirmInto(PropertyResult& r, const PropertyType& type, Evidence evidence, const rules::Interpreter& in, const rules::Engine& engine, const char* flag);

}  // namespace holon::checker
