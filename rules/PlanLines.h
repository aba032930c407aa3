#pragma once
// Reading a run written as JSON Lines in holon plan --plan-out's format (holon hex --steps-out and
// holon roombots --out write it too; planner::planLine writes its step lines): a first line
// {"plan": "holon" | "run": KIND, "system", "source", "start": CONFIGURATION (with "offset" when
// the board reached below 0), ...}, then one line per rule instance fired, {"round", "rule",
// "cells": its pattern cells in order, "after": their states after it}, or a metamodule lost to a
// fault, {"round", "fault": "lose", "cells": [CELL]}. The one reader of the format, for holon
// replay and holon view: each line parsed and its shape checked, an error naming FILE:LINE.

#include "rules/Lattice.h"

#include <nlohmann/json.hpp>

#include <cstdint>
#include <istream>
#include <string>
#include <vector>

namespace holon::rules {

/// A lattice point [x, y] or [x, y, z] of integers within ±2^30 (beyond it a point lies outside
/// every region, and the sum of two would overflow); throws InputError naming `where`.
Vec pointFromJson(const nlohmann::json& j, const std::string& where);

struct PlanLine {
    std::int64_t round = 0;
    bool fault = false;      // a metamodule lost: its one cell empties
    std::string rule;        // the rule fired ("" for a fault)
    std::vector<Vec> cells;  // the cells, the start's offset added
    nlohmann::json json;     // the line as written ("cells", "after": one state per cell)
};

class PlanLineReader {
public:
    /// The longest line read: a 10^7-metamodule start configuration is about 300 MB.
    static constexpr std::size_t kMaxLineBytes = std::size_t{1} << 30;
    /// Reads the first line (InputError "PATH:1: ..." when it is not a JSON object).
    PlanLineReader(std::istream& in, std::string path);
    const nlohmann::json& head() const { return head_; }
    /// "plan", or the "run" the first line names ("hex", "roombots"), or "".
    std::string kind() const;
    /// The first line's start configuration (InputError when there is none).
    const nlohmann::json& start() const;
    /// The next step or fault, blank lines skipped; false at the end.
    bool next(PlanLine& line);
    /// "PATH:N" of the line read last, for messages.
    std::string where() const { return path_ + ":" + std::to_string(lineNo_); }
    int lineNumber() const { return lineNo_; }

private:
    nlohmann::json parse(const std::string& text) const;
    std::istream* in_;
    std::string path_;
    int lineNo_ = 1;
    nlohmann::json head_;
    Vec offset_;
    std::int64_t lastRound_ = 0;
    std::size_t coordinates_ = 0;  // of every cell: the start region's lattice's, else the first cell's
};

}  // namespace holon::rules
