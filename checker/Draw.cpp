// Drawing configurations and counterexample traces. The aim is that a person sees the problem at a
// glance: each frame shows which cells the rule changed (red), which cells it only looked at (the
// context and blocking cells of seed 000 Fig. 1a, dashed), and in the last frame the cells a
// violated property points at (crossed, e.g. the part cut off from the rest).

#include "checker/Draw.h"

#include <cmath>
#include <map>
#include <sstream>

namespace holon::checker {

namespace {

bool isSquare(const rules::Engine& e) { return e.region().lattice().kind() == rules::LatticeKind::Square2D; }

/// Direction of the first dir-valued field a state holds, or -1.
int pointerOf(const rules::Engine& e, CellValue v) {
    if (!v) return -1;
    const auto& fields = e.model().alphabet().fields(v);
    for (std::size_t f = 0; f < fields.size(); ++f)
        if (e.model().system().fields[f].kind == rules::FieldKind::Dir && fields[f] != rules::kAbsent) return fields[f];
    return -1;
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
    const rules::Vec a = e.region().cell(p.cells[0]);
    std::string title = e.model().rules()[p.rule].name + " at (" + std::to_string(a.x) + "," + std::to_string(a.y);
    if (e.region().lattice().dimension() == 3) title += "," + std::to_string(a.z);
    return title + ")";
}

}  // namespace

char cellChar(const rules::Engine& e, int, CellValue v) {
    if (!v) return '.';
    const rules::Alphabet& a = e.model().alphabet();
    if (char g = a.glyph(v)) return g;
    if (isSquare(e)) {
        static const char arrows[] = {'>', 'v', '<', '^'};
        if (int d = pointerOf(e, v); d >= 0) return arrows[d];
    }
    return a.name(v)[0];
}

std::string drawAscii(const rules::Engine& e, const std::vector<CellValue>& cells) {
    return drawCells(e.region(), [&](int i) { return cellChar(e, i, cells[i]); });
}

std::string drawCells(const rules::Region& r, const std::function<char(int)>& charOf) {
    const rules::Vec lo = r.lower(), ext = r.extent();
    const bool hex = r.lattice().kind() == rules::LatticeKind::Hex2D;
    std::ostringstream out;
    for (int y = 0; y < ext.y; ++y) {
        if (hex) out << std::string(static_cast<std::size_t>(std::abs(lo.y + y)), ' ');
        for (int z = 0; z < ext.z; ++z) {
            if (z) out << "   ";
            bool first = true;
            for (int x = 0; x < ext.x; ++x) {
                const int i = r.indexOf({lo.x + x, lo.y + y, lo.z + z});
                if (i < 0) continue;
                if (hex && !first) out << ' ';
                out << charOf(i);
                first = false;
            }
        }
        out << '\n';
    }
    return out.str();
}

std::string drawInputsAscii(const rules::Engine& e) {
    const auto& names = e.model().system().inputs;
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
    std::ostringstream out;
    for (std::size_t k = 0; k < t.steps.size(); ++k) {
        out << "-- " << k << ": " << stepTitle(t, e, k) << '\n' << drawAscii(e, t.steps[k].cells);
        for (int i : changedCells(t, k)) {
            const rules::Vec v = e.region().cell(i);
            out << "   (" << v.x << "," << v.y << (e.region().lattice().dimension() == 3 ? "," + std::to_string(v.z) : "") << ") "
                << e.model().alphabet().name(t.steps[k - 1].cells[i]) << " -> " << e.model().alphabet().name(t.steps[k].cells[i]) << '\n';
        }
    }
    if (t.loop) out << "-- the last state loops back to state " << *t.loop << '\n';
    if (!t.marked.empty()) {
        out << "-- marked:";
        for (int i : t.marked) out << " (" << e.region().cell(i).x << "," << e.region().cell(i).y << ")";
        out << '\n';
    }
    return out.str();
}

std::string drawTraceSvg(const Trace& t, const rules::Engine& e, const std::string& title) {
    static const char* palette[] = {"#4e79a7", "#f28e2b", "#59a14f", "#e15759", "#76b7b2", "#edc948", "#b07aa1", "#ff9da7", "#9c755f", "#bab0ac"};
    const rules::Region& r = e.region();
    const rules::Lattice& lattice = r.lattice();
    const bool hex = lattice.kind() == rules::LatticeKind::Hex2D;
    const double s = 26;  // cell size
    const rules::Vec lo = r.lower(), ext = r.extent();
    // Cell centre within a frame: hex cells at their axial positions, 3D regions as z slices.
    auto rawCentre = [&](rules::Vec v) {
        if (hex) return std::pair<double, double>{s * std::sqrt(3.0) * 0.5 * (v.x + v.y / 2.0), s * 0.75 * v.y};
        const double slice = (v.z - lo.z) * (ext.x + 1) * s;
        return std::pair<double, double>{slice + (v.x - lo.x) * s, (v.y - lo.y) * s};
    };
    double minX = 1e9, minY = 1e9, maxX = -1e9, maxY = -1e9;
    for (const rules::Vec& v : r.cells()) {
        auto [x, y] = rawCentre(v);
        minX = std::min(minX, x), maxX = std::max(maxX, x), minY = std::min(minY, y), maxY = std::max(maxY, y);
    }
    auto centre = [&](rules::Vec v) {
        auto [x, y] = rawCentre(v);
        return std::pair<double, double>{x - minX + s / 2, y - minY + s / 2};
    };
    double frameW = std::max(170.0, maxX - minX + s + 24), frameH = maxY - minY + s + 44;
    const int perRow = std::max(1, std::min<int>(5, static_cast<int>(t.steps.size())));
    const int rows = (static_cast<int>(t.steps.size()) + perRow - 1) / perRow;
    // Colour by the state's first enum value, so U/P/F or D/C/B1 keep one colour each.
    std::map<std::string, std::string> colour;
    auto colourOf = [&](CellValue v) {
        std::string key = e.model().alphabet().name(v);
        key = key.substr(0, key.find('&'));
        auto it = colour.find(key);
        if (it == colour.end()) it = colour.emplace(key, palette[colour.size() % 10]).first;
        return it->second;
    };
    const double legendH = 30;
    std::ostringstream out;
    const double width = std::max(perRow * frameW + 20, 20 + 8.0 * static_cast<double>(title.size()));
    out << "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" << width << "\" height=\"" << rows * frameH + 50 + legendH
        << "\" font-family=\"sans-serif\" font-size=\"11\">\n<rect width=\"100%\" height=\"100%\" fill=\"white\"/>\n"
        << "<text x=\"10\" y=\"20\" font-size=\"14\" font-weight=\"bold\">" << title << "</text>\n";
    for (std::size_t k = 0; k < t.steps.size(); ++k) {
        const double ox = 10 + (k % perRow) * frameW, oy = 40 + (k / perRow) * frameH;
        out << "<g transform=\"translate(" << ox << "," << oy << ")\">\n<text x=\"0\" y=\"0\">" << k << ": " << stepTitle(t, e, k) << "</text>\n";
        out << "<g transform=\"translate(0,8)\">\n";
        const auto changed = changedCells(t, k);
        std::vector<int> context;
        if (t.steps[k].placed >= 0) {
            const auto& p = e.instances()[t.steps[k].placed];
            for (int c = 0; c < p.size; ++c)
                if (std::find(changed.begin(), changed.end(), p.cells[c]) == changed.end()) context.push_back(p.cells[c]);
        }
        for (int i = 0; i < r.size(); ++i) {
            const CellValue v = t.steps[k].cells[i];
            auto [cx, cy] = centre(r.cell(i));
            const bool isChanged = std::find(changed.begin(), changed.end(), i) != changed.end();
            const bool isContext = std::find(context.begin(), context.end(), i) != context.end();
            const std::string fill = v ? colourOf(v) : "#ffffff";
            const std::string stroke = isChanged ? "stroke=\"#d62728\" stroke-width=\"3\"" : isContext ? "stroke=\"#ff7f0e\" stroke-width=\"2.5\" stroke-dasharray=\"4,2\"" : "stroke=\"#999\" stroke-width=\"0.8\"";
            if (hex) {
                out << "<polygon points=\"";
                for (int c = 0; c < 6; ++c) {
                    const double a = M_PI / 180 * (60 * c - 30);
                    out << cx + s * 0.5 * std::cos(a) << "," << cy + s * 0.5 * std::sin(a) << " ";
                }
                out << "\" fill=\"" << fill << "\" " << stroke << "/>\n";
            } else {
                out << "<rect x=\"" << cx - s / 2 + 1 << "\" y=\"" << cy - s / 2 + 1 << "\" width=\"" << s - 2 << "\" height=\"" << s - 2
                    << "\" fill=\"" << fill << "\" " << stroke << "/>\n";
            }
            if (v) {
                const rules::Alphabet& a = e.model().alphabet();
                std::string label = a.glyph(v) ? std::string(1, a.glyph(v)) : a.name(v).substr(0, a.name(v).find('&'));
                out << "<text x=\"" << cx << "\" y=\"" << cy + 4 << "\" text-anchor=\"middle\" fill=\"white\">" << label << "</text>\n";
                if (int d = pointerOf(e, v); d >= 0 && lattice.dimension() == 2) {
                    auto [tx, ty] = centre(r.cell(i) + lattice.direction(d));
                    out << "<line x1=\"" << cx << "\" y1=\"" << cy << "\" x2=\"" << (cx + tx) / 2 << "\" y2=\"" << (cy + ty) / 2
                        << "\" stroke=\"black\" stroke-width=\"2\"/>\n";
                }
            }
            std::string inputMarks;
            for (std::size_t n = 0; n < e.model().system().inputs.size(); ++n)
                if ((e.inputs()[i] >> n) & 1u) inputMarks += (inputMarks.empty() ? "" : ",") + std::to_string(n + 1);
            if (!inputMarks.empty())
                out << "<text x=\"" << cx - s / 2 + 3 << "\" y=\"" << cy - s / 2 + 9 << "\" font-size=\"7\" fill=\"#222\">" << inputMarks << "</text>\n";
            if (k + 1 == t.steps.size() && std::find(t.marked.begin(), t.marked.end(), i) != t.marked.end())
                out << "<path d=\"M" << cx - 8 << "," << cy - 8 << " L" << cx + 8 << "," << cy + 8 << " M" << cx + 8 << "," << cy - 8 << " L"
                    << cx - 8 << "," << cy + 8 << "\" stroke=\"#d62728\" stroke-width=\"3\"/>\n";
        }
        if (lattice.dimension() == 3)
            for (int z = 0; z < ext.z; ++z)
                out << "<text x=\"" << z * (ext.x + 1) * s << "\" y=\"" << ext.y * s + 12 << "\">z=" << lo.z + z << "</text>\n";
        out << "</g></g>\n";
    }
    double lx = 10;
    const double ly = 40 + rows * frameH + 10;
    out << "<rect x=\"" << lx << "\" y=\"" << ly << "\" width=\"14\" height=\"14\" fill=\"white\" stroke=\"#d62728\" stroke-width=\"3\"/><text x=\"" << lx + 18 << "\" y=\"" << ly + 11 << "\">changed</text>\n";
    lx += 80;
    out << "<rect x=\"" << lx << "\" y=\"" << ly << "\" width=\"14\" height=\"14\" fill=\"white\" stroke=\"#ff7f0e\" stroke-width=\"2.5\" stroke-dasharray=\"4,2\"/><text x=\"" << lx + 18 << "\" y=\"" << ly + 11 << "\">context / blocking</text>\n";
    lx += 130;
    for (const auto& [name, c] : colour) {
        out << "<rect x=\"" << lx << "\" y=\"" << ly << "\" width=\"14\" height=\"14\" fill=\"" << c << "\"/><text x=\"" << lx + 18 << "\" y=\"" << ly + 11 << "\">" << name << "</text>\n";
        lx += 30 + 7 * name.size();
    }
    const auto& inputs = e.model().system().inputs;
    for (std::size_t n = 0; n < inputs.size(); ++n) {
        const std::string text = std::to_string(n + 1) + ": input " + inputs[n];
        out << "<text x=\"" << lx << "\" y=\"" << ly + 11 << "\" font-size=\"9\" fill=\"#222\">" << text << "</text>\n";
        lx += 12 + 6 * text.size();
    }
    out << "</svg>\n";
    return out.str();
}

}  // namespace holon::checker
