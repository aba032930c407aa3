// The shape bench (issue 28): how the allocators of a mass-conserving planner system do on shapes
// that are not boxes. Draws seeded start/target pairs (ShapeGenerator: polyominoes, polycubes,
// thin trees, rings, spirals, letters, voxel solids; target lighter or heavier than the start;
// small and large overlaps), runs the system with each allocator and the intermediate planner on
// the same problem, and prints per allocator the distribution (median, 90th percentile, worst) of
//   transfers / the transport lower bound (Transport.cpp; problems whose bound is 0 are counted
//   apart), rounds / the intermediate planner's rounds, and rounds / the floor: the larger of the
//   intermediate planner's rounds and the cut bound (RoundBound.cpp), which no run may beat (exit 3
//   when one does: the bound would be wrong),
// with how many runs did not complete (exit 1 when any did not). Seed 000 §V measured allocators on
// blocks only.
// Usage: shape_bench [--pairs2d N] [--pairs3d N] [--cells N] [--seed S] [--system NAME]
//                    [--allocators a,b,c] [--timeout SECONDS] [--csv FILE] [--only I]
//                    [--shapes-out DIR]
// --only I runs problem I alone (each problem is drawn from the seed and its index, so it is the
// same as in the whole bench); --shapes-out writes each problem's start and target as JSON cell
// lists (DIR/2d_I_start.json, ...) for `holon plan --from ... --to ...`.

#include "PlanSupport.h"
#include "ShapeGenerator.h"

#include "planner/RoundBound.h"
#include "rules/Error.h"

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <map>
#include <sstream>
#include <string>
#include <vector>

using namespace holon;

namespace {

struct Options {
    int pairs2d = 50, pairs3d = 30, cells = 300;
    std::uint64_t seed = 1;
    std::string system = "planner_general1";
    std::vector<std::string> allocators = {"random", "gradient", "demand", "eager", "optimal"};
    double timeout = 120;
    std::string csv, shapesOut;
    int only = -1;
};

struct Outcome {
    bool complete = false;
    std::int64_t transfers = 0, rounds = 0;
    std::int64_t firstChange = -1;  // the round of the first creation or deletion, -1 if none
    double seconds = 0;
    std::string stopped;
};

Outcome run(const rules::Model& model, const bench::ShapePair& pair, const std::string& allocator, double timeout, std::uint64_t seed) {
    planner::Problem problem = planner::makeProblem(model, pair.start, pair.target, rules::Vec{}, seed);
    auto alloc = planner::makeAllocator(allocator, problem, seed);
    planner::RunOptions options;
    options.scheduler = planner::Scheduler::Sync, options.seed = seed, options.budget = Budget(timeout);
    planner::Execution ex(problem, *alloc, options);
    std::int64_t firstChange = -1;
    planner::RunObserver observer;
    observer.roundEnd = [&](const planner::RunStats& now) {
        if (firstChange < 0 && now.creations + now.deletions > 0) firstChange = now.rounds;
        return true;
    };
    const planner::RunStats s = ex.run(observer);
    return {s.complete, s.transfers, s.rounds, firstChange, s.seconds, stopReasonName(s.stopped)};
}

struct Distribution {
    std::vector<double> values;
    std::string show() const {
        if (values.empty()) return "     -      -      -";
        std::vector<double> v = values;
        std::sort(v.begin(), v.end());
        char buf[64];
        std::snprintf(buf, sizeof buf, "%6.2f %6.2f %6.2f", v[v.size() / 2], v[std::min(v.size() - 1, v.size() * 9 / 10)], v.back());
        return buf;
    }
};

struct Tally {
    Distribution transfers, rounds, overFloor;
    int incomplete = 0, zeroBound = 0;
    double seconds = 0;
};

void writeCells(const std::string& path, const planner::Shape& shape) {
    std::ofstream out(path);
    out << '[';
    for (std::size_t k = 0; k < shape.cells.size(); ++k) {
        const rules::Vec v = shape.cells[k];
        out << (k ? "," : "") << '[' << v.x << ',' << v.y;
        if (shape.dimension == 3) out << ',' << v.z;
        out << ']';
    }
    out << "]\n";
    if (!out) throw std::runtime_error("cannot write " + path);
}

std::vector<std::string> splitCommas(const std::string& text) {
    std::vector<std::string> out;
    std::stringstream in(text);
    for (std::string part; std::getline(in, part, ',');)
        if (!part.empty()) out.push_back(part);
    return out;
}

Options parse(int argc, char** argv) {
    Options o;
    for (int i = 1; i < argc; ++i) {
        const std::string flag = argv[i];
        if (i + 1 >= argc) throw std::invalid_argument(flag + " needs a value");
        const std::string value = argv[++i];
        if (flag == "--pairs2d") o.pairs2d = std::stoi(value);
        else if (flag == "--pairs3d") o.pairs3d = std::stoi(value);
        else if (flag == "--cells") o.cells = std::stoi(value);
        else if (flag == "--seed") o.seed = std::stoull(value);
        else if (flag == "--system") o.system = value;
        else if (flag == "--allocators") o.allocators = splitCommas(value);
        else if (flag == "--timeout") o.timeout = std::stod(value);
        else if (flag == "--csv") o.csv = value;
        else if (flag == "--only") o.only = std::stoi(value);
        else if (flag == "--shapes-out") o.shapesOut = value;
        else throw std::invalid_argument("unknown option " + flag);
    }
    if (o.only >= std::max(o.pairs2d, o.pairs3d)) throw std::invalid_argument("--only must be below --pairs2d or --pairs3d");
    if (o.pairs2d < 0 || o.pairs3d < 0 || o.cells < 4 || o.timeout <= 0) throw std::invalid_argument("pairs >= 0, --cells >= 4, --timeout > 0");
    return o;
}

}  // namespace

int main(int argc, char** argv) try {
    const Options o = parse(argc, argv);
    std::ofstream csv;
    if (!o.csv.empty()) {
        csv.open(o.csv);
        csv << "dimension,index,family,start,target,bound,intermediate_rounds,round_bound,allocator,complete,transfers,rounds,seconds,stopped,first_change_round\n";
    }
    int incomplete = 0, belowBound = 0;
    const rules::System general = rules::librarySystem(o.system), intermediate = rules::librarySystem("planner_intermediate");
    std::printf("shape bench: %s, seed %llu, about %d metamodules per start (0.5x-1.5x), sync rounds\n", o.system.c_str(), (unsigned long long)o.seed, o.cells);
    for (int dimension : {2, 3}) {
        const int pairs = dimension == 2 ? o.pairs2d : o.pairs3d;
        if (pairs == 0) continue;
        const rules::Lattice& lattice = rules::Lattice::get(dimension == 3 ? rules::LatticeKind::Cubic3D : rules::LatticeKind::Square2D);
        const rules::Model generalModel(general, lattice), intermediateModel(intermediate, lattice);
        std::map<std::string, Tally> tally;
        Distribution cutOverBase;   // per problem: the cut bound on rounds (RoundBound.cpp) over the intermediate's
        Distribution beforeChange;  // per problem: the fewest rounds before a creation or deletion, over the intermediate's
        int redrawn = 0;
        std::vector<double> sizes;
        for (int index = 0; index < pairs; ++index) {
            if (o.only >= 0 && index != o.only) continue;
            bench::ShapePair pair;
            std::int64_t bound = -1, roundBound = 0;
            for (int attempt = 0;; ++attempt) {
                pair = bench::shapePair(dimension, o.seed, index, attempt, o.cells, 1.9);
                try {
                    const planner::Problem problem = planner::makeProblem(generalModel, pair.start, pair.target, rules::Vec{}, o.seed);
                    bound = planner::transferLowerBound(problem);
                    if (const auto b = planner::roundLowerBound(problem)) roundBound = b->rounds;
                    break;
                } catch (const InputError&) {
                    ++redrawn;  // the drawn sizes are more than the system's mass allows
                    if (attempt == 50) throw;
                }
            }
            sizes.push_back(double(pair.start.cells.size()));
            if (!o.shapesOut.empty())
                for (const auto& [name, shape] : {std::pair{"start", &pair.start}, std::pair{"target", &pair.target}})
                    writeCells(o.shapesOut + "/" + std::to_string(dimension) + "d_" + std::to_string(index) + "_" + name + ".json", *shape);
            const Outcome base = run(intermediateModel, pair, "random", o.timeout, o.seed);
            std::int64_t fewestBeforeChange = -1;
            for (const std::string& allocator : o.allocators) {
                const Outcome r = run(generalModel, pair, allocator, o.timeout, o.seed);
                if (r.firstChange >= 0 && (fewestBeforeChange < 0 || r.firstChange < fewestBeforeChange)) fewestBeforeChange = r.firstChange;
                Tally& t = tally[allocator];
                t.seconds += r.seconds;
                if (!r.complete) ++t.incomplete, ++incomplete;
                else {
                    if (r.rounds < roundBound) {
                        std::fprintf(stderr, "shape_bench: %dD problem %d: %s took %lld rounds, below the cut bound %lld: the bound is wrong\n", dimension, index,
                                     allocator.c_str(), (long long)r.rounds, (long long)roundBound);
                        ++belowBound;
                    }
                    if (base.complete) t.overFloor.values.push_back(double(r.rounds) / double(std::max({base.rounds, roundBound, std::int64_t{1}})));
                    if (bound > 0) t.transfers.values.push_back(double(r.transfers) / double(bound));
                    else ++t.zeroBound;
                    if (base.complete && base.rounds > 0) t.rounds.values.push_back(double(r.rounds) / double(base.rounds));
                }
                if (csv.is_open())
                    csv << dimension << ',' << index << ',' << pair.family << ',' << pair.start.cells.size() << ',' << pair.target.cells.size() << ',' << bound << ','
                        << base.rounds << ',' << roundBound << ',' << allocator << ',' << (r.complete ? 1 : 0) << ',' << r.transfers << ',' << r.rounds << ',' << r.seconds << ','
                        << r.stopped << ',' << r.firstChange << '\n';
            }
            if (base.complete && base.rounds > 0) cutOverBase.values.push_back(double(roundBound) / double(base.rounds));
            if (fewestBeforeChange > 0 && base.complete && base.rounds > 0) beforeChange.values.push_back(double(fewestBeforeChange - 1) / double(base.rounds));
        }
        if (sizes.empty()) continue;  // --only names no problem of this dimension
        std::sort(sizes.begin(), sizes.end());
        std::printf("\n%dD: %d pairs (%d draws refused by the mass check and redrawn); start sizes %g..%g, median %g\n", dimension, pairs, redrawn, sizes.front(),
                    sizes.back(), sizes[sizes.size() / 2]);
        std::printf("%-10s %-22s %-22s %-22s %10s %9s %8s\n", "allocator", "transfers/bound", "rounds/intermediate", "rounds/floor", "incomplete", "bound=0",
                    "run s");
        std::printf("%-10s %-22s %-22s %-22s\n", "", "median    p90  worst", "median    p90  worst", "median    p90  worst");
        for (const std::string& allocator : o.allocators) {
            const Tally& t = tally[allocator];
            std::printf("%-10s %-22s %-22s %-22s %10d %9d %8.1f\n", allocator.c_str(), t.transfers.show().c_str(), t.rounds.show().c_str(),
                        t.overFloor.show().c_str(), t.incomplete, t.zeroBound, t.seconds);
        }
        const auto cutOver3 = std::count_if(cutOverBase.values.begin(), cutOverBase.values.end(), [](double v) { return v > 3; });
        std::printf("%-33s %-22s (over 3 on %d of %zu problems)\n", "cut bound on rounds/intermediate", cutOverBase.show().c_str(), int(cutOver3),
                    cutOverBase.values.size());
        const auto over3 = std::count_if(beforeChange.values.begin(), beforeChange.values.end(), [](double v) { return v > 3; });
        std::printf("%-33s %-22s (over 3 on %d of %zu problems)\n", "rounds before a creation/deletion", beforeChange.show().c_str(), int(over3),
                    beforeChange.values.size());
    }
    if (belowBound > 0) return 3;  // an internal error: a proven bound was beaten
    return incomplete == 0 ? 0 : 1;
} catch (const std::exception& e) {
    std::fprintf(stderr, "shape_bench: %s\n", e.what());
    return 2;
}
