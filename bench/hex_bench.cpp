// Hole-motion sculpting speed (issue: hex back-end, seed 003 §V): one run of square -> T per array
// size and variant (the paper's algorithm, holon's --improved), one thread, repeated with seeds
// 1..R; prints the median wall time per run and per timestep, time per module and timestep, and
// the median maximum compliance. Target: a 400 x 400 run of 10,000 timesteps within 60 s.
// Usage: hex_bench [--runs R] [--steps S] [--sizes 100,200,300,400] [--from square] [--to T]

#include "planner/hex/SculptRun.h"

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <sstream>
#include <string>
#include <vector>

using namespace holon::planner::hex;

namespace {

double median(std::vector<double> v) {
    std::sort(v.begin(), v.end());
    const std::size_t n = v.size();
    return n % 2 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
}

std::vector<int> parseSizes(const std::string& list) {
    std::vector<int> out;
    std::stringstream in(list);
    for (std::string item; std::getline(in, item, ',');) out.push_back(std::atoi(item.c_str()));
    return out;
}

}  // namespace

int main(int argc, char** argv) {
    int runs = 3, steps = 10000;
    std::vector<int> sizes{100, 200, 300, 400};
    std::string from = "square", to = "T";
    for (int i = 1; i < argc; ++i) {
        const std::string a = argv[i];
        const bool more = i + 1 < argc;
        if (a == "--runs" && more) runs = std::atoi(argv[++i]);
        else if (a == "--steps" && more) steps = std::atoi(argv[++i]);
        else if (a == "--sizes" && more) sizes = parseSizes(argv[++i]);
        else if (a == "--from" && more) from = argv[++i];
        else if (a == "--to" && more) to = argv[++i];
        else {
            std::fprintf(stderr, "usage: hex_bench [--runs R] [--steps S] [--sizes 100,200,...] [--from SHAPE] [--to SHAPE]\n");
            return 2;
        }
    }
    if (runs < 1 || steps < 1 || sizes.empty()) {
        std::fprintf(stderr, "hex_bench: --runs and --steps must be positive, --sizes non-empty\n");
        return 2;
    }
    std::printf("%s -> %s, %d timesteps, medians of %d runs (seeds 1..%d), one thread\n", from.c_str(), to.c_str(), steps, runs, runs);
    std::printf("| variant | size | modules | s/run | ms/timestep | ns per module and timestep | max compliance %% |\n|---|---:|---:|---:|---:|---:|---:|\n");
    for (const bool improved : {false, true})
        for (int size : sizes) {
            std::vector<double> seconds, compliance;
            double modules = 0;
            for (int r = 0; r < runs; ++r) {
                SculptSetup setup;
                setup.from = from, setup.to = to, setup.size = size, setup.steps = steps;
                SculptOptions& o = setup.options;
                o.seed = static_cast<std::uint64_t>(r + 1);
                o.dropOverhangs = o.flexibleGrowth = o.roll = o.deleteOverflow = o.growInside = o.keepConnected = o.migrate = o.balance = improved;
                const SculptResult result = runSculpt(setup);
                seconds.push_back(result.seconds), compliance.push_back(result.maxCompliance);
                modules = static_cast<double>(result.modules);
            }
            const double s = median(seconds);
            std::printf("| %s | %d | %.0f | %.2f | %.3f | %.1f | %.2f |\n", improved ? "--improved" : "paper", size, modules, s, 1e3 * s / steps,
                        1e9 * s / steps / modules, 100 * median(compliance));
            std::fflush(stdout);
        }
    return 0;
}
