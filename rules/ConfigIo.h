#pragma once
// Reading and writing configurations: canonical JSON for every system, ASCII art for 2D systems
// whose states have one-character names ('.' empty, one character per cell, first line = row 0).

#include "rules/Interpreter.h"

#include <nlohmann/json.hpp>
#include <optional>
#include <ostream>
#include <string>

namespace holon::rules {

/// A configuration as holon's canonical JSON: "cells" (each its fields and "at"), "inputs" (per
/// input, its cells), "region", "system", and "offset" unless it is null; written compactly, a
/// cell at a time (a configuration of millions of cells never stands in memory as a document).
/// The text is the library's dump of the same document.
void writeConfigJson(std::ostream& out, const Interpreter& in, const Configuration& c, const nlohmann::json& offset = nullptr);
/// The same as a document (writeConfigJson read back).
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
/// A picture smaller than the region is its top-left corner, the rest empty (a small start on a
/// large region needs no rows of dots); one larger is refused.
Configuration configFromAscii(const Interpreter& in, const std::string& text);
/// A per-cell mask in ASCII art: every character other than '.' and blanks marks a cell.
std::vector<bool> maskFromAscii(const Region& region, const std::string& text);
/// For a picture smaller than the region, what it leaves out ("2 of its 16 rows, 5 of its 16
/// columns"), so the reader can say so; "" when it draws the whole region, or is not a picture.
std::string pictureShortfall(const Region& region, const std::string& text);

/// `text` without a leading UTF-8 byte-order mark (some editors write one; it made a JSON file
/// read as ASCII art, and a picture's first row one character too wide).
std::string withoutBom(const std::string& text);

/// Parses JSON whose objects name each key once: a key given twice throws InputError (the
/// library keeps the last one silently: a configuration with two "cells" lists lost the first).
/// The text is checked first (checkJsonText).
nlohmann::json parseJsonOnceEach(const std::string& text);

/// A JSON library error as a user reads it: its text without the "[json.exception.parse_error.101] "
/// tag ("parse error at line 1, column 2: syntax error ...").
std::string jsonErrorText(const std::exception& e);

/// Refuses JSON nested deeper than any configuration or trace, and a NUL byte (the parser takes it
/// for the end and drops the rest), with InputError naming the line and column, before a parser
/// recurses into the text.
void checkJsonText(const std::string& text);

/// True for an ITF trace (holon's --trace-out: an object with "states"), false for a configuration.
bool isItfTrace(const nlohmann::json& j);
/// The states of an ITF trace, a non-empty array (else InputError).
const nlohmann::json& itfStates(const nlohmann::json& itf);
/// One state of an ITF trace as a configuration's JSON, ITF's encodings (#map, #tup, #set,
/// #bigint) decoded: {"cells": [{"at": [x, y], FIELD: VALUE, ...}, ...], "inputs": {NAME: [[x, y],
/// ...]}}. The one walker of ITF states (configFromItf, holon view); InputError names the fix.
nlohmann::json itfStateJson(const nlohmann::json& state);
/// State `index` of an ITF trace (the last when none is given) with the inputs it carries: each
/// state's "cells" is {"#map": [[{"#tup": [x, y]}, {FIELD: VALUE, ...}], ...]} and its "inputs"
/// {NAME: {"#set": [{"#tup": [x, y]}, ...]}}. Throws InputError naming the state and the fix.
Configuration configFromItf(const Interpreter& in, const nlohmann::json& itf, std::optional<int> index, std::uint32_t* inputsNamed = nullptr);

/// A configuration file's text, read once: `spec` is FILE, or FILE#N for state N of an ITF trace.
/// Everything taken from the file (the configuration, the names it gives, a picture's shortfall)
/// comes from this text: a pipe or FIFO can be read only once.
struct ConfigText {
    std::string spec, path, text;
    std::optional<int> index;
};
ConfigText readConfigText(const std::string& spec);

/// Reads a configuration from a file: an ITF trace (`FILE#N` picks state N, the last by default),
/// JSON if it starts with '{', ASCII art otherwise (which names no inputs: `inputsNamed` as for
/// configFromJson).
Configuration readConfigFile(const Interpreter& in, const std::string& spec, std::uint32_t* inputsNamed = nullptr);
/// The same for a file already read.
Configuration configFromText(const Interpreter& in, const ConfigText& file, std::uint32_t* inputsNamed = nullptr);
/// The same for text already read (`path` only names it in messages).
Configuration configFromText(const Interpreter& in, const std::string& text, std::optional<int> index = std::nullopt,
                             std::uint32_t* inputsNamed = nullptr, const std::string& path = "the configuration");

}  // namespace holon::rules
