#pragma once
// The one writer of ITF traces (Apalache's Informal Trace Format): the checker's counterexamples
// and the planner monitor's violations both go through it, and rules/ConfigIo reads either back.

#include "rules/Model.h"

#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

namespace holon::rules {

/// What a trace's "#meta" says about the whole trace; an empty region is left out.
struct ItfHeader {
    std::string source, system, region, property, description;
};

class ItfWriter {
public:
    /// `withInputs`: every state carries the inputs as a second variable, "inputs".
    ItfWriter(const Model& model, ItfHeader header, bool withInputs);
    /// {"#tup": [x, y]}: a cell's position as ITF writes it.
    nlohmann::json tuple(Vec v) const;
    /// Appends a state: its "#meta", and its cells: cells(f) calls f(position, value) for every
    /// occupied cell. `inputs`: {NAME: {"#set": [tuple, ...]}} when the trace has inputs.
    template <class Cells>
    void state(nlohmann::json meta, Cells&& cells, const nlohmann::json& inputs = nullptr) {
        nlohmann::json map = nlohmann::json::array();
        cells([&](Vec at, CellValue v) { map.push_back(entry(at, v)); });
        append(std::move(meta), std::move(map), inputs);
    }
    /// The trace; `loop`: the state a lasso's last state returns to.
    nlohmann::json json(std::optional<int> loop = std::nullopt) const;

private:
    void append(nlohmann::json meta, nlohmann::json map, const nlohmann::json& inputs);
    nlohmann::json entry(Vec at, CellValue v) const;  // [{"#tup": at}, {FIELD: VALUE, ...}]
    const Model* model_;
    ItfHeader header_;
    bool withInputs_;
    nlohmann::json states_ = nlohmann::json::array();
};

}  // namespace holon::rules
