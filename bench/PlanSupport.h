#pragma once
// Shared by the planner benchmarks: build a problem from library rules and shape strings, run it.

#include "planner/Execution.h"
#include "rules/Library.h"

#include <memory>
#include <string>

namespace holon::bench {

struct PlanRun {
    rules::System system;
    std::unique_ptr<rules::Model> model;
    planner::Problem problem;
    planner::RunStats stats;
    std::int64_t lowerBound = -1;
};

/// The problem laid out, not run yet.
inline std::unique_ptr<PlanRun> layoutPlan(const std::string& rules, const std::string& from, const std::string& to, int scale, std::uint64_t seed) {
    auto r = std::make_unique<PlanRun>();
    r->system = rules::librarySystem(rules);
    planner::Shape a = planner::parseShape(from, scale), b = planner::parseShape(to, scale);
    r->model = std::make_unique<rules::Model>(r->system, rules::Lattice::get(a.dimension == 3 ? rules::LatticeKind::Cubic3D : rules::LatticeKind::Square2D));
    r->problem = planner::makeProblem(*r->model, std::move(a), std::move(b), std::nullopt, seed);
    return r;
}

inline std::unique_ptr<PlanRun> runPlan(const std::string& rules, const std::string& from, const std::string& to, int scale, const std::string& allocator,
                                        planner::Scheduler scheduler, std::uint64_t seed, const planner::RunObserver& observer = {}, bool bound = true) {
    auto r = layoutPlan(rules, from, to, scale, seed);
    auto alloc = planner::makeAllocator(allocator, r->problem, seed);
    planner::RunOptions options;
    options.scheduler = scheduler, options.seed = seed;
    planner::Execution ex(r->problem, *alloc, options);
    r->stats = ex.run(observer);
    if (bound) r->lowerBound = planner::transferLowerBound(r->problem);
    return r;
}

}  // namespace holon::bench
