#pragma once
// One sculpting experiment of seed 003 §V: a source and target geometry on an N x N hex array,
// run for a number of timesteps, with the three metrics of §V-A recorded every timestep.

#include "planner/hex/HoleSculptor.h"
#include "rules/Budget.h"

#include <functional>
#include <string>
#include <vector>

namespace holon::planner::hex {

struct SculptSample {
    float completeness, stability, compliance;
    std::int32_t holes;  // alive after the timestep
};

struct SculptResult {
    std::int64_t modules = 0, startHoles = 0, endHoles = 0, holeBudget = 0, islands = 0;
    int steps = 0, triRegions = 0;
    StopReason stopped = StopReason::Finished;  // every timestep made, or the limit that came first
    double maxCompleteness = 0, maxStability = 0, maxCompliance = 0, finalCompliance = 0, seconds = 0;
    SculptCounts counts;
    SculptResidue residue;             // at the end of the run
    std::vector<SculptSample> series;  // one sample per timestep, after it
};

struct SculptSetup {
    std::string from = "square", to = "T";
    int size = 100, steps = 10000;
    double triFraction = 0.075;  // tri-region edge as a fraction of the array side
    SculptOptions options;
};

/// Memory one experiment's sculptor keeps while it runs, for --memory: the array's board cells,
/// each with the sculptor's per-cell state (shapes, holes, tri-regions, search marks: 50 to 65
/// bytes measured at N = 800, counted as 96). Its series takes a SculptSample per timestep more.
std::uint64_t sculptBytes(const SculptSetup& setup);

/// Runs one experiment. `frame(sculptor)` is called after every timestep (may be empty); `budget`
/// is asked before each: once it is spent the run ends there, result.steps telling how many
/// timesteps it ran and result.stopped why. `started(sculptor)` (may be empty) is called before the
/// first timestep.
SculptResult runSculpt(const SculptSetup& setup, const std::function<void(const HoleSculptor&)>& frame = {}, const Budget& budget = Budget(),
                       const std::function<void(const HoleSculptor&)>& started = {});

/// An SVG picture of the ensemble: modules, hole cells, and the target's outline points left empty.
std::string sculptSvg(const HoleSculptor& sculptor);

}  // namespace holon::planner::hex
