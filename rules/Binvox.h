#pragma once
// .binvox voxel files (Patrick Min's binvox voxelizer and viewvox; the format of many voxelised
// model collections): a 3D shape as a cube of d^3 voxels, run-length encoded.

#include "rules/Lattice.h"

#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

namespace holon::rules {

/// What scanBinvox learnt of a file: the grid's side, where voxel (0,0,0) lies in holon's
/// coordinates, and how many voxels are filled.
struct BinvoxInfo {
    int dim = 0;
    Vec origin;
    std::uint64_t filled = 0;
};

/// The largest grid side read or written: 2^20 (d^3 fits in 64 bits with room to spare).
constexpr int kMaxBinvoxDim = 1 << 20;
/// The largest grid side written: 1024, a file of at least 8 MiB even when almost empty.
constexpr int kMaxBinvoxWriteDim = 1024;

/// Checks a whole file (header, every run, the total) and counts its filled voxels without making
/// them, so the caller can refuse a shape too large before it is built. Throws InputError whose
/// message starts with "byte N: " for the first byte that is wrong.
BinvoxInfo scanBinvox(std::string_view bytes);
/// The filled voxels of a file scanBinvox accepted, as cells shifted by its origin, sorted.
std::vector<Vec> binvoxCells(std::string_view bytes, const BinvoxInfo& info);
/// A binvox file (version 1) of 3D cells: the smallest cube holding them, its lowest corner in the
/// header's translate and the side in its scale, so binvoxCells gives the same cells back. Throws
/// InputError when the cube's side is beyond kMaxBinvoxWriteDim.
std::string writeBinvox(const std::vector<Vec>& cells);

}  // namespace holon::rules
