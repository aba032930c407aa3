#pragma once
// What a plan run leaves behind: the plan as JSON Lines, a CSV time series of creation and
// deletion completion (seed 000 Fig. 8), SVG snapshots (2D; z-slices for 3D), summary.json, and a
// progress bar on a terminal. Every file goes through the checked writer (rules/OutputFile.h):
// the plan and the CSV grow in temporaries renamed into place at finish(), so a run that fails or
// is interrupted never leaves a half-written file.

#include "planner/Execution.h"
#include "rules/Interpreter.h"
#include "rules/OutputFile.h"

#include <nlohmann/json.hpp>

#include <functional>
#include <optional>
#include <string>
#include <vector>

namespace holon::planner {

struct ReportOptions {
    std::string outDir;   // summary.json, completion.csv, snapshot-*.svg; empty: none
    std::string planOut;  // JSON Lines; empty: none
    /// How the caller names outDir and planOut in messages (its command-line options).
    std::string outOption, planOutOption;
    bool progressBar = false;
};

/// A run's figures, why it stopped, and the first 20 cells short of its goal with what each waits
/// on: summary.json, and what plan --json prints, so the two have the same keys.
nlohmann::json runSummary(const Problem& problem, const Execution& execution, const RunStats& stats, std::int64_t transferLowerBound);

class Report {
public:
    /// The files a run writes into ReportOptions::outDir (patterns, for rules::prepareOutputDir):
    /// any other file there may be another output's.
    static const std::vector<std::string>& outDirFiles();
    /// Creates the output folder and starts the files; a path that cannot be written throws
    /// InputError here, before the run.
    Report(const Problem& problem, const Execution& execution, ReportOptions options);
    ~Report();
    void fired(std::int64_t anchor, int shape, const BoxEngine::Value* old);
    void roundEnd(const RunStats& stats);
    /// A metamodule lost to an injected fault: a "fault" line in the plan (holon replay empties the cell).
    void lost(std::int64_t cell);
    /// An entry summary.json gets besides the run's figures (the system, the faults injected).
    void addSummary(const std::string& key, nlohmann::json value) { extra_[key] = std::move(value); }
    /// Writes the last snapshot and summary.json (with why the run stopped: "interrupted" for a
    /// signal) and commits the plan and the CSV as complete files.
    void finish(const RunStats& stats, std::int64_t transferLowerBound);
    /// Writes that failed once the run had started (a full disk), each with its reason. They do
    /// not stop the run: the caller prints its summary first, then reports them.
    const std::vector<std::string>& writeErrors() const { return errors_; }

private:
    void snapshot(const std::string& label);
    void attempt(const std::function<void()>& write);
    const Problem* problem_;
    const Execution* execution_;
    ReportOptions options_;
    std::optional<rules::OutputStream> plan_, csv_;
    std::vector<std::string> errors_;
    nlohmann::json extra_ = nlohmann::json::object();
    std::int64_t lastRound_ = -1, lastStep_ = 0;
    int nextQuarter_ = 1;
    double lastBar_ = -1;
};

/// A configuration on the planner's board as the reference interpreter sees it: on the box region
/// square:WxH or cubic:WxHxD that holds the board, target input included; boards reaching below 0
/// are shifted by `shift` into the region. For what the interpreter judges (invariants after a
/// fault, the rule a stuck cell waits on) and for writeConfiguration.
class BoardConfiguration {
public:
    BoardConfiguration(const Problem& problem, const std::vector<BoxEngine::Value>& cells);
    BoardConfiguration(const BoardConfiguration&) = delete;
    BoardConfiguration& operator=(const BoardConfiguration&) = delete;
    const rules::Interpreter& interpreter() const { return interpreter_; }
    const rules::Configuration& configuration() const { return configuration_; }
    /// The region position of a board point.
    Vec position(Vec p) const { return p + shift_; }
    Vec shift() const { return shift_; }

private:
    Vec shift_;
    rules::Region region_;
    rules::Interpreter interpreter_;
    rules::Configuration configuration_;
};

/// One step line of a plan (holon plan --plan-out; holon hex --steps-out adds the system):
/// {"round", "rule", "cells": its pattern cells in order, "after": their states in `cells`, after
/// the instance of `shape` at `anchor` fired ({} for an empty cell)}. rules/StepLines reads it.
nlohmann::json planLine(const BoxEngine& engine, std::int64_t round, std::int64_t anchor, int shape, const BoxEngine::Value* cells);

/// A configuration on the planner's board, with the target input, as holon's canonical JSON
/// (rules::configToJson) on the box region square:WxH or cubic:WxHxD that holds the board, so
/// `holon check --from` reads it. A board that does not start at the origin is shifted into the
/// region and the shift is recorded as "offset".
void writeConfiguration(std::ostream& out, const Problem& problem, const std::vector<BoxEngine::Value>& cells);

/// Board cells whose state the goal does not accept yet (at most `limit`, in board order) and how
/// many there are in all: where a run that stopped short is stuck.
std::pair<std::vector<std::int64_t>, std::int64_t> cellsShortOfGoal(const Execution& execution, std::size_t limit);

/// An SVG picture of a configuration with a legend, oriented as the checker's pictures (y down the
/// page): 2D boards directly, 3D boards as every z slice, in rows of up to eight.
std::string drawBoard(const Problem& problem, const std::vector<BoxEngine::Value>& cells, const std::string& title);

}  // namespace holon::planner
