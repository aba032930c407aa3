// The binvox format (patrickmin.com/binvox/binvox.html): an ASCII header
//   #binvox 1
//   dim D D D
//   translate TX TY TZ        (optional)
//   scale S                   (optional)
//   data
// then byte pairs (value, count), count 1 to 255, covering the D^3 voxels exactly, in the order
// index = x*D*D + z*D + y (y fastest, then z, then x). A voxel (i,j,k) has its centre at
// ((i,j,k) + 0.5) / D * S + T in the mesh's coordinates. Version 2 files (binvox_merge) allow any
// value from 1 to 255 for a filled voxel; both are read, version 1 written.
// holon cells are unit cubes [x, x+1): writing translate = the shape's lowest corner and scale = D
// puts voxel (i,j,k) exactly on cell (i,j,k) + translate, so reading a file holon wrote gives the
// same cells back, offset included. A file from elsewhere (scale != D or a translate that is not a
// whole number of cells) is read in voxel indices, its lowest corner at (0,0,0).

#include "rules/Binvox.h"

#include "rules/Error.h"
#include "rules/Limits.h"

#include <algorithm>
#include <climits>
#include <cmath>
#include <functional>
#include <sstream>

namespace holon::rules {

namespace {

[[noreturn]] void badAt(std::size_t offset, const std::string& why) { throw InputError("byte " + std::to_string(offset) + ": " + why); }

/// The header read up to "data\n": the grid side, the translate and scale if given, and the offset
/// of the first run.
struct Header {
    int version = 1, dim = 0;
    double translate[3] = {0, 0, 0}, scale = 1;
    bool placed = false;  // translate and scale given
    std::size_t dataStart = 0;
};

Header readHeader(std::string_view bytes) {
    Header h;
    std::size_t at = 0;
    // One header line, without its '\n' (a '\r' before it tolerated); the line's offset in `start`.
    const auto line = [&](std::size_t& start) {
        start = at;
        const std::size_t end = bytes.find('\n', at);
        if (end == std::string_view::npos) badAt(at, "the header ends early; binvox headers are lines ending in a newline, the last one 'data'");
        if (end - at > 200) badAt(at, "a header line of " + std::to_string(end - at) + " bytes; binvox header lines are short ('dim D D D', 'translate X Y Z', 'scale S', 'data')");
        std::string_view text = bytes.substr(at, end - at);
        if (!text.empty() && text.back() == '\r') text.remove_suffix(1);
        at = end + 1;
        return std::string(text);
    };
    std::size_t start = 0;
    const std::string first = line(start);
    if (first == "#binvox 2") h.version = 2;
    else if (first != "#binvox 1") badAt(0, "not a binvox file: the first line must be '#binvox 1' (or 2)");
    bool haveDim = false, haveTranslate = false, haveScale = false;
    while (true) {
        const std::string text = line(start);
        std::istringstream in(text);
        std::string key, extra;
        in >> key;
        if (key == "data") {
            if (in >> extra) badAt(start, "'data' must be alone on its line");
            break;
        }
        // A key given twice is refused: the last one won silently.
        const auto once = [&](bool& seen) {
            if (seen) badAt(start, "'" + key + "' is given twice; a binvox header gives each line once");
            seen = true;
        };
        if (key == "dim") {
            once(haveDim);
            long long d[3];
            if (!(in >> d[0] >> d[1] >> d[2]) || (in >> extra)) badAt(start, "expected 'dim D D D' with three whole numbers");
            if (d[0] != d[1] || d[1] != d[2]) badAt(start, "the grid is " + std::to_string(d[0]) + "x" + std::to_string(d[1]) + "x" + std::to_string(d[2]) + "; binvox grids are cubes (dim D D D)");
            if (d[0] < 1 || d[0] > kMaxBinvoxDim) badAt(start, "dim " + std::to_string(d[0]) + " is not from 1 to " + std::to_string(kMaxBinvoxDim));
            h.dim = static_cast<int>(d[0]);
        } else if (key == "translate") {
            once(haveTranslate);
            if (!(in >> h.translate[0] >> h.translate[1] >> h.translate[2]) || (in >> extra)) badAt(start, "expected 'translate X Y Z' with three numbers");
        } else if (key == "scale") {
            once(haveScale);
            if (!(in >> h.scale) || (in >> extra)) badAt(start, "expected 'scale S' with one number");
        } else {
            badAt(start, "unknown header line '" + text.substr(0, 40) + "'; a binvox header has dim, translate, scale and data");
        }
    }
    if (!haveDim) badAt(start, "'data' before 'dim D D D'; the header must give the grid's size");
    h.placed = haveTranslate && haveScale;
    h.dataStart = at;
    return h;
}

/// Walks the runs of a file: `run(first voxel index, count, filled)` for each; checks that every
/// count is at least 1, every value 0 or 1 (version 2: up to 255), and the runs cover D^3 voxels
/// exactly with no byte after them.
void forEachRun(std::string_view bytes, const Header& h, const std::function<void(std::uint64_t, int, bool)>& run) {
    const std::uint64_t total = std::uint64_t(h.dim) * std::uint64_t(h.dim) * std::uint64_t(h.dim);
    std::uint64_t index = 0;
    std::size_t at = h.dataStart;
    while (index < total) {
        if (at + 2 > bytes.size())
            badAt(at, "the file ends after " + std::to_string(index) + " of the " + std::to_string(total) + " voxels of a " + std::to_string(h.dim) + "^3 grid (truncated?)");
        const auto value = static_cast<unsigned char>(bytes[at]), count = static_cast<unsigned char>(bytes[at + 1]);
        if (h.version == 1 && value > 1) badAt(at, "voxel value " + std::to_string(value) + "; a version 1 file has only 0 and 1");
        if (count == 0) badAt(at + 1, "a run of 0 voxels; counts are 1 to 255");
        if (index + count > total)
            badAt(at + 1, "a run of " + std::to_string(count) + " voxels from voxel " + std::to_string(index) + " overruns the " + std::to_string(total) +
                              " voxels of a " + std::to_string(h.dim) + "^3 grid");
        run(index, count, value != 0);
        index += count, at += 2;
    }
    if (const std::size_t extra = bytes.size() - at; extra > 0)
        badAt(at, std::to_string(extra) + (extra == 1 ? " byte" : " bytes") + " after the last of the " + std::to_string(total) + " voxels");
}

/// Where voxel (0,0,0) lies: the translate of a file holon wrote (scale = D, translate whole
/// numbers), else the origin. A whole-number translate beyond the coordinate range is refused: it
/// was read as the origin, and a model placed far from the target was planned as if it overlapped.
Vec originOf(const Header& h) {
    if (!h.placed || h.scale != h.dim) return {};
    for (double t : h.translate)
        if (t != std::floor(t)) return {};
    int v[3];
    for (int k = 0; k < 3; ++k) {
        const double t = h.translate[k];
        if (std::fabs(t) + h.dim > kMaxCoordinate)
            throw InputError("the header's translate puts voxels beyond the coordinate range of +-" + std::to_string(kMaxCoordinate) + "; move the model closer to the origin");
        v[k] = static_cast<int>(t);
    }
    return {v[0], v[1], v[2]};
}

}  // namespace

BinvoxInfo scanBinvox(std::string_view bytes) {
    const Header h = readHeader(bytes);
    BinvoxInfo info;
    info.dim = h.dim, info.origin = originOf(h);
    forEachRun(bytes, h, [&](std::uint64_t, int count, bool filled) {
        if (filled) info.filled += count;
    });
    return info;
}

std::vector<Vec> binvoxCells(std::string_view bytes, const BinvoxInfo& info) {
    const Header h = readHeader(bytes);
    const std::uint64_t d = std::uint64_t(h.dim);
    std::vector<Vec> cells;
    cells.reserve(info.filled);
    forEachRun(bytes, h, [&](std::uint64_t first, int count, bool filled) {
        if (!filled) return;
        for (std::uint64_t i = first; i < first + std::uint64_t(count); ++i) {
            const int x = static_cast<int>(i / (d * d)), z = static_cast<int>(i / d % d), y = static_cast<int>(i % d);
            cells.push_back(Vec{x, y, z} + info.origin);
        }
    });
    std::sort(cells.begin(), cells.end());
    return cells;
}

std::string writeBinvox(const std::vector<Vec>& cells) {
    if (cells.empty()) throw InputError("binvox: the shape has no cells");
    Vec lo{INT_MAX, INT_MAX, INT_MAX}, hi{INT_MIN, INT_MIN, INT_MIN};
    for (Vec c : cells) {
        lo = {std::min(lo.x, c.x), std::min(lo.y, c.y), std::min(lo.z, c.z)};
        hi = {std::max(hi.x, c.x), std::max(hi.y, c.y), std::max(hi.z, c.z)};
    }
    const std::int64_t side = std::max({std::int64_t(hi.x) - lo.x, std::int64_t(hi.y) - lo.y, std::int64_t(hi.z) - lo.z}) + 1;
    if (side > kMaxBinvoxWriteDim)
        throw InputError("binvox: the shape spans " + std::to_string(side) + " cells; a binvox grid is a cube of side at most " + std::to_string(kMaxBinvoxWriteDim) +
                         " here (the file would hold " + std::to_string(side) + "^3 voxels); write a smaller shape");
    const std::uint64_t d = std::uint64_t(side);
    std::vector<bool> filled(d * d * d, false);
    for (Vec c : cells) {
        const Vec v = c - lo;
        filled[std::uint64_t(v.x) * d * d + std::uint64_t(v.z) * d + std::uint64_t(v.y)] = true;
    }
    std::string out = "#binvox 1\ndim " + std::to_string(d) + " " + std::to_string(d) + " " + std::to_string(d) + "\ntranslate " + std::to_string(lo.x) + " " +
                      std::to_string(lo.y) + " " + std::to_string(lo.z) + "\nscale " + std::to_string(d) + "\ndata\n";
    for (std::uint64_t i = 0; i < filled.size();) {
        const bool value = filled[i];
        std::uint64_t count = 0;
        while (i < filled.size() && filled[i] == value && count < 255) ++i, ++count;
        out += static_cast<char>(value ? 1 : 0);
        out += static_cast<char>(count);
    }
    return out;
}

}  // namespace holon::rules
