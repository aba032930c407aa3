#pragma once
// A sculpting run step by step, for `holon hex --steps-out` and the browser viewer (holon view):
// JSON Lines in holon plan --plan-out's format. The first line,
// {"run": "hex", "system": "hex_holes", "source": FILE, "start": {"lattice": "hex2d", "points":
// [[q, r], ...], "cells": [{"at": [q, r], "state": "M"}, ...], "inputs": {"target": [...]}}},
// then one line per rule instance applied, {"round": TIMESTEP, "system": NAME, "rule": NAME,
// "cells": [[q, r], ...], "after": [{...}, ...]}: its pattern cells in order and their states
// after it ({} for an empty cell), every hex system's states being hex_holes's M, H and C.

#include "planner/Recorder.h"
#include "planner/hex/HoleSculptor.h"

#include <optional>
#include <ostream>

namespace holon::planner::hex {

class SculptSteps {
public:
    /// Writes the first line; from then on, while it lives, hears every instance applied on this thread.
    SculptSteps(std::ostream& out, const HoleSculptor& sculptor);
    /// After each timestep: writes the timestep's last instance.
    void timestepEnded();

private:
    void flush();
    std::ostream* out_;
    std::optional<Applied> pending_;  // its after-states are known when the next instance starts
    int timestep_ = 1;
    Recorder recorder_;
};

}  // namespace holon::planner::hex
