#pragma once
// Z3's limits and failures, in one place: its process-wide memory limit, and what a Z3 failure or
// a reason for "unknown" means for an obligation (running out of memory is a limit, exit 3; any
// other Z3 failure is a bug in holon, exit 4, never bad input). Z3 itself is behind Smt.h.

#include "checker/Smt.h"

#include <cstdint>
#include <string>

namespace holon::checker {

/// Z3's memory limit for this process (Z3's memory_max_size), in MiB; 0: none.
void limitSolverMemory(std::uint64_t mib);
/// In a forked child racing `ways - 1` others: this child's share of what the limit leaves free
/// (the parent's memory, shared with the child, counts once).
void shareSolverMemory(int ways);

/// Whether a Z3 failure or reason for "unknown" is Z3 running out of memory.
bool outOfMemory(const std::string& message);
/// A reason for "unknown" as a verdict's summary says it: naming the memory limit where it was hit.
/// Z3's "interrupted from keyboard" (it catches SIGINT while solving) throws Interrupted(SIGINT).
std::string unknownReason(const std::string& reason);
/// Whether Z3's reason for unknown is a limit it reached (time, memory, a cancel), not a question
/// it cannot decide.
bool limitReached(const std::string& reason);
/// A Z3 failure as an obligation's summary: running out of memory (with the limit); any other
/// failure throws InternalError.
std::string solverFailure(const smt::Failure& e);
/// Makes Z3 usable again after it ran out of memory: Z3 4.8.12 makes no new context until its
/// memory is reset (it returns none; Smt.h's Context throws then). Only with no context alive.
void recoverSolverMemory();

}  // namespace holon::checker
