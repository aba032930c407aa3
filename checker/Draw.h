#pragma once
// Pictures of configurations and traces for a person: ASCII for the terminal, SVG for a file.

#include "checker/Trace.h"

#include <functional>
#include <string>

namespace holon::checker {

/// One character per cell: the state's one-character name, an arrow for a square-lattice pointer
/// (a P shows where its parent is), else the first letter of its name; '.' for empty.
char cellChar(const rules::Engine& engine, int cell, CellValue v);
std::string drawAscii(const rules::Engine& engine, const std::vector<CellValue>& cells);
/// The region's layout with one character per cell from `charOf(cell)` (3D: z slices side by side).
std::string drawCells(const rules::Region& region, const std::function<char(int cell)>& charOf);
/// The engine's inputs, one mask per input ("-- input target:" and '#' where it holds), so a reader
/// sees which input values a trace needs; empty for a system without inputs.
std::string drawInputsAscii(const rules::Engine& engine);
/// Every state of the trace with the rule that led to it and the cells that changed.
std::string drawTraceAscii(const Trace& trace, const rules::Engine& engine);
/// Frames left to right; changed cells outlined in red, the rule's other cells (context, blocking)
/// dashed, marked cells crossed, cells where an input holds labelled with its number (the legend
/// names it); 3D regions drawn as z slices.
std::string drawTraceSvg(const Trace& trace, const rules::Engine& engine, const std::string& title);

}  // namespace holon::checker
