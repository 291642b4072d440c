// The bake's probe stage: an authored probe inside solid geometry is baked but warned about.
#include <gtest/gtest.h>

#include "bake_scenes.hpp"

namespace onelight::bake {
namespace {

// A probe authored inside the solid block is baked but warned about, by name.
TEST(BakeProbes, AProbeInsideSolidGeometryIsWarnedAbout) {
    world::SourceLevel level = test::smallRoomWithProbes();
    EXPECT_TRUE(bakeLevel(level, test::fastBakeOptions()).report.warnings.empty());
    level.entities[1].position = glm::vec3(0.0f, 0.0f, 0.25f);  // inside the block
    const BakeResult r = bakeLevel(level, test::fastBakeOptions());
    ASSERT_EQ(r.report.warnings.size(), 1u);
    EXPECT_NE(r.report.warnings[0].find("probe 'probe1'"), std::string::npos)
        << r.report.warnings[0];
    EXPECT_NE(r.report.warnings[0].find("inside solid geometry"), std::string::npos);
    EXPECT_EQ(r.baked.probes.size(), 3u);
}

}  // namespace
}  // namespace onelight::bake
