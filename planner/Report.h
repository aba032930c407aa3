#pragma once
// What a plan run leaves behind: the plan as JSON Lines, a CSV time series of creation and
// deletion completion (seed 000 Fig. 8), SVG snapshots (2D; z-slices for 3D), summary.json, and a
// progress bar on a terminal.

#include "planner/Execution.h"

#include <fstream>
#include <memory>
#include <string>

namespace holon::planner {

struct ReportOptions {
    std::string outDir;   // summary.json, completion.csv, snapshot-*.svg; empty: none
    std::string planOut;  // JSON Lines; empty: none
    bool progressBar = false;
};

class Report {
public:
    Report(const Problem& problem, const Execution& execution, ReportOptions options);
    ~Report();
    void fired(std::int64_t anchor, int shape, const BoxEngine::Value* old);
    void roundEnd(const RunStats& stats);
    void finish(const RunStats& stats, std::int64_t transferLowerBound);

private:
    void snapshot(const std::string& label);
    const Problem* problem_;
    const Execution* execution_;
    ReportOptions options_;
    std::unique_ptr<std::ofstream> plan_, csv_;
    std::int64_t lastRound_ = -1, lastStep_ = 0;
    int nextQuarter_ = 1;
    double lastBar_ = -1;
};

/// An SVG picture of a configuration: 2D boards directly, 3D boards as a row of z-slices.
std::string drawBoard(const Problem& problem, const std::vector<BoxEngine::Value>& cells, const std::string& title);

}  // namespace holon::planner
