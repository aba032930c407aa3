// .binvox files (rules/Binvox.h): a small file checked byte for byte against the format's
// definition worked by hand, round trips (offset included), foreign files, and malformed files
// refused at the byte that is wrong.

#include "rules/Binvox.h"
#include "rules/Error.h"

#include <doctest/doctest.h>

#include <algorithm>
#include <random>
#include <set>

using holon::InputError;
using holon::rules::Vec;
namespace r = holon::rules;

namespace {

std::vector<Vec> read(const std::string& bytes) {
    return r::binvoxCells(bytes, r::scanBinvox(bytes));
}

std::string refusal(const std::string& bytes) {
    try {
        read(bytes);
    } catch (const InputError& e) {
        return e.what();
    }
    return "accepted";
}

const std::string kCubeHeader = "#binvox 1\ndim 2 2 2\ntranslate 0 0 0\nscale 2\ndata\n";  // 49 bytes

}  // namespace

TEST_CASE("a 2x2x2 binvox file, worked by hand") {
    // index = x*4 + z*2 + y: (0,0,0) -> 0, (1,1,0) -> 5, (1,0,1) -> 6; voxels 1 0 0 0 0 1 1 0.
    const std::vector<Vec> cells = {{0, 0, 0}, {1, 0, 1}, {1, 1, 0}};
    const std::string expected = kCubeHeader + std::string("\x01\x01\x00\x04\x01\x02\x00\x01", 8);
    CHECK(kCubeHeader.size() == 49);
    CHECK(r::writeBinvox(cells) == expected);
    CHECK(read(expected) == cells);
    const r::BinvoxInfo info = r::scanBinvox(expected);
    CHECK(info.dim == 2);
    CHECK(info.filled == 3);
}

TEST_CASE("the offset is kept in translate, the cube as wide as the longest extent") {
    const std::vector<Vec> cells = {{-3, 5, 7}, {-3, 5, 9}};  // spans 3 along z: a 3^3 grid
    const std::string bytes = r::writeBinvox(cells);
    CHECK(bytes.rfind("#binvox 1\ndim 3 3 3\ntranslate -3 5 7\nscale 3\ndata\n", 0) == 0);
    CHECK(read(bytes) == cells);
}

TEST_CASE("round trips: random shapes come back the same") {
    std::mt19937 random(7);
    for (int trial = 0; trial < 50; ++trial) {
        std::set<Vec> cells;
        const int n = 1 + static_cast<int>(random() % 300), span = 1 + static_cast<int>(random() % 40);
        const Vec base{static_cast<int>(random() % 1000) - 500, static_cast<int>(random() % 1000) - 500, static_cast<int>(random() % 1000) - 500};
        for (int k = 0; k < n; ++k)
            cells.insert(base + Vec{static_cast<int>(random() % span), static_cast<int>(random() % span), static_cast<int>(random() % span)});
        const std::vector<Vec> sorted(cells.begin(), cells.end());
        CHECK(read(r::writeBinvox(sorted)) == sorted);
    }
}

TEST_CASE("a file from elsewhere is read in voxel indices") {
    // No translate/scale, and one with a mesh's normalisation: both give voxel (i,j,k) as cell (i,j,k).
    const std::string data("\x00\x07\x01\x01", 4);  // voxel 7 = (1,1,1)
    CHECK(read("#binvox 1\ndim 2 2 2\ndata\n" + data) == std::vector<Vec>{{1, 1, 1}});
    CHECK(read("#binvox 1\r\ndim 2 2 2\r\ntranslate -0.12 0.5 3\r\nscale 7.2\r\ndata\r\n" + data) == std::vector<Vec>{{1, 1, 1}});
    // Version 2: any value 1 to 255 is a filled voxel.
    CHECK(read("#binvox 2\ndim 2 2 2\ndata\n" + std::string("\x00\x07\xc8\x01", 4)) == std::vector<Vec>{{1, 1, 1}});
    // A holon-style placement (scale = dim, whole translate) beyond the coordinate range is refused:
    // it was read as the origin, and the model planned as if it overlapped the target.
    CHECK(read("#binvox 1\ndim 2 2 2\ntranslate 10 0 0\nscale 2\ndata\n" + data) == std::vector<Vec>{{11, 1, 1}});
    CHECK_THROWS_WITH_AS(read("#binvox 1\ndim 2 2 2\ntranslate 536870911 0 0\nscale 2\ndata\n" + data), doctest::Contains("beyond the coordinate range"), holon::InputError);
}

TEST_CASE("malformed files are refused at the byte that is wrong") {
    const std::string good = kCubeHeader + std::string("\x01\x01\x00\x04\x01\x02\x00\x01", 8);
    // Truncated: the last pair lost, the file ends at byte 55 after 7 of 8 voxels.
    CHECK(refusal(good.substr(0, 55)) == "byte 55: the file ends after 7 of the 8 voxels of a 2^3 grid (truncated?)");
    CHECK(refusal(good.substr(0, 56)) == "byte 55: the file ends after 7 of the 8 voxels of a 2^3 grid (truncated?)");
    CHECK(refusal("#binvox 3\n") == "byte 0: not a binvox file: the first line must be '#binvox 1' (or 2)");
    CHECK(refusal("PK\x03\x04").find("byte 0: the header ends early") == 0);
    CHECK(refusal("#binvox 1\ndim 2 2 3\ndata\n").find("byte 10: the grid is 2x2x3") == 0);
    CHECK(refusal("#binvox 1\ndim 0 0 0\ndata\n").find("byte 10: dim 0 is not from 1 to") == 0);
    CHECK(refusal("#binvox 1\ndata\n") == "byte 10: 'data' before 'dim D D D'; the header must give the grid's size");
    CHECK(refusal("#binvox 1\ndim 2 2 2\ncolour red\ndata\n").find("byte 20: unknown header line 'colour red'") == 0);
    // A line given twice was taken last-wins; a long line was said to end the header early.
    CHECK(refusal("#binvox 1\ndim 2 2 2\ndim 4 4 4\ndata\n") == "byte 20: 'dim' is given twice; a binvox header gives each line once");
    CHECK(refusal("#binvox 1\ndim 2 2 2\nscale 1\nscale 2\ndata\n") == "byte 28: 'scale' is given twice; a binvox header gives each line once");
    CHECK(refusal("#binvox 1\ntranslate " + std::string(300, '0') + " 0 0\ndata\n").find("byte 10: a header line of 314 bytes") == 0);
    // A run past the 8 voxels: the count byte of the second pair (offset 52).
    CHECK(refusal(kCubeHeader + std::string("\x01\x01\x00\x09", 4)) == "byte 52: a run of 9 voxels from voxel 1 overruns the 8 voxels of a 2^3 grid");
    CHECK(refusal(kCubeHeader + std::string("\x01\x00", 2)) == "byte 50: a run of 0 voxels; counts are 1 to 255");
    CHECK(refusal(kCubeHeader + std::string("\x02\x08", 2)) == "byte 49: voxel value 2; a version 1 file has only 0 and 1");
    CHECK(refusal(good + "\n") == "byte 57: 1 byte after the last of the 8 voxels");
}

TEST_CASE("a shape too wide for a binvox cube is refused before the grid is made") {
    CHECK_THROWS_WITH_AS(r::writeBinvox({{0, 0, 0}, {5000, 0, 0}}),
                         "binvox: the shape spans 5001 cells; a binvox grid is a cube of side at most 1024 here (the file would hold 5001^3 voxels); write a smaller shape",
                         InputError);
}
