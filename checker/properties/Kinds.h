#pragma once
// The property types of checker/Property.h, one .cpp each, and what their explicit-state checks
// share: how a verdict reads on an incomplete graph, and the nearest of the states that violate.

#include "checker/Property.h"
#include "checker/Trace.h"

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

namespace holon::checker::properties {

std::unique_ptr<PropertyType> invariant(const rules::Property& p);
std::unique_ptr<PropertyType> progress(const rules::Property& p);
/// Deadlock freedom, built in for a system with a goal: progress with no assumption.
std::unique_ptr<PropertyType> deadlock();
std::unique_ptr<PropertyType> ranking(const rules::Property& p);
std::unique_ptr<PropertyType> holonomic(const rules::Property& p);
std::unique_ptr<PropertyType> conserves(const rules::Property& p);
/// AG EF goal, built in for a system with a goal.
std::unique_ptr<PropertyType> goalReachable();

/// No violation found: holds on a whole graph, unknown on a part of it.
void holdsOrUnknown(PropertyResult& r, const ExploredGraph& g, const std::string& holdsText);

/// Among `states`, those `bad` accepts make `r` violated: how many, and a shortest trace to the
/// nearest. False when there is none.
template <class Bad>
bool violatedAtNearest(PropertyResult& r, const Explorer& ex, const std::vector<StateId>& states, Bad bad, const std::string& which,
                       const std::string& description, const char* countKey) {
    std::uint64_t count = 0;
    StateId first = kNoState;
    for (StateId s : states)
        if (bad(s) && (count++ == 0 || ex.pathTo(s).size() < ex.pathTo(first).size())) first = s;
    if (count == 0) return false;
    r.verdict = Verdict::Violated;
    r.trace = traceTo(ex, first);
    r.trace->property = r.name;
    r.summary = std::to_string(count) + (count == 1 ? " state " : " states ") + which;
    r.trace->description = description;
    r.witness = {{countKey, count}, {"distance", r.trace->steps.size() - 1}};
    return true;
}

}  // namespace holon::checker::properties
