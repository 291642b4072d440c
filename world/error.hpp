// onelight's one error convention: a failure is an exception. Bad input (a level source, a
// package, an image, a replay script, a command line, a file that cannot be read or written)
// throws world::Error with a one-line message naming the file, the place and what was expected;
// it is caught once, at the top of a command, which prints it and exits non-zero. Nothing
// returns an error code or an error string.
#pragma once

#include <stdexcept>
#include <string>

namespace onelight::world {

/// A one-line message naming the file, the place and what was expected.
class Error : public std::runtime_error {
public:
    explicit Error(const std::string& message) : std::runtime_error(message) {}
};

}  // namespace onelight::world
