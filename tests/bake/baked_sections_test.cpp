// The baked sections (package ids 32..35) written from a real bake and read back: the round
// trip keeps every texel, cell and probe, and each corruption is refused naming its section.
#include <cstring>

#include <gtest/gtest.h>

#include "bake_scenes.hpp"
#include "tests/support/error_message.hpp"
#include "world/package/baked_sections.hpp"
#include "world/package/format.hpp"

namespace onelight::bake {
namespace {

TEST(BakedSections, RoundTripAndErrorsNameTheSection) {
    const BakeResult r = bakeLevel(test::smallRoomWithProbes(), test::fastBakeOptions());
    std::vector<package::RawSection> sections = package::encodeBakedSections(r.baked);
    ASSERT_EQ(sections.size(), 5u);  // 32..34, the probes and the visibility
    EXPECT_EQ(sections.back().id, package::kSectionVisibility);
    const package::BakedContents back = package::decodeBakedSections(sections, r.level, "x.olpak");
    EXPECT_TRUE(back.present);
    EXPECT_FALSE(back.baked.visibility.empty());
    EXPECT_TRUE(back.baked.visibility == r.baked.visibility);
    EXPECT_NE(onelight::test::errorMessage([&] {
                  const std::vector<package::RawSection> alone = {sections.back()};
                  (void)package::decodeBakedSections(alone, r.level, "x.olpak");
              }).find("x.olpak: section visibility present without baked lighting"),
              std::string::npos);
    EXPECT_EQ(back.baked.texels.size(), r.baked.texels.size());
    EXPECT_EQ(back.baked.grid.cells.size(), r.baked.grid.cells.size());
    ASSERT_EQ(back.baked.probes.size(), 3u);
    EXPECT_EQ(back.baked.probes[2].texels, r.baked.probes[2].texels);
    EXPECT_EQ(back.baked.probes[0].boxMax, glm::vec3(1.5f, 1.0f, 2.0f));

    // What decoding `broken` throws ("" when nothing).
    auto errorOf = [&](const std::vector<package::RawSection>& broken) {
        return onelight::test::errorMessage(
            [&] { (void)package::decodeBakedSections(broken, r.level, "x.olpak"); });
    };
    const std::vector<package::RawSection> probesAlone(sections.begin() + 3, sections.end());
    EXPECT_NE(errorOf(probesAlone).find("x.olpak: section probes present without baked lighting"),
              std::string::npos)
        << errorOf(probesAlone);
    std::vector<package::RawSection> badProbe = sections;
    badProbe[3].bytes[16 + 12 * 4] = 3;  // probe 0's face_size 8 -> 3: not a power of two
    EXPECT_NE(errorOf(badProbe).find("record 0: faceSize 3"), std::string::npos)
        << errorOf(badProbe);

    std::vector<package::RawSection> truncated = sections;
    truncated[0].bytes.resize(truncated[0].bytes.size() - 32);
    truncated[0].count -= 1;
    EXPECT_NE(errorOf(truncated).find("lightmap_texels"), std::string::npos) << errorOf(truncated);

    std::vector<package::RawSection> badLight = sections;
    const uint32_t bogus = 77;  // not a light of the level
    std::memcpy(badLight[2].bytes.data() + 56 + 72, &bogus, 4);
    EXPECT_NE(errorOf(badLight).find("dominantPrimary 77"), std::string::npos) << errorOf(badLight);

    std::vector<package::RawSection> onlyTwo(sections.begin(), sections.begin() + 2);
    EXPECT_NE(errorOf(onlyTwo).find("light_grid missing"), std::string::npos) << errorOf(onlyTwo);
}

}  // namespace
}  // namespace onelight::bake
