#pragma once
// The run-time monitor of `holon plan --check`: after every step (async) or round (sync) it checks
// that the occupied cells are connected, that the mass is what it was (for systems that declare
// `conserves mass`) and that no cell holds a state outside the alphabet; the first violation stops
// the run and is written as an ITF trace. Each step or round is checked from what it changed
// (Monitor.cpp says why that is complete); the whole configuration is re-checked from scratch at
// rounds 1, 4, 16, 64, ... and at the end, so a write the engine did not report cannot hide.

#include "planner/Execution.h"
#include "rules/Components.h"
#include "rules/OutputFile.h"

#include <string>

namespace holon::planner {

class Monitor {
public:
    Monitor(const Problem& problem, const Execution& execution);
    void fired(std::int64_t anchor, int shape, const BoxEngine::Value* old);
    /// A metamodule lost to an injected fault (planner/Faults.h) between rounds: its mass leaves
    /// the books. The fault model, not the monitor, judges whether the loss disconnected the
    /// ensemble, and a run goes on only when it did not, so a disconnection the monitor sees is
    /// always the planner's.
    void lost(std::int64_t cell, BoxEngine::Value old);
    /// Checks the step or round that just ended; false once a property is violated.
    bool roundEnd(const RunStats& stats);
    /// The from-scratch check of the final configuration; false when a property is violated.
    bool finish(const RunStats& stats);
    bool violated() const { return !violation_.empty(); }
    std::string summary() const;
    /// The last step or round before the violation and the configuration it led to, as ITF;
    /// throws InputError (with the reason) when the file cannot be written.
    void writeTrace(const rules::OutputFile& file) const;

private:
    bool connected() const;
    bool changesKeepConnected();
    bool oneComponent(const std::vector<std::int64_t>& sources);
    bool linkedNearby(std::int64_t cell) const;
    std::uint32_t freshEpoch();
    void checkFromScratch();
    bool report(const RunStats& stats, const char* how);
    const Problem* problem_;
    const Execution* execution_;
    std::int64_t initialMass_ = 0, mass_ = 0, checks_ = 0, fullChecks_ = 0, nextFullCheck_ = 1;
    bool conservesMass_ = false;
    std::vector<BoxEngine::Value> before_;  // the previous values of the cells the current step or round wrote
    std::vector<std::pair<std::int64_t, int>> lastFired_;
    std::string violation_;
    // Scratch for the incremental check, board-sized, reused: a cell's stamp says it was seen by
    // the current check; its label, which search reached it.
    std::vector<std::uint32_t> stamp_;
    rules::Flood flood_;  // the clusters of changed cells
    std::vector<std::int32_t> label_;
    std::uint32_t epoch_ = 0;
    std::int64_t occupied_ = 0;
    std::vector<std::int32_t> parent_;
    std::vector<std::int64_t> visited_;
    std::vector<std::vector<std::int64_t>> frontier_;  // each search's queue; head_: its next cell
    std::vector<std::size_t> head_;
    // Offsets of the cells within two steps of a cell, which of them are its neighbours, and the
    // neighbour links among them: where an emptied cell's neighbours usually meet again.
    std::vector<std::int64_t> window_;
    std::vector<bool> windowNeighbour_;
    std::vector<std::uint64_t> windowLinks_;  // per window cell, its neighbours in the window as a word
};

}  // namespace holon::planner
