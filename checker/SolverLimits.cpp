// Z3's memory limit and the meaning of its failures (see SolverLimits.h). Z3 counts its own
// allocations against memory_max_size and throws "out of memory" past it, from wherever it was
// (building a term, solving, printing), and then refuses every new context until its memory is reset.

#include "checker/SolverLimits.h"

#include "rules/Error.h"
#include "rules/Parameter.h"

#include <csignal>
#include <cstdint>
#include <sys/resource.h>

namespace holon::checker {

namespace {

std::uint64_t limitMiB = 0;

/// Sets Z3's limit; 0 (none) as the largest it takes: with an explicit 0, Z3 4.8.12 threw
/// std::bad_alloc from solvers of later contexts (the unit tests run verify many times).
void setLimit(std::uint64_t mib) { smt::setMemoryLimit(mib == 0 || mib > UINT32_MAX ? UINT32_MAX : mib); }

}  // namespace

void limitSolverMemory(std::uint64_t mib) {
    if (mib == limitMiB) return;
    limitMiB = mib;
    setLimit(mib);
}

void shareSolverMemory(int ways) {
    if (limitMiB == 0 || ways <= 1) return;
    const std::uint64_t used = smt::allocatedMiB(), limit = limitMiB;
    setLimit(used >= limit ? limit : used + (limit - used) / static_cast<std::uint64_t>(ways));
}

bool outOfMemory(const std::string& message) {
    return message.find("out of memory") != std::string::npos || message.find("memout") != std::string::npos ||
           message.find("max. memory") != std::string::npos;
}

std::string unknownReason(const std::string& reason) {
    // Z3 catches SIGINT itself while it solves and answers unknown; the user asked holon to stop.
    if (reason.find("interrupted from keyboard") != std::string::npos) throw Interrupted(SIGINT);
    if (!outOfMemory(reason) || limitMiB == 0) return reason;
    // A process limit (ulimit -v) below Z3's is reached first: naming Z3's limit then sent the user
    // to the wrong knob.
    rlimit space{};
    if (getrlimit(RLIMIT_AS, &space) == 0 && space.rlim_cur != RLIM_INFINITY && (space.rlim_cur >> 20) < limitMiB)
        return "out of memory (the process's address-space limit, ulimit -v, is " + std::to_string(space.rlim_cur >> 20) +
               " MiB, below Z3's limit of " + std::to_string(limitMiB) + " MiB; raise it, or give " + rules::parameterName(rules::Parameter::Memory) + " below it)";
    return "out of memory (Z3's memory limit is " + std::to_string(limitMiB) + " MiB)";
}

bool limitReached(const std::string& reason) {
    return outOfMemory(reason) || reason.find("timeout") != std::string::npos || reason.find("canceled") != std::string::npos || reason.find("resource") != std::string::npos;
}

std::string solverFailure(const smt::Failure& e) {
    if (!outOfMemory(e.what())) throw InternalError(std::string("Z3 failed: ") + e.what());
    return "Z3 ran " + unknownReason(e.what());
}

void recoverSolverMemory() {
    smt::resetMemory();
    setLimit(limitMiB);
}

}  // namespace holon::checker
