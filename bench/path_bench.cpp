// Shortest-path throughput (`holon path`, issue 29): seeded random pairs of connected pixel
// configurations (Eden growth from a random cell, sizes drawn from 1 to a third of the region) on
// a region whose legal space is tens of millions of states; each pair's shortest path is searched
// breadth-first and its length, states searched and rate printed, then the median and worst.
// Usage: path_bench [--region square:6x5] [--pairs 7] [--seed 1] [--threads 2]

#include "checker/Path.h"
#include "rules/Library.h"

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <random>
#include <string>
#include <sys/resource.h>
#include <vector>

using namespace holon;

namespace {

/// A connected set of `size` cells grown one random frontier cell at a time.
std::vector<rules::CellValue> edenShape(const rules::Region& region, int size, std::mt19937& rng) {
    std::vector<rules::CellValue> cells(region.size(), 0);
    std::vector<int> frontier{std::uniform_int_distribution<int>(0, region.size() - 1)(rng)};
    for (int placed = 0; placed < size && !frontier.empty();) {
        const std::size_t k = std::uniform_int_distribution<std::size_t>(0, frontier.size() - 1)(rng);
        const int cell = frontier[k];
        frontier.erase(frontier.begin() + static_cast<std::ptrdiff_t>(k));
        if (cells[cell]) continue;
        cells[cell] = 1, ++placed;
        for (int d = 0; d < region.lattice().degree(); ++d)
            if (const int n = region.neighbour(cell, d); n >= 0 && !cells[n]) frontier.push_back(n);
    }
    return cells;
}

/// CPU seconds of this process so far (user + system): the rate per CPU second holds on a shared,
/// noisy machine where wall-clock rates do not.
double cpuSeconds() {
    rusage u{};
    getrusage(RUSAGE_SELF, &u);
    return static_cast<double>(u.ru_utime.tv_sec + u.ru_stime.tv_sec) + 1e-6 * static_cast<double>(u.ru_utime.tv_usec + u.ru_stime.tv_usec);
}

double median(std::vector<double> v) {
    std::sort(v.begin(), v.end());
    return v.empty() ? 0 : v.size() % 2 ? v[v.size() / 2]
                                        : (v[v.size() / 2 - 1] + v[v.size() / 2]) / 2;
}

}  // namespace

int main(int argc, char** argv) {
    std::string spec = "square:6x5";
    int pairs = 7, threads = 2;
    unsigned seed = 1;
    for (int i = 1; i + 1 < argc; i += 2) {
        if (!std::strcmp(argv[i], "--region")) spec = argv[i + 1];
        else if (!std::strcmp(argv[i], "--pairs")) pairs = std::atoi(argv[i + 1]);
        else if (!std::strcmp(argv[i], "--seed")) seed = static_cast<unsigned>(std::atoi(argv[i + 1]));
        else if (!std::strcmp(argv[i], "--threads")) threads = std::atoi(argv[i + 1]);
        else return std::fprintf(stderr, "usage: path_bench [--region SPEC] [--pairs N] [--seed S] [--threads T]\n"), 2;
    }
    const rules::System system = rules::librarySystem("pixel");
    const rules::Region region = rules::Region::parse(spec);
    const rules::Model model(system, region.lattice());
    const rules::Engine engine(model, region, std::vector<std::uint32_t>(region.size(), 0));
    std::mt19937 rng(seed);
    std::vector<double> seconds, rates, cpuRates;
    std::printf("pixel on %s, %d seeded pairs (seed %u), %d threads\n%6s %12s %9s %14s %18s\n", spec.c_str(), pairs, seed, threads, "length", "states", "seconds",
                "states/s/core", "states/CPU-second");
    for (int p = 0; p < pairs; ++p) {
        std::uniform_int_distribution<int> size(1, std::max(1, region.size() / 3));
        checker::PathQuery query;
        query.from = {edenShape(region, size(rng), rng), engine.inputs()};
        query.to = rules::Configuration{edenShape(region, size(rng), rng), engine.inputs()};
        query.limits.threads = threads;
        const double cpu0 = cpuSeconds();
        const checker::PathResult r = checker::shortestPath(engine, query);
        const double cpuRate = static_cast<double>(r.stats.states) / std::max(cpuSeconds() - cpu0, 1e-9);
        if (r.outcome != checker::PathOutcome::Found) return std::fprintf(stderr, "pair %d: no path (pixel is holonomic: a bug)\n", p), 1;
        const double rate = static_cast<double>(r.stats.states) / std::max(r.stats.seconds, 1e-9) / threads;
        seconds.push_back(r.stats.seconds), rates.push_back(rate), cpuRates.push_back(cpuRate);
        std::printf("%6zu %12llu %9.2f %14.0f %18.0f\n", r.trace.steps.size() - 1, static_cast<unsigned long long>(r.stats.states), r.stats.seconds, rate, cpuRate);
    }
    std::printf("seconds: median %.2f, worst %.2f; states/s per core: median %.0f, worst %.0f; states per CPU-second: median %.0f, worst %.0f\n",
                median(seconds), *std::max_element(seconds.begin(), seconds.end()), median(rates), *std::min_element(rates.begin(), rates.end()),
                median(cpuRates), *std::min_element(cpuRates.begin(), cpuRates.end()));
}
