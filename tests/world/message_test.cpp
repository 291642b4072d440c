// Error messages as commands print them: quoted input clipped (clipForMessage) and whole
// messages kept to one short line (oneLineMessage).
#include <string>

#include <gtest/gtest.h>

#include "world/file_read.hpp"

namespace onelight::world {
namespace {

TEST(Message, ClipForMessageShowsTheHeadAndTheLength) {
    EXPECT_EQ(clipForMessage("short"), "short");
    EXPECT_EQ(clipForMessage(std::string(100, 'x'), 10), "xxxxxxxxxx... (100 characters)");
    EXPECT_EQ(clipForMessage("a\nb\x7f"), "a?b?");
}

TEST(Message, OneLineMessageClipsLongWordsAndBreaksNoLine) {
    EXPECT_EQ(oneLineMessage("level.gltf: nodes[3]: expected an object"),
              "level.gltf: nodes[3]: expected an object");
    EXPECT_EQ(oneLineMessage("map\nname: bad\r"), "map?name: bad?");
    const std::string path = "/usr/share/games/openarena/baseoa/pak6-patch088.pk3:maps/oa_ctf2.bsp";
    ASSERT_GT(path.size(), 64u);
    EXPECT_EQ(oneLineMessage(path + ": damaged"),
              "/usr/share/games...tch088.pk3:maps/oa_ctf2.bsp: (69 characters) damaged");
    const std::string message = oneLineMessage(std::string(5000, 'a') + " b");
    EXPECT_LE(message.size(), 70u) << message;
    EXPECT_NE(message.find("(5000 characters) b"), std::string::npos) << message;
    EXPECT_EQ(oneLineMessage(""), "");
    EXPECT_EQ(oneLineMessage("two  spaces "), "two  spaces ");
}

}  // namespace
}  // namespace onelight::world
