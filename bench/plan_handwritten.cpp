// The compiled planner against a hand-written C++ planner (bench/HandwrittenPlanner.*) on the
// million-metamodule problems of plan_bench, same scheduler, same seed policy. The target:
// the compiled engine within 1.2x of the hand-written time. Prints medians of several runs of the
// execution alone (problem layout excluded on both sides) and the median of the per-run ratios
// (each pair runs back to back, so the ratio is robust to the shared machine's load drifting).
// Usage: plan_handwritten [--runs N] [--scale-down K] [--case 2d|3d]   (K divides the box sides, for quick runs)

#include "HandwrittenPlanner.h"
#include "PlanSupport.h"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

using namespace holon;

namespace {
double median(std::vector<double> v) {
    std::sort(v.begin(), v.end());
    return v[v.size() / 2];
}
}  // namespace

int main(int argc, char** argv) {
    int runs = 7, down = 1;
    std::string only;
    for (int i = 1; i + 1 < argc; i += 2) {
        const std::string flag = argv[i];
        if (flag == "--runs") runs = std::max(1, std::atoi(argv[i + 1]));
        if (flag == "--scale-down") down = std::max(1, std::atoi(argv[i + 1]));
        if (flag == "--case") only = argv[i + 1];
    }
    std::printf("compiled vs hand-written planner: planner_intermediate, sync rounds, medians of %d runs\n", runs);
    std::printf("%-4s %10s %9s %9s %12s %12s %9s\n", "case", "metamod.", "rounds", "rounds hw", "compiled s", "hand s", "ratio");
    for (const bool three : {false, true}) {
        if (!only.empty() && only != (three ? "3d" : "2d")) continue;
        const int side2 = 1000 / down, side3 = 100 / down;
        const std::string from = three ? "box:" + std::to_string(side3) + "x" + std::to_string(side3) + "x" + std::to_string(side3)
                                       : "box:" + std::to_string(side2) + "x" + std::to_string(side2);
        const std::string to = three ? "box:" + std::to_string(2 * side3) + "x" + std::to_string(side3) + "x" + std::to_string(side3 / 2)
                                     : "box:" + std::to_string(2 * side2) + "x" + std::to_string(side2 / 2);
        std::vector<double> compiled, hand, ratio;
        long long meta = 0, rounds = 0, roundsHand = 0;
        bool ok = true;
        for (int k = 0; k < runs; ++k) {
            auto r = bench::layoutPlan("planner_intermediate", from, to, 1, 1 + k);
            const planner::Problem& p = r->problem;
            auto runCompiled = [&] {
                auto allocator = planner::makeAllocator("random", p, 1 + k);
                planner::RunOptions options;
                options.seed = 1 + k;
                planner::Execution ex(p, *allocator, options);
                const planner::RunStats s = ex.run();
                compiled.push_back(s.seconds);
                meta = s.metamodules, rounds = s.rounds;
                ok = ok && s.complete;
            };
            auto runHand = [&] {
                bench::HandwrittenPlanner hw(p, 1 + k);
                const auto begin = std::chrono::steady_clock::now();
                ok = hw.run() && ok;
                hand.push_back(std::chrono::duration<double>(std::chrono::steady_clock::now() - begin).count());
                roundsHand = hw.rounds();
                ok = ok && hw.occupied() == static_cast<std::int64_t>(p.target.cells.size());
            };
            // Alternate which goes first, so neither always runs on a warmer (or busier) machine.
            if (k % 2) runHand(), runCompiled();
            else runCompiled(), runHand();
            ratio.push_back(compiled.back() / hand.back());
        }
        std::printf("%-4s %10lld %9lld %9lld %12.3f %12.3f %8.2fx%s\n", three ? "3d" : "2d", meta, rounds, roundsHand, median(compiled), median(hand),
                    median(ratio), ok ? "" : "  NOT COMPLETE");
    }
    return 0;
}
