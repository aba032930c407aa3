// The property types of the rule IR, built by a switch over rules::Property::Kind (no default:
// the compiler lists this place when a kind is added), the built-in ones of a system with a goal,
// and what every type shares: a counterexample confirmed by replaying its trace through the
// reference interpreter, recorded on the result for callers of check() and verify() alike.

#include "checker/Property.h"

#include "checker/properties/Kinds.h"
#include "rules/Error.h"

namespace holon::checker {

std::unique_ptr<PropertyType> propertyType(const rules::Property& p) {
    switch (p.kind) {
    case rules::Property::Kind::Invariant: return properties::invariant(p);
    case rules::Property::Kind::Progress: return properties::progress(p);
    case rules::Property::Kind::Ranking: return properties::ranking(p);
    case rules::Property::Kind::Holonomic: return properties::holonomic(p);
    case rules::Property::Kind::Conserves: return properties::conserves(p);
    }
    throw InternalError("a property kind with no type");
}

std::vector<std::unique_ptr<PropertyType>> checkablePropertyTypes(const rules::System& system) {
    std::vector<std::unique_ptr<PropertyType>> types;
    for (const rules::Property& p : system.properties) types.push_back(propertyType(p));
    if (system.goal) {
        types.push_back(properties::deadlock());
        types.push_back(properties::goalReachable());
    }
    return types;
}

bool PropertyType::confirm(const PropertyResult& r, Evidence, const rules::Interpreter& in, const rules::Engine& engine, std::string* why) const {
    if (!r.trace || r.trace->steps.empty()) {
        if (why) *why = "the counterexample has no trace";
        return false;
    }
    return replay(*r.trace, engine, in, why);
}

bool PropertyType::confirmBrokenStep(const PropertyResult& r, const rules::Interpreter& in, const rules::Engine& engine, std::string* why, const char* keeps,
                                     const std::function<bool(const CellValue*, const CellValue*, int)>& broken) const {
    if (!PropertyType::confirm(r, Evidence::Path, in, engine, why)) return false;
    const auto& steps = r.trace->steps;
    if (steps.size() == 2 && broken(steps[0].cells.data(), steps[1].cells.data(), steps[1].placed)) return true;
    if (why) *why = steps.size() == 2 ? std::string("the interpreter's step ") + keeps : "the counterexample is not one step";
    return false;
}

void confirmInto(PropertyResult& r, const PropertyType& type, Evidence evidence, const rules::Interpreter& in, const rules::Engine& engine, const char* flag) {
    std::string why;
    const bool ok = type.confirm(r, evidence, in, engine, &why);
    r.confirmation = Confirmation{ok, ok ? "" : why};
    if (!r.witness.is_object()) r.witness = nlohmann::json::object();
    r.witness[flag] = ok;
    if (r.trace) r.witness["trace"] = traceJson(*r.trace, engine, in);
}

namespace properties {

void holdsOrUnknown(PropertyResult& r, const ExploredGraph& g, const std::string& holdsText) {
    r.verdict = g.complete ? Verdict::Holds : Verdict::Unknown;
    r.limited = !g.complete;
    r.summary = g.complete ? holdsText : "no violation among the " + std::to_string(g.explorer.stats().states) + " states explored before the limit";
}

}  // namespace properties

}  // namespace holon::checker
