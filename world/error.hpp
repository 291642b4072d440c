// The one error type of the level compiler: a one-line message naming file, place and what was
// expected. Thrown by import and compile, caught by the command.
#pragma once

#include <stdexcept>
#include <string>

namespace onelight::world {

class CompileError : public std::runtime_error {
public:
    explicit CompileError(const std::string& message) : std::runtime_error(message) {}
};

}  // namespace onelight::world
