#pragma once
// Counterexample traces: a sequence of configurations, each reached by one rule instance, written
// in Apalache's Informal Trace Format and replayable through the reference interpreter.

#include "checker/Explorer.h"
#include "rules/Interpreter.h"

#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

namespace holon::checker {

/// "1 step", "3 steps": the length of a trace, for messages.
inline std::string stepCount(std::size_t n) { return std::to_string(n) + (n == 1 ? " step" : " steps"); }

struct Trace {
    struct Step {
        std::vector<CellValue> cells;
        int placed = -1;  // the engine instance that led here; -1 for the first state
    };
    std::vector<Step> steps;
    std::optional<int> loop;  // index the last state loops back to (lassos: livelocks)
    std::string property, description;
    /// Cells to point out in the last state (a blocking cell, the cut-off part).
    std::vector<int> marked;
};

/// The BFS-tree path to a state, as a trace.
Trace traceTo(const Explorer& explorer, StateId id);
/// The BFS-tree path to `from`, then the step along its edge `edge` (an index into the explorer's
/// successor rows): the witness of a property, or of a difference, that lives on one step.
Trace traceWithStep(const Explorer& explorer, StateId from, std::uint64_t edge);
/// A trace along a list of states, choosing for each step an instance that leads to the next.
Trace traceAlong(const Explorer& explorer, const std::vector<StateId>& states);

/// ITF: {"#meta", "vars": ["cells"], "states": [{"#meta": {"index", "rule", "cells"}, "cells": {"#map": ...}}], "loop"},
/// the instance's cells in pattern order; the last state's "#meta" also has "marked" when the trace marks cells;
/// a system with inputs also has the variable "inputs", the engine's, by name: {"target": {"#set": [...]}}.
nlohmann::json toItf(const Trace& trace, const rules::Engine& engine, const std::string& source);
/// A trace as configurations, for --json: each state with the rule that led to it.
nlohmann::json traceJson(const Trace& trace, const rules::Engine& engine, const rules::Interpreter& in);
/// Replays every step through the reference interpreter: true when each step is an enabled instance
/// whose successor is exactly the next state (and the first state is legal).
bool replay(const Trace& trace, const rules::Engine& engine, const rules::Interpreter& in, std::string* why = nullptr);

}  // namespace holon::checker
