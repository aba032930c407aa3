#pragma once
// The run-time monitor of `holon plan --check`: after every step (async) or round (sync) it
// re-checks, from scratch, that the occupied cells are connected, that the mass is what it was
// (for systems that declare `conserves mass`) and that no cell holds a state outside the
// alphabet; the first violation stops the run and is written as an ITF trace.

#include "planner/Execution.h"
#include "rules/OutputFile.h"

#include <string>

namespace holon::planner {

class Monitor {
public:
    Monitor(const Problem& problem, const Execution& execution);
    void fired(std::int64_t anchor, int shape, const BoxEngine::Value* old);
    /// Checks the configuration; false once a property is violated.
    bool roundEnd(const RunStats& stats);
    bool violated() const { return !violation_.empty(); }
    std::string summary() const;
    /// The last step or round before the violation and the configuration it led to, as ITF;
    /// throws InputError (with the reason) when the file cannot be written.
    void writeTrace(const rules::OutputFile& file) const;

private:
    bool connected() const;
    const Problem* problem_;
    const Execution* execution_;
    std::int64_t initialMass_ = 0, checks_ = 0;
    bool conservesMass_ = false;
    std::vector<BoxEngine::Value> before_;  // the configuration before the current step or round
    std::vector<std::pair<std::int64_t, int>> lastFired_;
    std::string violation_;
};

}  // namespace holon::planner
