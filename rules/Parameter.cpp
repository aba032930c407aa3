// The names of rules/Parameter.h: the library API's, and the hook through which a program that
// exposes the parameters under names of its own (the CLI's options) has messages use those.

#include "rules/Parameter.h"

#include "rules/Error.h"

#include <atomic>

namespace holon::rules {

namespace {

/// Installed once before any thread runs, read from worker threads: atomic, so that a library
/// user who installs names late still reads a whole pointer.
std::atomic<ParameterNames> installed{nullptr};

}  // namespace

std::string apiParameterName(Parameter p) {
    switch (p) {
    case Parameter::Memory: return "Limits::memoryBytes";
    case Parameter::Timeout: return "Limits::timeoutSeconds";
    case Parameter::MaxStates: return "Limits::maxStates";
    case Parameter::Initial: return "CheckOptions::initial";
    case Parameter::All: return "CheckOptions::all";
    case Parameter::From: return "PathQuery::from";
    case Parameter::To: return "PathQuery::to";
    case Parameter::Goal: return "the system's goal";
    case Parameter::Search: return "PathQuery::search";
    case Parameter::Region: return "rules::Region";
    case Parameter::Rules: return "rules::Model";
    case Parameter::Scale: return "scale (parseShape)";
    case Parameter::Allocator: return "allocatorKind's name";
    case Parameter::Lose: return "FaultOptions::losses";
    case Parameter::HexDisks: return "hex::DiskMetamodules";
    case Parameter::SculptFrom: return "SculptSetup::from";
    case Parameter::SculptTo: return "SculptSetup::to";
    case Parameter::Size: return "SculptSetup::size";
    case Parameter::Tri: return "planTriRegions' side";
    case Parameter::Strategy: return "roombots::Strategy";
    case Parameter::Metamodule: return "roombots::Coupling";
    case Parameter::MakeClouds: return "CloudTable::compute";
    case Parameter::Robot: return "VisibleSimRobot";
    }
    throw InternalError("apiParameterName: a Parameter out of range");
}

std::string parameterName(Parameter p) {
    const ParameterNames names = installed.load(std::memory_order_acquire);
    return names ? names(p) : apiParameterName(p);
}

void setParameterNames(ParameterNames names) { installed.store(names, std::memory_order_release); }

}  // namespace holon::rules
