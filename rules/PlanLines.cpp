// The reader of plan-format JSON Lines (PlanLines.h). A line is parsed only after its nesting is
// checked (checkJsonText), so a hostile file cannot make the parser recurse, and as the other
// readers parse (a key given twice is refused); a line is read up to kMaxLineBytes, so /dev/zero
// ends in a message, not all of memory. Cells are read as bounded lattice points with the start's
// offset added, so callers index their cells directly.

#include "rules/PlanLines.h"

#include "rules/ConfigIo.h"
#include "rules/Error.h"

#include <algorithm>
#include <cstdlib>
#include <cstring>

namespace holon::rules {

Vec pointFromJson(const nlohmann::json& j, const std::string& where) {
    const auto small = [](const nlohmann::json& c) {
        return c.is_number_unsigned() ? c.get<std::uint64_t>() < (1u << 30) : c.is_number_integer() && std::abs(c.get<std::int64_t>()) < (1 << 30);
    };
    if (!j.is_array() || j.size() < 2 || j.size() > 3 || !std::all_of(j.begin(), j.end(), small))
        throw InputError(where + ": a cell is [x, y] or [x, y, z] of integers, found " + j.dump());
    return {j[0].get<int>(), j[1].get<int>(), j.size() == 3 ? j[2].get<int>() : 0};
}

namespace {

/// std::getline with a bound: false at the end of the input; InputError past kMaxLineBytes or at a
/// NUL byte (/dev/zero is refused at once).
bool boundedLine(std::istream& in, std::string& line, const std::string& where) {
    line.clear();
    char chunk[1 << 16];
    for (;;) {
        in.get(chunk, sizeof chunk, '\n');
        const auto got = static_cast<std::size_t>(in.gcount());
        if (std::memchr(chunk, '\0', got)) throw InputError(where + ": a NUL byte; a plan's lines are JSON text: is it the right file?");
        line.append(chunk, got);
        if (line.size() > PlanLineReader::kMaxLineBytes)
            throw InputError(where + ": a line longer than " + std::to_string(PlanLineReader::kMaxLineBytes >> 20) + " MiB; is it the right file?");
        if (in.eof()) return !line.empty();
        if (in.fail()) in.clear();  // an empty read: the next character is the newline
        if (in.peek() == '\n') {
            in.get();
            return true;
        }
    }
}

}  // namespace

PlanLineReader::PlanLineReader(std::istream& in, std::string path) : in_(&in), path_(std::move(path)) {
    std::string first;
    boundedLine(in, first, path_ + ":1");
    head_ = parse(first);
    if (!head_.is_object()) throw InputError(where() + ": expected a JSON object");
    if (head_.contains("start") && head_["start"].is_object() && head_["start"].contains("offset")) {
        offset_ = pointFromJson(head_["start"]["offset"], where() + ": offset");
        coordinates_ = head_["start"]["offset"].size();
    }
    // The start's region names its lattice, and with it the cells' dimension.
    if (head_.contains("start") && head_["start"].is_object() && head_["start"].contains("region") && head_["start"]["region"].is_string())
        coordinates_ = head_["start"]["region"].get<std::string>().rfind("cubic", 0) == 0 ? 3 : 2;
}

std::string PlanLineReader::kind() const {
    const auto text = [&](const char* key) { return head_.contains(key) && head_[key].is_string() ? head_[key].get<std::string>() : ""; };
    return text("plan") == "holon" ? "plan" : text("run");
}

const nlohmann::json& PlanLineReader::start() const {
    if (!head_.contains("start") || !head_["start"].is_object())
        throw InputError(path_ + ":1: the first line has no \"start\" configuration; write the file again with the holon command that made it");
    return head_["start"];
}

nlohmann::json PlanLineReader::parse(const std::string& text) const {
    try {
        return parseJsonOnceEach(text);
    } catch (const nlohmann::json::exception& e) {  // parse_error, and out_of_range for a number past a double
        throw InputError(where() + ": not a JSON line (" + jsonErrorText(e) + "); the file is cut short or was edited by hand: write it again");
    } catch (const InputError& e) {
        // A place in the line's one-line record is a column of this line: FILE:LINE:COL, not
        // "FILE:2: line 1, column 40" (a key given twice).
        const std::string what = e.what(), record = "line 1, column ";
        if (const auto colon = what.find(": "); what.rfind(record, 0) == 0 && colon != std::string::npos)
            throw InputError(where() + ":" + what.substr(record.size(), colon - record.size()) + what.substr(colon));
        throw InputError(where() + ": " + e.what());
    }
}

bool PlanLineReader::next(PlanLine& line) {
    std::string text;
    do {
        if (!boundedLine(*in_, text, path_ + ":" + std::to_string(lineNo_ + 1))) return false;
        ++lineNo_;
    } while (text.find_first_not_of(" \t\r") == std::string::npos);
    nlohmann::json j = parse(text);
    const bool fault = j.is_object() && j.contains("fault");
    if (fault && !(j["fault"] == "lose" && j.contains("round") && j["round"].is_number_integer() && j.contains("cells") && j["cells"].is_array() && j["cells"].size() == 1))
        throw InputError(where() + ": a fault must be {\"round\": R, \"fault\": \"lose\", \"cells\": [[x, y]]}");
    if (!fault && (!j.is_object() || !j.contains("round") || !j["round"].is_number_integer() || !j.contains("rule") || !j["rule"].is_string() || !j.contains("cells") ||
                   !j["cells"].is_array() || !j.contains("after") || !j["after"].is_array() || j["after"].size() != j["cells"].size()))
        throw InputError(where() + ": a step must be {\"round\": R, \"rule\": NAME, \"cells\": [[x, y], ...], \"after\": [{...}, ...]}, one state after per cell");
    // What holon writes, and nothing else: an edited file with rounds out of order, a key holon
    // never writes or a cell of another dimension was replayed as legal.
    for (const auto& [key, value] : j.items())
        if (key != "round" && key != "cells" && (fault ? key != "fault" : key != "rule" && key != "after" && key != "system" && key != "time"))
            throw InputError(where() + ": unknown key \"" + key + "\"; the file was edited by hand: write it again");
    line.round = j["round"].get<std::int64_t>();
    if (line.round < (fault ? 1 : 0) || line.round < lastRound_)
        throw InputError(where() + ": round " + std::to_string(line.round) + (line.round >= 0 && line.round < lastRound_ ? " after round " + std::to_string(lastRound_) : "") +
                         "; rounds count from " + (fault ? "1 for a loss (after that round)" : "0") + " and never go back");
    lastRound_ = line.round;
    line.fault = fault;
    line.rule = fault ? "" : j["rule"].get<std::string>();
    line.cells.clear();
    for (const auto& c : j["cells"]) {
        line.cells.push_back(pointFromJson(c, where()) + offset_);
        if (coordinates_ == 0) coordinates_ = c.size();
        if (c.size() != coordinates_) throw InputError(where() + ": cell " + c.dump() + " has " + std::to_string(c.size()) + " coordinates, the plan's cells " + std::to_string(coordinates_));
    }
    line.json = std::move(j);
    return true;
}

}  // namespace holon::rules
