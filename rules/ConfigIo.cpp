// Configuration formats. JSON lists the occupied cells in region order with every present field by
// name (directions by the lattice's direction names), and the cells of each input; it is canonical:
// one configuration has one text. ASCII art draws square regions row by row and hex regions as
// offset rows (row r indented by |r| spaces, cells separated by a space) so the picture looks like
// the lattice. An ITF trace (checker/Trace.cpp writes them) is read back one state at a time, so a
// counterexample can be explored again from any of its states. Messages quote at most a short
// excerpt of a JSON value, and JSON nested deeper than any configuration is refused before it is
// parsed (serialising it for a message, or reading it, would recurse once per level).

#include "rules/ConfigIo.h"

#include "rules/Error.h"
#include "rules/Escape.h"
#include "rules/OutputFile.h"
#include "rules/Parameter.h"
#include "rules/Picture.h"
#include "rules/StopSignals.h"
#include "rules/TextFile.h"

#include <algorithm>
#include <filesystem>
#include <sstream>
#include <unordered_set>

namespace holon::rules {

namespace {

nlohmann::json position(const Region& region, Vec v) { return pointJson(region.lattice(), v); }

/// A JSON value, or a name read from one, as a message quotes it.
std::string quote(const nlohmann::json& v) { return excerpt(v.dump(-1, ' ', false, nlohmann::json::error_handler_t::replace)); }
std::string quote(const std::string& name) { return excerpt(name); }

/// The cells of each ASCII row, in order: square rows are x = 0..W-1; hex rows are the cells of
/// row r from west to east.
std::vector<std::vector<int>> asciiRows(const Region& region) {
    const Lattice& lattice = region.lattice();
    if (lattice.dimension() == 3) throw InputError("ASCII art is for 2D regions; write 3D configurations as JSON");
    std::vector<std::vector<int>> rows(region.extent().y);
    for (int i = 0; i < region.size(); ++i) rows[region.cell(i).y - region.lower().y].push_back(i);
    for (auto& row : rows) std::sort(row.begin(), row.end(), [&](int a, int b) { return region.cell(a).x < region.cell(b).x; });
    return rows;
}

std::vector<std::string> rowTokens(const Region& region, const std::string& line) {
    std::vector<std::string> tokens;
    if (region.lattice().kind() == LatticeKind::Hex2D) {
        std::istringstream in(line);
        for (std::string t; in >> t;)
            for (char ch : t) tokens.push_back(std::string(1, ch));
    } else {
        for (char ch : line) tokens.push_back(std::string(1, ch == ' ' ? '.' : ch));
    }
    return tokens;
}

}  // namespace

std::string withoutBom(const std::string& text) { return text.rfind("\xEF\xBB\xBF", 0) == 0 ? text.substr(3) : text; }

namespace {

/// The parse as a SAX pass that builds the value (the library's own builder), checks that every
/// object names each key once, and reads the job's deadline and the signal catcher every 2^16
/// values. The library's callback parser would check the keys too, but it looks for discarded
/// values among the parent's elements at the end of every object: quadratic in a list of cells (a
/// 160,000-cell configuration took 11 s to read, a million cells over two minutes). A key pass
/// before the library's parse cost a second lexing of the text, and neither could be stopped: a
/// 162 MB plan's start line took 6 s to read after --timeout 0.5.
class CheckedParse {
public:
    using json = nlohmann::json;
    /// The text as the parser reads it, a character at a time: each step records how far the
    /// parser has read, so that a repeated key can be given its line and column (the SAX
    /// callbacks are given no position).
    class Reading {
    public:
        using iterator_category = std::input_iterator_tag;
        using value_type = char;
        using difference_type = std::ptrdiff_t;
        using pointer = const char*;
        using reference = const char&;
        Reading(const char* at, const char** read) : at_(at), read_(read) {}
        reference operator*() const { return *at_; }
        Reading& operator++() { return *read_ = ++at_, *this; }
        bool operator==(const Reading& other) const { return at_ == other.at_; }
        bool operator!=(const Reading& other) const { return at_ != other.at_; }

    private:
        const char* at_;
        const char** read_;
    };

    CheckedParse(json& result, const std::string& text) : build_(result), text_(&text), read_(text.data()) {}
    Reading begin() { return {text_->data(), &read_}; }
    Reading end() { return {text_->data() + text_->size(), &read_}; }
    bool null() { return poll(), build_.null(); }
    bool boolean(bool b) { return poll(), build_.boolean(b); }
    bool number_integer(json::number_integer_t n) { return poll(), build_.number_integer(n); }
    bool number_unsigned(json::number_unsigned_t n) { return poll(), build_.number_unsigned(n); }
    bool number_float(json::number_float_t n, const json::string_t& text) { return poll(), build_.number_float(n, text); }
    bool string(json::string_t& v) { return poll(), build_.string(v); }
    bool binary(json::binary_t& v) { return poll(), build_.binary(v); }
    // Containers count too: a 60 MB file of [] and {} held no other value, and ran 3 s past the
    // deadline and a signal (robustness audit 6).
    bool start_object(std::size_t n) { return poll(), open_.emplace_back(), build_.start_object(n); }
    bool end_object() { return open_.pop_back(), build_.end_object(); }
    bool start_array(std::size_t n) { return poll(), build_.start_array(n); }
    bool end_array() { return build_.end_array(); }
    bool key(json::string_t& key) {
        poll();
        // A set: one object of a 64 MiB file may have a million keys.
        if (!open_.back().insert(key).second)
            throw InputError(keyPlace() + "the key \"" + excerpt(key, 60) + "\" appears twice in one object; give each key once");
        return build_.key(key);
    }
    // A template as the builder's is: it throws `e` as its own type (parse_error, with its byte).
    template <class Exception>
    bool parse_error(std::size_t at, const std::string& token, const Exception& e) {
        return build_.parse_error(at, token, e);
    }

private:
    void poll() {
        if (++values_ % (1u << 16) == 0) StopSignals::checkJob("reading JSON");
    }
    /// "line L, column C: " of the key just read: the parser has read up to its closing quote.
    std::string keyPlace() const {
        const char* const text = text_->data();
        std::size_t at = static_cast<std::size_t>(read_ - text);
        at = at > 0 ? at - 1 : 0;  // the closing quote
        while (at > 0 && !(text[at - 1] == '"' && (at < 2 || text[at - 2] != '\\'))) --at;
        at = at > 0 ? at - 1 : 0;  // the opening quote
        const std::size_t lineStart = text_->rfind('\n', at), from = lineStart == std::string::npos ? 0 : lineStart + 1;
        const auto line = 1 + std::count(text, text + at, '\n');
        // Columns count characters, not bytes: a UTF-8 continuation byte is 10xxxxxx.
        const auto column = 1 + std::count_if(text + from, text + at, [](char c) { return (static_cast<unsigned char>(c) & 0xC0) != 0x80; });
        return "line " + std::to_string(line) + ", column " + std::to_string(column) + ": ";
    }
    // The library's value builder: not in its documented API, but the one json::parse uses.
    nlohmann::detail::json_sax_dom_parser<json> build_;
    std::vector<std::unordered_set<std::string>> open_;  // the keys of each open object, innermost last
    std::uint32_t values_ = 0;
    const std::string* text_;
    const char* read_;  // how far the parser has read (Reading)
};

}  // namespace

nlohmann::json parseJsonOnceEach(const std::string& text) {
    checkJsonText(text);
    nlohmann::json result;
    CheckedParse parse(result, text);
    nlohmann::json::sax_parse(parse.begin(), parse.end(), &parse);
    return result;
}

std::string jsonErrorText(const std::exception& e) {
    const std::string what = e.what();
    const auto tag = what.rfind("[json.exception.", 0) == 0 ? what.find("] ") : std::string::npos;
    return tag == std::string::npos ? what : what.substr(tag + 2);
}

void checkJsonText(const std::string& text) {
    int depth = 0, line = 1;
    std::size_t lineStart = 0;
    bool inString = false;
    for (std::size_t i = 0; i < text.size(); ++i) {
        const char c = text[i];
        if (inString) {
            if (c == '\\') ++i;
            else if (c == '"') inString = false;
        } else if (c == '"') {
            inString = true;
        } else if (c == '[' || c == '{') {
            if (++depth > kMaxJsonDepth)
                throw InputError("line " + std::to_string(line) + ", column " + std::to_string(i - lineStart + 1) + ": JSON nested deeper than " +
                                 std::to_string(kMaxJsonDepth) + " levels; a configuration or a trace is at most 6 deep");
        } else if (c == ']' || c == '}') {
            --depth;
        } else if (c == '\n') {
            ++line, lineStart = i + 1;
        }
        // The JSON library reads a NUL as the end of the input: what follows was silently dropped.
        if (c == '\0')
            throw InputError("line " + std::to_string(line) + ", column " + std::to_string(i - lineStart + 1) + ": a NUL byte; JSON text has none: is it the right file?");
    }
}

nlohmann::json stateFields(const Model& model, CellValue v) {
    nlohmann::json record = nlohmann::json::object();
    if (v == 0) return record;
    const auto& fields = model.alphabet().fields(v);
    for (std::size_t f = 0; f < fields.size(); ++f) {
        const Field& field = model.system().fields[f];
        // An unconditional pointer that points nowhere is written "none", so a reader sees every
        // field the state has; a conditional field that is off is left out.
        if (fields[f] == kAbsent) {
            if (field.kind == FieldKind::Dir && field.whenField < 0) record[field.name] = "none";
            continue;
        }
        if (field.kind == FieldKind::Enum) record[field.name] = field.values[fields[f]];
        else if (field.kind == FieldKind::Dir) record[field.name] = model.lattice().directionName(fields[f]);
        else record[field.name] = fields[f];
    }
    return record;
}

nlohmann::json pointJson(const Lattice& lattice, Vec v) {
    if (lattice.dimension() == 3) return {v.x, v.y, v.z};
    return {v.x, v.y};
}

namespace {

/// One occupied cell as a configuration lists it: its fields and "at".
nlohmann::json cellRecord(const Model& model, const Region& region, int i, CellValue v) {
    nlohmann::json cell = stateFields(model, v);
    cell["at"] = position(region, region.cell(i));
    return cell;
}

}  // namespace

void writeConfigJson(std::ostream& out, const Interpreter& in, const Configuration& c, const nlohmann::json& offset) {
    // Written a cell at a time: the document of a 10^6-cell plan took gigabytes in memory (and an
    // allocation failing inside the JSON library ended holon). Keys in the order the library dumps
    // them (cells, inputs, offset, region, system), so a document read back dumps the same text.
    const Region& region = in.region();
    const Model& model = in.model();
    const System& system = model.system();
    out << "{\"cells\":[";
    bool first = true;
    for (int i = 0; i < region.size(); ++i)
        if (c.cells[i]) out << (first ? "" : ",") << cellRecord(model, region, i, c.cells[i]).dump(), first = false;
    out << ']';
    if (!system.inputs.empty()) {
        std::vector<std::size_t> order(system.inputs.size());
        for (std::size_t k = 0; k < order.size(); ++k) order[k] = k;
        std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return system.inputs[a] < system.inputs[b]; });
        out << ",\"inputs\":{";
        for (std::size_t n = 0; n < order.size(); ++n) {
            const std::size_t k = order[n];
            out << (n ? "," : "") << nlohmann::json(system.inputs[k]).dump() << ":[";
            bool firstCell = true;
            for (int i = 0; i < region.size(); ++i)
                if ((c.inputs[i] >> k) & 1u) out << (firstCell ? "" : ",") << position(region, region.cell(i)).dump(), firstCell = false;
            out << ']';
        }
        out << '}';
    }
    if (!offset.is_null()) out << ",\"offset\":" << offset.dump();
    out << ",\"region\":" << nlohmann::json(region.spec()).dump() << ",\"system\":" << nlohmann::json(system.name).dump() << '}';
}

// One writer of the format: the document is the streamed text read back (configurations made
// this way are trace states and table rows, small).
nlohmann::json configToJson(const Interpreter& in, const Configuration& c) {
    std::ostringstream text;
    writeConfigJson(text, in, c);
    return nlohmann::json::parse(text.str());
}

Configuration configFromJson(const Interpreter& in, const nlohmann::json& j, std::uint32_t* inputsNamed) {
    const Region& region = in.region();
    const Model& model = in.model();
    const System& system = model.system();
    const int dim = region.lattice().dimension();
    auto cellIndex = [&](const nlohmann::json& at) {
        if (!at.is_array() || static_cast<int>(at.size()) != dim || !std::all_of(at.begin(), at.end(), [](auto& x) { return x.is_number_integer(); }))
            throw InputError("a cell position must be " + std::string(dim == 3 ? "[x, y, z]" : "[x, y]") + ", found " + quote(at));
        // A coordinate beyond an int lies outside every region (get<int> would wrap it inside).
        for (const auto& x : at)
            if ((x.is_number_unsigned() && x.get<std::uint64_t>() > std::uint64_t(INT32_MAX)) || x.get<std::int64_t>() < INT32_MIN || x.get<std::int64_t>() > INT32_MAX)
                throw InputError("cell " + quote(at) + " lies outside region " + region.spec());
        Vec v{at[0].get<int>(), at[1].get<int>(), dim == 3 ? at[2].get<int>() : 0};
        const int i = region.indexOf(v);
        if (i < 0) throw InputError("cell " + quote(at) + " lies outside region " + region.spec());
        return i;
    };
    if (!j.is_object()) throw InputError("a configuration is a JSON object with \"cells\"");
    if (j.contains("region") && j["region"].is_string() && j["region"].get<std::string>() != region.spec())
        throw InputError("the configuration is for region " + quote(j["region"].get<std::string>()) + ", not " + region.spec());
    Configuration c = in.empty();
    if (inputsNamed) *inputsNamed = 0;
    if (!j.contains("cells") || !j["cells"].is_array()) throw InputError("a configuration needs a \"cells\" array");
    std::size_t read = 0;
    for (const auto& cell : j["cells"]) {
        // A start line of 10^6 cells takes a second here, after its parse (robustness audit 6).
        if (++read % (1u << 14) == 0) StopSignals::checkJob("reading a configuration");
        if (!cell.is_object() || !cell.contains("at")) throw InputError("each cell is an object with \"at\" and its fields");
        const int i = cellIndex(cell["at"]);
        if (c.cells[i]) throw InputError("cell " + quote(cell["at"]) + " is listed twice");
        std::vector<int> fields(system.fields.size(), kAbsent);
        for (const auto& [key, value] : cell.items()) {
            if (key == "at") continue;
            const int f = system.fieldIndex(key);
            if (f < 0) throw InputError("cell " + quote(cell["at"]) + ": system '" + system.name + "' has no field '" + quote(key) + "'");
            const Field& field = system.fields[f];
            if (field.kind == FieldKind::Int) {
                if (!value.is_number_integer()) throw InputError("cell " + quote(cell["at"]) + ": field '" + quote(key) + "' holds an integer");
                fields[f] = value.get<int>();
                continue;
            }
            if (!value.is_string()) throw InputError("cell " + quote(cell["at"]) + ": field '" + quote(key) + "' holds a name");
            const std::string name = value.get<std::string>();
            if (field.kind == FieldKind::Dir) {
                auto d = region.lattice().directionByName(name);
                if (!d && name != "none") throw InputError("cell " + quote(cell["at"]) + ": '" + quote(name) + "' is not a direction of " + region.lattice().name());
                fields[f] = d ? *d : kAbsent;
            } else {
                auto it = std::find(field.values.begin(), field.values.end(), name);
                if (it == field.values.end()) throw InputError("cell " + quote(cell["at"]) + ": '" + quote(name) + "' is not a state of field '" + quote(key) + "'");
                fields[f] = static_cast<int>(it - field.values.begin());
            }
        }
        const int value = model.alphabet().find(fields);
        if (value <= 0) throw InputError("cell " + quote(cell["at"]) + ": these fields do not make a state of '" + system.name + "' (a field is missing, or set where its 'if' does not hold)");
        c.cells[i] = static_cast<CellValue>(value);
    }
    if (j.contains("inputs")) {
        if (!j["inputs"].is_object()) throw InputError("\"inputs\" maps input names to lists of cells");
        for (const auto& [name, list] : j["inputs"].items()) {
            const int k = system.inputIndex(name);
            if (k < 0) throw InputError("system '" + system.name + "' has no input '" + quote(name) + "'");
            if (!list.is_array()) throw InputError("input '" + quote(name) + "' is a list of cells");
            for (const auto& at : list) c.inputs[cellIndex(at)] |= 1u << k;
            if (inputsNamed) *inputsNamed |= 1u << k;
        }
    }
    return c;
}

std::string configToAscii(const Interpreter& in, const Configuration& c) {
    const Region& region = in.region();
    const Alphabet& alphabet = in.model().alphabet();
    const bool hex = region.lattice().kind() == LatticeKind::Hex2D;
    std::string out;
    for (const auto& row : asciiRows(region)) {
        if (row.empty()) continue;
        if (hex) out += std::string(static_cast<std::size_t>(std::abs(region.cell(row[0]).y)), ' ');
        for (std::size_t k = 0; k < row.size(); ++k) {
            const CellValue v = c.cells[row[k]];
            const char g = v ? alphabet.glyph(v) : '.';
            if (!g) throw InputError("state '" + alphabet.name(v) + "' has no one-character name; write this configuration as JSON");
            if (hex && k) out += ' ';
            out += g;
        }
        out += '\n';
    }
    return out;
}

Configuration configFromAscii(const Interpreter& in, const std::string& text) {
    const Region& region = in.region();
    const Alphabet& alphabet = in.model().alphabet();
    Configuration c = in.empty();
    const auto rows = asciiRows(region);
    const auto textLines = pictureRows(withoutBom(text), region.lattice().kind() != LatticeKind::Hex2D);
    if (textLines.size() > rows.size())
        throw InputError("the picture has " + std::to_string(textLines.size()) + " rows; region " + region.spec() + " has " + std::to_string(rows.size()));
    for (std::size_t r = 0; r < textLines.size(); ++r) {
        const auto tokens = rowTokens(region, textLines[r]);
        if (tokens.size() > rows[r].size())
            throw InputError("row " + std::to_string(r + 1) + " of the picture has " + std::to_string(tokens.size()) +
                             " cells; the region's row has " + std::to_string(rows[r].size()));
        for (std::size_t k = 0; k < tokens.size(); ++k) {
            const char ch = tokens[k][0];
            if (ch == '.' || ch == '_') continue;
            const int v = alphabet.byGlyph(ch);
            if (v < 0) throw InputError("row " + std::to_string(r + 1) + ", column " + std::to_string(k + 1) + ": '" +
                                        escapeText(std::string(1, ch)) + "' is not a one-character state of '" + in.model().system().name + "'");
            c.cells[rows[r][k]] = static_cast<CellValue>(v);
        }
    }
    return c;
}

std::vector<bool> maskFromAscii(const Region& region, const std::string& text) {
    std::vector<bool> mask(region.size(), false);
    const auto rows = asciiRows(region);
    const auto textLines = pictureRows(withoutBom(text), region.lattice().kind() != LatticeKind::Hex2D);
    if (textLines.size() > rows.size()) throw InputError("the mask has more rows than region " + region.spec());
    for (std::size_t r = 0; r < textLines.size(); ++r) {
        const auto tokens = rowTokens(region, textLines[r]);
        if (tokens.size() > rows[r].size()) throw InputError("row " + std::to_string(r + 1) + " of the mask is wider than the region");
        for (std::size_t k = 0; k < tokens.size(); ++k) mask[rows[r][k]] = tokens[k][0] != '.' && tokens[k][0] != '_';
    }
    return mask;
}

std::string pictureShortfall(const Region& region, const std::string& withBom) {
    const std::string text = withoutBom(withBom);
    const auto first = text.find_first_not_of(" \t\r\n");
    if (first == std::string::npos || text[first] == '{' || region.lattice().dimension() == 3) return "";
    const auto rows = asciiRows(region);
    const auto lines = pictureRows(text, region.lattice().kind() != LatticeKind::Hex2D);
    std::size_t columns = 0, regionColumns = 0;
    for (const auto& line : lines) columns = std::max(columns, rowTokens(region, line).size());
    for (const auto& row : rows) regionColumns = std::max(regionColumns, row.size());
    if (lines.size() >= rows.size() && columns >= regionColumns) return "";
    return "it draws " + std::to_string(lines.size()) + " of the region's " + std::to_string(rows.size()) + " rows and " + std::to_string(columns) +
           " of its " + std::to_string(regionColumns) + " columns";
}

namespace {

/// An ITF integer: a JSON number, or {"#bigint": "123"} as ITF writes large ones.
nlohmann::json itfScalar(const nlohmann::json& v) {
    if (v.is_object() && v.contains("#bigint") && v["#bigint"].is_string()) {
        try {
            return std::stoll(v["#bigint"].get<std::string>());
        } catch (const std::exception&) {
            throw InputError("\"#bigint\" holds the digits of an integer, found " + quote(v));
        }
    }
    return v;
}

/// An ITF position {"#tup": [x, y]} as the [x, y] of a configuration.
nlohmann::json itfPoint(const nlohmann::json& v) {
    if (!v.is_object() || !v.contains("#tup") || !v["#tup"].is_array()) throw InputError("a cell position in a trace is {\"#tup\": [x, y]}, found " + quote(v));
    nlohmann::json at = nlohmann::json::array();
    for (const auto& x : v["#tup"]) at.push_back(itfScalar(x));
    return at;
}

}  // namespace

bool isItfTrace(const nlohmann::json& j) { return j.is_object() && j.contains("states") && !j.contains("cells"); }

const nlohmann::json& itfStates(const nlohmann::json& itf) {
    if (!isItfTrace(itf) || !itf["states"].is_array()) throw InputError("an ITF trace is a JSON object with a \"states\" array");
    if (itf["states"].empty()) throw InputError("the trace has no states");
    return itf["states"];
}

nlohmann::json itfStateJson(const nlohmann::json& state) {
    if (!state.is_object() || !state.contains("cells") || !state["cells"].is_object() || !state["cells"].contains("#map") || !state["cells"]["#map"].is_array())
        throw InputError("a state's \"cells\" is {\"#map\": [[{\"#tup\": [x, y]}, {FIELD: VALUE, ...}], ...]}");
    nlohmann::json config{{"cells", nlohmann::json::array()}};
    for (const auto& entry : state["cells"]["#map"]) {
        if (!entry.is_array() || entry.size() != 2 || !entry[1].is_object())
            throw InputError("each entry of \"cells\" is a pair [{\"#tup\": [x, y]}, {FIELD: VALUE, ...}], found " + quote(entry));
        nlohmann::json cell = nlohmann::json::object();
        for (const auto& [field, value] : entry[1].items()) cell[field] = itfScalar(value);
        cell["at"] = itfPoint(entry[0]);
        config["cells"].push_back(cell);
    }
    if (state.contains("inputs")) {
        if (!state["inputs"].is_object()) throw InputError("a state's \"inputs\" maps each input's name to {\"#set\": [{\"#tup\": [x, y]}, ...]}");
        nlohmann::json inputs = nlohmann::json::object();
        for (const auto& [name, set] : state["inputs"].items()) {
            if (!set.is_object() || !set.contains("#set") || !set["#set"].is_array())
                throw InputError("input '" + quote(name) + "' is {\"#set\": [{\"#tup\": [x, y]}, ...]}");
            inputs[name] = nlohmann::json::array();
            for (const auto& at : set["#set"]) inputs[name].push_back(itfPoint(at));
        }
        config["inputs"] = inputs;
    }
    return config;
}

Configuration configFromItf(const Interpreter& in, const nlohmann::json& itf, std::optional<int> index, std::uint32_t* inputsNamed) {
    const auto& states = itfStates(itf);
    const int count = static_cast<int>(states.size());
    const int k = index.value_or(count - 1);
    if (k < 0 || k >= count)
        throw InputError("the trace has " + std::to_string(count) + (count == 1 ? " state" : " states") + ", numbered 0 to " + std::to_string(count - 1) +
                         "; pick one as FILE#N, or give FILE alone for the last");
    if (itf.contains("#meta") && itf["#meta"].is_object() && itf["#meta"].contains("region") && itf["#meta"]["region"].is_string() &&
        itf["#meta"]["region"].get<std::string>() != in.region().spec()) {
        const std::string named = itf["#meta"]["region"].get<std::string>();
        // Advice only for a region that can be checked: "run with --region square:0x0" was none.
        std::string advice = "; run with " + parameterName(Parameter::Region) + " " + named;
        try {
            Region::parse(named);
        } catch (const InputError& e) {
            advice = "; and the trace's region cannot be used: " + std::string(e.what());
        }
        throw InputError("the trace is for region " + excerpt(named, 80) + ", not " + in.region().spec() + advice, Parameter::Region);
    }
    // The state becomes a configuration's JSON, so one reader checks cells, fields and inputs.
    try {
        return configFromJson(in, itfStateJson(states[k]), inputsNamed);
    } catch (const InputError& e) {
        throw InputError("state " + std::to_string(k) + ": " + e.what());
    }
}

ConfigText readConfigText(const std::string& spec) {
    // FILE#N picks state N of an ITF trace; a file whose own name holds '#' is read as it is.
    ConfigText file{spec, spec, "", std::nullopt};
    std::error_code missing;
    if (const auto hash = spec.rfind('#'); hash != std::string::npos && !std::filesystem::exists(spec, missing)) {
        file.path = spec.substr(0, hash);
        const std::string n = spec.substr(hash + 1);
        if (n.empty() || n.size() > 9 || n.find_first_not_of("0123456789") != std::string::npos)
            throw InputError(spec + ": after '#' comes the index of a state of an ITF trace, as in " + file.path + "#0 for the first state");
        file.index = std::stoi(n);
    }
    OutputClaims::reading("the configuration", file.path);
    try {
        file.text = readTextFile(file.path);
    } catch (const InputError& e) {
        throw InputError(spec + ": " + e.what());
    }
    return file;
}

Configuration configFromText(const Interpreter& in, const ConfigText& file, std::uint32_t* inputsNamed) {
    try {
        return configFromText(in, file.text, file.index, inputsNamed, file.path);
    } catch (const InputError& e) {
        throw InputError(file.spec + ": " + e.what());
    }
}

Configuration readConfigFile(const Interpreter& in, const std::string& spec, std::uint32_t* inputsNamed) { return configFromText(in, readConfigText(spec), inputsNamed); }

Configuration configFromText(const Interpreter& in, const std::string& withBom, std::optional<int> index, std::uint32_t* inputsNamed,
                             const std::string& path) {
    const std::string text = withoutBom(withBom);
    const auto first = text.find_first_not_of(" \t\r\n");
    if (inputsNamed) *inputsNamed = 0;
    // An empty file is a mistake (a failed redirection, the wrong file), not an empty configuration.
    if (first == std::string::npos)
        throw InputError("the file is empty; a configuration is JSON or ASCII art, with '.' for each empty cell");
    try {
        if (text[first] == '{') {
            const nlohmann::json j = parseJsonOnceEach(text);
            if (isItfTrace(j)) return configFromItf(in, j, index, inputsNamed);
            if (index) throw InputError("'#" + std::to_string(*index) + "' picks a state of an ITF trace, and this is a configuration; give " + path + " without it");
            return configFromJson(in, j, inputsNamed);
        }
        // A JSON array was read as a picture ("row 1 of the picture has 15 cells"): say what it is.
        // No state is drawn as '[', so a picture never starts with one.
        if (text[first] == '[')
            throw InputError("a JSON array; a configuration is a JSON object with a \"cells\" array, as {\"cells\": [{\"at\": [0, 0], ...}]} (docs/cli.md), or ASCII art");
        if (index) throw InputError("'#" + std::to_string(*index) + "' picks a state of an ITF trace, and this is ASCII art; give " + path + " without it");
        return configFromAscii(in, text);
    } catch (const nlohmann::json::exception& e) {
        throw InputError("not valid JSON: " + excerpt(jsonErrorText(e), 300));
    }
}

}  // namespace holon::rules
