// Planner at a million metamodules (issue: performance). Each case runs in its own process so
// peak memory is per case; medians of several runs are printed:
//   2d  box:1000x1000 -> box:2000x500, planner_intermediate, synchronous rounds
//   3d  box:100x100x100 -> box:200x100x50, planner_intermediate, synchronous rounds
// Wall time covers laying out the problem, compiling the rules onto the board and running.
// Usage: plan_bench [--runs N]        plan_bench --case 2d|3d

#include "PlanSupport.h"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <sstream>
#include <string>
#include <sys/resource.h>
#include <vector>

using namespace holon;

namespace {

void runCase(const std::string& name) {
    const bool three = name == "3d";
    const auto start = std::chrono::steady_clock::now();
    auto r = bench::runPlan("planner_intermediate", three ? "box:100x100x100" : "box:1000x1000", three ? "box:200x100x50" : "box:2000x500", 1, "random",
                            planner::Scheduler::Sync, 1, {}, false);
    const double wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    rusage usage{};
    getrusage(RUSAGE_SELF, &usage);
    const rules::Vec e = r->problem.board->extent();
    const double boxCells = double(e.x) * e.y * (three ? e.z : 1);
    std::printf("%d %.4f %.4f %lld %lld %lld %.1f %.2f %.0f\n", r->stats.complete ? 1 : 0, wall, r->stats.seconds, (long long)r->stats.metamodules,
                (long long)r->stats.rounds, (long long)r->stats.evaluations, usage.ru_maxrss / 1024.0, usage.ru_maxrss * 1024.0 / boxCells, boxCells);
}

double median(std::vector<double> v) {
    std::sort(v.begin(), v.end());
    return v[v.size() / 2];
}

}  // namespace

int main(int argc, char** argv) {
    int runs = 3;
    for (int i = 1; i + 1 < argc; i += 2) {
        const std::string flag = argv[i];
        if (flag == "--case") {
            runCase(argv[i + 1]);
            return 0;
        }
        if (flag == "--runs") runs = std::max(1, std::atoi(argv[i + 1]));
    }
    std::printf("planner benchmark: planner_intermediate, sync rounds, medians of %d runs (one process each)\n", runs);
    std::printf("%-4s %10s %8s %9s %9s %14s %10s %10s %11s\n", "case", "metamod.", "rounds", "wall s", "run s", "evals/s", "peak MiB", "B/cell", "box cells");
    for (const char* name : {"2d", "3d"}) {
        std::vector<double> wall, run, mib, bpc, evals;
        long long meta = 0, rounds = 0;
        double box = 0;
        int complete = 1;
        for (int k = 0; k < runs; ++k) {
            const std::string cmd = std::string(argv[0]) + " --case " + name;
            FILE* p = popen(cmd.c_str(), "r");
            int c = 0;
            double w = 0, s = 0, m = 0, b = 0, bx = 0;
            long long mm = 0, rr = 0, ev = 0;
            if (!p || std::fscanf(p, "%d %lf %lf %lld %lld %lld %lf %lf %lf", &c, &w, &s, &mm, &rr, &ev, &m, &b, &bx) != 9) return 1;
            pclose(p);
            complete &= c;
            wall.push_back(w), run.push_back(s), mib.push_back(m), bpc.push_back(b), evals.push_back(double(ev) / s);
            meta = mm, rounds = rr, box = bx;
        }
        std::printf("%-4s %10lld %8lld %9.3f %9.3f %14.0f %10.1f %10.1f %11.0f%s\n", name, meta, rounds, median(wall), median(run), median(evals), median(mib),
                    median(bpc), box, complete ? "" : "  NOT COMPLETE");
    }
    return 0;
}
