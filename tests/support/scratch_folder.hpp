// Scratch folders for tests: fresh and empty under the system's temporary folder, named after a
// label and the process, and removed when the process ends. When a test failed they are kept for
// a look, and each is named on stderr.
#pragma once

#include <filesystem>
#include <string>

namespace onelight::test {

/// A fresh empty folder "<temp>/<prefix>-<pid>", emptied when it already exists (the same label
/// twice in one process gives the same folder).
[[nodiscard]] std::filesystem::path scratchFolder(const std::string& prefix);

}  // namespace onelight::test
