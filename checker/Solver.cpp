// Z3's memory limit and the meaning of its failures (see Solver.h). Z3 counts its own allocations
// against memory_max_size and throws "out of memory" past it, from wherever it was (building a
// term, solving, printing), and then refuses every new context until its memory is reset.

#include "checker/Solver.h"

#include "rules/Error.h"

#include <csignal>
#include <cstdint>
#include <vector>

namespace holon::checker {

namespace {

std::uint64_t limitMiB = 0;

/// Sets Z3's limit; 0 (none) as the largest it takes: with an explicit 0, Z3 4.8.12 threw
/// std::bad_alloc from solvers of later contexts (the unit tests run verify many times).
void setLimit(std::uint64_t mib) {
    z3::set_param("memory_max_size", std::to_string(mib == 0 || mib > UINT32_MAX ? UINT32_MAX : mib).c_str());
}

}  // namespace

void limitSolverMemory(std::uint64_t mib) {
    if (mib == limitMiB) return;
    limitMiB = mib;
    setLimit(mib);
}

void shareSolverMemory(int ways) {
    if (limitMiB == 0 || ways <= 1) return;
    const std::uint64_t used = Z3_get_estimated_alloc_size() >> 20, limit = limitMiB;
    setLimit(used >= limit ? limit : used + (limit - used) / static_cast<std::uint64_t>(ways));
}

void ContextRelease::operator()(z3::context* c) const {
    if (!budget_.expired()) {
        delete c;
        return;
    }
    // Kept reachable, not dropped: it is memory the process holds on purpose, not a leak. The list
    // itself is never destroyed, so it still holds them when the leak check runs at exit.
    static auto* const kept = new std::vector<z3::context*>;
    kept->push_back(c);
}

Context newContext(const Budget& budget) {
    const Z3_config config = Z3_mk_config();
    const Z3_context probe = config ? Z3_mk_context_rc(config) : nullptr;
    if (config) Z3_del_config(config);
    if (!probe) throw z3::exception("out of memory");
    Z3_del_context(probe);
    return Context(new z3::context, ContextRelease(budget));
}

bool outOfMemory(const std::string& message) {
    return message.find("out of memory") != std::string::npos || message.find("memout") != std::string::npos ||
           message.find("max. memory") != std::string::npos;
}

std::string unknownReason(const std::string& reason) {
    // Z3 catches SIGINT itself while it solves and answers unknown; the user asked holon to stop.
    if (reason.find("interrupted from keyboard") != std::string::npos) throw Interrupted(SIGINT);
    if (!outOfMemory(reason) || limitMiB == 0) return reason;
    return "out of memory (Z3's memory limit is " + std::to_string(limitMiB) + " MiB)";
}

std::string solverFailure(const z3::exception& e) {
    if (!outOfMemory(e.msg())) throw InternalError(std::string("Z3 failed: ") + e.msg());
    return "Z3 ran " + unknownReason(e.msg());
}

void recoverSolverMemory() {
    Z3_reset_memory();
    setLimit(limitMiB);
}

}  // namespace holon::checker
