#pragma once
// VisibleSim world files (XML): the configuration files of the VisibleSim modular-robot simulator,
// so a holon configuration or planning problem opens there. Checked against VisibleSim's
// doc/UserManual.md and simulatorCore (Simulator::parseWorld/parseBlockList, TargetGrid, the
// SCLattice and HHLattice classes) at commit 86bca12 (2021-06-02), the newest on GitHub.

#include "rules/Lattice.h"

#include <array>
#include <string>
#include <string_view>
#include <vector>

namespace holon::rules {

/// The module types holon writes: slidingCubes and blinkyBlocks on VisibleSim's cube lattice
/// (square2d and cubic3d), hexanodes on its hexagonal one (hex2d).
enum class VisibleSimRobot { SlidingCubes,
                             BlinkyBlocks,
                             Hexanodes };

/// "slidingCubes", "blinkyBlocks", "hexanodes": the names of VisibleSim's module types.
const char* visibleSimRobotName(VisibleSimRobot robot);

/// One module (or target cell) in holon's coordinates with its colour, "#rrggbb".
struct VisibleSimCell {
    Vec at;
    std::string colour;
};

/// A cell in VisibleSim's lattice coordinates before the shift into its grid: cubic3d as is;
/// square2d and hex2d with y negated, as holon's y runs down the page and VisibleSim's up (hex2d
/// axial (q, r) becomes (q + r, -r), VisibleSim's axial basis with E (1,0) and NE (0,1)). The map
/// is its own inverse.
Vec toVisibleSimAxes(const Lattice& lattice, Vec v);

/// The world: a blockList with `blocks` and, when `targets` is not empty, a grid target with them
/// (a reconfiguration goal); every cell shifted by the same amount so the smallest coordinate is
/// `margin`, gridSize the extent of both plus `margin` empty cells on each side (in the plane for 2D
/// lattices: their worlds are one layer), room for modules to move around the shape; blockSize the
/// robot's default; `comments` become XML comments at the top (what the file holds, the colour
/// legend). Throws InputError when the robot does not live on the lattice or there is no block.
std::string visibleSimWorld(const Lattice& lattice, VisibleSimRobot robot, const std::vector<VisibleSimCell>& blocks,
                            const std::vector<VisibleSimCell>& targets, const std::vector<std::string>& comments, int margin = 0);

/// A VisibleSim world read back: its modules and the cells of its first grid target, in holon's
/// cells, and the lattice they are on.
struct VisibleSimCells {
    const Lattice* lattice = nullptr;
    std::vector<Vec> blocks, targets;
};

/// Reads the modules of a world (<block> and <blocksLine> in its <blockList>) and the cells of its
/// first <target format="grid"> (<cell>, <targetLine>). The comment holon writes ("holon square2d
/// cell (x, y) is at position ...") gives the lattice and the map back to holon's coordinates, so
/// a world holon wrote reads back as the same cells; a world from elsewhere is square2d when its
/// grid is one layer (y flipped within the grid) and cubic3d otherwise. Throws InputError starting
/// "line L, column C: " for malformed XML, a position outside gridSize, a cell given twice, more
/// than `maxCells` cells, or what holon does not read (<blockBox>, <csg>, in world coordinates).
VisibleSimCells readVisibleSimWorld(std::string_view text, std::size_t maxCells);

}  // namespace holon::rules
