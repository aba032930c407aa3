// Planner at scale (issues: performance, 28 "Rounds grow with the area, not the diameter"). Each
// case runs in its own process, under `ulimit -v` (--cap-gib), so peak memory is per case; medians
// of several runs are printed. Rows:
//   fig7 K      seed 000's block experiment 6x3x2 -> 3x3x4 scaled by K (36 K^3 metamodules: 36 ..
//               2304 in the paper, K = 31 past 10^6), intermediate, and general1 with the gradient,
//               demand (the shape bench's best, docs/allocators.md) and eager (fewer rounds at scale)
//               allocators
//   2d          box:1000x1000 -> box:2000x500 (10^6), intermediate; 2d-g1 the same with general1
//   3d          box:100x100x100 -> box:200x100x50 (10^6), intermediate
//   2d-1e7      box:3163x3163 -> box:6326x1582 (10^7), intermediate
// All synchronous rounds. rounds/D divides the rounds by the diameter D (the bounding box's extents
// summed); "wall s" covers laying out the problem, compiling the rules and running (not the
// transfer bound), "cpu s" the process's CPU time for the same (what counts on a shared machine);
// B/mm is the peak resident memory per metamodule of the start.
// A run stops at --timeout seconds of wall time (default 60, the target) and is then printed
// NOT COMPLETE with the rounds it made.
// --threads N sets planner::RunOptions::threads (default 2: a round's independent work on two
// threads on large boards; 1 runs on one, with the same plans).
// Usage: plan_bench [--runs N] [--max-k K] [--cap-gib G] [--timeout S] [--threads N] [--with-1e7] [--only PREFIX]
//        plan_bench [--threads N] --case RULES FROM TO SCALE ALLOCATOR TIMEOUT

#include "PlanSupport.h"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <sys/resource.h>
#include <vector>

using namespace holon;

namespace {

struct Case {
    std::string name, rules, from, to, allocator;
    int scale = 1;
};

void runCase(const Case& c, double timeout, int threads) {
    const auto start = std::chrono::steady_clock::now();
    auto r = bench::layoutPlan(c.rules, c.from, c.to, c.scale, 1);
    auto allocator = planner::makeAllocator(c.allocator, r->problem, 1);
    planner::RunOptions options;
    options.budget = Budget(timeout);
    options.threads = threads;
    r->stats = planner::Execution(r->problem, *allocator, options).run();
    const double wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    rusage usage{};
    getrusage(RUSAGE_SELF, &usage);
    const rules::Vec e = r->problem.board->extent();
    const long long diameter = (long long)e.x + e.y + (r->problem.start.dimension == 3 ? e.z : 0);
    const double metamodules = double(r->problem.start.cells.size());
    const double cpu = double(usage.ru_utime.tv_sec + usage.ru_stime.tv_sec) + double(usage.ru_utime.tv_usec + usage.ru_stime.tv_usec) / 1e6;
    std::printf("%d %.4f %.4f %lld %lld %lld %.1f %.1f %lld\n", r->stats.complete ? 1 : 0, wall, cpu, (long long)r->problem.start.cells.size(), (long long)r->stats.rounds,
                (long long)r->stats.transfers, usage.ru_maxrss / 1024.0, usage.ru_maxrss * 1024.0 / metamodules, diameter);
}

double median(std::vector<double> v) {
    std::sort(v.begin(), v.end());
    return v[v.size() / 2];
}

}  // namespace

int main(int argc, char** argv) {
    int runs = 3, maxK = 31, threads = planner::RunOptions{}.threads;
    double capGiB = 12, timeout = 60;
    bool with1e7 = false;
    std::string only;
    for (int i = 1; i < argc; ++i) {
        const std::string flag = argv[i];
        if (flag == "--case" && i + 6 < argc) {
            runCase({"", argv[i + 1], argv[i + 2], argv[i + 3], argv[i + 5], std::atoi(argv[i + 4])}, std::atof(argv[i + 6]), threads);
            return 0;
        }
        if (flag == "--runs" && i + 1 < argc) runs = std::max(1, std::atoi(argv[++i]));
        else if (flag == "--max-k" && i + 1 < argc) maxK = std::atoi(argv[++i]);
        else if (flag == "--cap-gib" && i + 1 < argc) capGiB = std::atof(argv[++i]);
        else if (flag == "--timeout" && i + 1 < argc) timeout = std::atof(argv[++i]);
        else if (flag == "--only" && i + 1 < argc) only = argv[++i];
        else if (flag == "--threads" && i + 1 < argc) threads = std::max(1, std::atoi(argv[++i]));
        else if (flag == "--with-1e7") with1e7 = true;
        else {
            std::fprintf(stderr,
                         "usage: plan_bench [--runs N] [--max-k K] [--cap-gib G] [--timeout S] [--threads N] [--with-1e7] [--only PREFIX]\n"
                         "       plan_bench [--threads N] --case RULES FROM TO SCALE ALLOCATOR TIMEOUT\n");
            return 2;
        }
    }
    std::vector<Case> cases;
    for (int k : {1, 2, 3, 4, 8, 16, 22, 31}) {
        if (k > maxK) continue;
        cases.push_back({"fig7 K=" + std::to_string(k), "planner_intermediate", "box:6x3x2", "box:3x3x4", "random", k});
        for (const char* allocator : {"gradient", "demand", "eager"}) cases.push_back({"fig7 K=" + std::to_string(k), "planner_general1", "box:6x3x2", "box:3x3x4", allocator, k});
    }
    cases.push_back({"2d", "planner_intermediate", "box:1000x1000", "box:2000x500", "random"});
    cases.push_back({"3d", "planner_intermediate", "box:100x100x100", "box:200x100x50", "random"});
    for (const char* allocator : {"gradient", "demand", "eager"}) cases.push_back({"2d-g1", "planner_general1", "box:1000x1000", "box:500x2000", allocator});
    if (with1e7) cases.push_back({"2d-1e7", "planner_intermediate", "box:3163x3163", "box:6326x1582", "random"});
    std::printf("planner benchmark: sync rounds, medians of %d runs (one process each, ulimit -v %.0f GiB)\n", runs, capGiB);
    std::printf("%-10s %-22s %10s %8s %8s %11s %9s %9s %10s %8s\n", "case", "system / allocator", "metamod.", "rounds", "rounds/D", "transfers", "wall s", "cpu s", "peak MiB",
                "B/mm");
    for (const Case& c : cases) {
        if (c.name.rfind(only, 0) != 0) continue;  // --only: a prefix of the case names
        std::vector<double> wall, cpu, mib, bpm, rounds;
        long long meta = 0, transfers = 0, diameter = 1;
        int complete = 1, ok = 1;
        for (int k = 0; k < runs && ok; ++k) {
            const std::string cmd = "ulimit -v " + std::to_string((long long)(capGiB * 1024 * 1024)) + "; '" + argv[0] + "' --case " + c.rules + " " + c.from + " " + c.to + " " +
                                    std::to_string(c.scale) + " " + c.allocator + " " + std::to_string(timeout);
            FILE* p = popen(cmd.c_str(), "r");
            int done = 0;
            double w = 0, u = 0, m = 0, b = 0;
            long long mm = 0, rr = 0, tt = 0, dd = 0;
            ok = p && std::fscanf(p, "%d %lf %lf %lld %lld %lld %lf %lf %lld", &done, &w, &u, &mm, &rr, &tt, &m, &b, &dd) == 9;
            if (p) pclose(p);
            if (!ok) break;
            complete &= done;
            wall.push_back(w), cpu.push_back(u), mib.push_back(m), bpm.push_back(b), rounds.push_back(double(rr));
            meta = mm, transfers = tt, diameter = std::max(1LL, dd);
        }
        const std::string label = c.rules.substr(8) + (c.rules == "planner_intermediate" ? "" : " / " + c.allocator);
        if (!ok) {
            std::printf("%-10s %-22s  FAILED (out of memory under the cap, or crashed)\n", c.name.c_str(), label.c_str());
            continue;
        }
        std::printf("%-10s %-22s %10lld %8.0f %8.1f %11lld %9.2f %9.2f %10.1f %8.0f%s\n", c.name.c_str(), label.c_str(), meta, median(rounds),
                    median(rounds) / double(diameter), transfers, median(wall), median(cpu), median(mib), median(bpm), complete ? "" : "  NOT COMPLETE");
        std::fflush(stdout);
    }
    return 0;
}
