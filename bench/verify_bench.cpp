// Proof-obligation timing (issue: Z3 proofs): seconds per planner lemma (seed 000 §IV-C) for the
// U/P/F planner over intermediate (or --system, e.g. planner_general1), per region, and how it grows. Each cell is the median of the
// runs; "unknown" means the per-obligation timeout was hit.
// Then --reach (Spacer, every reachable state): Progress of the planners over general2 and
// general3 on square:3x2 from examples/verify's start (two creations and a deletion).
// Usage: verify_bench [--runs N] [--timeout S] [--regions square:2x2,square:3x3,...] [--system NAME]

#include "checker/Obligations.h"
#include "rules/ConfigIo.h"
#include "rules/Library.h"
#include "rules/TextFile.h"

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <sstream>
#include <string>
#include <vector>

using namespace holon;

int main(int argc, char** argv) {
    int runs = 3;
    double timeout = 60;
    std::string systemName = "planner_intermediate";
    std::string regions = "square:3x3,square:4x3,square:4x4,square:5x5,hex:r1,hex:r2,cubic:2x2x2,cubic:3x2x2,cubic:3x3x2,cubic:3x3x3";
    for (int i = 1; i + 1 < argc; i += 2) {
        const std::string flag = argv[i];
        if (flag == "--runs") runs = std::atoi(argv[i + 1]);
        else if (flag == "--timeout") timeout = std::atof(argv[i + 1]);
        else if (flag == "--regions") regions = argv[i + 1];
        else if (flag == "--system") systemName = argv[i + 1];
    }
    const rules::System system = rules::librarySystem(systemName);
    std::printf("verify benchmark: %s, median of %d runs, timeout %.0f s per obligation\n", systemName.c_str(), runs, timeout);
    std::printf("%-14s %6s %14s %14s %14s %10s\n", "region", "cells", "safety s", "termination s", "progress s", "total s");
    std::istringstream list(regions);
    for (std::string spec; std::getline(list, spec, ',');) {
        const rules::Region region = rules::Region::parse(spec);
        const rules::Model model(system, region.lattice());
        std::vector<std::vector<double>> seconds(3);
        std::vector<std::string> verdict(3, "proved");
        for (int r = 0; r < runs; ++r) {
            checker::VerifyOptions o;
            o.timeoutSeconds = timeout;
            const auto report = checker::verify(model, region, o);
            for (int k = 0; k < 3; ++k) {
                seconds[k].push_back(report.obligations[k].result.seconds);
                if (report.obligations[k].result.verdict != checker::Verdict::Holds) verdict[k] = checker::proofVerdictName(report.obligations[k].result.verdict);
            }
        }
        double total = 0;
        std::string cells[3];
        for (int k = 0; k < 3; ++k) {
            std::sort(seconds[k].begin(), seconds[k].end());
            const double m = seconds[k][seconds[k].size() / 2];
            total += m;
            char buf[64];
            if (verdict[k] == "proved") std::snprintf(buf, sizeof buf, "%.2f", m);
            else std::snprintf(buf, sizeof buf, "%s %.1f", verdict[k] == "counterexample" ? "refuted" : verdict[k].c_str(), m);
            cells[k] = buf;
        }
        std::printf("%-14s %6d %14s %14s %14s %10.2f\n", spec.c_str(), region.size(), cells[0].c_str(), cells[1].c_str(), cells[2].c_str(), total);
    }

    std::printf("\n--reach on square:3x2 from examples/verify/general_start.json, median of %d runs\n", runs);
    std::printf("%-22s %16s %10s\n", "system", "progress@reach s", "clauses");
    const std::string examples = std::string(HOLON_SOURCE_DIR) + "/examples/verify/";
    for (const char* stem : {"planner_general2", "planner_general3"}) {
        const rules::System planner = rules::librarySystem(stem);
        const rules::Region region = rules::Region::parse("square:3x2");
        const rules::Model model(planner, region.lattice());
        const rules::Interpreter in(model, region);
        rules::Configuration start = rules::readConfigFile(in, examples + "general_start.json");
        const auto mask = rules::maskFromAscii(region, rules::readTextFile(examples + "general_target.txt"));
        for (int i = 0; i < region.size(); ++i) start.inputs[i] = mask[i] ? 1u : 0u;
        std::vector<double> seconds;
        std::string verdict = "proved", clauses;
        for (int r = 0; r < runs; ++r) {
            checker::VerifyOptions o;
            o.timeoutSeconds = timeout;
            o.properties = {"progress"};
            o.reach = true;
            o.initial = {start};
            const auto report = checker::verify(model, region, o);
            const auto& reach = report.obligations.back().result;
            seconds.push_back(reach.seconds);
            if (reach.verdict != checker::Verdict::Holds) verdict = checker::proofVerdictName(reach.verdict);
            else clauses = std::to_string(reach.witness["inductive_invariant"].size());
        }
        std::sort(seconds.begin(), seconds.end());
        char cell[64];
        std::snprintf(cell, sizeof cell, verdict == "proved" ? "%.2f" : "%.0f %s", seconds[seconds.size() / 2], verdict == "proved" ? "" : verdict.c_str());
        std::printf("%-22s %16s %10s\n", stem, cell, clauses.c_str());
    }
    return 0;
}
