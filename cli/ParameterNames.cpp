// The one table from the library's parameters to the options that set them, so that a library
// message ("raise " + parameterName(Parameter::Memory)) reads "raise --memory" from the command
// line and names the API's field to a library user. A new Parameter fails to compile here
// (-Werror=switch) until it has an option.

#include "cli/ParameterNames.h"

#include "rules/Error.h"

namespace holon::cli {

std::string optionName(rules::Parameter p) {
    using rules::Parameter;
    switch (p) {
    case Parameter::Memory: return "--memory";
    case Parameter::Timeout: return "--timeout";
    case Parameter::MaxStates: return "--max-states";
    case Parameter::Initial: return "--from";
    case Parameter::All: return "--all";
    case Parameter::From: return "--from";
    case Parameter::To: return "--to";
    case Parameter::Goal: return "--goal";
    case Parameter::Search: return "--search";
    case Parameter::Region: return "--region";
    case Parameter::Rules: return "--rules";
    case Parameter::Scale: return "--scale";
    case Parameter::Allocator: return "--allocator";
    case Parameter::Lose: return "--lose";
    case Parameter::HexDisks: return "--hex-disks";
    case Parameter::SculptFrom: return "--from";
    case Parameter::SculptTo: return "--to";
    case Parameter::Size: return "--size";
    case Parameter::Tri: return "--tri";
    case Parameter::Strategy: return "--strategy";
    case Parameter::Metamodule: return "--metamodule";
    case Parameter::MakeClouds: return "holon roombots --make-clouds";  // the messages quote it as a command
    case Parameter::Robot: return "--robot";
    }
    throw InternalError("optionName: a Parameter out of range");
}

void installOptionNames() { rules::setParameterNames(optionName); }

}  // namespace holon::cli
