// Assembling a structure from walking Roombots metamodules (seed 001 §IV-A, §V): the strategies by
// name, each run on the same simulated floor (World.cpp) — the paper's force-field strategies
// (ForceField.cpp) and holon's reservation strategy (Reservation.cpp).

#include "planner/roombots/Assembly.h"

#include "planner/roombots/World.h"
#include "rules/Error.h"
#include "rules/Parameter.h"

namespace holon::planner::roombots {

const char* strategyName(Strategy s) {
    static constexpr const char* kNames[] = {"greedy", "slope", "step", "reserve"};
    return kNames[static_cast<int>(s)];
}

Strategy parseStrategy(const std::string& name) {
    for (Strategy s : {Strategy::Greedy, Strategy::Slope, Strategy::Step, Strategy::Reserve})
        if (name == strategyName(s)) return s;
    throw InputError(rules::parameterName(rules::Parameter::Strategy) + ": unknown strategy '" + name + "'; use greedy, slope, step or reserve", rules::Parameter::Strategy);
}

AssemblyResult assemble(const CloudTable& table, Coupling coupling, Strategy strategy, const Setting& setting, const AssemblyOptions& options) {
    if (strategy == Strategy::Reserve) return detail::assembleByReservation(table, coupling, setting, options);
    return detail::assembleByForceField(table, coupling, strategy, setting, options);
}

}  // namespace holon::planner::roombots
