// The four geometries of seed 003 Fig. 8. The paper does not give their dimensions; ours have the
// same area (a square of side a = 0.66 of the frame's width, the shorter side, about 60,000 points at N = 400, the
// paper's "approximately 60,000 modules"), so that a plan between any two needs no net change of
// volume: the T (height a) has a bar 1.5a wide and 0.3a thick over a stem 0.79a wide, the
// rectangle is 1.5a by a/1.5, the circle has radius a/sqrt(pi).

#include "planner/hex/HexShapes.h"

#include "rules/Components.h"
#include "rules/ConfigIo.h"
#include "rules/Error.h"
#include "rules/Escape.h"
#include "rules/OutputFile.h"
#include "rules/Parameter.h"
#include "rules/Picture.h"
#include "rules/TextFile.h"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <functional>

namespace holon::planner::hex {

namespace {

using Inside = std::function<bool(double, double)>;  // relative to the array centre

Inside namedShape(const std::string& name, double a) {
    if (name == "square") return [a](double x, double y) { return std::abs(x) <= a / 2 && std::abs(y) <= a / 2; };
    if (name == "T") {
        const double bar = 0.3 * a, stem = (1.0 - 1.5 * 0.3) / 0.7 * a;  // equal area: 1.5·0.3 + 0.7·stem = 1
        return [a, bar, stem](double x, double y) {
            if (std::abs(y) > a / 2) return false;
            return y >= a / 2 - bar ? std::abs(x) <= 0.75 * a : std::abs(x) <= stem / 2;
        };
    }
    if (name == "rectangle") return [a](double x, double y) { return std::abs(x) <= 0.75 * a && std::abs(y) <= a / 3; };
    if (name == "circle") {
        const double r = a / std::sqrt(M_PI);
        return [r](double x, double y) { return x * x + y * y <= r * r; };
    }
    return nullptr;
}

std::vector<std::uint8_t> readPicture(const HexArray& array, const std::string& path, const std::string& role) {
    // exists(), not opening the file: opening a FIFO waited for its writer and took what it wrote,
    // and the read below then waited for a second writer.
    if (std::error_code missing; !std::filesystem::exists(path, missing))
        throw InputError(role + " '" + path + "': not square, T, rectangle or circle, and no such file");
    std::string text;
    try {
        rules::OutputClaims::reading("the picture", path);  // --steps-out must not replace it
        text = rules::withoutBom(rules::readTextFile(path));
    } catch (const InputError& e) {
        throw InputError(role + " '" + path + "': " + e.what());
    }
    // Every character before the picture's size: anything else was read as empty (a NUL byte or a
    // stray letter drew a hole silently), and a multi-byte character counted as several columns, so
    // the message was about the width, not the character.
    // Up to the last line that draws something: blank lines after it, tabs included, are dropped
    // as pictureRows drops them.
    const std::size_t last = text.find_last_not_of(" \t\r\n");
    const std::size_t drawn = last == std::string::npos ? 0 : std::min(text.size(), text.find('\n', last));
    for (std::size_t at = 0, row = 1, rowStart = 0; at < drawn; ++at) {
        const char c = text[at];
        if (c == '\n') ++row, rowStart = at + 1;
        if (c == '#' || c == '.' || c == ' ' || c == '\n' || (c == '\r' && at + 1 < text.size() && text[at + 1] == '\n')) continue;
        // The whole of a UTF-8 character, for the message: its lead byte says how long it is.
        const auto lead = static_cast<unsigned char>(c);
        const std::size_t length = lead >= 0xF0 ? 4 : lead >= 0xE0 ? 3
                                                  : lead >= 0xC0   ? 2
                                                                   : 1;
        throw InputError(role + " " + path + ":" + std::to_string(row) + ":" + std::to_string(at - rowStart + 1) + ": '" +
                         rules::excerpt(std::string_view(text).substr(at, length)) + "' is not a picture character; draw a module as '#' and an empty point as '.' or a space");
    }
    std::vector<std::string> lines;
    try {
        lines = rules::pictureRows(text, true);
    } catch (const InputError& e) {
        throw InputError(role + " '" + path + "': " + e.what());
    }
    const int n = array.n();
    if (static_cast<int>(lines.size()) != n || static_cast<int>(lines[0].size()) != n)
        throw InputError(role + " '" + path + "': " + std::to_string(lines.size()) + " rows of " + std::to_string(lines.empty() ? 0 : lines[0].size()) +
                         " characters, but " + rules::parameterName(rules::Parameter::Size) + " is " + std::to_string(n) + "; draw N rows of N characters");
    std::vector<std::uint8_t> shape(array.size(), 0);
    for (int r = 0; r < n; ++r)
        for (int i = 0; i < n; ++i) shape[array.pictureIndex(r, i)] = lines[r][i] == '#';
    return shape;
}

}  // namespace

bool connected(const HexArray& array, const std::vector<std::uint8_t>& shape) {
    const auto inShape = [&](std::int64_t i) { return shape[i] != 0; };
    rules::Flood flood;
    return rules::connected(
        flood, shape.size(),
        [&](auto&& f) {
            for (std::int64_t i : array.points())
                if (shape[i]) f(i);
        },
        rules::offsetEdges(
            6, [&](int d) { return array.step(d); }, inShape));
}

bool isPictureFile(const std::string& spec) { return !namedShape(spec, 1.0); }

std::vector<std::uint8_t> sculptShape(const HexArray& array, const std::string& spec, const std::string& role) {
    std::vector<std::uint8_t> shape;
    const double a = 0.66 * array.frameWidth(), cx = array.frameWidth() / 2, cy = array.frameHeight() / 2;
    if (Inside inside = namedShape(spec, a)) {
        shape.assign(array.size(), 0);
        for (std::int64_t i : array.points()) shape[i] = inside(array.frameX(i) - cx, array.frameY(i) - cy);
    } else {
        shape = readPicture(array, spec, role);
    }
    if (filledCount(array, shape) == 0) throw InputError(role + " '" + spec + "' is empty at " + rules::parameterName(rules::Parameter::Size) + " " + std::to_string(array.n()));
    if (!connected(array, shape)) throw InputError(role + " '" + spec + "' is not connected; holes sculpt one connected mass");
    return shape;
}

std::int64_t filledCount(const HexArray& array, const std::vector<std::uint8_t>& shape) {
    std::int64_t count = 0;
    for (std::int64_t i : array.points()) count += shape[i];
    return count;
}

}  // namespace holon::planner::hex
