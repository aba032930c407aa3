#pragma once
// Pictures of an assembly run: the top view of the foot traces with the force vectors followed (as
// seed 001 Fig. 6) and isometric snapshots of the assembly (as Fig. 7).

#include "planner/roombots/Assembly.h"

#include <string>

namespace holon::planner::roombots {

std::string footTraceSvg(const Setting& setting, const AssemblyResult& result);
/// Isometric view of metamodules' cells (one entry per metamodule).
std::string isometricSvg(const Setting& setting, const std::vector<std::array<Cell, 4>>& cells);
/// The assembly as a strip of isometric views, one each time a seed was filled (and the end of a
/// deadlocked run), as the snapshot series of Fig. 7.
std::string assemblySvg(const Setting& setting, const AssemblyResult& result);
/// The run action by action for the browser viewer (holon view), JSON Lines in holon plan
/// --plan-out's format: a first line {"run": "roombots", "title", "colours": [per metamodule],
/// "start": {"region": "cubic:WxHxD", "offset": [x, y, z], "cells": [{"at": [x, y, z], "module": M},
/// ...], "inputs": {"structure": [every seed's cells]}}} (positions in the region: a run's cell plus
/// the offset), then one line per action, {"round": K, "time": SECONDS, "rule": "step" or "seat",
/// "cells": the cells the metamodule leaves and takes, "after": [{} or {"module": M}, ...]}.
std::string runSteps(const Setting& setting, const AssemblyResult& result, const std::string& title);

}  // namespace holon::planner::roombots
