// The ITF trace writer (https://apalache-mc.org/docs/adr/015adr-trace.html): a JSON object with
// "#meta", "vars" and "states", each state a record of the variables. A configuration's cells are
// the variable "cells", a map from positions ({"#tup": [x, y]}) to the state's fields by name;
// inputs, constant along a trace, are repeated in every state because ITF wants every variable in
// every state.

#include "rules/ItfWriter.h"

#include "rules/ConfigIo.h"

namespace holon::rules {

ItfWriter::ItfWriter(const Model& model, ItfHeader header, bool withInputs)
    : model_(&model), header_(std::move(header)), withInputs_(withInputs) {}

nlohmann::json ItfWriter::tuple(Vec v) const { return {{"#tup", pointJson(model_->lattice(), v)}}; }

nlohmann::json ItfWriter::entry(Vec at, CellValue v) const { return {tuple(at), stateFields(*model_, v)}; }

void ItfWriter::append(nlohmann::json meta, nlohmann::json map, const nlohmann::json& inputs) {
    nlohmann::json state{{"#meta", std::move(meta)}, {"cells", {{"#map", std::move(map)}}}};
    if (withInputs_) state["inputs"] = inputs;
    states_.push_back(std::move(state));
}

nlohmann::json ItfWriter::json(std::optional<int> loop) const {
    nlohmann::json meta{{"format", "ITF"},
                        {"format-description", "https://apalache-mc.org/docs/adr/015adr-trace.html"},
                        {"source", header_.source},
                        {"system", header_.system},
                        {"property", header_.property},
                        {"description", header_.description}};
    if (!header_.region.empty()) meta["region"] = header_.region;
    nlohmann::json itf{{"#meta", meta}, {"vars", withInputs_ ? nlohmann::json{"cells", "inputs"} : nlohmann::json{"cells"}}, {"states", states_}};
    if (loop) itf["loop"] = *loop;
    return itf;
}

}  // namespace holon::rules
