// The collision-cloud table of seed 001 §IV-A f and Fig. 3b: every touched cube of the 3D grid while
// a metamodule changes shape, per configuration and transition, computed by sampling the joint motion
// (Kinematics.cpp) and stored in an external file that running metamodules only look up.
//
// choice: the paper keys its table by initial and final shape; shapes are too coarse for clouds (an L
// reaches an L by many joint paths), so the table is keyed by the joint setting a metamodule stands in
// and lists one transition per target posture: the one sweeping the fewest cells, then the fastest,
// then the lowest joint index. Only postures a walk can reach are tabulated (the start I and every
// step's reversal, closed under stepping), which keeps the file near 2 MB. Clouds are bit masks over
// the 7 x 7 x 4 box of cells a metamodule can touch from its foot.

#include "planner/roombots/CollisionClouds.h"

#include "rules/ConfigIo.h"
#include "rules/Error.h"
#include "rules/OutputFile.h"
#include "rules/Parameter.h"
#include "rules/TextFile.h"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <numbers>
#include <optional>
#include <set>
#include <sstream>
#include <stdexcept>
#include <tuple>

namespace holon::planner::roombots {
namespace {

constexpr int kReach = 3, kWidth = 2 * kReach + 1, kHeight = 4, kBits = kWidth * kWidth * kHeight;

int bit(const Cell& c) {
    if (std::abs(c.x) > kReach || std::abs(c.y) > kReach || c.z < 0 || c.z >= kHeight)
        throw std::logic_error("collision cloud leaves the table's box");
    return ((c.z * kWidth) + (c.y + kReach)) * kWidth + (c.x + kReach);
}

std::string encode(const std::vector<Cell>& cloud) {
    std::vector<bool> bits(kBits);
    for (const Cell& c : cloud) bits[bit(c)] = true;
    std::string hex;
    for (int i = 0; i < kBits; i += 4) {
        int nibble = 0;
        for (int k = 0; k < 4 && i + k < kBits; ++k) nibble |= bits[i + k] << k;
        hex += "0123456789abcdef"[nibble];
    }
    return hex;
}

std::vector<Cell> decode(const std::string& hex) {
    std::vector<Cell> cells;
    for (int i = 0; i < kBits; ++i) {
        const char ch = hex.at(i / 4);
        const int nibble = ch <= '9' ? ch - '0' : ch - 'a' + 10;
        if (!(nibble >> (i % 4) & 1)) continue;
        const int x = i % kWidth - kReach, y = i / kWidth % kWidth - kReach, z = i / (kWidth * kWidth);
        cells.push_back({x, y, z});
    }
    std::sort(cells.begin(), cells.end());
    return cells;
}

double seconds(const Joints& a, const Joints& b) {
    double slowest = 0;
    for (int k = 0; k < 6; ++k) {
        const bool swivel = k == 1 || k == 4;
        const int positions = swivel ? 4 : 3;
        const int d = ((b.q[k] - a.q[k]) % positions + positions) % positions;
        const double turns = static_cast<double>(std::min(d, positions - d)) / positions;
        slowest = std::max(slowest, turns * (swivel ? 3.0 : 2.0));
    }
    return slowest;
}

bool standsOnFloor(const Posture& p) {
    std::set<Cell> distinct(p.cells.begin(), p.cells.end());
    if (distinct.size() != 4) return false;
    for (const Cell& c : p.cells)
        if (c.z < 0) return false;
    return true;
}

}  // namespace

CloudTable CloudTable::compute(const Budget& budget) {
    CloudTable table;
    for (Coupling coupling : kCouplings) {
        const Metamodule m(coupling);
        // Target postures: steps by (cells, head yaw), seats by cells.
        std::map<std::tuple<Transition::Kind, std::array<Cell, 4>, int>, std::vector<Joints>> targets;
        for (int i = 0; i < kJointSettings; ++i) {
            const Joints j = Joints::fromIndex(i);
            const Posture p = m.posture(j, 0);
            if (!standsOnFloor(p)) continue;
            if (p.stance()) targets[{Transition::Kind::Step, p.cells, p.headYaw}].push_back(j);
            targets[{Transition::Kind::Seat, p.cells, 0}].push_back(j);
        }
        auto& rows = table.table_[static_cast<int>(coupling)];
        std::set<int> pending{0};
        while (!pending.empty()) {
            budget.check("computing the collision-cloud table");
            const Joints from = Joints::fromIndex(*pending.begin());
            pending.erase(pending.begin());
            auto& row = rows[from.index()];
            for (const auto& [key, members] : targets) {
                std::optional<Transition> best;
                for (const Joints& to : members) {
                    std::vector<Cell> cloud = m.sweep(from, to, 0, kSamples, kRadius);
                    if (cloud.empty()) continue;
                    const double s = seconds(from, to);
                    if (!best || cloud.size() < best->cloud.size() || (cloud.size() == best->cloud.size() && s < best->seconds - 1e-9))
                        best = Transition{std::get<0>(key), to, s, std::move(cloud)};
                }
                if (!best) continue;
                if (best->kind == Transition::Kind::Step) {
                    const int next = reversed(best->to).index();
                    if (!rows.count(next)) pending.insert(next);
                }
                row.push_back(std::move(*best));
            }
        }
    }
    return table;
}

std::string CloudTable::json() const {
    std::ostringstream out;
    out << "{\"format\": \"holon-roombots-clouds-1\", \"samples\": " << kSamples << ", \"radius\": " << kRadius
        << ",\n \"box\": \"bit ((z*7)+(y+3))*7+(x+3) of x,y in -3..3, z in 0..3, cells relative to the foot at yaw 0\",\n"
        << " \"couplings\": {";
    for (Coupling c : kCouplings) {
        out << (c == Coupling::PAR ? "\n" : ",\n") << "  \"" << couplingName(c) << "\": [";
        bool firstRow = true;
        for (const auto& [from, row] : table_[static_cast<int>(c)])
            for (const Transition& t : row) {
                char seconds[32];
                std::snprintf(seconds, sizeof seconds, "%.3f", t.seconds);
                out << (firstRow ? "\n" : ",\n") << "   [" << from << ", " << t.to.index() << ", \""
                    << (t.kind == Transition::Kind::Step ? "step" : "seat") << "\", " << seconds << ", \"" << encode(t.cloud) << "\"]";
                firstRow = false;
            }
        out << "]";
    }
    out << "}}\n";
    return out.str();
}

CloudTable CloudTable::load(const std::string& path) {
    // Read like every other input: claimed (no output may replace it), bounded in size, a FIFO
    // stops on a signal, and the JSON checked for depth, NUL bytes and keys given twice.
    rules::OutputClaims::reading("the collision-cloud table", path);
    std::error_code error;
    if (!std::filesystem::exists(path, error))
        throw InputError(path + ": cannot read the collision-cloud table; regenerate it with `" + rules::parameterName(rules::Parameter::MakeClouds) + " " + path + "`",
                         rules::Parameter::MakeClouds);
    const std::string text = rules::readTextFile(path);
    CloudTable table;
    try {
        const nlohmann::json j = [&] {
            try {
                return rules::parseJsonOnceEach(text);
            } catch (const InputError& e) {
                throw InputError(path + ": " + e.what() + "; regenerate it with `" + rules::parameterName(rules::Parameter::MakeClouds) + "`", rules::Parameter::MakeClouds);
            }
        }();
        if (j.at("format") != "holon-roombots-clouds-1") throw InputError(path + ": not a holon collision-cloud table (format)");
        for (Coupling c : kCouplings) {
            const auto& rows = j.at("couplings").at(couplingName(c));
            const std::string where = std::string(" in the ") + couplingName(c) + " table";
            // Every field is checked: an unknown kind was read as "seat", negative durations,
            // fractional or wrapped joint indices and non-hex clouds were taken as they came.
            if (!rows.is_array() || rows.empty()) throw InputError(path + ": no transitions" + where + "; regenerate it");
            for (const auto& e : rows) {
                if (!e.is_array() || e.size() != 5 || !e.at(0).is_number_integer() || !e.at(1).is_number_integer())
                    throw InputError(path + ": a transition is [from, to, kind, seconds, cloud] with whole joint settings" + where);
                const std::int64_t from = e.at(0), to = e.at(1);
                if (from < 0 || from >= kJointSettings || to < 0 || to >= kJointSettings) throw InputError(path + ": joint setting out of range" + where);
                const std::string kind = e.at(2);
                if (kind != "step" && kind != "seat") throw InputError(path + ": transition kind '" + kind + "'" + where + "; use step or seat");
                const double seconds = e.at(3);
                if (!(seconds >= 0) || !std::isfinite(seconds)) throw InputError(path + ": a transition's duration must be a number of seconds, 0 or more" + where);
                const std::string hex = e.at(4);
                if (static_cast<int>(hex.size()) != (kBits + 3) / 4 || hex.find_first_not_of("0123456789abcdef") != std::string::npos)
                    throw InputError(path + ": malformed cloud" + where + " (" + std::to_string((kBits + 3) / 4) + " lower-case hex digits)");
                table.table_[static_cast<int>(c)][static_cast<int>(from)].push_back(
                    Transition{kind == "step" ? Transition::Kind::Step : Transition::Kind::Seat, Joints::fromIndex(static_cast<int>(to)), seconds, decode(hex)});
            }
        }
    } catch (const nlohmann::json::exception& e) {
        throw InputError(path + ": malformed collision-cloud table (" + rules::jsonErrorText(e) + "); regenerate it with `" + rules::parameterName(rules::Parameter::MakeClouds) + "`",
                         rules::Parameter::MakeClouds);
    }
    return table;
}

std::string CloudTable::defaultPath() { return std::string(HOLON_ROOMBOTS_DATA_DIR) + "/clouds.json"; }

const std::vector<Transition>& CloudTable::from(Coupling c, const Joints& from) const {
    static const std::vector<Transition> kNone;
    const auto& rows = table_[static_cast<int>(c)];
    const auto it = rows.find(from.index());
    return it == rows.end() ? kNone : it->second;
}

std::size_t CloudTable::size() const {
    std::size_t n = 0;
    for (const auto& rows : table_)
        for (const auto& [from, row] : rows) n += row.size();
    return n;
}

}  // namespace holon::planner::roombots
