#pragma once
// Running jobs in forked children: a job's answer comes back as JSON through a pipe, and the child
// ends with _exit, skipping destructors (Z3 4.8.12 takes longer to free a context after Spacer
// than to solve). A race of solver jobs (firstDecisive), or one job beside other work (ForkedTask).

#include "rules/Budget.h"

#include <functional>
#include <nlohmann/json.hpp>
#include <optional>
#include <vector>

namespace holon::checker {

/// A job computes its answer; `forked` tells it that its process ends right after, so what it
/// allocates need not be freed.
using ForkedJob = std::function<nlohmann::json(bool forked)>;

struct ForkedAnswer {
    int job = -1;           // the job that gave `answer`; -1: none answered
    nlohmann::json answer;  // on failure: {"error": why}, with "resources": true when memory ran out or the process was killed
};

/// Runs the jobs at once, one child each, and returns the first answer `decisive` accepts (the
/// other children are killed), else the first answer to arrive. An InputError thrown by a job
/// ends the race and is thrown again here. When a child cannot be started, job 0 runs in this process instead.
/// Children never outlive the race: past `budget` (and a short grace for the jobs' own timeouts
/// to answer) they are killed and the answer is {"error": "timeout ..."}; SIGINT or SIGTERM kills
/// them and throws Interrupted; a child whose parent dies is killed by the kernel.
ForkedAnswer firstDecisive(const std::vector<ForkedJob>& jobs, const std::function<bool(const nlohmann::json&)>& decisive,
                           const Budget& budget = Budget());

/// One job in a forked child while this process goes on: a yardstick computed on the other core
/// beside the work it measures. A child still running when the task is destroyed is killed.
class ForkedTask {
public:
    explicit ForkedTask(ForkedJob job);
    ~ForkedTask();
    ForkedTask(const ForkedTask&) = delete;
    ForkedTask& operator=(const ForkedTask&) = delete;

    /// The job's answer. It waits while `budget` lasts (deadline and stop signals): once it is
    /// spent the child is killed and the answer is nullopt. When no child could be started, the
    /// job runs here, now, unless the budget is already spent.
    std::optional<nlohmann::json> answer(const Budget& budget);

private:
    void stop();
    ForkedJob job_;
    int pid_ = -1, fd_ = -1;
};

}  // namespace holon::checker
