#pragma once
// Running solver jobs in forked children: a job's answer comes back as JSON through a pipe, and the
// child ends with _exit, skipping destructors (Z3 4.8.12 takes longer to free a context after
// Spacer than to solve).

#include "rules/Budget.h"

#include <functional>
#include <nlohmann/json.hpp>
#include <vector>

namespace holon::checker {

/// A job computes its answer; `forked` tells it that its process ends right after, so what it
/// allocates need not be freed.
using ForkedJob = std::function<nlohmann::json(bool forked)>;

struct ForkedAnswer {
    int job = -1;           // the job that gave `answer`; -1: none answered
    nlohmann::json answer;  // on failure: {"error": why}
};

/// Runs the jobs at once, one child each, and returns the first answer `decisive` accepts (the
/// other children are killed), else the first answer to arrive. An InputError thrown by a job
/// ends the race and is thrown again here. When a child cannot be started, job 0 runs in this process instead.
/// Children never outlive the race: past `budget` (and a short grace for the jobs' own timeouts
/// to answer) they are killed and the answer is {"error": "timeout ..."}; SIGINT or SIGTERM kills
/// them and throws Interrupted; a child whose parent dies is killed by the kernel.
ForkedAnswer firstDecisive(const std::vector<ForkedJob>& jobs, const std::function<bool(const nlohmann::json&)>& decisive,
                           const Budget& budget = Budget());

}  // namespace holon::checker
