#pragma once
// Pictures of an assembly run: the top view of the foot traces with the force vectors followed (as
// seed 001 Fig. 6) and an isometric view of the metamodules at the end (as Fig. 7's last frame).

#include "planner/roombots/Assembly.h"

#include <string>

namespace holon::planner::roombots {

std::string footTraceSvg(const Setting& setting, const AssemblyResult& result);
std::string isometricSvg(const Setting& setting, const AssemblyResult& result);

}  // namespace holon::planner::roombots
