// The reader of plan-format JSON Lines (PlanLines.h). A line is parsed only after its nesting is
// checked (checkJsonDepth), so a hostile file cannot make the parser recurse; cells are read as
// bounded lattice points with the start's offset added, so callers index their cells directly.

#include "rules/PlanLines.h"

#include "rules/ConfigIo.h"
#include "rules/Error.h"

#include <algorithm>
#include <cstdlib>

namespace holon::rules {

Vec pointFromJson(const nlohmann::json& j, const std::string& where) {
    const auto small = [](const nlohmann::json& c) {
        return c.is_number_unsigned() ? c.get<std::uint64_t>() < (1u << 30) : c.is_number_integer() && std::abs(c.get<std::int64_t>()) < (1 << 30);
    };
    if (!j.is_array() || j.size() < 2 || j.size() > 3 || !std::all_of(j.begin(), j.end(), small))
        throw InputError(where + ": a cell is [x, y] or [x, y, z] of integers, found " + j.dump());
    return {j[0].get<int>(), j[1].get<int>(), j.size() == 3 ? j[2].get<int>() : 0};
}

PlanLineReader::PlanLineReader(std::istream& in, std::string path) : in_(&in), path_(std::move(path)) {
    std::string first;
    std::getline(in, first);
    head_ = parse(first);
    if (!head_.is_object()) throw InputError(where() + ": expected a JSON object");
    if (head_.contains("start") && head_["start"].is_object() && head_["start"].contains("offset"))
        offset_ = pointFromJson(head_["start"]["offset"], where() + ": offset");
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
        checkJsonDepth(text);
        return nlohmann::json::parse(text);
    } catch (const nlohmann::json::exception& e) {  // parse_error, and out_of_range for a number past a double
        throw InputError(where() + ": not a JSON line (" + jsonErrorText(e) + "); the file is cut short or was edited by hand: write it again");
    } catch (const InputError& e) {
        throw InputError(where() + ": " + e.what());
    }
}

bool PlanLineReader::next(PlanLine& line) {
    std::string text;
    do {
        if (!std::getline(*in_, text)) return false;
        ++lineNo_;
    } while (text.find_first_not_of(" \t\r") == std::string::npos);
    nlohmann::json j = parse(text);
    const bool fault = j.is_object() && j.contains("fault");
    if (fault && !(j["fault"] == "lose" && j.contains("round") && j["round"].is_number_integer() && j.contains("cells") && j["cells"].is_array() && j["cells"].size() == 1))
        throw InputError(where() + ": a fault must be {\"round\": R, \"fault\": \"lose\", \"cells\": [[x, y]]}");
    if (!fault && (!j.is_object() || !j.contains("round") || !j["round"].is_number_integer() || !j.contains("rule") || !j["rule"].is_string() || !j.contains("cells") ||
                   !j["cells"].is_array() || !j.contains("after") || !j["after"].is_array() || j["after"].size() != j["cells"].size()))
        throw InputError(where() + ": a step must be {\"round\": R, \"rule\": NAME, \"cells\": [[x, y], ...], \"after\": [{...}, ...]}, one state after per cell");
    line.round = j["round"].get<std::int64_t>();
    line.fault = fault;
    line.rule = fault ? "" : j["rule"].get<std::string>();
    line.cells.clear();
    for (const auto& c : j["cells"]) line.cells.push_back(pointFromJson(c, where()) + offset_);
    line.json = std::move(j);
    return true;
}

}  // namespace holon::rules
