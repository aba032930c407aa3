#pragma once
// ASCII pictures, one reader for all of them: plan's shapes, hex's geometries, configurations and
// input masks. They agree on what a row is (a line, '\r' dropped, trailing blank lines ignored) and
// on raggedness: a rectangular picture whose rows differ in width is refused, not padded or cut.

#include <string>
#include <vector>

namespace holon::rules {

/// The rows of a picture, top first. With `rectangular` (every picture of a rectangular grid:
/// shapes, hex geometries, square-lattice configurations and masks; not hexagon pictures, whose
/// rows are indented) a row of another width than the first throws InputError naming the line and
/// both widths, for the caller to prefix with the file.
std::vector<std::string> pictureRows(const std::string& text, bool rectangular);

}  // namespace holon::rules
