#include "tests/support/scratch_folder.hpp"

#include <unistd.h>

#include <algorithm>
#include <cstdio>
#include <mutex>
#include <system_error>
#include <vector>

#include <gtest/gtest.h>

namespace onelight::test {
namespace {

// The folders this process made. Its destructor runs at exit, before GoogleTest's own singleton
// (made earlier, by main) is gone.
struct ScratchFolders {
    std::mutex lock;
    std::vector<std::filesystem::path> folders;
    ~ScratchFolders() {
        const bool failed = ::testing::UnitTest::GetInstance()->Failed();
        for (const std::filesystem::path& folder : folders) {
            if (failed) {
                std::fprintf(stderr, "a test failed: its scratch folder %s is kept\n",
                             folder.c_str());
                continue;
            }
            std::error_code ignored;
            std::filesystem::remove_all(folder, ignored);
        }
    }
};

ScratchFolders& scratchFolders() {
    static ScratchFolders folders;
    return folders;
}

}  // namespace

std::filesystem::path scratchFolder(const std::string& prefix) {
    const std::filesystem::path folder =
        std::filesystem::temp_directory_path() / (prefix + "-" + std::to_string(::getpid()));
    std::filesystem::remove_all(folder);
    std::filesystem::create_directories(folder);
    ScratchFolders& all = scratchFolders();
    const std::lock_guard<std::mutex> hold(all.lock);
    if (std::find(all.folders.begin(), all.folders.end(), folder) == all.folders.end())
        all.folders.push_back(folder);
    return folder;
}

}  // namespace onelight::test
