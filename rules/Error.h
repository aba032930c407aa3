#pragma once
// The one exception type holon throws for bad input or misuse; the CLI turns it into exit code 2.

#include <stdexcept>
#include <string>

namespace holon {

class InputError : public std::runtime_error {
public:
    explicit InputError(const std::string& message) : std::runtime_error(message) {}
};

}  // namespace holon
