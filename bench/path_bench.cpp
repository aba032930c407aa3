// Shortest-path throughput (`holon path`, issue 29): seeded random pairs of connected pixel
// configurations (Eden growth from a random cell, sizes drawn from 1 to a third of the region) on
// a region whose legal space is tens of millions of states; each pair's shortest path is searched
// forward (the explorer, all threads), bidirectionally and by A* (one thread each), each run
// `repeats` times; per pair the length (the same for all three, or the bench fails), and per
// search the states stored, the median seconds and states/s per core; then the largest forward
// search's three times, and per search the median and worst over the pairs.
// Usage: path_bench [--region square:6x5] [--pairs 7] [--seed 1] [--threads 2] [--repeats 3]

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
    int pairs = 7, threads = 2, repeats = 3;
    unsigned seed = 1;
    for (int i = 1; i + 1 < argc; i += 2) {
        if (!std::strcmp(argv[i], "--region")) spec = argv[i + 1];
        else if (!std::strcmp(argv[i], "--pairs")) pairs = std::atoi(argv[i + 1]);
        else if (!std::strcmp(argv[i], "--seed")) seed = static_cast<unsigned>(std::atoi(argv[i + 1]));
        else if (!std::strcmp(argv[i], "--threads")) threads = std::atoi(argv[i + 1]);
        else if (!std::strcmp(argv[i], "--repeats")) repeats = std::atoi(argv[i + 1]);
        else return std::fprintf(stderr, "usage: path_bench [--region SPEC] [--pairs N] [--seed S] [--threads T] [--repeats R]\n"), 2;
    }
    if (pairs < 1 || threads < 1 || repeats < 1) return std::fprintf(stderr, "path_bench: --pairs, --threads and --repeats must be at least 1\n"), 2;
    const rules::System system = rules::librarySystem("pixel");
    const rules::Region region = rules::Region::parse(spec);
    const rules::Model model(system, region.lattice());
    const rules::Engine engine(model, region, std::vector<std::uint32_t>(region.size(), 0));
    std::mt19937 rng(seed);
    // Forward runs on the explorer's threads; bidirectional and A* on one.
    const checker::PathSearch searches[] = {checker::PathSearch::Forward, checker::PathSearch::Bidirectional, checker::PathSearch::AStar};
    const int threadsOf[] = {threads, 1, 1};
    struct Run {
        std::uint64_t states = 0;
        double seconds = 0, perCore = 0, perCpu = 0;
    };
    std::vector<std::vector<Run>> runs(3);  // per search, per pair: the median of the repeats
    std::printf("pixel on %s, %d seeded pairs (seed %u), median of %d runs each; forward on %d threads, bidirectional and A* on 1\n", spec.c_str(), pairs, seed,
                repeats, threads);
    std::printf("%4s %6s | %-38s | %-38s | %-38s\n", "pair", "length", "forward: states, s, states/s/core", "bidirectional: states, s, states/s/core",
                "A*: states, s, states/s/core");
    for (int p = 0; p < pairs; ++p) {
        std::uniform_int_distribution<int> size(1, std::max(1, region.size() / 3));
        checker::PathQuery query;
        query.from = {edenShape(region, size(rng), rng), engine.inputs()};
        query.to = rules::Configuration{edenShape(region, size(rng), rng), engine.inputs()};
        std::size_t length = 0;
        std::printf("%4d", p);
        std::string line;
        for (int s = 0; s < 3; ++s) {
            query.search = searches[s];
            query.limits.threads = threadsOf[s];
            std::vector<double> seconds, perCore, perCpu;
            std::uint64_t states = 0;
            for (int r = 0; r < repeats; ++r) {
                const double cpu0 = cpuSeconds();
                const checker::PathResult result = checker::shortestPath(engine, query);
                const double cpu = std::max(cpuSeconds() - cpu0, 1e-9);
                if (result.outcome != checker::PathOutcome::Found) return std::fprintf(stderr, "\npair %d: no path (pixel is holonomic: a bug)\n", p), 1;
                if (result.search != searches[s]) return std::fprintf(stderr, "\npair %d: %s ran instead of %s\n", p, checker::pathSearchName(result.search).c_str(), checker::pathSearchName(searches[s]).c_str()), 1;
                const std::size_t steps = result.trace.steps.size() - 1;
                if (s == 0 && r == 0) length = steps;
                else if (steps != length) return std::fprintf(stderr, "\npair %d: %s found %zu steps, forward %zu\n", p, checker::pathSearchName(searches[s]).c_str(), steps, length), 1;
                states = result.stats.states;
                seconds.push_back(result.stats.seconds);
                perCore.push_back(static_cast<double>(states) / std::max(result.stats.seconds, 1e-9) / threadsOf[s]);
                perCpu.push_back(static_cast<double>(states) / cpu);
            }
            runs[s].push_back({states, median(seconds), median(perCore), median(perCpu)});
            char cell[64];
            std::snprintf(cell, sizeof cell, "%12llu %8.3f %12.0f", static_cast<unsigned long long>(states), median(seconds), median(perCore));
            line += std::string(" | ") + cell + std::string(38 - std::min<std::size_t>(38, std::strlen(cell)), ' ');
        }
        std::printf(" %6zu%s\n", length, line.c_str());
    }
    // The pair whose forward search stored the most states: the "shortest path through a space of
    // 10^7 states" of issue 29 when the region is square:6x5.
    std::size_t largest = 0;
    for (std::size_t p = 1; p < runs[0].size(); ++p)
        if (runs[0][p].states > runs[0][largest].states) largest = p;
    std::printf("largest forward search (pair %zu, %llu states):", largest, static_cast<unsigned long long>(runs[0][largest].states));
    for (int s = 0; s < 3; ++s)
        std::printf(" %s %.3f s (%.3f CPU-s)%s", checker::pathSearchName(searches[s]).c_str(), runs[s][largest].seconds,
                    static_cast<double>(runs[s][largest].states) / std::max(runs[s][largest].perCpu, 1e-9), s < 2 ? "," : "\n");
    for (int s = 0; s < 3; ++s) {
        std::vector<double> seconds, perCore, perCpu;
        for (const Run& r : runs[s]) seconds.push_back(r.seconds), perCore.push_back(r.perCore), perCpu.push_back(r.perCpu);
        std::printf("%-13s seconds: median %.3f, worst %.3f; states/s per core: median %.0f, worst %.0f; states per CPU-second: median %.0f\n",
                    checker::pathSearchName(searches[s]).c_str(), median(seconds), *std::max_element(seconds.begin(), seconds.end()), median(perCore),
                    *std::min_element(perCore.begin(), perCore.end()), median(perCpu));
    }
}
