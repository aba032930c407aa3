// Writes VisibleSim world files. VisibleSim reads a <world gridSize="X,Y,Z"> holding a <blockList>
// of <block position="x,y,z" color="r,g,b"/> and, for reconfiguration, a <targetList> of
// <target format="grid"> with <cell position=... color=.../>; every position must lie in
// [0, gridSize) on each axis or the simulator refuses the file ("module at ... is out of grid").
// Cube robots (slidingCubes, blinkyBlocks) sit on a cubic grid with z up; hexanodes on an axial
// hexagonal grid in the plane z = 0 whose world position is (x + y/2, y*sqrt(3)/2), so its
// gridSize bounds a parallelogram of axial coordinates. blockSize is ignored by the simulator at
// the commit checked (each robot has its default) and written as that default, so an older
// VisibleSim that reads it draws the same; hexanodes also read an orientation (0 to 5), written 0.

#include "rules/VisibleSim.h"

#include "rules/Error.h"
#include "rules/Parameter.h"

#include <algorithm>
#include <climits>
#include <sstream>

namespace holon::rules {

namespace {

/// The default block size of each robot in VisibleSim (slidingCubesWorld.h, blinkyBlocksWorld.h,
/// hexanodesWorld.h): its world units per cell.
const char* blockSize(VisibleSimRobot robot) {
    switch (robot) {
    case VisibleSimRobot::SlidingCubes: return "10,10,10";
    case VisibleSimRobot::BlinkyBlocks: return "40,40,41";
    case VisibleSimRobot::Hexanodes: return "50,50,12.5";
    }
    return "";
}

/// "#rrggbb" as VisibleSim's "r,g,b" (0 to 255 each).
std::string rgb(const std::string& colour) {
    if (colour.size() != 7 || colour[0] != '#') throw std::logic_error("colour '" + colour + "' is not #rrggbb");
    std::string out;
    for (int k = 0; k < 3; ++k) out += (k ? "," : "") + std::to_string(std::stoi(colour.substr(1 + 2 * k, 2), nullptr, 16));
    return out;
}

/// Text inside an XML comment: no "--" (which would end it early) and printable ASCII only.
std::string commentText(const std::string& text) {
    std::string out;
    for (char c : text) {
        const char safe = c >= 32 && c < 127 ? c : '?';
        if (safe == '-' && !out.empty() && out.back() == '-') out += ' ';
        out += safe;
    }
    if (!out.empty() && out.back() == '-') out += ' ';
    return out;
}

}  // namespace

const char* visibleSimRobotName(VisibleSimRobot robot) {
    switch (robot) {
    case VisibleSimRobot::SlidingCubes: return "slidingCubes";
    case VisibleSimRobot::BlinkyBlocks: return "blinkyBlocks";
    case VisibleSimRobot::Hexanodes: return "hexanodes";
    }
    return "";
}

Vec toVisibleSimAxes(const Lattice& lattice, Vec v) {
    switch (lattice.kind()) {
    case LatticeKind::Square2D: return {v.x, -v.y, 0};
    case LatticeKind::Cubic3D: return v;
    case LatticeKind::Hex2D: return {v.x + v.y, -v.y, 0};
    }
    return v;
}

std::string visibleSimWorld(const Lattice& lattice, VisibleSimRobot robot, const std::vector<VisibleSimCell>& blocks,
                            const std::vector<VisibleSimCell>& targets, const std::vector<std::string>& comments, int margin) {
    const bool hex = lattice.kind() == LatticeKind::Hex2D;
    if (hex != (robot == VisibleSimRobot::Hexanodes))
        throw InputError(parameterName(Parameter::Robot) + " " + visibleSimRobotName(robot) + ": VisibleSim's " + visibleSimRobotName(robot) + " live on " +
                             (hex ? "a cube lattice, not on hex2d; give " + parameterName(Parameter::Robot) + " hexanodes"
                                  : "the hexagonal lattice, not on " + lattice.name() + "; give " + parameterName(Parameter::Robot) + " slidingCubes or blinkyBlocks"),
                         Parameter::Robot);
    if (blocks.empty()) throw InputError("a VisibleSim world needs at least one block; the configuration is empty");
    Vec lo{INT_MAX, INT_MAX, INT_MAX}, hi{INT_MIN, INT_MIN, INT_MIN};
    for (const auto* list : {&blocks, &targets})
        for (const VisibleSimCell& c : *list) {
            const Vec v = toVisibleSimAxes(lattice, c.at);
            lo = {std::min(lo.x, v.x), std::min(lo.y, v.y), std::min(lo.z, v.z)};
            hi = {std::max(hi.x, v.x), std::max(hi.y, v.y), std::max(hi.z, v.z)};
        }
    const Vec room{margin, margin, lattice.dimension() == 3 ? margin : 0};
    lo = lo - room, hi = hi + room;
    const auto position = [&](Vec at) {
        const Vec v = toVisibleSimAxes(lattice, at) - lo;
        return std::to_string(v.x) + "," + std::to_string(v.y) + "," + std::to_string(v.z);
    };
    std::ostringstream out;
    out << "<?xml version=\"1.0\" standalone=\"no\" ?>\n";
    for (const std::string& c : comments) out << "<!-- " << commentText(c) << " -->\n";
    const char* axes = lattice.kind() == LatticeKind::Cubic3D ? "(x, y, z)" : hex ? "(x + y, -y, 0)"
                                                                                  : "(x, -y, 0)";
    out << "<!-- holon " << lattice.name() << " cell " << (hex ? "(x, y) axial" : lattice.dimension() == 3 ? "(x, y, z)"
                                                                                                           : "(x, y)")
        << " is at position " << axes
        << " - (" << lo.x << ", " << lo.y << ", " << lo.z << ") -->\n";
    // Extents in 64 bits: coordinates reach +-kMaxCoordinate (rules/Limits.h), so a difference fits, a difference plus one too.
    out << "<world gridSize=\"" << std::int64_t(hi.x) - lo.x + 1 << "," << std::int64_t(hi.y) - lo.y + 1 << "," << std::int64_t(hi.z) - lo.z + 1 << "\">\n";
    out << "  <blockList blockSize=\"" << blockSize(robot) << "\">\n";
    for (const VisibleSimCell& b : blocks)
        out << "    <block position=\"" << position(b.at) << "\"" << (hex ? " orientation=\"0\"" : "") << " color=\"" << rgb(b.colour) << "\"/>\n";
    out << "  </blockList>\n";
    if (!targets.empty()) {
        out << "  <targetList>\n    <target format=\"grid\">\n";
        for (const VisibleSimCell& t : targets) out << "      <cell position=\"" << position(t.at) << "\" color=\"" << rgb(t.colour) << "\"/>\n";
        out << "    </target>\n  </targetList>\n";
    }
    out << "</world>\n";
    return out.str();
}

}  // namespace holon::rules
