// Seed 000 §V reproduced: the 6x3x2 -> 3x3x4 block experiment scaled by K (36 K^3 metamodules),
// for intermediate and general1 with the random, gradient and optimal allocators, synchronous
// rounds; then every general system (general2/3, general-lock2/3) with every allocator.
// Prints the tables behind Fig. 7 (actions vs ensemble size) and writes into OUT:
//   fig7.csv, fig7.svg  creations, deletions, transfers and the transport bound vs size (log-log)
//   fig8.csv, fig8.svg  creation and deletion completion over rounds at 2304 metamodules (log time)
//   systems.csv         transfers per system and allocator at 288 and 2304 metamodules
// Usage: plan_figures [OUT] [--max-k K] [--max-k-random K] [--max-k-gradient K] [--max-k-optimal K] [--seed N]

#include "PlanSupport.h"
#include "rules/Svg.h"

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>
#include <string>
#include <vector>

using namespace holon;

namespace {

struct Series {
    std::string name, colour;
    std::vector<std::pair<double, double>> points;
};

/// A log-log (or log-x) line plot as SVG.
std::string plot(const std::string& title, const std::string& xLabel, const std::string& yLabel, const std::vector<Series>& series, bool logY) {
    double x0 = 1e300, x1 = -1e300, y0 = 1e300, y1 = -1e300;
    auto tx = [](double x) { return std::log10(std::max(x, 1e-9)); };
    auto ty = [&](double y) { return logY ? std::log10(std::max(y, 1e-9)) : y; };
    for (const Series& s : series)
        for (auto [x, y] : s.points) x0 = std::min(x0, tx(x)), x1 = std::max(x1, tx(x)), y0 = std::min(y0, ty(y)), y1 = std::max(y1, ty(y));
    if (logY) y0 = std::floor(y0), y1 = std::ceil(y1);
    x0 = std::floor(x0), x1 = std::ceil(x1);
    if (x1 <= x0) x1 = x0 + 1;
    if (y1 <= y0) y1 = y0 + 1;
    const double W = 820, H = 400, L = 70, B = 50, T = 30;
    auto px = [&](double x) { return L + (tx(x) - x0) / (x1 - x0) * (W - L - 250); };
    auto py = [&](double y) { return T + (1 - (ty(y) - y0) / (y1 - y0)) * (H - T - B); };
    holon::rules::Svg svg;
    svg.text(L, 18, title, {{"font-size", 13}});
    for (double e = x0; e <= x1 + 1e-9; ++e) {
        const double x = L + (e - x0) / (x1 - x0) * (W - L - 250);
        std::ostringstream label;
        label << "1e" << e;
        svg.line(x, T, x, H - B, {{"stroke", "#ddd"}}).text(x - 10, H - B + 15, label.str());
    }
    const double yStep = logY ? 1 : (y1 - y0) / 5;
    for (double e = y0; e <= y1 + 1e-9; e += yStep) {
        const double y = T + (1 - (e - y0) / (y1 - y0)) * (H - T - B);
        svg.line(L, y, W - 250, y, {{"stroke", "#ddd"}}).text(8, y + 4, logY ? "1e" + std::to_string(int(e)) : std::to_string(int(std::round(e))));
    }
    svg.text((W - 250) / 2, H - 12, xLabel).text(8, T - 8, yLabel);
    int row = 0;
    for (const Series& s : series) {
        std::vector<std::pair<double, double>> points;
        for (auto [x, y] : s.points) points.push_back({px(x), py(y)});
        svg.polyline(points, {{"fill", "none"}, {"stroke", s.colour}, {"stroke-width", 2}});
        for (auto [x, y] : points) svg.circle(x, y, 2.5, {{"fill", s.colour}});
        svg.rect(W - 240, T + row * 18, 12, 4, {{"fill", s.colour}}).text(W - 224, T + row * 18 + 6, s.name);
        ++row;
    }
    return svg.document(W, H, {{"font-family", "sans-serif"}, {"font-size", 11}});
}

}  // namespace

int main(int argc, char** argv) {
    std::string out = "out/plan";
    int maxK = 31, maxKRandom = 4, maxKGradient = 8, maxKOptimal = 6;
    std::uint64_t seed = 1;
    for (int i = 1; i < argc; ++i) {
        const std::string a = argv[i];
        if (a == "--max-k" && i + 1 < argc) maxK = std::atoi(argv[++i]);
        else if (a == "--max-k-random" && i + 1 < argc) maxKRandom = std::atoi(argv[++i]);
        else if (a == "--max-k-gradient" && i + 1 < argc) maxKGradient = std::atoi(argv[++i]);
        else if (a == "--max-k-optimal" && i + 1 < argc) maxKOptimal = std::atoi(argv[++i]);
        else if (a == "--seed" && i + 1 < argc) seed = std::strtoull(argv[++i], nullptr, 10);
        else if (!a.empty() && a[0] != '-') out = a;
        else {  // a flag is never an output folder
            const bool help = a == "--help" || a == "-h";
            if (!help) std::fprintf(stderr, "plan_figures: unknown option '%s'\n", a.c_str());
            std::fprintf(help ? stdout : stderr, "usage: plan_figures [OUT] [--max-k K] [--max-k-random K] [--max-k-gradient K] [--max-k-optimal K] [--seed N]\n");
            return help ? 0 : 2;
        }
    }
    std::filesystem::create_directories(out);
    std::ofstream csv(out + "/fig7.csv");
    csv << "metamodules,system,allocator,creations,deletions,transfers,transfer_lower_bound,rounds,seconds,complete\n";
    std::printf("seed 000 Fig. 7: 6x3x2 -> 3x3x4 scaled by K, sync rounds, seed %llu\n", (unsigned long long)seed);
    std::printf("%9s %-22s %10s %10s %12s %12s %7s %8s %9s\n", "metamod.", "system / allocator", "creations", "deletions", "transfers", "lower bound", "ratio",
                "rounds", "seconds");
    std::map<std::string, Series> series;
    series["actions"] = {"intermediate: creations+deletions", "#3d6fb0", {}};
    series["random"] = {"general1 random: transfers", "#c03030", {}};
    series["gradient"] = {"general1 gradient: transfers", "#20a060", {}};
    series["optimal"] = {"general1 optimal: transfers", "#8040c0", {}};
    series["bound"] = {"transport lower bound", "#888888", {}};
    std::vector<int> ks;
    for (int k : {1, 2, 3, 4, 6, 8, 12, 16, 22, 31})  // 31: past 10^6 metamodules
        if (k <= maxK) ks.push_back(k);
    for (int k : ks) {
        struct Job {
            const char *rules, *allocator, *key;
            int maxK;
        };
        for (const Job& job : {Job{"planner_intermediate", "random", "actions", maxK}, Job{"planner_general1", "random", "random", maxKRandom},
                               Job{"planner_general1", "gradient", "gradient", maxKGradient}, Job{"planner_general1", "optimal", "optimal", maxKOptimal}}) {
            if (k > job.maxK) continue;
            const bool general = std::string(job.rules) != "planner_intermediate";
            auto r = bench::runPlan(job.rules, "box:6x3x2", "box:3x3x4", k, job.allocator, planner::Scheduler::Sync, seed, {}, general);
            const planner::RunStats& s = r->stats;
            const double ratio = r->lowerBound > 0 ? double(s.transfers) / double(r->lowerBound) : 0;
            std::printf("%9lld %-22s %10lld %10lld %12lld %12s %7s %8lld %9.3f%s\n", (long long)(36LL * k * k * k),
                        (std::string(job.rules).substr(8) + (general ? std::string(" / ") + job.allocator : "")).c_str(), (long long)s.creations,
                        (long long)s.deletions, (long long)s.transfers, general ? std::to_string(r->lowerBound).c_str() : "-",
                        general ? (std::to_string(ratio).substr(0, 4) + "x").c_str() : "-", (long long)s.rounds, s.seconds, s.complete ? "" : " NOT COMPLETE");
            csv << 36LL * k * k * k << ',' << job.rules << ',' << (general ? job.allocator : "") << ',' << s.creations << ',' << s.deletions << ',' << s.transfers
                << ',' << (general ? std::to_string(r->lowerBound) : "") << ',' << s.rounds << ',' << s.seconds << ',' << s.complete << '\n';
            const double n = 36.0 * k * k * k;
            if (!general) series["actions"].points.push_back({n, double(s.creations + s.deletions)});
            else {
                series[job.key].points.push_back({n, double(std::max<std::int64_t>(1, s.transfers))});
                if (std::string(job.allocator) == "gradient") series["bound"].points.push_back({n, double(std::max<std::int64_t>(1, r->lowerBound))});
            }
        }
    }
    std::ofstream(out + "/fig7.svg") << plot("actions vs ensemble size (6x3x2 -> 3x3x4)", "metamodules", "actions",
                                             {series["actions"], series["random"], series["gradient"], series["optimal"], series["bound"]}, true);

    // Every general system with every allocator (random only at 288 metamodules: it is slow).
    std::ofstream sys(out + "/systems.csv");
    sys << "metamodules,system,allocator,transfers,transfer_lower_bound,rounds,seconds,complete\n";
    std::printf("\nevery general system: transfers (rounds), 6x3x2 -> 3x3x4, sync, seed %llu\n", (unsigned long long)seed);
    std::printf("%9s %-22s %16s %16s %16s %12s\n", "metamod.", "system", "random", "gradient", "optimal", "lower bound");
    for (int k : {2, 4})
        for (const char* rules : {"planner_general1", "planner_general2", "planner_general3", "planner_general_lock2", "planner_general_lock3"}) {
            std::printf("%9d %-22s", 36 * k * k * k, std::string(rules).substr(8).c_str());
            std::int64_t bound = 0;
            for (const char* allocator : {"random", "gradient", "optimal"}) {
                if (k > 2 && std::string(allocator) == "random") {
                    std::printf(" %16s", "-");
                    continue;
                }
                auto r = bench::runPlan(rules, "box:6x3x2", "box:3x3x4", k, allocator, planner::Scheduler::Sync, seed, {}, true);
                const planner::RunStats& st = r->stats;
                bound = r->lowerBound;
                const std::string cell = std::to_string(st.transfers) + " (" + std::to_string(st.rounds) + ")" + (st.complete ? "" : "!");
                std::printf(" %16s", cell.c_str());
                sys << 36 * k * k * k << ',' << rules << ',' << allocator << ',' << st.transfers << ',' << r->lowerBound << ',' << st.rounds << ',' << st.seconds << ','
                    << st.complete << '\n';
            }
            std::printf(" %12lld\n", (long long)bound);
        }

    // Fig. 8: completion over time at 2304 metamodules (K = 4).
    std::ofstream csv8(out + "/fig8.csv");
    csv8 << "system,round,creation_completion,deletion_completion\n";
    std::vector<Series> curves;
    struct Curve {
        const char *rules, *allocator, *label, *colour;
    };
    for (const Curve& c : {Curve{"planner_intermediate", "random", "intermediate", "#3d6fb0"}, Curve{"planner_general1", "random", "general1 random", "#c03030"},
                           Curve{"planner_general1", "gradient", "general1 gradient", "#20a060"},
                           Curve{"planner_general1", "optimal", "general1 optimal", "#8040c0"}}) {
        Series create{std::string(c.label) + " create", c.colour, {}}, destroy{std::string(c.label) + " delete", c.colour, {}};
        std::int64_t toCreate = 1152, toDelete = 1152;
        planner::RunObserver observer;
        observer.roundEnd = [&](const planner::RunStats& s) {
            const double cr = 100.0 * double(s.creations) / double(toCreate), de = 100.0 * double(s.deletions) / double(toDelete);
            if (create.points.empty() || create.points.back().second != cr || destroy.points.back().second != de) {
                create.points.push_back({double(s.rounds), cr}), destroy.points.push_back({double(s.rounds), de});
                csv8 << c.label << ',' << s.rounds << ',' << cr << ',' << de << '\n';
            }
            return true;
        };
        bench::runPlan(c.rules, "box:6x3x2", "box:3x3x4", 4, c.allocator, planner::Scheduler::Sync, seed, observer, false);
        curves.push_back(create);
        destroy.colour = std::string(c.colour) + "\" stroke-dasharray=\"5,3";
        curves.push_back(destroy);
    }
    std::ofstream(out + "/fig8.svg") << plot("completion at 2304 metamodules (solid: creation, dashed: deletion)", "round", "% complete", curves, false);
    std::printf("wrote %s/fig7.csv, fig7.svg, fig8.csv, fig8.svg, systems.csv (\"!\": not complete)\n", out.c_str());
    return 0;
}
