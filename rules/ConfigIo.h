#pragma once
// Reading and writing configurations: canonical JSON for every system, ASCII art for 2D systems
// whose states have one-character names ('.' empty, one character per cell, first line = row 0).

#include "rules/Interpreter.h"

#include <nlohmann/json.hpp>
#include <string>

namespace holon::rules {

nlohmann::json configToJson(const Interpreter& in, const Configuration& c);
/// A cell state's fields by name ({"label": "P", "parent": "+x"}); empty for the vacuum.
nlohmann::json stateFields(const Model& model, CellValue v);
/// A lattice point as [x, y] or [x, y, z].
nlohmann::json pointJson(const Lattice& lattice, Vec v);
/// Throws InputError naming the offending cell or value. `inputsNamed`, if given, gets bit k set
/// for each input k the "inputs" object names (an empty list included: the input holds nowhere).
Configuration configFromJson(const Interpreter& in, const nlohmann::json& j, std::uint32_t* inputsNamed = nullptr);

/// Throws InputError when the lattice is 3D or a state has no one-character name.
std::string configToAscii(const Interpreter& in, const Configuration& c);
Configuration configFromAscii(const Interpreter& in, const std::string& text);
/// A per-cell mask in ASCII art: every character other than '.' and blanks marks a cell.
std::vector<bool> maskFromAscii(const Region& region, const std::string& text);

/// Reads a configuration from a file, JSON if it starts with '{', ASCII art otherwise (which
/// names no inputs: `inputsNamed` as for configFromJson).
Configuration readConfigFile(const Interpreter& in, const std::string& path, std::uint32_t* inputsNamed = nullptr);

}  // namespace holon::rules
