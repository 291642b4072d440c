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
    // An ordinary path stays whole; a word past 128 characters keeps its head and its end.
    const std::string path = "/usr/share/games/openarena/baseoa/pak6-patch088.pk3:maps/oa_ctf2.bsp";
    EXPECT_EQ(oneLineMessage(path + ": damaged"), path + ": damaged");
    const std::string deep = "/" + std::string(200, 'd') + "/oa_ctf2.bsp:";
    EXPECT_EQ(oneLineMessage(deep + " damaged"), "/" + std::string(31, 'd') + "..." +
                                                     std::string(51, 'd') +
                                                     "/oa_ctf2.bsp: (214 characters) damaged");
    const std::string message = oneLineMessage(std::string(5000, 'a') + " b");
    EXPECT_LE(message.size(), 125u) << message;
    EXPECT_NE(message.find("(5000 characters) b"), std::string::npos) << message;
    EXPECT_EQ(oneLineMessage(""), "");
    EXPECT_EQ(oneLineMessage("two  spaces "), "two  spaces ");
}

}  // namespace
}  // namespace onelight::world
