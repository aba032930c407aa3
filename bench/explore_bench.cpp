// Explorer throughput (issue: reconfiguration-graph explorer). Two workloads, each run several
// times in its own process so peak memory is per workload; medians are printed:
//   pixel    every legal configuration of square:5x5 (pixel with connectivity)
//   general1 general1 with connectivity on square:5x5, reachable from the 2x5 block of D in rows 0-1
// Usage: explore_bench [--runs N] [--threads T]      (runs both, prints a table)
//        explore_bench --case NAME --threads T       (one run, one line of figures)

#include "checker/Explorer.h"
#include "rules/Library.h"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <iostream>
#include <sstream>
#include <string>
#include <sys/resource.h>
#include <unistd.h>
#include <vector>

using namespace holon;

namespace {

struct Figures {
    double seconds = 0, enumerateSeconds = 0, states = 0, edges = 0, bytesPerState = 0, peakMiB = 0;
};

Figures runCase(const std::string& name, int threads) {
    const bool pixel = name == "pixel";
    rules::System system = rules::librarySystem(pixel ? "pixel" : "general1");
    rules::Region region = rules::Region::parse("square:5x5");
    rules::Model model(system, region.lattice());
    rules::Engine engine(model, region, {});
    checker::Explorer::Options options;
    options.limits.threads = threads;
    options.recordEdges = false;  // throughput of the search itself
    checker::Explorer ex(engine, options);
    Figures f;
    const auto start = std::chrono::steady_clock::now();
    if (pixel) {
        ex.addAllLegal();
        f.enumerateSeconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    } else {
        std::vector<rules::CellValue> cells(region.size(), 0);
        const int d = model.alphabet().byGlyph('D');
        for (int y = 0; y < 2; ++y)
            for (int x = 0; x < 5; ++x) cells[region.indexOf({x, y, 0})] = static_cast<rules::CellValue>(d);
        ex.addInitial(cells.data());
    }
    const auto& s = ex.explore();
    f.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    f.states = static_cast<double>(s.states);
    f.edges = static_cast<double>(s.edges);
    f.bytesPerState = static_cast<double>(ex.bytesPerState());
    rusage usage{};
    getrusage(RUSAGE_SELF, &usage);
    f.peakMiB = usage.ru_maxrss / 1024.0;
    return f;
}

double median(std::vector<double> v) {
    std::sort(v.begin(), v.end());
    return v[v.size() / 2];
}

}  // namespace

int main(int argc, char** argv) {
    std::string only;
    int runs = 5, threads = 2;
    for (int i = 1; i + 1 < argc; i += 2) {
        const std::string flag = argv[i];
        if (flag == "--case") only = argv[i + 1];
        else if (flag == "--runs") runs = std::atoi(argv[i + 1]);
        else if (flag == "--threads") threads = std::atoi(argv[i + 1]);
    }
    if (!only.empty()) {
        Figures f = runCase(only, threads);
        std::printf("%.6f %.6f %.0f %.0f %.1f %.1f\n", f.seconds, f.enumerateSeconds, f.states, f.edges, f.bytesPerState, f.peakMiB);
        return 0;
    }
    char path[4096] = {};
    if (readlink("/proc/self/exe", path, sizeof(path) - 1) <= 0) return 2;
    const std::string self = path;
    std::printf("explorer benchmark: medians of %d runs, %d threads\n", runs, threads);
    std::printf("%-10s %10s %10s %9s %11s %12s %12s %14s %10s %9s\n", "workload", "states", "edges", "seconds", "enumerate s", "states/s",
                "states/s/core", "edges/s", "bytes/st", "peak MiB");
    for (const std::string name : {"pixel", "general1"}) {
        std::vector<double> sec, enumerate, bps, peak;
        double states = 0, edges = 0;
        for (int r = 0; r < runs; ++r) {
            const std::string cmd = self + " --case " + name + " --threads " + std::to_string(threads);
            FILE* p = popen(cmd.c_str(), "r");
            if (!p) return 2;
            Figures f;
            if (std::fscanf(p, "%lf %lf %lf %lf %lf %lf", &f.seconds, &f.enumerateSeconds, &f.states, &f.edges, &f.bytesPerState, &f.peakMiB) != 6) return 2;
            pclose(p);
            sec.push_back(f.seconds), enumerate.push_back(f.enumerateSeconds), bps.push_back(f.bytesPerState), peak.push_back(f.peakMiB);
            states = f.states, edges = f.edges;
        }
        const double s = median(sec);
        std::printf("%-10s %10.0f %10.0f %9.3f %11.3f %12.0f %12.0f %14.0f %10.1f %9.1f\n", name.c_str(), states, edges, s, median(enumerate), states / s,
                    states / s / threads, edges / s, median(bps), median(peak));
    }
    return 0;
}
