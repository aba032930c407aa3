// Shapes for planning problems (issue: start and target shapes in 2D and 3D). The block shapes
// reproduce seed 000 §V (6x3x2 -> 3x3x4, scaled); the others are the usual test shapes of the
// shape-formation literature: a T, a disc, a ring and a chair (seed 001's chair, as voxels).

#include "planner/Shape.h"

#include "rules/Binvox.h"
#include "rules/Components.h"
#include "rules/ConfigIo.h"
#include "rules/Error.h"
#include "rules/Escape.h"
#include "rules/Limits.h"
#include "rules/OutputFile.h"
#include "rules/Parameter.h"
#include "rules/Picture.h"
#include "rules/TextFile.h"
#include "rules/VisibleSim.h"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <charconv>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <functional>
#include <optional>
#include <sstream>

namespace holon::planner {

namespace {

[[noreturn]] void bad(std::string_view argument, const std::string& why, std::optional<rules::Parameter> about = std::nullopt) {
    throw InputError("shape '" + std::string(argument) + "': " + why, about);
}

std::vector<int> numbers(std::string_view argument, std::string_view text, char separator, std::size_t minCount, std::size_t maxCount) {
    std::vector<int> out;
    std::size_t start = 0;
    while (true) {
        const std::size_t end = text.find(separator, start);
        const std::string_view part = text.substr(start, end == std::string_view::npos ? text.npos : end - start);
        int v = 0;
        auto [p, ec] = std::from_chars(part.data(), part.data() + part.size(), v);
        if (part.empty() || ec != std::errc{} || p != part.data() + part.size() || v < 1 || v > 1000000)
            bad(argument, "'" + std::string(part) + "' is not a size between 1 and 1000000");
        out.push_back(v);
        if (end == std::string_view::npos) break;
        start = end + 1;
    }
    if (out.size() < minCount || out.size() > maxCount)
        bad(argument, "expected " + std::to_string(minCount) + (minCount == maxCount ? "" : " or " + std::to_string(maxCount)) + " numbers");
    return out;
}

/// What a shape's cell takes while it is made: the cell and its copy in the sorted or scaled shape.
constexpr std::uint64_t kBytesPerCell = 2 * sizeof(Vec);

/// Checked before a shape's cells are made: the count (computed with rules::checkedProduct, so a
/// product past 2^64 fails too) against the planner's limit, their memory against --memory.
void checkSize(std::string_view argument, std::uint64_t cells, std::size_t maxCells, std::uint64_t memoryBytes) {
    if (cells > maxCells)
        bad(argument, rules::countText(cells) + " cells is more than the limit of " + std::to_string(maxCells) + "; choose a smaller shape or " + rules::parameterName(rules::Parameter::Scale),
            rules::Parameter::Scale);
    rules::requireMemory(rules::checkedProduct({cells, kBytesPerCell}), memoryBytes, "shape '" + std::string(argument) + "' (" + std::to_string(cells) + " cells)");
}

/// A coordinate read from a file, refused beyond +-rules::kMaxCoordinate (an int would wrap it silently).
int coordinate(std::string_view argument, std::int64_t v, const std::string& where) {
    if (v < -rules::kMaxCoordinate || v > rules::kMaxCoordinate)
        bad(argument, where + ": coordinate " + std::to_string(v) + " is beyond +-" + std::to_string(rules::kMaxCoordinate) + "; move the shape nearer the origin");
    return static_cast<int>(v);
}

/// A file's cells each once: a cell listed twice is a mistake in the file, named by `where(k)` of
/// both entries, not merged in silence.
void requireDistinct(std::string_view argument, const Shape& shape, const std::function<std::string(std::size_t)>& where) {
    const std::vector<Vec>& cells = shape.cells;
    std::vector<std::pair<Vec, std::size_t>> sorted(cells.size());
    for (std::size_t k = 0; k < cells.size(); ++k) sorted[k] = {cells[k], k};
    std::sort(sorted.begin(), sorted.end());
    for (std::size_t k = 1; k < sorted.size(); ++k)
        if (sorted[k].first == sorted[k - 1].first) {
            const Vec c = sorted[k].first;
            bad(argument, where(sorted[k].second) + ": cell " + showCell(c, shape.dimension) + " is listed twice (also " + where(sorted[k - 1].second) + "); list each cell once");
        }
}

Shape box(std::string_view argument, std::string_view dims, std::size_t maxCells, std::uint64_t memoryBytes) {
    const std::vector<int> n = numbers(argument, dims, 'x', 2, 3);
    Shape s;
    s.dimension = static_cast<int>(n.size());
    const int depth = s.dimension == 3 ? n[2] : 1;
    checkSize(argument, rules::checkedProduct({std::uint64_t(n[0]), std::uint64_t(n[1]), std::uint64_t(depth)}), maxCells, memoryBytes);
    s.cells.reserve(std::size_t(n[0]) * n[1] * depth);
    for (int x = 0; x < n[0]; ++x)
        for (int y = 0; y < n[1]; ++y)
            for (int z = 0; z < depth; ++z) s.cells.push_back({x, y, z});
    return s;
}

/// A T of width N: a bar N wide and ceil(N/3) thick on top of a centred stem ceil(N/3) wide and N
/// tall; on top as the pictures show it, where y runs down the page (the bar at the smallest y).
Shape tee(std::string_view argument, std::string_view size, std::size_t maxCells, std::uint64_t memoryBytes) {
    const int n = numbers(argument, size, ',', 1, 1)[0];
    const int t = (n + 2) / 3;
    checkSize(argument, std::uint64_t(n) * t * 2, maxCells, memoryBytes);
    Shape s;
    const int stem = (n - t) / 2;
    for (int x = 0; x < n; ++x)
        for (int y = 0; y < n + t; ++y)
            if (y < t || (x >= stem && x < stem + t)) s.cells.push_back({x, y, 0});
    return s;
}

/// Cells whose centre lies at distance r with r1 <= r <= r2 from the centre (R2, R2).
Shape annulus(std::string_view argument, int r1, int r2, std::size_t maxCells, std::uint64_t memoryBytes) {
    checkSize(argument, (2 * std::uint64_t(r2) + 1) * (2 * std::uint64_t(r2) + 1), maxCells, memoryBytes);
    Shape s;
    for (int x = 0; x <= 2 * r2; ++x)
        for (int y = 0; y <= 2 * r2; ++y) {
            const long d2 = long(x - r2) * (x - r2) + long(y - r2) * (y - r2);
            if (d2 <= long(r2) * r2 && d2 >= long(r1) * r1) s.cells.push_back({x, y, 0});
        }
    return s;
}

/// A chair of size N: an NxN seat at height N on four 1x1 legs, a backrest N high on the back edge.
Shape chair(std::string_view argument, std::string_view size, std::size_t maxCells, std::uint64_t memoryBytes) {
    const int n = numbers(argument, size, ',', 1, 1)[0];
    if (n < 2) bad(argument, "a chair needs N >= 2");
    checkSize(argument, std::uint64_t(n) * n * 3, maxCells, memoryBytes);
    Shape s;
    s.dimension = 3;
    for (int x = 0; x < n; ++x)
        for (int y = 0; y < n; ++y)
            for (int z = 0; z <= 2 * n; ++z) {
                const bool leg = z < n && (x == 0 || x == n - 1) && (y == 0 || y == n - 1);
                const bool seat = z == n;
                const bool back = z > n && y == n - 1;
                if (leg || seat || back) s.cells.push_back({x, y, z});
            }
    return s;
}

Shape fromJson(std::string_view argument, const std::string& text) {
    nlohmann::json j;
    try {
        j = rules::parseJsonOnceEach(text);
    } catch (const nlohmann::json::exception& e) {  // parse_error, and out_of_range for a number past a double
        bad(argument, "not valid JSON: " + rules::jsonErrorText(e));
    } catch (const InputError& e) {  // a key given twice
        bad(argument, e.what());
    }
    const nlohmann::json& list = j.is_object() && j.contains("cells") ? j["cells"] : j;
    if (!list.is_array()) bad(argument, "expected a JSON array of cells, or an object with a \"cells\" array");
    Shape s;
    s.dimension = 0;
    const auto where = [](std::size_t i) { return "cell " + std::to_string(i); };
    for (std::size_t i = 0; i < list.size(); ++i) {
        const nlohmann::json& c = list[i];
        if (!c.is_array() || c.size() < 2 || c.size() > 3 || !std::all_of(c.begin(), c.end(), [](auto& v) { return v.is_number_integer(); }))
            bad(argument, where(i) + " is not [x, y] or [x, y, z] with integer coordinates");
        const int dim = static_cast<int>(c.size());
        if (s.dimension && dim != s.dimension) bad(argument, where(i) + " has " + std::to_string(dim) + " coordinates, earlier cells " + std::to_string(s.dimension));
        s.dimension = dim;
        const auto at = [&](std::size_t k) {  // an unsigned beyond int64 is beyond the range too
            return coordinate(argument, c[k].is_number_unsigned() && c[k].get<std::uint64_t>() > std::uint64_t(INT64_MAX) ? INT64_MAX : c[k].get<std::int64_t>(), where(i));
        };
        s.cells.push_back({at(0), at(1), dim == 3 ? at(2) : 0});
    }
    if (!s.dimension) s.dimension = 2;
    requireDistinct(argument, s, where);
    return s;
}

/// Lines "x y z"; '#' starts a comment.
Shape fromVoxels(std::string_view argument, const std::string& text) {
    Shape s;
    s.dimension = 3;
    std::istringstream in(text);
    std::string line;
    std::vector<int> lineOf;
    for (int number = 1; std::getline(in, line); ++number) {
        if (auto hash = line.find('#'); hash != std::string::npos) line.erase(hash);
        std::istringstream fields(line);
        std::int64_t x = 0, y = 0, z = 0;
        std::string extra;
        if (!(fields >> extra)) continue;
        fields.clear(), fields.seekg(0);
        const std::string where = "line " + std::to_string(number);
        if (!(fields >> x >> y >> z) || (fields >> extra)) bad(argument, where + ": expected three integers 'x y z'");
        s.cells.push_back({coordinate(argument, x, where), coordinate(argument, y, where), coordinate(argument, z, where)});
        lineOf.push_back(number);
    }
    requireDistinct(argument, s, [&](std::size_t k) { return "line " + std::to_string(lineOf[k]); });
    return s;
}

/// ASCII art (rules/Picture.h: rows equally wide): '#', 'X', 'x', 'O', 'o', '@', '*' or '1' is a
/// cell, '.', ' ', '_' or '0' is empty; the first line is the top row.
Shape fromAscii(std::string_view argument, const std::string& text) {
    std::vector<std::string> lines;
    try {
        lines = rules::pictureRows(text, true);
    } catch (const InputError& e) {
        bad(argument, e.what());
    }
    Shape s;
    if (lines.size() > std::size_t(rules::kMaxCoordinate) || (!lines.empty() && lines[0].size() > std::size_t(rules::kMaxCoordinate)))
        bad(argument, "the picture is larger than " + std::to_string(rules::kMaxCoordinate) + " cells across");
    const int rows = static_cast<int>(lines.size());
    for (int r = 0; r < rows; ++r)
        for (int c = 0; c < static_cast<int>(lines[r].size()); ++c) {
            const char ch = lines[r][c];
            // Line r is row y = r, as in the checker's pictures (rules/ConfigIo.h): y runs down the page.
            if (std::string_view("#XxOo@*1").find(ch) != std::string_view::npos) s.cells.push_back({c, r, 0});
            else if (std::string_view(". _0\t").find(ch) == std::string_view::npos)
                bad(argument, "line " + std::to_string(r + 1) + ", column " + std::to_string(c + 1) + ": '" + rules::escapeText(std::string(1, ch)) +
                                  "' is neither a cell ('#', or X x O o @ * 1) nor empty ('.', or space _ 0 tab)");
        }
    return s;
}

/// A .binvox voxel file (rules/Binvox.h): checked and counted first, so a shape too large is
/// refused before its cells are made; a malformed file is named with the byte that is wrong.
Shape fromBinvox(std::string_view argument, const std::string& bytes, std::size_t maxCells, std::uint64_t memoryBytes) {
    Shape s;
    s.dimension = 3;
    try {
        const rules::BinvoxInfo info = rules::scanBinvox(bytes);
        checkSize(argument, info.filled, maxCells, memoryBytes);
        s.cells = rules::binvoxCells(bytes, info);
    } catch (const InputError& e) {
        bad(argument, e.what());
    }
    return s;
}

/// A VisibleSim world (rules/VisibleSim.h): its modules, or with `target` its first grid target.
Shape fromVisibleSim(std::string_view argument, const std::string& text, bool target, std::size_t maxCells) {
    Shape s;
    try {
        const rules::VisibleSimCells world = rules::readVisibleSimWorld(text, maxCells);
        if (world.lattice->kind() == rules::LatticeKind::Hex2D)
            bad(argument, "a hex2d (hexanodes) world; plan runs on square2d and cubic3d, hex shapes are for holon hex");
        s.dimension = world.lattice->dimension();
        s.cells = target ? world.targets : world.blocks;
    } catch (const InputError& e) {
        if (std::string_view(e.what()).starts_with("shape '")) throw;
        bad(argument, e.what());
    }
    if (target && s.cells.empty()) bad(argument, "the world has no grid target (<targetList><target format=\"grid\">)");
    return s;
}

Shape fromFile(std::string_view argument, std::size_t maxCells, std::uint64_t memoryBytes) {
    // WORLD.xml#target: the target of a VisibleSim world, when no file has that name.
    std::string path(argument);
    // exists(), not opening the file: opening a FIFO waits for its writer (readTextFile does, and
    // a signal stops it there).
    std::error_code missing;
    const bool target = path.ends_with(".xml#target") && !std::filesystem::exists(path, missing);
    if (target) path.resize(path.size() - 7);
    if (!std::filesystem::exists(path, missing)) {
        std::string known;
        for (const auto& [name, what] : shapeGenerators()) known += (known.empty() ? "" : ", ") + name;
        bad(argument, "neither a shape generator (" + known + ") nor a readable file");
    }
    rules::OutputClaims::reading("the shape", path);
    const std::string text = rules::readTextFile(path);
    auto endsWith = [&](std::string_view suffix) { return path.size() >= suffix.size() && path.compare(path.size() - suffix.size(), suffix.size(), suffix) == 0; };
    if (endsWith(".binvox")) return fromBinvox(argument, text, maxCells, memoryBytes);
    const std::string body = rules::withoutBom(text);  // a text format: an editor's byte-order mark is not a character of it
    if (endsWith(".json")) return fromJson(argument, body);
    if (endsWith(".xml")) return fromVisibleSim(argument, body, target, maxCells);
    if (endsWith(".xyz") || endsWith(".vox")) return fromVoxels(argument, body);
    return fromAscii(argument, body);
}

}  // namespace

const std::vector<std::pair<std::string, std::string>>& shapeGenerators() {
    static const std::vector<std::pair<std::string, std::string>> list = {
        {"box:WxH", "a W by H rectangle"},
        {"box:WxHxD", "a W by H by D block"},
        {"T:N", "a T, N wide"},
        {"disc:R", "a disc of radius R"},
        {"ring:R1,R2", "a ring between radii R1 and R2"},
        {"chair:N", "a 3D chair with an NxN seat"},
    };
    return list;
}

Shape scaled(const Shape& shape, int k, std::size_t maxCells, std::uint64_t memoryBytes) {
    const std::string scale = rules::parameterName(rules::Parameter::Scale);
    if (k < 1) bad(shape.name, scale + " must be at least 1", rules::Parameter::Scale);
    if (k == 1) return shape;
    const std::uint64_t block = rules::checkedProduct({std::uint64_t(k), std::uint64_t(k), shape.dimension == 3 ? std::uint64_t(k) : 1});
    checkSize(shape.name, rules::checkedProduct({shape.cells.size(), block}), maxCells, memoryBytes);
    // Every scaled coordinate (c * k + k - 1) stays within rules::kMaxCoordinate, so no int wraps.
    for (Vec c : shape.cells)
        for (int v : {c.x, c.y, c.z})
            if (std::int64_t(std::abs(v) + 1) * k > rules::kMaxCoordinate)
                bad(shape.name, scale + " " + std::to_string(k) + " puts cell (" + std::to_string(c.x) + "," + std::to_string(c.y) + "," + std::to_string(c.z) + ") beyond +-" + std::to_string(rules::kMaxCoordinate) + "; choose a smaller " + scale + " or move the shape nearer the origin",
                    rules::Parameter::Scale);
    Shape out;
    out.dimension = shape.dimension, out.name = shape.name;
    out.cells.reserve(shape.cells.size() * block);
    const int kz = shape.dimension == 3 ? k : 1;
    for (Vec c : shape.cells)
        for (int dx = 0; dx < k; ++dx)
            for (int dy = 0; dy < k; ++dy)
                for (int dz = 0; dz < kz; ++dz) out.cells.push_back({c.x * k + dx, c.y * k + dy, c.z * kz + dz});
    // Sorting 4 million cells took a second of a large plan's setup; the blocks of a box come sorted.
    if (!std::is_sorted(out.cells.begin(), out.cells.end())) std::sort(out.cells.begin(), out.cells.end());
    return out;
}

Shape parseShape(std::string_view argument, int scale, std::uint64_t memoryBytes, std::size_t maxCells) {
    const std::size_t colon = argument.find(':');
    const std::string_view kind = colon == std::string_view::npos ? std::string_view() : argument.substr(0, colon);
    const std::string_view rest = colon == std::string_view::npos ? std::string_view() : argument.substr(colon + 1);
    Shape s;
    if (kind == "box") s = box(argument, rest, maxCells, memoryBytes);
    else if (kind == "T") s = tee(argument, rest, maxCells, memoryBytes);
    else if (kind == "disc") s = annulus(argument, 0, numbers(argument, rest, ',', 1, 1)[0], maxCells, memoryBytes);
    else if (kind == "ring") {
        const std::vector<int> r = numbers(argument, rest, ',', 2, 2);
        if (r[0] >= r[1]) bad(argument, "the inner radius must be smaller than the outer one");
        s = annulus(argument, r[0], r[1], maxCells, memoryBytes);
    } else if (kind == "chair") s = chair(argument, rest, maxCells, memoryBytes);
    else s = fromFile(argument, maxCells, memoryBytes);
    s.name = std::string(argument);
    // Distinct: generators make each cell once, files are checked.
    if (!std::is_sorted(s.cells.begin(), s.cells.end())) std::sort(s.cells.begin(), s.cells.end());
    if (s.cells.empty()) bad(argument, "the shape has no cells");
    checkSize(argument, s.cells.size(), maxCells, memoryBytes);
    return scaled(s, scale, maxCells, memoryBytes);
}

std::vector<std::vector<Vec>> components(const std::vector<Vec>& cells, int dimension) {
    std::vector<std::vector<Vec>> out;
    if (cells.empty()) return out;
    Vec lo = cells[0], hi = cells[0];
    for (Vec c : cells) {
        lo = {std::min(lo.x, c.x), std::min(lo.y, c.y), std::min(lo.z, c.z)};
        hi = {std::max(hi.x, c.x), std::max(hi.y, c.y), std::max(hi.z, c.z)};
    }
    const long w = hi.x - lo.x + 3, h = hi.y - lo.y + 3, d = hi.z - lo.z + 3;
    auto index = [&](Vec c) { return ((c.z - lo.z + 1) * h + (c.y - lo.y + 1)) * w + (c.x - lo.x + 1); };
    std::vector<char> in(static_cast<std::size_t>(w * h * d), 0);
    for (Vec c : cells) in[index(c)] = 1;
    const long steps[6] = {1, -1, w, -w, w * h, -w * h};
    rules::Flood flood;
    rules::components(
        flood, in.size(),
        [&](auto&& f) {
            for (Vec c : cells) f(index(c));
        },
        rules::offsetEdges(
            dimension == 3 ? 6 : 4, [&](int k) { return steps[k]; }, [&](std::int64_t j) { return in[j] != 0; }),
        [&](std::int64_t i, int k) {
            if (k == static_cast<int>(out.size())) out.emplace_back();
            out[k].push_back({static_cast<int>(i % w) + lo.x - 1, static_cast<int>(i / w % h) + lo.y - 1, static_cast<int>(i / (w * h)) + lo.z - 1});
        });
    return out;
}

std::string showCell(Vec v, int dimension) {
    return "(" + std::to_string(v.x) + "," + std::to_string(v.y) + (dimension == 3 ? "," + std::to_string(v.z) : "") + ")";
}

}  // namespace holon::planner
