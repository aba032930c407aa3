#pragma once
// Assembling a structure from Roombots metamodules that walk on a structured floor (seed 001 §IV-A):
// the paper's decentralised force-field strategies and holon's reservation strategy, simulated in
// continuous time on the grid-level model, with collisions and deadlocks detected the same way for all.

#include "planner/roombots/CollisionClouds.h"
#include "planner/roombots/Structures.h"
#include "rules/Budget.h"

#include <cstdint>
#include <functional>
#include <string>
#include <vector>

namespace holon::planner::roombots {

/// greedy, slope, step: Eq. 2 (a)-(c); reserve: in seeding order, each metamodule plans its whole
/// walk and starts when roombots_reserve.holon lets it (no walk under way shares a floor column).
enum class Strategy : std::uint8_t { Greedy,
                                     Slope,
                                     Step,
                                     Reserve };
const char* strategyName(Strategy s);
Strategy parseStrategy(const std::string& name);  // throws InputError
constexpr std::array<Strategy, 3> kPaperStrategies{Strategy::Greedy, Strategy::Slope, Strategy::Step};

/// One shape transition of one metamodule (a step of the inch-worm walk or the final seating).
struct Action {
    int module = 0;
    double begin = 0, end = 0;      // simulated seconds
    Cell from, to;                  // foot before and after
    double forceX = 0, forceY = 0;  // the force vector it followed (Eq. 1); 0 for reserve
    bool seat = false;
    std::array<Cell, 4> cells{};  // the metamodule's cells after it
};

struct AssemblyResult {
    bool completed = false, deadlocked = false;
    int collisions = 0;
    std::vector<int> moves;  // per metamodule
    double meanMoves = 0;
    double seconds = 0;  // simulated time until the last seat or the deadlock
    std::vector<Action> actions;
    std::vector<Seed> placed;                                 // seeds filled, in order
    std::vector<std::array<Cell, 4>> start;                   // every metamodule's cells at the start
    std::vector<std::array<Cell, 4>> cells;                   // every metamodule's cells at the end
    std::vector<std::vector<std::array<Cell, 4>>> snapshots;  // every metamodule's cells each time a seed was filled
    std::string reason;                                       // why a deadlock was declared
    /// reserve: the coordination rule's start configuration with the walks the run took as its
    /// inputs, a configuration file for `holon check rules/library/roombots_reserve.holon`.
    std::string coordination;
};

struct AssemblyOptions {
    int stallSteps = 12;  // K: deadlock when no metamodule came closer to an active seed for K steps
    /// Asked before every action; once it is spent the run stops and assemble() throws
    /// AssemblyStopped (a deadline or a signal: a run cut short is not a run, so no result is made of it).
    Budget budget;
};

/// Thrown by assemble() when AssemblyOptions::budget is spent.
struct AssemblyStopped {};

/// A seeding order derived from the seeds' cells and the kinematics: each seed, when its turn comes,
/// can be walked to and filled, and leaves every later seed fillable. The given order if none exists.
/// `budget` is asked before each candidate seed; once it is spent, AssemblyStopped is thrown.
Recipe automaticRecipe(const CloudTable& table, Coupling coupling, const Setting& setting, const Budget& budget = Budget());

/// The seeds no metamodule of this configuration can change shape into, even on an empty floor
/// (indices into the recipe).
std::vector<int> unfillableSeeds(const CloudTable& table, Coupling coupling, const Setting& setting);

AssemblyResult assemble(const CloudTable& table, Coupling coupling, Strategy strategy, const Setting& setting,
                        const AssemblyOptions& options = {});

}  // namespace holon::planner::roombots
