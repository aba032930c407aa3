// The array geometry of seed 003 §V-A ("square arrays of 100 .. 400 lattice points per side"):
// row r (0 at the top) holds the points q = -floor(r/2) + i, i < N, so that rows alternate by half
// a module and the array is a rectangle N wide and (N-1)·sqrt(3)/2 high.

#include "planner/hex/HexArray.h"

#include "rules/Error.h"
#include "rules/Parameter.h"

namespace holon::planner::hex {

namespace {

Board makeBoard(int n) {
    const std::string size = rules::parameterName(rules::Parameter::Size) + " " + std::to_string(n);
    if (n < 12) throw InputError(size + ": the array needs at least 12 lattice points per side", rules::Parameter::Size);
    if (n > 4000) throw InputError(size + ": at most 4000 lattice points per side", rules::Parameter::Size);
    const int shift = (n - 1) / 2;  // the last row starts this far left in q
    return Board(rules::Lattice::get(rules::LatticeKind::Hex2D), Vec{-shift, 0, 0}, Vec{n + shift, n, 1}, HexArray::kPad);
}

}  // namespace

std::int64_t HexArray::boardSize(int n) { return makeBoard(n).size(); }

HexArray::HexArray(int n) : n_(n), board_(makeBoard(n)), inside_(board_.size(), 0) {
    for (int r = 0; r < n; ++r) {
        const int q0 = -(r / 2);
        for (int i = 0; i < n; ++i) {
            const std::int64_t idx = board_.index(Vec{q0 + i, r, 0});
            inside_[idx] = 1;
            points_.push_back(idx);
        }
    }
}

std::vector<Vec> hexRing(int r) {
    std::vector<Vec> out;
    for (const Vec& v : hexDisk(r))
        if (hexDistance(v, {}) == r) out.push_back(v);
    return out;
}

std::vector<Vec> hexDisk(int r) {
    std::vector<Vec> out;
    for (int q = -r; q <= r; ++q)
        for (int s = -r; s <= r; ++s)
            if (hexDistance({q, s, 0}, {}) <= r) out.push_back({q, s, 0});
    return out;
}

}  // namespace holon::planner::hex
