// The message of what `f` throws, for tests that expect an error: "" when it throws nothing.
#pragma once

#include <exception>
#include <string>

namespace onelight::test {

template <class F>
std::string errorMessage(F&& f) {
    try {
        f();
    } catch (const std::exception& e) {
        return e.what();
    }
    return "";
}

}  // namespace onelight::test
