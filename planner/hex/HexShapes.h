#pragma once
// Source and target geometries for hole-motion sculpting (seed 003 §V-A, Fig. 8): square, T,
// rectangle and circle of equal area, centred on the array, or a picture file.

#include "planner/hex/HexArray.h"

#include <string>
#include <vector>

namespace holon::planner::hex {

/// Per board cell: 1 where the geometry is filled. `spec` is square, T, rectangle, circle or the
/// path of a text file with N lines of N characters ('#' filled, '.' or a space empty; the first
/// line is the top row). Throws InputError for an unknown name, a malformed file, or a geometry
/// that is empty or not connected.
std::vector<std::uint8_t> sculptShape(const HexArray& array, const std::string& spec, const std::string& role);

/// Whether `spec` names a picture file rather than one of the named geometries: what a command
/// declares it reads (rules::OutputClaims) before it clears or writes any output.
bool isPictureFile(const std::string& spec);

/// Whether the filled lattice points form one connected set (six neighbours); true when none are.
bool connected(const HexArray& array, const std::vector<std::uint8_t>& shape);

/// The number of filled lattice points.
std::int64_t filledCount(const HexArray& array, const std::vector<std::uint8_t>& shape);

}  // namespace holon::planner::hex
