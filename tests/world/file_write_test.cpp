// world::writeFileAtomically: the bytes written, a file replaced whole, a missing folder made,
// and every failure a world::Error naming the path that leaves neither the target nor a
// temporary behind; two writers of one path never share a temporary.
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <thread>
#include <vector>

#include <gtest/gtest.h>

#include "tests/support/error_message.hpp"
#include "tests/world/world_test_support.hpp"
#include "world/error.hpp"
#include "world/file_write.hpp"

namespace onelight::test {
namespace {

namespace fs = std::filesystem;

std::string contents(const fs::path& path) {
    std::ifstream in(path, std::ios::binary);
    return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

// Every file name in `folder` (not recursive).
std::vector<std::string> names(const fs::path& folder) {
    std::vector<std::string> out;
    for (const auto& entry : fs::directory_iterator(folder))
        out.push_back(entry.path().filename().string());
    return out;
}

// The message of the world::Error `f` throws; fails the test when it throws anything else.
template <class F>
std::string worldError(F&& f) {
    try {
        f();
    } catch (const world::Error& e) {
        return e.what();
    } catch (const std::exception& e) {
        ADD_FAILURE() << "not a world::Error: " << e.what();
        return e.what();
    }
    ADD_FAILURE() << "nothing thrown";
    return "";
}

TEST(FileWrite, WritesTheBytesAndNothingElse) {
    const fs::path folder = freshFolder("file_write_bytes");
    const std::vector<uint8_t> bytes = {0, 1, 2, 255, 10, 13, 0};
    world::writeFileAtomically((folder / "a.bin").string(), bytes);
    world::writeFileAtomically((folder / "b.txt").string(), std::string_view("text\n"));
    world::writeFileAtomically((folder / "empty").string(), std::string_view());
    EXPECT_EQ(contents(folder / "a.bin"), std::string(bytes.begin(), bytes.end()));
    EXPECT_EQ(contents(folder / "b.txt"), "text\n");
    EXPECT_TRUE(fs::is_regular_file(folder / "empty"));
    EXPECT_EQ(fs::file_size(folder / "empty"), 0u);
    EXPECT_EQ(names(folder).size(), 3u);  // no temporary left
}

TEST(FileWrite, MakesAMissingFolder) {
    const fs::path folder = freshFolder("file_write_folder");
    const fs::path nested = folder / "new" / "deeper" / "out.txt";
    world::writeFileAtomically(nested.string(), std::string_view("x"));
    EXPECT_EQ(contents(nested), "x");
}

TEST(FileWrite, ReplacesAnExistingFileWhole) {
    const fs::path folder = freshFolder("file_write_replace");
    const std::string path = (folder / "out.bin").string();
    world::writeFileAtomically(path, std::string(100000, 'a'));
    world::writeFileAtomically(path, std::string_view("bcd"));
    EXPECT_EQ(contents(path), "bcd");  // not "bcd" followed by the old file's tail
    EXPECT_EQ(names(folder), std::vector<std::string>{"out.bin"});
}

TEST(FileWrite, AFolderThatIsAFileIsANamedErrorAndLeavesNothing) {
    const fs::path folder = freshFolder("file_write_under_file");
    world::writeFileAtomically((folder / "file").string(), std::string_view("keep"));
    const std::string path = (folder / "file" / "out.bin").string();
    const std::string error =
        worldError([&] { world::writeFileAtomically(path, std::string_view("x")); });
    EXPECT_EQ(error.rfind(path + ": ", 0), 0u) << error;  // starts with the path
    EXPECT_NE(error.find("cannot create its folder"), std::string::npos) << error;
    EXPECT_NE(error.find("("), std::string::npos) << error;  // the system's reason
    EXPECT_EQ(contents(folder / "file"), "keep");
    EXPECT_EQ(names(folder), std::vector<std::string>{"file"});
}

TEST(FileWrite, ATemporaryThatCannotBeCreatedIsANamedErrorAndLeavesNothing) {
    // A name of 250 bytes is allowed; its temporary (name.tmp.PID.N) is longer than a file
    // name may be, so creating it fails, even for root.
    const fs::path folder = freshFolder("file_write_long_name");
    const std::string path = (folder / std::string(250, 'n')).string();
    const std::string error =
        worldError([&] { world::writeFileAtomically(path, std::string_view("x")); });
    EXPECT_EQ(error.rfind(path + ": cannot create ", 0), 0u) << error;
    EXPECT_NE(error.find("(File name too long)"), std::string::npos) << error;
    EXPECT_TRUE(names(folder).empty());
}

TEST(FileWrite, ARenameThatFailsIsANamedErrorAndLeavesNothing) {
    // The target is a folder that is not empty: the rename over it fails.
    const fs::path folder = freshFolder("file_write_over_folder");
    const fs::path target = folder / "out";
    world::writeFileAtomically((target / "inside").string(), std::string_view("keep"));
    const std::string error =
        worldError([&] { world::writeFileAtomically(target.string(), std::string_view("x")); });
    EXPECT_EQ(error.rfind(target.string() + ": cannot rename ", 0), 0u) << error;
    EXPECT_NE(error.find("into place ("), std::string::npos) << error;
    EXPECT_EQ(contents(target / "inside"), "keep");
    EXPECT_EQ(names(folder), std::vector<std::string>{"out"});
}

TEST(FileWrite, AWriterThatThrowsLeavesTheOldFileAndNoTemporary) {
    const fs::path folder = freshFolder("file_write_callback");
    const std::string path = (folder / "image.exr").string();
    world::writeFileAtomically(path, std::string_view("old"));
    std::string temporary;
    const std::string error = worldError([&] {
        world::writeFileAtomicallyWith(path, [&](const std::string& tmp) {
            temporary = tmp;
            std::ofstream(tmp, std::ios::binary) << "half";
            throw world::Error(path + ": cannot write the EXR (disk full)");
        });
    });
    EXPECT_EQ(error, path + ": cannot write the EXR (disk full)");
    EXPECT_EQ(fs::path(temporary).parent_path(), folder);  // beside the target
    EXPECT_NE(temporary, path + ".tmp");                   // unique to the writer
    EXPECT_EQ(contents(path), "old");
    EXPECT_EQ(names(folder), std::vector<std::string>{"image.exr"});
}

TEST(FileWrite, AWriterThatWritesNothingIsANamedError) {
    const fs::path folder = freshFolder("file_write_nothing");
    const std::string path = (folder / "out.bin").string();
    const std::string error =
        worldError([&] { world::writeFileAtomicallyWith(path, [](const std::string&) {}); });
    EXPECT_EQ(error.rfind(path + ": ", 0), 0u) << error;
    EXPECT_NE(error.find("was not written"), std::string::npos) << error;
    EXPECT_TRUE(names(folder).empty());
}

TEST(FileWrite, WritersOfOnePathInParallelEachWriteWhole) {
    const fs::path folder = freshFolder("file_write_parallel");
    const std::string path = (folder / "shared.bin").string();
    const std::string a(200000, 'a'), b(100000, 'b');
    std::thread first([&] {
        for (int i = 0; i < 40; ++i) world::writeFileAtomically(path, a);
    });
    std::thread second([&] {
        for (int i = 0; i < 40; ++i) world::writeFileAtomically(path, b);
    });
    first.join();
    second.join();
    const std::string last = contents(path);
    EXPECT_TRUE(last == a || last == b) << last.size() << " bytes";
    EXPECT_EQ(names(folder), std::vector<std::string>{"shared.bin"});
}

}  // namespace
}  // namespace onelight::test
