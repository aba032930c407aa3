#pragma once
// Progress for every region (issue 31) through a local progress certificate: outside the goal,
// every non-final cell has an enabled instance near it, or a non-final neighbour further along a
// well-founded measure that the proved invariants give (down a pointer tree, or nearer the cells a
// `reaches` conjunct leads to). Following such neighbours must end at an enabled instance, so no
// configuration outside the goal is stuck. The lemmas it rests on are in proofs/README.md
// ("Progress for every region").

#include "checker/StepObligation.h"

#include <string>
#include <vector>

namespace holon::checker {

struct ProgressPlan {
    std::vector<StepObligation> steps;  // the certificate's window query; empty when undecided
    std::string undecided;              // why the certificate does not apply
    std::string measures;               // the measures, in the order a chain may step down them
};

/// `invariants` are the system's invariants proved for every region (the certificate assumes
/// them); `probe` is any window's engine.
ProgressPlan planProgress(const rules::Model& model, const rules::Property& progress, const std::vector<const rules::Property*>& invariants,
                          const rules::Engine& probe);

}  // namespace holon::checker
