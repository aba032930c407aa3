// Reads VisibleSim worlds back (rules/VisibleSim.h), so a world made in VisibleSim, or one holon
// wrote, is a shape for `holon plan --from/--to`. The XML reader is the small subset VisibleSim's
// worlds use: a prolog, comments, elements with quoted attributes, text between tags ignored (the
// simulator's own examples have stray ';' there); every error is located by line and column. Of the
// world it takes what is in lattice cells: <block position>, <blocksLine> (the '1's of a row at
// line y, plane z), and the first grid target's <cell> and <targetLine>; <blockBox> and <csg> are
// in world units, which depend on the robot, and are refused by name.

#include "rules/Error.h"
#include "rules/Limits.h"
#include "rules/VisibleSim.h"

#include <algorithm>
#include <charconv>
#include <cstdlib>
#include <functional>
#include <map>
#include <optional>
#include <regex>

namespace holon::rules {

namespace {

/// Line and column of byte offsets, counted forward from the last one asked (the reader asks in
/// increasing order, errors aside).
class Places {
public:
    explicit Places(std::string_view text) : text_(text) {}
    std::string at(std::size_t offset) {
        if (offset < counted_) counted_ = 0, line_ = 1, lineStart_ = 0;
        for (; counted_ < offset && counted_ < text_.size(); ++counted_)
            if (text_[counted_] == '\n') ++line_, lineStart_ = counted_ + 1;
        return "line " + std::to_string(line_) + ", column " + std::to_string(offset - lineStart_ + 1);
    }
    [[noreturn]] void bad(std::size_t offset, const std::string& why) { throw InputError(at(offset) + ": " + why); }

private:
    std::string_view text_;
    std::size_t counted_ = 0, lineStart_ = 0;
    int line_ = 1;
};

/// A start tag: its path from the root ("world/blockList/block"), its attributes, its offset.
struct Element {
    std::string path;
    std::map<std::string, std::string> attributes;
    std::size_t offset = 0;
};

bool nameChar(char c) { return std::isalnum(static_cast<unsigned char>(c)) || c == '_' || c == '-' || c == '.' || c == ':'; }

constexpr std::size_t kMaxDepth = 64;

void walkXml(std::string_view text, Places& places, const std::function<void(const Element&)>& onElement,
             const std::function<void(std::string_view)>& onComment) {
    std::vector<std::pair<std::string, std::size_t>> open;
    bool rootSeen = false;
    const auto closing = [&](std::size_t from, std::string_view end, const char* what) {
        const std::size_t at = text.find(end, from);
        if (at == std::string_view::npos) places.bad(from, std::string(what) + " is not closed ('" + std::string(end) + "' missing)");
        return at;
    };
    for (std::size_t i = text.find('<'); i != std::string_view::npos; i = text.find('<', i)) {
        const std::string_view rest = text.substr(i);
        if (rest.starts_with("<!--")) {
            const std::size_t end = closing(i + 4, "-->", "a comment");
            onComment(text.substr(i + 4, end - i - 4));
            i = end + 3;
        } else if (rest.starts_with("<?") || rest.starts_with("<!")) {
            i = closing(i + 2, rest[1] == '?' ? "?>" : ">", rest[1] == '?' ? "a processing instruction" : "a declaration") + 1;
        } else if (rest.starts_with("</")) {
            const std::size_t end = closing(i + 2, ">", "an end tag");
            std::string name(text.substr(i + 2, end - i - 2));
            name.erase(std::find_if(name.rbegin(), name.rend(), [](char c) { return !std::isspace(static_cast<unsigned char>(c)); }).base(), name.end());
            if (open.empty()) places.bad(i, "</" + name + "> closes no element");
            if (open.back().first != name) places.bad(i, "</" + name + "> closes <" + open.back().first + "> (opened at " + places.at(open.back().second) + ")");
            open.pop_back();
            i = end + 1;
        } else {
            Element e;
            e.offset = i;
            std::size_t j = i + 1;
            while (j < text.size() && nameChar(text[j])) ++j;
            const std::string name(text.substr(i + 1, j - i - 1));
            if (name.empty()) places.bad(i, "'<' not followed by an element name");
            if (open.empty() && rootSeen) places.bad(i, "<" + name + "> after the root element has ended; a world file has one root, <world>");
            bool selfClosing = false;
            while (true) {
                while (j < text.size() && std::isspace(static_cast<unsigned char>(text[j]))) ++j;
                if (j >= text.size()) places.bad(i, "the tag <" + name + " is not closed ('>' missing)");
                if (text[j] == '>') break;
                if (text.substr(j).starts_with("/>")) {
                    selfClosing = true, ++j;
                    break;
                }
                const std::size_t nameStart = j;
                while (j < text.size() && nameChar(text[j])) ++j;
                const std::string attribute(text.substr(nameStart, j - nameStart));
                while (j < text.size() && std::isspace(static_cast<unsigned char>(text[j]))) ++j;
                if (attribute.empty() || j >= text.size() || text[j] != '=') places.bad(j, "expected an attribute name=\"value\" in <" + name + ">");
                ++j;
                while (j < text.size() && std::isspace(static_cast<unsigned char>(text[j]))) ++j;
                if (j >= text.size() || (text[j] != '"' && text[j] != '\'')) places.bad(j, "the value of " + attribute + " must be in quotes");
                const std::size_t end = text.find(text[j], j + 1);
                if (end == std::string_view::npos) places.bad(j, "the value of " + attribute + " is not closed");
                if (!e.attributes.emplace(attribute, std::string(text.substr(j + 1, end - j - 1))).second) places.bad(nameStart, "attribute " + attribute + " given twice");
                j = end + 1;
            }
            // A world nests 4 deep; each element's path names its ancestors, so depth must be
            // bounded (10^6 nested elements took over 10 minutes to read).
            if (open.size() >= kMaxDepth) places.bad(i, "<" + name + "> is nested " + std::to_string(open.size() + 1) + " elements deep; a VisibleSim world nests at most a few");
            for (const auto& [ancestor, offset] : open) e.path += ancestor + "/";
            e.path += name;
            rootSeen = true;
            onElement(e);
            if (!selfClosing) open.emplace_back(name, i);
            i = j + 1;
        }
    }
    if (!open.empty()) places.bad(open.back().second, "<" + open.back().first + "> is never closed");
    if (!rootSeen) places.bad(0, "no element; a VisibleSim world is an XML file with a <world> element");
}

std::optional<int> integer(std::string_view text) {
    while (!text.empty() && text.front() == ' ') text.remove_prefix(1);
    while (!text.empty() && text.back() == ' ') text.remove_suffix(1);
    int v = 0;
    const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), v);
    if (text.empty() || ec != std::errc{} || end != text.data() + text.size()) return std::nullopt;
    return v;
}

std::optional<Vec> triple(std::string_view text) {
    const std::size_t a = text.find(','), b = a == std::string_view::npos ? a : text.find(',', a + 1);
    if (b == std::string_view::npos || text.find(',', b + 1) != std::string_view::npos) return std::nullopt;
    const auto x = integer(text.substr(0, a)), y = integer(text.substr(a + 1, b - a - 1)), z = integer(text.substr(b + 1));
    if (!x || !y || !z) return std::nullopt;
    return Vec{*x, *y, *z};
}

}  // namespace

VisibleSimCells readVisibleSimWorld(std::string_view text, std::size_t maxCells) {
    Places places(text);
    Vec grid;
    std::vector<std::pair<Vec, std::size_t>> blocks, targets;  // position, offset of its element
    int targetsSeen = 0;
    bool readingTarget = false;
    std::optional<std::pair<const Lattice*, Vec>> holonMap;
    const auto attribute = [&](const Element& e, const std::string& name) -> const std::string* {
        const auto it = e.attributes.find(name);
        return it == e.attributes.end() ? nullptr : &it->second;
    };
    const auto add = [&](std::vector<std::pair<Vec, std::size_t>>& into, Vec p, std::size_t offset) {
        if (p.x < 0 || p.y < 0 || p.z < 0 || p.x >= grid.x || p.y >= grid.y || p.z >= grid.z)
            places.bad(offset, "position " + std::to_string(p.x) + "," + std::to_string(p.y) + "," + std::to_string(p.z) + " is outside the grid " +
                                   std::to_string(grid.x) + "," + std::to_string(grid.y) + "," + std::to_string(grid.z) + " (VisibleSim refuses it too)");
        if (blocks.size() + targets.size() >= maxCells) places.bad(offset, "more than " + std::to_string(maxCells) + " cells, the limit; give a smaller world");
        into.emplace_back(p, offset);
    };
    const auto position = [&](const Element& e) {
        const std::string* text = attribute(e, "position");
        if (!text) places.bad(e.offset, "<" + e.path.substr(e.path.rfind('/') + 1) + "> without a position=\"x,y,z\"");
        const auto p = triple(*text);
        if (!p) places.bad(e.offset, "position=\"" + text->substr(0, 40) + "\" is not three whole numbers x,y,z");
        return *p;
    };
    const auto line = [&](const Element& e, std::vector<std::pair<Vec, std::size_t>>& into) {
        const auto number = [&](const char* name) {
            const std::string* text = attribute(e, name);
            const std::optional<int> v = text ? integer(*text) : 0;
            if (!v) places.bad(e.offset, std::string(name) + "=\"" + text->substr(0, 40) + "\" is not a whole number");
            return *v;
        };
        const int y = number("line"), z = number("plane");
        const std::string* values = attribute(e, "values");
        if (!values) places.bad(e.offset, "a line of modules without values=\"0110...\"");
        for (std::size_t x = 0; x < values->size(); ++x) {
            if ((*values)[x] == '1') add(into, Vec{static_cast<int>(x), y, z}, e.offset);
            else if ((*values)[x] != '0') places.bad(e.offset, "values=\"...\" holds '" + std::string(1, (*values)[x]) + "'; a line of modules is 0s and 1s");
        }
    };
    walkXml(
        text, places,
        [&](const Element& e) {
            if (e.path == "world") {
                const std::string* size = attribute(e, "gridSize");
                const auto g = size ? triple(*size) : std::nullopt;
                if (!g || g->x < 1 || g->y < 1 || g->z < 1) places.bad(e.offset, "<world> needs gridSize=\"X,Y,Z\", three whole numbers from 1");
                grid = *g;
            } else if (!e.path.starts_with("world/")) {
                places.bad(e.offset, "the root element is <" + e.path.substr(0, e.path.find('/')) + ">; a VisibleSim world's is <world>");
            } else if (e.path == "world/blockList/block") {
                add(blocks, position(e), e.offset);
            } else if (e.path == "world/blockList/blocksLine") {
                line(e, blocks);
            } else if (e.path == "world/blockList/blockBox" || e.path == "world/blockList/csg") {
                places.bad(e.offset, "<" + e.path.substr(16) + "> is in world units, which depend on the robot; holon reads <block> and <blocksLine>: list the modules as those");
            } else if (e.path == "world/targetList/target") {
                const std::string* format = attribute(e, "format");
                readingTarget = ++targetsSeen == 1;
                if (readingTarget && (!format || *format != "grid"))
                    places.bad(e.offset, "the first target is format=\"" + (format ? format->substr(0, 20) : std::string()) + "\"; holon reads format=\"grid\" targets");
            } else if (readingTarget && e.path == "world/targetList/target/cell") {
                add(targets, position(e), e.offset);
            } else if (readingTarget && e.path == "world/targetList/target/targetLine") {
                line(e, targets);
            }
        },
        [&](std::string_view comment) {
            static const std::regex map(R"(holon (square2d|cubic3d|hex2d) cell .* is at position \(.*\) - \((-?[0-9]+), (-?[0-9]+), (-?[0-9]+)\))");
            std::cmatch m;
            if (std::regex_search(comment.data(), comment.data() + comment.size(), m, map))
                if (const Lattice* lattice = Lattice::byName(m[1].str()); lattice && integer(m[2].str()) && integer(m[3].str()) && integer(m[4].str()))
                    holonMap.emplace(lattice, Vec{*integer(m[2].str()), *integer(m[3].str()), *integer(m[4].str())});
        });
    // Without holon's map: one layer is square2d with y flipped within the grid, more is cubic3d.
    if (!holonMap) holonMap.emplace(grid.z == 1 ? &Lattice::get(LatticeKind::Square2D) : &Lattice::get(LatticeKind::Cubic3D), grid.z == 1 ? Vec{0, 1 - grid.y, 0} : Vec{});
    VisibleSimCells out;
    out.lattice = holonMap->first;
    for (auto [list, cells] : {std::pair{&blocks, &out.blocks}, std::pair{&targets, &out.targets}}) {
        std::sort(list->begin(), list->end());
        for (std::size_t k = 1; k < list->size(); ++k)
            if ((*list)[k].first == (*list)[k - 1].first)
                places.bad(std::max((*list)[k].second, (*list)[k - 1].second), "position " + std::to_string((*list)[k].first.x) + "," + std::to_string((*list)[k].first.y) + "," +
                                                                                   std::to_string((*list)[k].first.z) + " is given twice (also at " +
                                                                                   places.at(std::min((*list)[k].second, (*list)[k - 1].second)) + ")");
        for (const auto& [p, offset] : *list) {
            // In 64 bits first: a comment's offset and a large grid could take a coordinate past an
            // int, or past the +-kMaxCoordinate every holon shape keeps to.
            const std::int64_t q[3] = {std::int64_t(p.x) + holonMap->second.x, std::int64_t(p.y) + holonMap->second.y, std::int64_t(p.z) + holonMap->second.z};
            const bool hex = out.lattice->kind() == LatticeKind::Hex2D;
            if (std::max({std::llabs(q[0]), std::llabs(q[1]), std::llabs(q[2]), hex ? std::llabs(q[0] + q[1]) : 0}) > kMaxCoordinate)
                places.bad(offset, "this position is beyond +-" + std::to_string(kMaxCoordinate) + " in holon's coordinates; give a smaller grid or offset");
            cells->push_back(toVisibleSimAxes(*out.lattice, Vec{int(q[0]), int(q[1]), int(q[2])}));
        }
        std::sort(cells->begin(), cells->end());
    }
    return out;
}

}  // namespace holon::rules
