#pragma once
// rules/library/roombots_reserve.holon run on the floor grid: the reservation strategy asks it
// whether a metamodule may start its walk, and tells it when one sits. Internal to planner/roombots.

#include "planner/roombots/World.h"
#include "rules/Interpreter.h"

#include <memory>

namespace holon::planner::roombots::detail {

class CoordinationRule {
public:
    /// The metamodules of `feet`, the k-th filling seed k - 1 (as `W&to=k` at its foot), on the
    /// floor widened by `reach` columns each side. Throws InputError when there are more seeds
    /// than the rule file has walks.
    CoordinationRule(const Floor& floor, int reach, const std::vector<Cell>& feet);
    ~CoordinationRule();
    /// The metamodule filling seed k asks to start a walk that sweeps `cells`: its start rule
    /// fires when it is enabled (it matches and leads to a legal configuration). False: it waits.
    bool start(int seed, const std::vector<Cell>& cells);
    /// Its walk done, the metamodule of seed k sits (its rule must fire: a logic error otherwise).
    void sit(int seed);
    /// The start configuration (every metamodule waiting) with the walks set so far as inputs,
    /// as a configuration file `holon check` reads.
    std::string configurationJson() const;

private:
    struct System;
    /// Fires rule `name` + (seed + 1) at the seed's metamodule if it is enabled.
    bool fire(const std::string& name, int seed);
    int indexOf(const Cell& c) const;

    std::unique_ptr<System> system_;
    std::vector<Cell> feet_;
    rules::Configuration now_, waiting_;
    int x0_ = 0, y0_ = 0;
};

}  // namespace holon::planner::roombots::detail
