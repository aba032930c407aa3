#pragma once
// Start and target shapes of a planning problem: sets of lattice cells in 2D or 3D, given as a
// procedural string (`box:6x3x2`, `T:12`, `disc:8`, `ring:4,8`, `chair:3`) or a file (JSON cell
// list, ASCII art, voxel text, .binvox, a VisibleSim world), each scalable so that every cell becomes a KxK(xK) block.

#include "rules/Lattice.h"

#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

namespace holon::planner {

using rules::Vec;

struct Shape {
    int dimension = 2;
    std::vector<Vec> cells;  // sorted, distinct
    std::string name;        // what the user wrote, for messages
};

/// Parses a shape argument: a procedural string or, when it names no known generator, a file.
/// Throws InputError naming the argument and the fix: for a malformed file, a cell listed twice, a
/// coordinate beyond +-rules::kMaxCoordinate. `maxCells` bounds the scaled size (InputError);
/// `memoryBytes` (--memory) bounds the memory the cells take (LimitError), both checked before
/// the cells are made.
/// A cell as people read it in messages: (x,y) for 2D shapes, (x,y,z) for 3D.
std::string showCell(Vec v, int dimension);

Shape parseShape(std::string_view argument, int scale = 1, std::uint64_t memoryBytes = UINT64_MAX, std::size_t maxCells = std::size_t{1} << 27);

/// Every cell becomes a KxK (2D) or KxKxK (3D) block.
Shape scaled(const Shape& shape, int k, std::size_t maxCells, std::uint64_t memoryBytes = UINT64_MAX);

/// Face-connected components of a cell set (6- or 4-neighbourhood), in the order of their first
/// cells in `cells`, each cell of a component in the order a flood from that first cell reaches it.
std::vector<std::vector<Vec>> components(const std::vector<Vec>& cells, int dimension);

/// The procedural generators with a one-line description each, for --help and messages.
const std::vector<std::pair<std::string, std::string>>& shapeGenerators();

}  // namespace holon::planner
