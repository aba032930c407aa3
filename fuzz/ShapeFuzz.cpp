// libFuzzer target for shape files, the planners' input format: any byte string written as a shape
// file (JSON cell list, voxel text, ASCII art, .binvox, VisibleSim XML: the first byte picks which,
// its value mod 5 in that order) and read by
// planner::parseShape as `plan --from/--to` reads it, then as a hex picture for `hex --from/--to`
// on a 12x12 array; also as a procedural argument (`box:...`, `ring:...`) when it has no '/'.
// Accepted or refused with InputError or LimitError; crashes, hangs, leaks, sanitizer reports and
// any other exception are failures. A shape that is accepted is sorted, distinct and within the
// size it was allowed, and scaling it by 2 keeps that.

#include "planner/Shape.h"
#include "planner/hex/HexShapes.h"
#include "rules/Error.h"

#include <algorithm>
#include <cstdint>
#include <cstdlib>
#include <fstream>
#include <string>
#include <unistd.h>

namespace {

std::string scratch;

void accepted(const holon::planner::Shape& s, std::size_t maxCells) {
    if (s.cells.empty() || s.cells.size() > maxCells || !std::is_sorted(s.cells.begin(), s.cells.end()) ||
        std::adjacent_find(s.cells.begin(), s.cells.end()) != s.cells.end())
        std::abort();
}

template <class F>
void refusedOrAccepted(F&& f) {
    try {
        f();
    } catch (const holon::InputError&) {
    } catch (const holon::LimitError&) {
    }
}

}  // namespace

extern "C" int LLVMFuzzerInitialize(int*, char***) {
    char dir[] = "/tmp/holon_shape_fuzz_XXXXXX";
    if (!mkdtemp(dir)) std::abort();
    scratch = dir;
    return 0;
}

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    if (size == 0) return 0;
    static const char* const kinds[] = {".json", ".xyz", ".txt", ".binvox", ".xml"};
    const std::string path = scratch + "/shape" + kinds[data[0] % 5];
    const std::string text(reinterpret_cast<const char*>(data) + 1, size - 1);
    std::ofstream(path, std::ios::binary | std::ios::trunc) << text;
    constexpr std::size_t kMax = 1 << 16;
    refusedOrAccepted([&] {
        const holon::planner::Shape s = holon::planner::parseShape(path, 1, kMax);
        accepted(s, kMax);
        accepted(holon::planner::scaled(s, 2, kMax * 8), kMax * 8);
    });
    if (text.find('/') == std::string::npos && text.size() < 64)
        refusedOrAccepted([&] { accepted(holon::planner::parseShape(text, 1, kMax), kMax); });
    refusedOrAccepted([&] {
        static const holon::planner::hex::HexArray array(12);
        (void)holon::planner::hex::sculptShape(array, path, "--from");
    });
    return 0;
}
