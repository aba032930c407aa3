#pragma once
// `holon verify --every-size`: the obligations that one step of one rule instance decides, proved
// on a window (Window.h) and so for every region of the lattice (issue 31; the cutoff argument is
// in proofs/README.md). A window counterexample is completed to a concrete region around it by the
// bounded encoding and confirmed there by the reference interpreter before it counts.

#include "checker/Obligations.h"

#include <functional>
#include <string>
#include <vector>

namespace holon::checker {

/// Every size takes what every proof run takes, and nothing of a bounded region's.
using EverySizeOptions = ProofOptions;

struct EverySizeReport {
    VerifyReport report;  // each obligation's scope says what its verdict covers
    /// Per obligation (same order): its counterexample drawn on the concrete region that confirms
    /// it, or on the window when none does; empty without one.
    std::vector<std::string> drawings;
    /// The properties that are not decided by one step on a window (progress, holonomy, an
    /// invariant with a non-local conjunct): verdict unknown, and a bounded proof can stand in.
    std::vector<std::string> notLocal;
};

/// Conservation, rankings and invariants made of local conjuncts, for every region of the model's
/// lattice. `model` must be on that lattice.
EverySizeReport verifyEverySize(const rules::Model& model, const EverySizeOptions& options,
                                const std::function<void(const std::string&)>& onObligation = {});

}  // namespace holon::checker
