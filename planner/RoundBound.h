#pragma once
// A lower bound on the synchronous rounds of any plan of a mass-conserving planner system: the
// mass that must cross a cut, over what the cut lets through per round (see RoundBound.cpp).

#include "planner/Problem.h"

#include <optional>

namespace holon::planner {

struct RoundBound {
    std::int64_t rounds = 0;  // no synchronous plan reaches the target in fewer rounds
    /// The cut that gives it: `cells` cells that must gain (a creation side) or lose (a deletion
    /// side) `mass` units in all, through `gate` cells that pass at most `perCell` units a round each.
    std::int64_t cells = 0, mass = 0, gate = 0, perCell = 0;
    bool creation = true;
};

/// The bound for the problem's start and target under synchronous rounds; nullopt when the system
/// does not declare `conserves mass`, or no cell must gain or lose mass.
std::optional<RoundBound> roundLowerBound(const Problem& problem);

}  // namespace holon::planner
