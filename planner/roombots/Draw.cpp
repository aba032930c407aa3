// SVG pictures of a Roombots assembly run (seed 001 Figs. 6 and 7): the trace of every metamodule's
// foot seen from above, with the force vector it followed at each step as a quiver, over the goal
// structure's footprint; and an isometric view of the cells every metamodule fills at the end.

#include "planner/roombots/Draw.h"

#include "rules/Svg.h"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <sstream>
#include <tuple>

namespace holon::planner::roombots {
namespace {

const char* colourOf(int module) {
    static constexpr const char* kColours[] = {"#1f77b4", "#d62728", "#2ca02c", "#9467bd", "#ff7f0e", "#17becf", "#8c564b", "#e377c2"};
    return kColours[module % 8];
}

/// The isometric picture.
rules::SvgPicture isometric(const Setting& setting, const std::vector<std::array<Cell, 4>>& cells) {
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
    rules::Svg out;
    const double width = maxX - minX + 20, height = maxY - minY + 20;
    auto polygon = [&](std::initializer_list<std::array<double, 3>> corners, const char* fill, double shade) {
        std::vector<std::pair<double, double>> points;
        for (const auto& p : corners) points.push_back({ox + sx(p[0], p[1]), oy + sy(p[0], p[1], p[2])});
        out.polygon(points, {{"fill", fill}, {"fill-opacity", shade}, {"stroke", "#333"}, {"stroke-width", 0.5}});
    };
    for (const Seed& seed : setting.recipe.seeds)  // the goal's footprint on the floor
        for (const Cell& c : seed.cells)
            if (c.z == 0) polygon({{double(c.x), double(c.y), 0}, {c.x + 1.0, double(c.y), 0}, {c.x + 1.0, c.y + 1.0, 0}, {double(c.x), c.y + 1.0, 0}}, "#bbb", 0.4);
    for (const Cube& q : cubes) {
        const double x = q.c.x, y = q.c.y, z = q.c.z;
        polygon({{x, y, z + 1}, {x + 1, y, z + 1}, {x + 1, y + 1, z + 1}, {x, y + 1, z + 1}}, colourOf(q.module), 0.9);
        polygon({{x + 1, y, z}, {x + 1, y + 1, z}, {x + 1, y + 1, z + 1}, {x + 1, y, z + 1}}, colourOf(q.module), 0.7);
        polygon({{x, y + 1, z}, {x + 1, y + 1, z}, {x + 1, y + 1, z + 1}, {x, y + 1, z + 1}}, colourOf(q.module), 0.5);
    }
    return out.picture(width, height);
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
    const double s = 18, width = (x1 - x0 + 1) * s, height = (y1 - y0 + 1) * s;
    auto px = [&](double x) { return (x - x0 + 0.5) * s; };
    auto py = [&](double y) { return (y1 - y + 0.5) * s; };
    rules::Svg svg;
    for (int x = x0; x <= x1 + 1; ++x) svg.line(px(x - 0.5), 0, px(x - 0.5), height, {{"stroke", "#eee"}});
    for (int y = y0 - 1; y <= y1; ++y) svg.line(0, py(y + 0.5), width, py(y + 0.5), {{"stroke", "#eee"}});
    for (const Seed& seed : setting.recipe.seeds)
        for (const Cell& c : seed.cells) svg.rect(px(c.x - 0.5), py(c.y + 0.5), s, s, {{"fill", "#ccc"}, {"opacity", 0.5}});
    for (std::size_t m = 0; m < setting.starts.size(); ++m) {
        std::vector<std::pair<double, double>> path{{px(setting.starts[m].x), py(setting.starts[m].y)}};
        for (const Action& a : result.actions)
            if (a.module == static_cast<int>(m) && !a.seat) path.push_back({px(a.to.x), py(a.to.y)});
        svg.polyline(path, {{"fill", "none"}, {"stroke", colourOf(m)}, {"stroke-width", 1.5}});
        for (const Action& a : result.actions) {
            if (a.module != static_cast<int>(m) || a.seat) continue;
            svg.circle(px(a.to.x), py(a.to.y), 2, {{"fill", colourOf(m)}});
            const double n = std::hypot(a.forceX, a.forceY);
            if (n > 0)
                svg.line(px(a.from.x), py(a.from.y), px(a.from.x + 0.8 * a.forceX / n), py(a.from.y + 0.8 * a.forceY / n),
                         {{"stroke", colourOf(m)}, {"opacity", 0.6}});
        }
    }
    std::ostringstream caption;
    caption << (result.completed ? "completed" : "deadlocked") << ", " << result.collisions << " collisions, " << result.meanMoves
            << " moves per metamodule";
    svg.text(4, height + 14, caption.str());
    return svg.document(width, height + 20, {{"font-size", 11}});
}

std::string isometricSvg(const Setting& setting, const std::vector<std::array<Cell, 4>>& cells) {
    return isometric(setting, cells).document;
}

std::string assemblySvg(const Setting& setting, const AssemblyResult& result) {
    std::vector<std::vector<std::array<Cell, 4>>> frames = result.snapshots;
    if (frames.empty() || result.deadlocked) frames.push_back(result.cells);
    rules::Svg svg;
    double x = 0, height = 0;
    for (const auto& cells : frames) {
        const rules::SvgPicture p = isometric(setting, cells);
        svg.nested(p.document, x);
        x += p.width, height = std::max(height, p.height);
    }
    return svg.document(x, height);
}

std::string runSteps(const Setting& setting, const AssemblyResult& result, const std::string& title) {
    // The region: the box around every cell the run touches and every seed's.
    Cell lo = result.start.empty() ? Cell{} : result.start[0][0], hi = lo;
    const auto extend = [&](const Cell& c) {
        lo = {std::min(lo.x, c.x), std::min(lo.y, c.y), std::min(lo.z, c.z)}, hi = {std::max(hi.x, c.x), std::max(hi.y, c.y), std::max(hi.z, c.z)};
    };
    for (const auto& cells : result.start)
        for (const Cell& c : cells) extend(c);
    for (const Action& a : result.actions)
        for (const Cell& c : a.cells) extend(c);
    for (const Seed& seed : setting.recipe.seeds)
        for (const Cell& c : seed.cells) extend(c);
    const auto at = [&](const Cell& c) { return nlohmann::json{c.x - lo.x, c.y - lo.y, c.z - lo.z}; };
    nlohmann::json colours = nlohmann::json::array(), cells = nlohmann::json::array(), structure = nlohmann::json::array();
    for (std::size_t m = 0; m < result.start.size(); ++m) {
        colours.push_back(colourOf(static_cast<int>(m)));
        for (const Cell& c : result.start[m]) cells.push_back({{"at", at(c)}, {"module", m}});
    }
    for (const Seed& seed : setting.recipe.seeds)
        for (const Cell& c : seed.cells) structure.push_back(at(c));
    const std::string region = "cubic:" + std::to_string(hi.x - lo.x + 1) + "x" + std::to_string(hi.y - lo.y + 1) + "x" + std::to_string(hi.z - lo.z + 1);
    std::ostringstream out;
    out << nlohmann::json{{"run", "roombots"}, {"title", title}, {"colours", colours}, {"start", {{"region", region}, {"offset", {-lo.x, -lo.y, -lo.z}}, {"cells", cells}, {"inputs", {{"structure", structure}}}}}}
               .dump()
        << '\n';
    std::vector<std::array<Cell, 4>> now = result.start;
    for (std::size_t k = 0; k < result.actions.size(); ++k) {
        const Action& a = result.actions[k];
        nlohmann::json touched = nlohmann::json::array(), after = nlohmann::json::array();
        for (const Cell& c : now[a.module])
            if (std::find(a.cells.begin(), a.cells.end(), c) == a.cells.end()) touched.push_back({c.x, c.y, c.z}), after.push_back(nlohmann::json::object());
        for (const Cell& c : a.cells) touched.push_back({c.x, c.y, c.z}), after.push_back({{"module", a.module}});
        now[a.module] = a.cells;
        out << nlohmann::json{{"round", k}, {"time", a.begin}, {"rule", a.seat ? "seat" : "step"}, {"cells", touched}, {"after", after}}.dump() << '\n';
    }
    return out.str();
}

}  // namespace holon::planner::roombots
