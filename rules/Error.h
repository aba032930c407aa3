#pragma once
// The exception types holon throws: InputError for bad input or misuse (the CLI's exit code 2,
// with a message that names the place and the fix), LimitError for a job over a limit the user can
// raise (exit code 3), InternalError for a bug in holon itself (exit code 4, with a request for a
// report; never shown as bad input), Interrupted for a job stopped by a signal (128 + the signal).
// An InputError or LimitError about one user-settable parameter carries it (rules/Parameter.h), so
// that a caller can point at its own name for it; the message names it with rules::parameterName.

#include "rules/Parameter.h"

#include <csignal>
#include <optional>
#include <stdexcept>
#include <string>

namespace holon {

class InputError : public std::runtime_error {
public:
    explicit InputError(const std::string& message) : std::runtime_error(message) {}
    InputError(const std::string& message, std::optional<rules::Parameter> about) : std::runtime_error(message), parameter_(about) {}
    /// The parameter the message is about, when it is about one.
    std::optional<rules::Parameter> parameter() const { return parameter_; }

private:
    std::optional<rules::Parameter> parameter_;
};

/// A job refused or stopped by a limit the user set or can raise (the memory bound, the timeout):
/// exit code 3, with a message that names the limit.
class LimitError : public std::runtime_error {
public:
    explicit LimitError(const std::string& message) : std::runtime_error(message) {}
    LimitError(const std::string& message, std::optional<rules::Parameter> about) : std::runtime_error(message), parameter_(about) {}
    /// The limit the message is about, when it is about one.
    std::optional<rules::Parameter> parameter() const { return parameter_; }

private:
    std::optional<rules::Parameter> parameter_;
};

class InternalError : public std::logic_error {
public:
    explicit InternalError(const std::string& message) : std::logic_error(message) {}
};

/// A long job stopped by SIGINT or SIGTERM after it stopped its helpers (verify's solver
/// processes): the CLI exits 128 + the signal.
class Interrupted : public std::runtime_error {
public:
    explicit Interrupted(int signal) : std::runtime_error("interrupted by " + signalName(signal)), signal_(signal) {}
    int signal() const { return signal_; }
    static std::string signalName(int signal) { return signal == SIGINT ? "SIGINT" : signal == SIGTERM ? "SIGTERM"
                                                                                 : signal == SIGHUP    ? "SIGHUP"
                                                                                                       : "signal " + std::to_string(signal); }

private:
    int signal_;
};

}  // namespace holon
