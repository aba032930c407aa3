// SVG pictures of a Roombots assembly run (seed 001 Figs. 6 and 7): the trace of every metamodule's
// foot seen from above, with the force vector it followed at each step as a quiver, over the goal
// structure's footprint; and an isometric view of the cells every metamodule fills at the end.

#include "planner/roombots/Draw.h"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <tuple>

namespace holon::planner::roombots {
namespace {

const char* colour(int module) {
    static constexpr const char* kColours[] = {"#1f77b4", "#d62728", "#2ca02c", "#9467bd", "#ff7f0e", "#17becf", "#8c564b", "#e377c2"};
    return kColours[module % 8];
}

}  // namespace

std::string footTraceSvg(const Setting& setting, const AssemblyResult& result) {
    int x0 = 1 << 20, x1 = -(1 << 20), y0 = x0, y1 = x1;
    auto extend = [&](const Cell& c) { x0 = std::min(x0, c.x), x1 = std::max(x1, c.x), y0 = std::min(y0, c.y), y1 = std::max(y1, c.y); };
    for (const Seed& s : setting.recipe.seeds)
        for (const Cell& c : s.cells) extend(c);
    for (const Cell& c : setting.starts) extend(c);
    for (const Action& a : result.actions) extend(a.from), extend(a.to);
    x0 -= 1, y0 -= 1, x1 += 1, y1 += 1;
    const double s = 18;
    auto px = [&](double x) { return (x - x0 + 0.5) * s; };
    auto py = [&](double y) { return (y1 - y + 0.5) * s; };
    std::ostringstream svg;
    svg << "<svg xmlns='http://www.w3.org/2000/svg' width='" << (x1 - x0 + 1) * s << "' height='" << (y1 - y0 + 1) * s + 20
        << "' font-size='11'>\n<rect width='100%' height='100%' fill='white'/>\n";
    for (int x = x0; x <= x1 + 1; ++x)
        svg << "<line x1='" << px(x - 0.5) << "' x2='" << px(x - 0.5) << "' y1='0' y2='" << (y1 - y0 + 1) * s << "' stroke='#eee'/>\n";
    for (int y = y0 - 1; y <= y1; ++y)
        svg << "<line y1='" << py(y + 0.5) << "' y2='" << py(y + 0.5) << "' x1='0' x2='" << (x1 - x0 + 1) * s << "' stroke='#eee'/>\n";
    for (const Seed& seed : setting.recipe.seeds)
        for (const Cell& c : seed.cells)
            svg << "<rect x='" << px(c.x - 0.5) << "' y='" << py(c.y + 0.5) << "' width='" << s << "' height='" << s << "' fill='#ccc' opacity='0.5'/>\n";
    for (std::size_t m = 0; m < setting.starts.size(); ++m) {
        svg << "<polyline fill='none' stroke='" << colour(m) << "' stroke-width='1.5' points='" << px(setting.starts[m].x) << ','
            << py(setting.starts[m].y);
        for (const Action& a : result.actions)
            if (a.module == static_cast<int>(m) && !a.seat) svg << ' ' << px(a.to.x) << ',' << py(a.to.y);
        svg << "'/>\n";
        for (const Action& a : result.actions) {
            if (a.module != static_cast<int>(m) || a.seat) continue;
            svg << "<circle cx='" << px(a.to.x) << "' cy='" << py(a.to.y) << "' r='2' fill='" << colour(m) << "'/>\n";
            const double n = std::hypot(a.forceX, a.forceY);
            if (n > 0)
                svg << "<line x1='" << px(a.from.x) << "' y1='" << py(a.from.y) << "' x2='" << px(a.from.x + 0.8 * a.forceX / n) << "' y2='"
                    << py(a.from.y + 0.8 * a.forceY / n) << "' stroke='" << colour(m) << "' opacity='0.6'/>\n";
        }
    }
    svg << "<text x='4' y='" << (y1 - y0 + 1) * s + 14 << "'>" << (result.completed ? "completed" : "deadlocked") << ", "
        << result.collisions << " collisions, " << result.meanMoves << " moves per metamodule</text>\n</svg>\n";
    return svg.str();
}

std::string isometricSvg(const Setting& setting, const std::vector<std::array<Cell, 4>>& cells) {
    struct Cube {
        Cell c;
        int module;
    };
    std::vector<Cube> cubes;
    for (std::size_t m = 0; m < cells.size(); ++m)
        for (const Cell& c : cells[m]) cubes.push_back({c, static_cast<int>(m)});
    // Nearer cubes (larger x + y, then higher) are painted last.
    std::sort(cubes.begin(), cubes.end(), [](const Cube& a, const Cube& b) {
        return std::tuple(a.c.x + a.c.y, a.c.z, a.c.x) < std::tuple(b.c.x + b.c.y, b.c.z, b.c.x);
    });
    const double s = 30, a = s * 0.866, b = s * 0.5;
    double minX = 1e9, maxX = -1e9, minY = 1e9, maxY = -1e9;
    auto sx = [&](double x, double y) { return (x - y) * a; };
    auto sy = [&](double x, double y, double z) { return (x + y) * b - z * s; };
    for (const Cube& q : cubes)
        for (int dx = 0; dx < 2; ++dx)
            for (int dy = 0; dy < 2; ++dy)
                for (int dz = 0; dz < 2; ++dz) {
                    minX = std::min(minX, sx(q.c.x + dx, q.c.y + dy)), maxX = std::max(maxX, sx(q.c.x + dx, q.c.y + dy));
                    minY = std::min(minY, sy(q.c.x + dx, q.c.y + dy, q.c.z + dz)), maxY = std::max(maxY, sy(q.c.x + dx, q.c.y + dy, q.c.z + dz));
                }
    for (const Seed& seed : setting.recipe.seeds)
        for (const Cell& c : seed.cells) minX = std::min(minX, sx(c.x, c.y + 1)), maxX = std::max(maxX, sx(c.x + 1, c.y));
    const double ox = 10 - minX, oy = 10 - minY;
    std::ostringstream svg;
    svg << "<svg xmlns='http://www.w3.org/2000/svg' width='" << maxX - minX + 20 << "' height='" << maxY - minY + 20
        << "'>\n<rect width='100%' height='100%' fill='white'/>\n";
    auto polygon = [&](std::initializer_list<std::array<double, 3>> corners, const char* fill, double shade) {
        svg << "<polygon points='";
        for (const auto& p : corners) svg << ox + sx(p[0], p[1]) << ',' << oy + sy(p[0], p[1], p[2]) << ' ';
        svg << "' fill='" << fill << "' fill-opacity='" << shade << "' stroke='#333' stroke-width='0.5'/>\n";
    };
    for (const Seed& seed : setting.recipe.seeds)  // the goal's footprint on the floor
        for (const Cell& c : seed.cells)
            if (c.z == 0) polygon({{double(c.x), double(c.y), 0}, {c.x + 1.0, double(c.y), 0}, {c.x + 1.0, c.y + 1.0, 0}, {double(c.x), c.y + 1.0, 0}}, "#bbb", 0.4);
    for (const Cube& q : cubes) {
        const double x = q.c.x, y = q.c.y, z = q.c.z;
        polygon({{x, y, z + 1}, {x + 1, y, z + 1}, {x + 1, y + 1, z + 1}, {x, y + 1, z + 1}}, colour(q.module), 0.9);
        polygon({{x + 1, y, z}, {x + 1, y + 1, z}, {x + 1, y + 1, z + 1}, {x + 1, y, z + 1}}, colour(q.module), 0.7);
        polygon({{x, y + 1, z}, {x + 1, y + 1, z}, {x + 1, y + 1, z + 1}, {x, y + 1, z + 1}}, colour(q.module), 0.5);
    }
    svg << "</svg>\n";
    return svg.str();
}

std::string assemblySvg(const Setting& setting, const AssemblyResult& result) {
    std::vector<std::vector<std::array<Cell, 4>>> frames = result.snapshots;
    if (frames.empty() || result.deadlocked) frames.push_back(result.cells);
    std::ostringstream body;
    double x = 0, height = 0;
    for (const auto& cells : frames) {
        std::string frame = isometricSvg(setting, cells);
        const std::size_t w = frame.find("width='") + 7, h = frame.find("height='") + 8;
        const double width = std::stod(frame.substr(w)), frameHeight = std::stod(frame.substr(h));
        frame.replace(0, frame.find('>') + 1, "<svg x='" + std::to_string(x) + "' width='" + std::to_string(width) + "' height='" +
                                                   std::to_string(frameHeight) + "'>");
        body << frame;
        x += width, height = std::max(height, frameHeight);
    }
    return "<svg xmlns='http://www.w3.org/2000/svg' width='" + std::to_string(x) + "' height='" + std::to_string(height) +
           "'>\n<rect width='100%' height='100%' fill='white'/>\n" + body.str() + "</svg>\n";
}

}  // namespace holon::planner::roombots
