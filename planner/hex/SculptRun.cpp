// The experiment loop of seed 003 §V-A and an SVG view of an ensemble (as the paper's Fig. 10
// frames): modules grey (black outside the target), hole cells pale blue, target points still empty in
// red.

#include "planner/hex/SculptRun.h"

#include "planner/hex/HexShapes.h"
#include "rules/Parameter.h"
#include "rules/Svg.h"

#include <algorithm>
#include <chrono>
#include <sstream>

namespace holon::planner::hex {

std::uint64_t sculptBytes(const SculptSetup& setup) {
    return static_cast<std::uint64_t>(HexArray::boardSize(setup.size)) * 96;
}

SculptResult runSculpt(const SculptSetup& setup, const std::function<void(const HoleSculptor&)>& frame, const Budget& budget,
                       const std::function<void(const HoleSculptor&)>& started) {
    const auto begin = std::chrono::steady_clock::now();
    // The setup reads the budget between its phases, each seconds long on large arrays: a signal
    // or the deadline waited for all of them (hex --size 4000 --timeout 1 ran 6 s).
    SculptResult result;
    const auto stoppedDuringSetup = [&] {
        if (const auto why = budget.reached()) return result.stopped = *why, true;
        return false;
    };
    const HexArray array(setup.size);
    if (stoppedDuringSetup()) return result;
    const auto source = sculptShape(array, setup.from, rules::parameterName(rules::Parameter::SculptFrom));
    if (stoppedDuringSetup()) return result;
    const auto target = sculptShape(array, setup.to, rules::parameterName(rules::Parameter::SculptTo));
    if (stoppedDuringSetup()) return result;
    const TriPlan plan = planTriRegions(array, source, target, std::max(2.0, setup.triFraction * setup.size), budget);
    if (stoppedDuringSetup()) return result;
    HoleSculptor sculptor(array, source, target, plan, setup.options);
    result.modules = sculptor.modules();
    result.startHoles = sculptor.holes();
    result.holeBudget = sculptor.holeBudget();
    result.triRegions = static_cast<int>(plan.regions.size());
    result.series.reserve(setup.steps);
    if (started) started(sculptor);
    int t = 0;
    for (; t < setup.steps; ++t) {
        if (const auto why = budget.reached(Progress{0, static_cast<std::uint64_t>(t), 0})) {
            result.stopped = *why;
            break;
        }
        sculptor.step();
        const SculptSample s{static_cast<float>(sculptor.completeness()), static_cast<float>(sculptor.stability()),
                             static_cast<float>(sculptor.compliance()), static_cast<std::int32_t>(sculptor.holes())};
        result.series.push_back(s);
        result.maxCompleteness = std::max<double>(result.maxCompleteness, s.completeness);
        result.maxStability = std::max<double>(result.maxStability, s.stability);
        result.maxCompliance = std::max<double>(result.maxCompliance, s.compliance);
        if (frame) frame(sculptor);
    }
    result.steps = t;
    result.finalCompliance = sculptor.compliance();
    result.endHoles = sculptor.holes();
    result.islands = sculptor.islands();
    result.counts = sculptor.counts();
    result.residue = sculptor.residue();
    result.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - begin).count();
    return result;
}

std::string sculptSvg(const HoleSculptor& sculptor) {
    const HexArray& array = sculptor.array();
    const double scale = std::max(1.0, 800.0 / array.n()), r = 0.5 * scale;
    rules::Svg svg;
    for (std::int64_t i : array.points()) {
        const char* fill = sculptor.module(i) ? (sculptor.target()[i] ? "#888" : "#222") : sculptor.holeCell(i) ? "#cde"
                                                                                       : sculptor.target()[i]   ? "#e44"
                                                                                                                : nullptr;
        if (fill) svg.circle((array.frameX(i) + 0.5) * scale, (array.frameHeight() - array.frameY(i) + 0.5) * scale, r, {{"fill", fill}});
    }
    return svg.document((array.frameWidth() + 1) * scale, (array.frameHeight() + 1) * scale);
}

}  // namespace holon::planner::hex
