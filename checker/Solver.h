#pragma once
// Z3's limits and failures, in one place: its process-wide memory limit, and what a Z3 exception or
// a reason for "unknown" means for an obligation (running out of memory is a limit, exit 3; any
// other Z3 failure is a bug in holon, exit 4, never bad input).

#include "checker/Budget.h"

#include <cstdint>
#include <memory>
#include <string>
#include <z3++.h>

namespace holon::checker {

/// Z3's memory limit for this process (Z3's memory_max_size), in MiB; 0: none.
void limitSolverMemory(std::uint64_t mib);
/// In a forked child racing `ways - 1` others: this child's share of what the limit leaves free
/// (the parent's memory, shared with the child, counts once).
void shareSolverMemory(int ways);

/// Frees a context, unless its obligation's budget is spent. z3++ 4.8.12's move assignment of an
/// expression never releases the expression it overwrites (ast::operator=(ast&&)), so every
/// `q = q && x` leaks the old q; Z3 frees what leaked only with the context, layer by layer, in time
/// quadratic in the formulas' depth (40 s after a 0.5 s timeout for Progress on square:12x12).
/// Past the deadline that time is not spent: the context stays allocated until the process ends.
class ContextRelease {
public:
    explicit ContextRelease(const Budget& budget = Budget()) : budget_(budget) {}
    void operator()(z3::context* c) const;

private:
    Budget budget_;
};
using Context = std::unique_ptr<z3::context, ContextRelease>;

/// A new Z3 context for an obligation with `budget`; throws z3::exception("out of memory") where
/// Z3 cannot make one within its memory limit (z3++ 4.8.12 would use the null context it gets and crash).
Context newContext(const Budget& budget = Budget());

/// Whether a Z3 failure or reason for "unknown" is Z3 running out of memory.
bool outOfMemory(const std::string& message);
/// A reason for "unknown" as a verdict's summary says it: naming the memory limit where it was hit.
/// Z3's "interrupted from keyboard" (it catches SIGINT while solving) throws Interrupted(SIGINT).
std::string unknownReason(const std::string& reason);
/// A Z3 exception as an obligation's summary: running out of memory (with the limit); any other
/// failure throws InternalError.
std::string solverFailure(const z3::exception& e);
/// Makes Z3 usable again after it ran out of memory: Z3 4.8.12 makes no new context until its
/// memory is reset (it returns none, and z3++ crashes on it). Only with no context alive.
void recoverSolverMemory();

}  // namespace holon::checker
