#pragma once
// How `holon verify --every-size` proves an invariant for every region (issue 31): conjunct by
// conjunct, each either a condition on every cell (decided on the window as it is), a non-local
// form with a frame lemma (`some(T)`, `connected(T)`, `reaches(T, f, S)`: a local condition on one
// step that keeps it, decided on the window), or a `connected(X)` that follows from the conjuncts
// before it. The lemmas and why they hold are in proofs/README.md ("Non-local conjuncts").

#include "checker/StepObligation.h"

#include <string>
#include <vector>

namespace holon::checker {

struct InvariantPlan {
    std::vector<StepObligation> steps;  // one window obligation per decided conjunct, in order
    std::vector<std::string> implied;   // per implied conjunct: which conjuncts give it, and by which lemma
    /// The conjuncts neither a window nor the ones before decide, and why; empty when there are none.
    std::string undecided;
    /// What a proof of the invariant takes on trust beyond the window obligations (the frame lemmas
    /// and Lemma C, proved on paper); empty when it uses none.
    std::string trusted;
};

/// Cell i of s steps along direction dir: its pointer field holds dir; every direction when
/// field < 0 (`nbr`).
smt::Term stepsAlong(SmtEncoding& enc, const SmtEncoding::State& s, int i, int field, int dir);

/// `probe` is any window's engine (it covers every input combination).
InvariantPlan planInvariant(const rules::Model& model, const rules::Property& p, const rules::Engine& probe);

}  // namespace holon::checker
