// Determinism and sharding: the same bytes at any thread count, and shards merged equal a
// whole bake byte for byte. Also the baked sections' reader round trip and its errors, the
// dominant primary with visibility and the light grid's inside-solid cells.
#include <cstring>

#include <gtest/gtest.h>
#include <tbb/global_control.h>

#include "bake/dominant/dominant_primary.hpp"
#include "bake_scenes.hpp"
#include "shading.hpp"
#include "world/compile/static_split.hpp"
#include "world/light_grid_sample.hpp"
#include "world/package/baked_sections.hpp"
#include "world/package/package_reader.hpp"

namespace onelight::bake {
namespace {

using world::LightRole;

world::SourceLevel small_room() {
    world::SourceLevel level;
    const uint32_t m = test::add_lambert_material(level, 0.6f);
    test::add_box(level, {-1.5f, -1.0f, 0.0f}, {1.5f, 1.0f, 2.0f}, m, true, "room");
    test::add_box(level, {-0.3f, -0.3f, 0.0f}, {0.3f, 0.3f, 0.5f}, m, false, "block");
    level.lights.push_back(test::point_light({-0.8f, 0.2f, 1.6f}, 40.0f, LightRole::primary));
    level.lights.push_back(test::point_light({0.9f, -0.3f, 1.5f}, 30.0f, LightRole::primary));
    return level;
}

// The room with a glossy block and three authored probes (one box-projected), so that the
// probe stage runs and two shards split its probes 1 + 2.
world::SourceLevel small_room_with_probes() {
    world::SourceLevel level = small_room();
    world::Material glossy = level.materials[0];
    glossy.name = "glossy";
    glossy.material_class = world::MaterialClass::dielectric;
    glossy.specular_color = glm::vec3(0.04f);
    glossy.gloss = 0.8f;
    level.materials.push_back(glossy);
    for (world::MeshInstance& m : level.instances)
        if (m.node_name == "block") m.material = 1;
    for (const glm::vec3 p :
         {glm::vec3(-1.0f, 0.0f, 1.0f), glm::vec3(0.0f, 0.5f, 1.2f), glm::vec3(1.0f, 0.0f, 0.8f)}) {
        world::Entity e;
        e.name = "probe" + std::to_string(level.entities.size());
        e.flags = world::entity_probe;
        e.position = p;
        if (level.entities.empty()) {
            e.probe_box_min = {-1.5f, -1.0f, 0.0f};
            e.probe_box_max = {1.5f, 1.0f, 2.0f};
        }
        level.entities.push_back(e);
    }
    return level;
}

BakeOptions fast_options() {
    BakeOptions o = test::test_options(4.0f);
    o.indirect_samples = 16;
    o.shadow_samples = 4;
    o.grid_samples = 16;
    o.grid_cell_size = 0.75f;
    o.probe_face_size = 8;
    o.probe_samples = 4;
    return o;
}

TEST(BakeDeterminism, OneAndTwoThreadsGiveIdenticalBytes) {
    const world::SourceLevel level = small_room_with_probes();
    std::vector<uint8_t> one, two;
    {
        tbb::global_control limit(tbb::global_control::max_allowed_parallelism, 1);
        const BakeResult r = bake_level(level, fast_options());
        one = package_bytes(r.level, r.baked);
    }
    {
        tbb::global_control limit(tbb::global_control::max_allowed_parallelism, 2);
        const BakeResult r = bake_level(level, fast_options());
        two = package_bytes(r.level, r.baked);
    }
    ASSERT_EQ(one.size(), two.size());
    EXPECT_TRUE(one == two);
}

TEST(BakeDeterminism, ShardsMergedEqualAWholeBake) {
    const world::SourceLevel level = small_room_with_probes();
    const BakeResult whole = bake_level(level, fast_options());
    ASSERT_EQ(whole.baked.probes.size(), 3u);
    // Each probe's E_avg is exactly what the runtime reads from the finished grid there.
    for (const world::EnvironmentProbe& p : whole.baked.probes) {
        const glm::vec3 runtime = glm::max(
            ambientCubeAverage(world::sampleLightGrid(whole.baked.grid, p.position).ambientCube),
            glm::vec3(onelight::glsl::PROBE_MIN_IRRADIANCE));
        EXPECT_EQ(p.irradiance_average, runtime);
        EXPECT_GT(p.irradiance_average.x, 0.1f);  // lit room: far above the floor
    }
    std::vector<world::BakedLighting> parts;
    world::CompiledLevel compiled;
    for (uint32_t i : {1u, 0u}) {  // any order
        BakeOptions o = fast_options();
        o.shard_index = i;
        o.shard_count = 2;
        BakeResult part = bake_level(level, o);
        // Through the package, as `merge` reads it.
        const std::vector<uint8_t> bytes = package_bytes(part.level, part.baked);
        const package::PackageReadResult read = package::parse_package(bytes, "part");
        ASSERT_TRUE(read.ok()) << read.error;
        const package::BakedReadResult baked =
            package::decode_baked_sections(read.baked_sections, read.level, "part");
        ASSERT_TRUE(baked.ok()) << baked.error;
        EXPECT_EQ(baked.baked.shard_count, 2u);
        parts.push_back(baked.baked);
        compiled = read.level;
    }
    world::BakedLighting merged;
    ASSERT_EQ(merge_baked_lighting(compiled, parts, merged), "");
    EXPECT_TRUE(package_bytes(compiled, merged) == package_bytes(whole.level, whole.baked));
    EXPECT_TRUE(test::all_finite_non_negative(merged));

    parts.pop_back();
    EXPECT_NE(merge_baked_lighting(compiled, parts, merged).find("1 parts given"),
              std::string::npos);
}

// A probe authored inside the solid block is baked but warned about, by name.
TEST(BakeProbes, AProbeInsideSolidGeometryIsWarnedAbout) {
    world::SourceLevel level = small_room_with_probes();
    EXPECT_TRUE(bake_level(level, fast_options()).report.warnings.empty());
    level.entities[1].position = glm::vec3(0.0f, 0.0f, 0.25f);  // inside the block
    const BakeResult r = bake_level(level, fast_options());
    ASSERT_EQ(r.report.warnings.size(), 1u);
    EXPECT_NE(r.report.warnings[0].find("probe 'probe1'"), std::string::npos)
        << r.report.warnings[0];
    EXPECT_NE(r.report.warnings[0].find("inside solid geometry"), std::string::npos);
    EXPECT_EQ(r.baked.probes.size(), 3u);
}

TEST(BakedSections, RoundTripAndErrorsNameTheSection) {
    const BakeResult r = bake_level(small_room_with_probes(), fast_options());
    std::vector<package::RawSection> sections = package::encode_baked_sections(r.baked);
    ASSERT_EQ(sections.size(), 4u);  // 32..34 and the probes
    package::BakedReadResult back = package::decode_baked_sections(sections, r.level, "x.olpak");
    ASSERT_TRUE(back.ok()) << back.error;
    EXPECT_TRUE(back.present);
    EXPECT_EQ(back.baked.texels.size(), r.baked.texels.size());
    EXPECT_EQ(back.baked.grid.cells.size(), r.baked.grid.cells.size());
    ASSERT_EQ(back.baked.probes.size(), 3u);
    EXPECT_EQ(back.baked.probes[2].texels, r.baked.probes[2].texels);
    EXPECT_EQ(back.baked.probes[0].box_max, glm::vec3(1.5f, 1.0f, 2.0f));

    const std::vector<package::RawSection> probes_alone(sections.begin() + 3, sections.end());
    back = package::decode_baked_sections(probes_alone, r.level, "x.olpak");
    EXPECT_NE(back.error.find("x.olpak: section probes present without baked lighting"),
              std::string::npos)
        << back.error;
    std::vector<package::RawSection> bad_probe = sections;
    bad_probe[3].bytes[16 + 12 * 4] = 3;  // probe 0's face_size 8 -> 3: not a power of two
    back = package::decode_baked_sections(bad_probe, r.level, "x.olpak");
    EXPECT_NE(back.error.find("record 0: face_size 3"), std::string::npos) << back.error;

    std::vector<package::RawSection> truncated = sections;
    truncated[0].bytes.resize(truncated[0].bytes.size() - 32);
    truncated[0].count -= 1;
    back = package::decode_baked_sections(truncated, r.level, "x.olpak");
    EXPECT_NE(back.error.find("lightmap_texels"), std::string::npos) << back.error;

    std::vector<package::RawSection> bad_light = sections;
    const uint32_t bogus = 77;  // not a light of the level
    std::memcpy(bad_light[2].bytes.data() + 56 + 72, &bogus, 4);
    back = package::decode_baked_sections(bad_light, r.level, "x.olpak");
    EXPECT_NE(back.error.find("dominant_primary 77"), std::string::npos) << back.error;

    std::vector<package::RawSection> only_two(sections.begin(), sections.begin() + 2);
    back = package::decode_baked_sections(only_two, r.level, "x.olpak");
    EXPECT_NE(back.error.find("light_grid missing"), std::string::npos) << back.error;
}

// Two primaries; the nearer one is hidden behind a wall from the query point: without
// visibility it would win, with visibility the other one does.
TEST(DominantPrimary, VisibilityDecidesTheDominantLight) {
    world::SourceLevel level;
    const uint32_t m = test::add_lambert_material(level, 0.5f);
    test::add_box(level, {0.5f, -2.0f, -1.0f}, {0.6f, 2.0f, 3.0f}, m, false, "wall");
    level.lights.push_back(test::point_light({1.0f, 0.0f, 1.0f}, 100.0f, LightRole::primary));
    level.lights.push_back(test::point_light({-3.0f, 0.0f, 1.0f}, 100.0f, LightRole::primary));
    const EmbreeDevice device;
    const world::SplitLevel split = world::split_static_dynamic(level);
    const BakeScene scene(device, split.static_geometry, level.materials);
    const BakeLights lights = make_bake_lights(level.lights, {}, glm::vec3(0.0f));
    AtomicRayCount rays;
    const world::PrimaryIlluminanceFn shadowed =
        make_shadowed_primary_illuminance(scene, lights, 16, &rays);
    const world::PrimaryIlluminanceFn unshadowed =
        world::make_unshadowed_primary_illuminance(level.lights);
    double e[2];
    unshadowed(glm::dvec3(0, 0, 1), glm::vec3(0.0f), e);
    EXPECT_EQ(world::dominant_primary(e), 0u);
    shadowed(glm::dvec3(0, 0, 1), glm::vec3(0.0f), e);
    EXPECT_EQ(e[0], 0.0);
    EXPECT_EQ(world::dominant_primary(e), 1u);
    EXPECT_GT(rays.shadow.load(), 0u);
}

// Cells whose centre is inside a solid block are flagged and hold no light; the others see
// the primary and hold it as dominant with full visibility.
TEST(LightGrid, CellsInsideSolidsAreMarked) {
    world::SourceLevel level;
    const uint32_t m = test::add_lambert_material(level, 0.5f);
    test::add_box(level, {0.0f, 0.0f, 0.0f}, {4.0f, 4.0f, 4.0f}, m, true, "room");
    test::add_box(level, {0.0f, 0.0f, 0.0f}, {2.0f, 4.0f, 4.0f}, m, false, "solid");
    level.lights.push_back(test::point_light({3.0f, 2.0f, 2.0f}, 50.0f, LightRole::primary));
    BakeOptions o = fast_options();
    o.grid_cell_size = 1.0f;
    const BakeResult r = bake_level(level, o);
    const world::LightGrid& g = r.baked.grid;
    ASSERT_EQ(g.dims, glm::uvec3(4, 4, 4));
    for (uint32_t i = 0; i < g.cells.size(); ++i) {
        const uint32_t x = i % 4;
        const world::LightGridCell& c = g.cells[i];
        if (x < 2) {
            EXPECT_EQ(c.flags, 1u) << i;
            EXPECT_EQ(c.dominant_primary, world::kNone);
        } else {
            EXPECT_EQ(c.flags, 0u) << i;
            EXPECT_EQ(c.dominant_primary, 0u);
            EXPECT_EQ(c.primary_visibility, 1.0f);
        }
    }
}

}  // namespace
}  // namespace onelight::bake
