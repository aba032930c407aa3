#pragma once
// The two exception types holon throws: InputError for bad input or misuse (the CLI's exit code 2,
// with a message that names the place and the fix), InternalError for a bug in holon itself (exit
// code 4, with a request for a report; never shown as bad input).

#include <stdexcept>
#include <string>

namespace holon {

class InputError : public std::runtime_error {
public:
    explicit InputError(const std::string& message) : std::runtime_error(message) {}
};

class InternalError : public std::logic_error {
public:
    explicit InternalError(const std::string& message) : std::logic_error(message) {}
};

}  // namespace holon
