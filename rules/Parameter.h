#pragma once
// The user-settable parameters the library's messages mention ("raise the memory bound", "the
// scale must be at least 1"), named once. The library never spells a command-line flag: a message
// asks parameterName(Parameter::Memory), which gives the library-API name (the field or argument
// that sets it, "Limits::memoryBytes") unless the program that exposes the library installs its
// own names with setParameterNames (the CLI's cli/ParameterNames.cpp: "--memory").

#include <string>

namespace holon::rules {

enum class Parameter { Memory,      // the memory bound of a job
                       Timeout,     // the wall-clock budget of a job
                       MaxStates,   // the states an exploration may store
                       Initial,     // the configurations an exploration starts from
                       All,         // explore every legal configuration instead
                       From,        // a path's start
                       To,          // a path's target
                       Goal,        // a path to the system's goal instead of a target
                       Search,      // the path search
                       Region,      // the bounded region of a rule system
                       Rules,       // the rule system
                       Scale,       // the block every shape cell becomes
                       Allocator,   // general_n's resource allocator
                       Lose,        // a metamodule lost after a round
                       HexDisks,    // plan's realisation by hex-lattice disks
                       SculptFrom,  // the hex sculptor's source shape
                       SculptTo,    // the hex sculptor's target shape
                       Size,        // the hex array's lattice points per side
                       Tri,         // the hex sculptor's tri-region edge
                       Strategy,    // the Roombots assembly strategy
                       Metamodule,  // the Roombots metamodule configuration
                       MakeClouds,  // computing the Roombots collision-cloud table
                       Robot };     // the VisibleSim module type

/// Names of the parameters as a program exposes them; every Parameter must have one.
using ParameterNames = std::string (*)(Parameter);

/// The name of `p` for messages: the installed names', else the library API's.
std::string parameterName(Parameter p);

/// The library API's name of `p` ("Limits::memoryBytes").
std::string apiParameterName(Parameter p);

/// Installs the names messages use from now on (null: the API's again). Called once at startup,
/// before any thread runs; a library user who installs none sees the API's names.
void setParameterNames(ParameterNames names);

}  // namespace holon::rules
