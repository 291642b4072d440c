// The dominant primary with visibility (bake/dominant): a light hidden behind a wall does not
// dominate, however near.
#include <gtest/gtest.h>

#include "bake/dominant/dominant_primary.hpp"
#include "bake_scenes.hpp"
#include "world/compile/static_split.hpp"

namespace onelight::bake {
namespace {

using world::LightRole;

// Two primaries; the nearer one is hidden behind a wall from the query point: without
// visibility it would win, with visibility the other one does.
TEST(DominantPrimary, VisibilityDecidesTheDominantLight) {
    world::SourceLevel level;
    const uint32_t m = test::addLambertMaterial(level, 0.5f);
    test::addBox(level, {0.5f, -2.0f, -1.0f}, {0.6f, 2.0f, 3.0f}, m, false, "wall");
    level.lights.push_back(test::pointLight({1.0f, 0.0f, 1.0f}, 100.0f, LightRole::kPrimary));
    level.lights.push_back(test::pointLight({-3.0f, 0.0f, 1.0f}, 100.0f, LightRole::kPrimary));
    const EmbreeDevice device;
    const world::SplitLevel split = world::splitStaticDynamic(level);
    const BakeScene scene(device, split.staticGeometry, level.materials);
    const BakeLights lights = makeBakeLights(scene, level.lights, {}, glm::vec3(0.0f));
    AtomicRayCount rays;
    const world::PrimaryIlluminanceFn shadowed =
        makeShadowedPrimaryIlluminance(scene, lights, 16, &rays);
    const world::PrimaryIlluminanceFn unshadowed =
        world::makeUnshadowedPrimaryIlluminance(level.lights);
    double e[2];
    unshadowed(glm::dvec3(0, 0, 1), glm::vec3(0.0f), e);
    EXPECT_EQ(world::dominantPrimary(e), 0u);
    shadowed(glm::dvec3(0, 0, 1), glm::vec3(0.0f), e);
    EXPECT_EQ(e[0], 0.0);
    EXPECT_EQ(world::dominantPrimary(e), 1u);
    EXPECT_GT(rays.shadow.load(), 0u);
}

}  // namespace
}  // namespace onelight::bake
