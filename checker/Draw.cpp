// Drawing configurations and counterexample traces. The aim is that a person sees the problem at a
// glance: each frame shows which cells the rule changed (red), which cells it only looked at (the
// context and blocking cells of seed 000 Fig. 1a, dashed), and in the last frame the cells a
// violated property points at (crossed, e.g. the part cut off from the rest). Nothing of a state
// may be lost in the picture: a cell shows every field (colour, text, arrows) and every input is
// drawn, since a counterexample that hides the resource or the lock of a cell explains nothing.

#include "checker/Draw.h"

#include "rules/Svg.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <set>
#include <sstream>

namespace holon::checker {

namespace {

using rules::FieldKind;

const rules::System& systemOf(const rules::Engine& e) {
    return e.model().system();
}

/// Index of the field that sets the fill colour (the first enum field), or -1.
int fillField(const rules::System& s) {
    for (std::size_t f = 0; f < s.fields.size(); ++f)
        if (s.fields[f].kind == FieldKind::Enum) return static_cast<int>(f);
    return -1;
}

std::string position(const rules::Region& r, int cell) {
    const rules::Vec v = r.cell(cell);
    return "(" + std::to_string(v.x) + "," + std::to_string(v.y) +
           (r.lattice().dimension() == 3 ? "," + std::to_string(v.z) : "") + ")";
}

std::vector<int> changedCells(const Trace& t, std::size_t k) {
    std::vector<int> out;
    if (k == 0) return out;
    for (std::size_t i = 0; i < t.steps[k].cells.size(); ++i)
        if (t.steps[k].cells[i] != t.steps[k - 1].cells[i]) out.push_back(static_cast<int>(i));
    return out;
}

std::string stepTitle(const Trace& t, const rules::Engine& e, std::size_t k) {
    if (t.steps[k].placed < 0) return k == 0 ? "initial" : "adjacent, not one rule step away";
    const auto& p = e.instances()[t.steps[k].placed];
    return e.model().stepRules(p.shape, false) + " at " + position(e.region(), p.cells[0]);
}

/// An ASCII arrow for an in-plane axis direction (square, and x/y of cubic), or 0.
char arrowChar(rules::Vec d) {
    if (d.z != 0) return 0;
    if (d.x == 1 && d.y == 0) return '>';
    if (d.x == -1 && d.y == 0) return '<';
    if (d.x == 0 && d.y == 1) return 'v';  // +y points down the page
    if (d.x == 0 && d.y == -1) return '^';
    return 0;
}

/// Greedy word wrap to lines of at most `width` characters; a longer word is cut.
std::vector<std::string> wrap(const std::string& text, std::size_t width) {
    width = std::max<std::size_t>(width, 8);
    std::vector<std::string> lines;
    std::istringstream in(text);
    std::string line;
    for (std::string word; in >> word;) {
        while (word.size() > width) {
            if (!line.empty()) lines.push_back(line), line.clear();
            lines.push_back(word.substr(0, width));
            word = word.substr(width);
        }
        if (!line.empty() && line.size() + 1 + word.size() > width) lines.push_back(line), line.clear();
        line += (line.empty() ? "" : " ") + word;
    }
    if (!line.empty() || lines.empty()) lines.push_back(line);
    return lines;
}

}  // namespace

// ---------------------------------------------------------------------------------------------
// ASCII

AsciiKey asciiKey(const rules::Engine& e, const std::vector<const std::vector<CellValue>*>& configurations) {
    const rules::Alphabet& a = e.model().alphabet();
    const rules::System& s = systemOf(e);
    std::set<CellValue> shown;
    for (const auto* cells : configurations)
        for (CellValue v : *cells)
            if (v) shown.insert(v);
    // Every one-character name of the system is reserved, shown or not, so a character never
    // reads as a state it is not; '_', '#' and '*' mean something in the rule language.
    std::set<char> taken{'.', '_', '#', '*', ' '};
    for (int v = 1; v < a.size(); ++v)
        if (char g = a.glyph(static_cast<CellValue>(v))) taken.insert(g);
    AsciiKey key;
    std::vector<std::string> entries;
    for (CellValue v : shown) {
        if (char g = a.glyph(v)) {
            key.chars[v] = g;
            continue;
        }
        std::string candidates;
        const auto& fields = a.fields(v);
        for (std::size_t f = 0; f < fields.size(); ++f)
            if (s.fields[f].kind == FieldKind::Dir && fields[f] != rules::kAbsent)
                if (char c = arrowChar(e.region().lattice().direction(fields[f]))) candidates += c;
        // Then plain letters: a value's initial would read as that value alone ('D' for D&U).
        candidates += "abcdefghijklmnopqrstuvwxyzABCDEFGHIJKLMNOPQRSTUVWXYZ0123456789+=%&@$~?!:;";
        char chosen = '?';
        for (char c : candidates)
            if (!taken.count(c)) {
                chosen = c;
                break;
            }
        taken.insert(chosen);
        key.chars[v] = chosen;
        entries.push_back(std::string(1, chosen) + " = " + a.name(v));
    }
    if (!entries.empty()) {
        std::string line = "-- legend:";
        for (std::size_t k = 0; k < entries.size(); ++k) {
            const std::string item = " " + entries[k] + (k + 1 < entries.size() ? "," : "");
            if (line.size() + item.size() > 100) key.legend += line + '\n', line = "  ";
            line += item;
        }
        key.legend += line + '\n';
    }
    return key;
}

std::string drawAscii(const rules::Engine& e, const std::vector<CellValue>& cells) {
    const AsciiKey key = asciiKey(e, {&cells});
    return key.legend + drawCells(e.region(), [&](int i) { return key(cells[i]); });
}

std::string drawCells(const rules::Region& r, const std::function<char(int)>& charOf) {
    const rules::Vec lo = r.lower(), ext = r.extent();
    const bool hex = r.lattice().kind() == rules::LatticeKind::Hex2D;
    const bool slices = r.lattice().dimension() == 3;
    // A slice is as wide as its cells or its heading "z=K", whichever is wider.
    std::size_t sliceWidth = static_cast<std::size_t>(ext.x);
    for (int z = 0; slices && z < ext.z; ++z)
        sliceWidth = std::max(sliceWidth, ("z=" + std::to_string(lo.z + z)).size());
    std::ostringstream out;
    if (slices) {
        for (int z = 0; z < ext.z; ++z) {
            const std::string head = "z=" + std::to_string(lo.z + z);
            out << (z ? "   " : "") << head
                << (z + 1 < ext.z ? std::string(sliceWidth - head.size(), ' ') : "");
        }
        out << '\n';
    }
    for (int y = 0; y < ext.y; ++y) {
        if (hex) out << std::string(static_cast<std::size_t>(std::abs(lo.y + y)), ' ');
        for (int z = 0; z < ext.z; ++z) {
            if (z) out << "   ";
            bool first = true;
            std::size_t written = 0;
            for (int x = 0; x < ext.x; ++x) {
                const int i = r.indexOf({lo.x + x, lo.y + y, lo.z + z});
                if (i < 0) continue;
                if (hex && !first) out << ' ';
                out << charOf(i);
                first = false;
                ++written;
            }
            if (slices && z + 1 < ext.z) out << std::string(sliceWidth - written, ' ');
        }
        out << '\n';
    }
    return out.str();
}

std::string drawInputsAscii(const rules::Engine& e) {
    const auto& names = systemOf(e).inputs;
    std::ostringstream out;
    for (std::size_t k = 0; k < names.size(); ++k) {
        bool any = false;
        for (std::uint32_t bits : e.inputs()) any = any || ((bits >> k) & 1u);
        out << "-- input " << names[k] << (any ? ":\n" : ": holds in no cell\n");
        if (any) out << drawCells(e.region(), [&](int i) { return (e.inputs()[i] >> k) & 1u ? '#' : '.'; });
    }
    return out.str();
}

std::string drawTraceAscii(const Trace& t, const rules::Engine& e) {
    std::vector<const std::vector<CellValue>*> all;
    for (const auto& step : t.steps) all.push_back(&step.cells);
    const AsciiKey key = asciiKey(e, all);
    const rules::Alphabet& a = e.model().alphabet();
    std::ostringstream out;
    out << key.legend;
    for (std::size_t k = 0; k < t.steps.size(); ++k) {
        out << "-- " << k << ": " << stepTitle(t, e, k) << '\n'
            << drawCells(e.region(), [&](int i) { return key(t.steps[k].cells[i]); });
        for (int i : changedCells(t, k))
            out << "   " << position(e.region(), i) << ' ' << a.name(t.steps[k - 1].cells[i]) << " -> "
                << a.name(t.steps[k].cells[i]) << '\n';
    }
    if (t.loop) out << "-- the last state loops back to state " << *t.loop << '\n';
    if (!t.marked.empty()) {
        out << "-- marked:";
        for (int i : t.marked) out << ' ' << position(e.region(), i);
        out << '\n';
    }
    out << drawInputsAscii(e);
    return out.str();
}

// ---------------------------------------------------------------------------------------------
// SVG

namespace {

// Fill colours for state values; no red or orange, which mark changed and context cells.
const char* const kPalette[] = {"#4e79a7", "#59a14f", "#edc948", "#b07aa1", "#76b7b2",
                                "#9c755f", "#bab0ac", "#ff9da7", "#2f4b7c", "#8cd17d"};
constexpr int kPaletteSize = sizeof(kPalette) / sizeof(kPalette[0]);
// One colour and dash per pointer field, one colour per input.
const char* const kPointerColour[] = {"#111111", "#6a1b9a", "#00695c", "#5d4037"};
const char* const kPointerDash[] = {"", "5,2", "2,2", "6,2,2,2"};
const char* const kInputColour[] = {"#1b5e20", "#0d47a1", "#880e4f", "#e65100",
                                    "#006064", "#4a148c", "#827717", "#263238"};
// The outlines of changed, context and other cells; the fill of a state without a fill field.
constexpr const char *kChanged = "#d62728", *kContext = "#ff7f0e", *kCell = "#999", *kNoFill = "#8d8d8d";
const rules::SvgAttrs kChangedPen{{"stroke", kChanged}, {"stroke-width", 3}};
const rules::SvgAttrs kContextPen{{"stroke", kContext}, {"stroke-width", 2.5}, {"stroke-dasharray", "4,2"}};
const rules::SvgAttrs kCellPen{{"stroke", kCell}, {"stroke-width", 0.8}};

/// The pen of pointer field j's arrows.
rules::SvgAttrs pointerPen(std::size_t j) {
    rules::SvgAttrs pen{{"stroke", kPointerColour[j % 4]}, {"stroke-width", 1.8}};
    if (*kPointerDash[j % 4]) pen.push_back({"stroke-dasharray", kPointerDash[j % 4]});
    pen.push_back({"marker-end", "url(#head" + std::to_string(j % 4) + ")"});
    return pen;
}

std::string translate(double x, double y) {
    std::ostringstream s;
    s << "translate(" << x << "," << y << ")";
    return s.str();
}

/// Path data of an x of half-width r centred on (cx, cy).
std::string cross(double cx, double cy, double r) {
    std::ostringstream s;
    s << "M" << cx - r << "," << cy - r << " L" << cx + r << "," << cy + r << " M" << cx + r << "," << cy - r
      << " L" << cx - r << "," << cy + r;
    return s.str();
}

std::uint32_t fnv(const std::string& s) {
    std::uint32_t h = 2166136261u;
    for (unsigned char c : s) h = (h ^ c) * 16777619u;
    return h;
}

bool light(const std::string& colour) {
    const int r = std::stoi(colour.substr(1, 2), nullptr, 16),
              g = std::stoi(colour.substr(3, 2), nullptr, 16),
              b = std::stoi(colour.substr(5, 2), nullptr, 16);
    return 0.299 * r + 0.587 * g + 0.114 * b > 150;
}

/// A left-to-right flow of legend items that wraps at the picture's width.
struct Flow {
    rules::Svg& out;
    double x0, width, x, y;
    void item(double w, const std::function<void(double x, double y)>& draw) {
        if (x > x0 && x + w > x0 + width) x = x0, y += 20;
        draw(x, y);
        x += w + 14;
    }
    void text(const std::string& s, const rules::SvgAttrs& attrs = {}) {
        item(6.2 * static_cast<double>(s.size()),
             [&](double px, double py) { out.text(px, py + 11, s, attrs); });
    }
};

}  // namespace

std::string valueColour(const rules::Field& field, int value) {
    const int n = static_cast<int>(field.values.size());
    if (n > kPaletteSize) return kPalette[value % kPaletteSize];
    // Each value's slot comes from its name; a clash goes to the next free slot, in declaration
    // order, so U/P/F (or D/C/B1) look the same in every system that declares them alike.
    std::vector<bool> used(kPaletteSize, false);
    int slot = 0;
    for (int k = 0; k <= value; ++k) {
        slot = static_cast<int>(fnv(field.values[k]) % kPaletteSize);
        while (used[slot]) slot = (slot + 1) % kPaletteSize;
        used[slot] = true;
    }
    return kPalette[slot];
}

std::string stateColour(const rules::Model& model, CellValue v) {
    const int fill = fillField(model.system());
    const int value = fill >= 0 ? model.alphabet().fields(v)[fill] : rules::kAbsent;
    return value != rules::kAbsent ? valueColour(model.system().fields[fill], value) : kNoFill;
}

std::string cellText(const rules::System& s, const std::vector<int>& fields) {
    std::string text;
    for (std::size_t f = 0; f < fields.size(); ++f) {
        if (fields[f] == rules::kAbsent) continue;
        switch (s.fields[f].kind) {
        case FieldKind::Enum:
            text += (text.empty() ? "" : " ") + s.fields[f].values[fields[f]];
            break;
        case FieldKind::Int:
            text += (text.empty() ? "" : " ") + std::to_string(fields[f]);
            break;
        case FieldKind::Dir:
            break;  // drawn as an arrow
        }
    }
    return text;
}

TraceColours traceColours() {
    return {kChanged, kContext, kCell, kNoFill, std::vector<std::string>(std::begin(kInputColour), std::end(kInputColour))};
}

rules::SvgPicture drawTrace(const Trace& t, const rules::Engine& e, const std::string& title) {
    const rules::Region& r = e.region();
    const rules::Lattice& lattice = r.lattice();
    const rules::System& system = systemOf(e);
    const rules::Alphabet& alphabet = e.model().alphabet();
    const bool hex = lattice.kind() == rules::LatticeKind::Hex2D;
    const bool slices = lattice.dimension() == 3;
    const int fill = fillField(system);
    std::vector<int> dirFields;
    for (std::size_t f = 0; f < system.fields.size(); ++f)
        if (system.fields[f].kind == FieldKind::Dir) dirFields.push_back(static_cast<int>(f));
    const auto& inputs = system.inputs;

    // What the trace shows: the values of each field, the longest cell text (the cell grows to fit it).
    std::vector<std::set<int>> shownValues(system.fields.size());
    std::size_t longest = 1;
    for (const auto& step : t.steps)
        for (CellValue v : step.cells) {
            if (!v) continue;
            const auto& fields = alphabet.fields(v);
            for (std::size_t f = 0; f < fields.size(); ++f) shownValues[f].insert(fields[f]);
            longest = std::max(longest, cellText(system, fields).size());
        }
    // Cell size: the text must fit, and beside it the shaft of an arrow and the head of a neighbour's.
    const double s = std::max(dirFields.empty() ? 26.0 : 40.0, 6.2 * static_cast<double>(longest) + 10);
    const rules::Vec lo = r.lower(), ext = r.extent();
    // Cell centre within a frame: hex cells at their axial positions, 3D regions as z slices.
    auto rawCentre = [&](rules::Vec v) {
        if (hex)
            return std::pair<double, double>{s * std::sqrt(3.0) * 0.5 * (v.x + v.y / 2.0), s * 0.75 * v.y};
        const double slice = (v.z - lo.z) * (ext.x + 1) * s;
        return std::pair<double, double>{slice + (v.x - lo.x) * s, (v.y - lo.y) * s};
    };
    double minX = 1e9, minY = 1e9, maxX = -1e9, maxY = -1e9;
    for (const rules::Vec& v : r.cells()) {
        auto [x, y] = rawCentre(v);
        minX = std::min(minX, x), maxX = std::max(maxX, x), minY = std::min(minY, y),
        maxY = std::max(maxY, y);
    }
    auto centre = [&](rules::Vec v) {
        auto [x, y] = rawCentre(v);
        return std::pair<double, double>{x - minX + s / 2, y - minY + s / 2};
    };
    // A cell's outline as a polygon (square: 4 corners, hex: 6), shrunk by `inset` pixels.
    auto corners = [&](int cell, double inset) {
        auto [cx, cy] = centre(r.cell(cell));
        std::vector<std::pair<double, double>> out;
        if (hex) {
            const double radius = s * 0.5 - inset / std::cos(M_PI / 6);
            for (int c = 0; c < 6; ++c) {
                const double a = M_PI / 180 * (60 * c - 30);
                out.push_back({cx + radius * std::cos(a), cy + radius * std::sin(a)});
            }
        } else {
            const double h = s * 0.5 - inset;
            out = {{cx - h, cy - h}, {cx + h, cy - h}, {cx + h, cy + h}, {cx - h, cy + h}};
        }
        return out;
    };
    // The side of a cell's polygon that faces in-plane direction d.
    auto sideToward = [&](int cell, int d) {
        const auto [cx, cy] = centre(r.cell(cell));
        const auto [nx, ny] = centre(r.cell(cell) + lattice.direction(d));
        const auto poly = corners(cell, 0);
        int best = 0;
        double bestDist = 1e18;
        for (std::size_t c = 0; c < poly.size(); ++c) {
            const auto& p = poly[c];
            const auto& q = poly[(c + 1) % poly.size()];
            const double dx = (p.first + q.first) / 2 - (cx + nx) / 2,
                         dy = (p.second + q.second) / 2 - (cy + ny) / 2;
            if (dx * dx + dy * dy < bestDist) bestDist = dx * dx + dy * dy, best = static_cast<int>(c);
        }
        return best;
    };

    const int steps = static_cast<int>(t.steps.size());
    const int perRow = std::max(1, std::min(5, steps));
    const int rows = (steps + perRow - 1) / perRow;
    const double regionW = maxX - minX + s, regionH = maxY - minY + s + (slices ? 16 : 0);
    const double frameW = std::max(150.0, regionW + 24);
    const double width = std::max(perRow * frameW + 20, 480.0);
    // Titles wrap to the width they have (bold 14 px DejaVu Sans is up to 9 px a character; 11 px about 6.2).
    const auto titleLines = wrap(title, static_cast<std::size_t>((width - 20) / 9.0));
    std::vector<std::vector<std::string>> frameTitles;
    std::size_t frameTitleLines = 1;
    for (int k = 0; k < steps; ++k) {
        const std::string loop = t.loop && k + 1 == steps ? ", then back to " + std::to_string(*t.loop) : "";
        frameTitles.push_back(wrap(std::to_string(k) + ": " + stepTitle(t, e, k) + loop,
                                   static_cast<std::size_t>((frameW - 12) / 6.2)));
        frameTitleLines = std::max(frameTitleLines, frameTitles.back().size());
    }
    const double titleH = 14 + 18.0 * static_cast<double>(titleLines.size());
    const double frameH = 13.0 * static_cast<double>(frameTitleLines) + 8 + regionH + 18;

    rules::Svg body;
    for (std::size_t l = 0; l < titleLines.size(); ++l)
        body.text(10, 22 + 18 * static_cast<double>(l), titleLines[l],
                  {{"font-size", 14}, {"font-weight", "bold"}});
    for (int k = 0; k < steps; ++k) {
        const double ox = 10 + (k % perRow) * frameW, oy = titleH + 12 + (k / perRow) * frameH;
        body.open("g", {{"transform", translate(ox, oy)}});
        for (std::size_t l = 0; l < frameTitles[k].size(); ++l)
            body.text(0, 13.0 * static_cast<double>(l), frameTitles[k][l]);
        body.open("g", {{"transform", translate(0, 13.0 * static_cast<double>(frameTitleLines - 1) + 8)}});
        const auto changed = changedCells(t, k);
        std::vector<int> context;
        if (t.steps[k].placed >= 0) {
            const auto& p = e.instances()[t.steps[k].placed];
            for (int c = 0; c < p.size; ++c)
                if (std::find(changed.begin(), changed.end(), p.cells[c]) == changed.end())
                    context.push_back(p.cells[c]);
        }
        // Cells: fill by the first enum field, the text of every field, the outline for changed and context
        // cells.
        for (int i = 0; i < r.size(); ++i) {
            const CellValue v = t.steps[k].cells[i];
            const bool isChanged = std::find(changed.begin(), changed.end(), i) != changed.end();
            const bool isContext = std::find(context.begin(), context.end(), i) != context.end();
            const std::string colour = v ? stateColour(e.model(), v) : "#ffffff";
            rules::SvgAttrs attrs{{"fill", colour}};
            const rules::SvgAttrs& stroke = isChanged ? kChangedPen : isContext ? kContextPen
                                                                                : kCellPen;
            attrs.insert(attrs.end(), stroke.begin(), stroke.end());
            body.polygon(corners(i, hex ? 0.5 : 1), attrs);
        }
        // Inputs: each input's cells outlined (inset, one colour each), its empty cells hatched.
        for (std::size_t n = 0; n < inputs.size(); ++n) {
            const double inset = 3.5 + 2.5 * static_cast<double>(n % 6);
            for (int i = 0; i < r.size(); ++i) {
                if (!((e.inputs()[i] >> n) & 1u)) continue;
                if (!t.steps[k].cells[i])
                    body.polygon(corners(i, hex ? 0.5 : 1),
                                 {{"fill", "url(#hatch" + std::to_string(n) + ")"}, {"stroke", "none"}});
                const auto poly = corners(i, inset);
                for (int d = 0; d < lattice.degree(); ++d) {
                    if (lattice.direction(d).z != 0) continue;
                    const int j = r.indexOf(r.cell(i) + lattice.direction(d));
                    if (j >= 0 && ((e.inputs()[j] >> n) & 1u)) continue;
                    const int c = sideToward(i, d);
                    const auto& p = poly[c];
                    const auto& q = poly[(c + 1) % poly.size()];
                    // A white casing under the line keeps it visible on a dark fill.
                    for (const auto& [pen, penWidth] :
                         {std::pair<const char*, double>{"#ffffff", 3.6}, {kInputColour[n % 8], 2.0}})
                        body.line(p.first, p.second, q.first, q.second,
                                  {{"stroke", pen}, {"stroke-width", penWidth}, {"stroke-linecap", "round"}});
                }
            }
        }
        if (k + 1 == steps)
            for (int i : t.marked) {
                auto [cx, cy] = centre(r.cell(i));
                body.path(cross(cx, cy, 8),
                          {{"stroke", "#d62728"}, {"stroke-width", 3}, {"stroke-opacity", 0.75}});
            }
        // Pointers above the outlines.
        for (int i = 0; i < r.size(); ++i) {
            const CellValue v = t.steps[k].cells[i];
            if (!v) continue;
            auto [cx, cy] = centre(r.cell(i));
            const auto& fields = alphabet.fields(v);
            for (std::size_t j = 0; j < dirFields.size(); ++j) {
                const int d = fields[dirFields[j]];
                if (d == rules::kAbsent) continue;
                const rules::Vec dv = lattice.direction(d);
                const char* pen = kPointerColour[j % 4];
                if (dv.z != 0) {
                    // Out of the slice: a dot in a circle toward +z, a cross toward -z (seen from -z).
                    const double px = cx + s * 0.3, py = cy - s * 0.3 + 7 * static_cast<double>(j), rad = 3.5;
                    body.circle(px, py, rad, {{"fill", "white"}, {"stroke", pen}, {"stroke-width", 1.2}});
                    if (dv.z > 0)
                        body.circle(px, py, 1.2, {{"fill", pen}});
                    else
                        body.path(cross(px, py, 2.2), {{"stroke", pen}, {"stroke-width", 1.2}});
                    continue;
                }
                auto [tx, ty] = centre(r.cell(i) + dv);
                const double dx = tx - cx, dy = ty - cy, len = std::hypot(dx, dy);
                // Fields side by side: each arrow is shifted to the left of its direction by its field's
                // slot, so two cells pointing at each other (a lock) show two arrows, not one line.
                const double shift =
                    (static_cast<double>(j) - (static_cast<double>(dirFields.size()) - 1) / 2) * 5 - 2.5;
                const double nx = -dy / len * shift, ny = dx / len * shift;
                body.line(cx + nx, cy + ny, cx + dx * 0.6 + nx, cy + dy * 0.6 + ny, pointerPen(j));
            }
        }
        // Texts last, with a halo of the fill colour, so an arrow under a text leaves it readable.
        for (int i = 0; i < r.size(); ++i) {
            const CellValue v = t.steps[k].cells[i];
            if (!v) continue;
            auto [cx, cy] = centre(r.cell(i));
            const auto& fields = alphabet.fields(v);
            const std::string colour = stateColour(e.model(), v);
            const std::string text = cellText(system, fields);
            if (!text.empty())
                body.text(cx, cy + 3.5, text,
                          {{"text-anchor", "middle"},
                           {"font-size", 10},
                           {"fill", light(colour) ? "#111" : "#fff"},
                           {"stroke", colour},
                           {"stroke-width", 2.5},
                           {"paint-order", "stroke"}});
        }
        if (slices)
            for (int z = 0; z < ext.z; ++z)
                body.text(z * (ext.x + 1) * s, ext.y * s + 13, "z=" + std::to_string(lo.z + z));
        body.close("g").close("g");
    }

    // The legend: what the outlines mean, every value shown by field, every pointer field and input.
    rules::Svg& legend = body;
    const double legendY = titleH + 12 + rows * frameH;
    Flow flow{legend, 10, width - 20, 10, legendY};
    auto swatch = [&](rules::SvgAttrs attrs, const std::string& label) {
        flow.item(18 + 6.2 * static_cast<double>(label.size()),
                  [&](double x, double y) { legend.legend(x, y, label, attrs); });
    };
    auto penned = [](rules::SvgAttrs attrs, const rules::SvgAttrs& pen) {
        attrs.insert(attrs.end(), pen.begin(), pen.end());
        return attrs;
    };
    swatch(penned({{"fill", "white"}}, kChangedPen), "changed");
    swatch(penned({{"fill", "white"}}, kContextPen), "context / blocking");
    if (!t.marked.empty())
        flow.item(80, [&](double x, double y) {
            legend.path(cross(x + 7, y + 7, 6), {{"stroke", "#d62728"}, {"stroke-width", 3}})
                .text(x + 18, y + 11, "marked");
        });
    flow.x = flow.x0, flow.y += 20;
    for (std::size_t f = 0; f < system.fields.size(); ++f) {
        const rules::Field& field = system.fields[f];
        std::vector<int> values(shownValues[f].begin(), shownValues[f].end());
        // A conditional field that is off is not a value; an unconditional pointer's none is.
        if (field.kind != FieldKind::Dir || field.whenField >= 0) std::erase(values, rules::kAbsent);
        if (values.empty()) continue;
        switch (field.kind) {
        case FieldKind::Enum: {
            flow.text(field.name + (static_cast<int>(f) == fill ? " (fill, text):" : " (text):"),
                      {{"font-weight", "bold"}});
            for (int x : values) {
                if (static_cast<int>(f) == fill) {
                    const std::string c = valueColour(field, x);
                    swatch({{"fill", c}}, field.values[x]);
                } else {
                    flow.text(field.values[x]);
                }
            }
            break;
        }
        case FieldKind::Int: {
            std::string list;
            for (int x : values) list += (list.empty() ? "" : ", ") + std::to_string(x);
            flow.text(field.name + " (text):", {{"font-weight", "bold"}});
            flow.text(list);
            break;
        }
        case FieldKind::Dir: {
            const std::size_t j =
                std::find(dirFields.begin(), dirFields.end(), static_cast<int>(f)) - dirFields.begin();
            flow.item(36, [&](double x, double y) { legend.line(x, y + 7, x + 30, y + 7, pointerPen(j)); });
            std::string list;
            for (int x : values)
                list += (list.empty() ? "" : ", ") +
                        (x == rules::kAbsent ? std::string("none") : lattice.directionName(x));
            flow.text(field.name + " (arrow" + (slices ? "; +z dot, -z cross" : "") + "): " + list);
            break;
        }
        }
        flow.x = flow.x0, flow.y += 20;
    }
    for (std::size_t n = 0; n < inputs.size(); ++n) {
        bool any = false;
        for (std::uint32_t bits : e.inputs()) any = any || ((bits >> n) & 1u);
        const std::string label = "input " + inputs[n] + (any ? "" : " (holds in no cell)");
        flow.item(18 + 6.2 * static_cast<double>(label.size()), [&](double x, double y) {
            legend.legend(x, y, label,
                          {{"fill", "url(#hatch" + std::to_string(n) + ")"},
                           {"stroke", kInputColour[n % 8]},
                           {"stroke-width", 2}});
        });
    }
    const double height = flow.y + (inputs.empty() ? 0 : 20) + 10;

    rules::Svg defs;
    for (int j = 0; j < 4; ++j) {
        defs.open("marker", {{"id", "head" + std::to_string(j)},
                             {"viewBox", "0 0 8 8"},
                             {"refX", 7},
                             {"refY", 4},
                             {"markerWidth", 7},
                             {"markerHeight", 7},
                             {"markerUnits", "userSpaceOnUse"},
                             {"orient", "auto"}});
        defs.path("M0,0 L8,4 L0,8 z", {{"fill", kPointerColour[j]}}).close("marker");
    }
    for (std::size_t n = 0; n < inputs.size(); ++n) {
        defs.open("pattern", {{"id", "hatch" + std::to_string(n)},
                              {"patternUnits", "userSpaceOnUse"},
                              {"width", 6},
                              {"height", 6},
                              {"patternTransform", std::string("rotate(") + (n % 2 ? "-45" : "45") + ")"}});
        defs.line(0, 0, 0, 6,
                  {{"stroke", kInputColour[n % 8]}, {"stroke-width", 1.5}, {"stroke-opacity", 0.45}})
            .close("pattern");
    }
    return body.picture(width, height, {{"font-family", "sans-serif"}, {"font-size", 11}}, &defs);
}

}  // namespace holon::checker
