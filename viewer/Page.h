#pragma once
// The viewer's page: viewer/viewer.html (embedded at build time) with a run's data in it, one
// self-contained HTML file that needs no network and no server.

#include "viewer/Run.h"

#include <string>

namespace holon::viewer {

/// The page data as JSON text: the cells (a box's corner and size, or every point), the state table with colours, the legend, the inputs,
/// the start configuration and the steps' changes, the bulky arrays as base64 of little-endian
/// typed arrays (the page decodes them in milliseconds; JSON arrays of numbers take seconds).
std::string pageData(const Run& run);
/// The whole HTML page of the run, sampled (sample()) when it is too big.
std::string page(Run run);

}  // namespace holon::viewer
