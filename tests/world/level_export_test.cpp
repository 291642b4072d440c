// onelight-bake export's writer (world/gltf/level_export.hpp): a level imported, written back as
// glTF and imported again is the same static scene: the same world-space triangles, materials,
// textures, lights, cameras and sky. What Blender's Cycles draws of a real map
// (scripts/cycles-check.py --scenes q3:MAP:CAMERA) rests on it.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "tests/world/level_generator.hpp"
#include "tests/world/world_test_support.hpp"
#include "world/gltf/level_export.hpp"
#include "world/images/image_decode.hpp"
#include "world/import/level_import.hpp"

namespace onelight::world {
namespace {

// Within a float's rounding of the larger magnitude (positions to about 60 m: 1e-5 relative).
bool near(float a, float b) {
    return std::fabs(a - b) <= 1e-5f * std::max({1.0f, std::fabs(a), std::fabs(b)});
}
bool near(glm::vec3 a, glm::vec3 b) {
    return near(a.x, b.x) && near(a.y, b.y) && near(a.z, b.z);
}
bool near(glm::vec4 a, glm::vec4 b) {
    return near(glm::vec3(a), glm::vec3(b)) && near(a.w, b.w);
}

// The static instances, in order (an export writes only these).
std::vector<const MeshInstance*> staticInstances(const SourceLevel& level) {
    std::vector<const MeshInstance*> out;
    for (const MeshInstance& m : level.instances)
        if (!m.dynamic) out.push_back(&m);
    return out;
}

// The static instances' triangles, corner by corner, in world space.
std::vector<glm::vec3> staticCorners(const SourceLevel& level) {
    std::vector<glm::vec3> out;
    for (const MeshInstance& m : level.instances) {
        if (m.dynamic) continue;
        for (uint32_t i : m.indices)
            out.push_back(glm::vec3(m.worldFromLocal *
                                    glm::dvec4(glm::dvec3(m.vertices.at(i).position), 1.0)));
    }
    return out;
}

void expectSameStaticScene(const SourceLevel& a, const SourceLevel& b) {
    const std::vector<glm::vec3> ca = staticCorners(a), cb = staticCorners(b);
    ASSERT_EQ(ca.size(), cb.size());
    size_t moved = 0;
    for (size_t i = 0; i < ca.size(); ++i) moved += near(ca[i], cb[i]) ? 0 : 1;
    EXPECT_EQ(moved, 0u) << "of " << ca.size() << " corners";

    // Materials by the static instances that use them (an import keeps only the used ones).
    const std::vector<const MeshInstance*> ia = staticInstances(a), ib = staticInstances(b);
    ASSERT_EQ(ia.size(), ib.size());
    for (size_t i = 0; i < ia.size(); ++i) {
        const Material &x = a.materials.at(ia[i]->material), &y = b.materials.at(ib[i]->material);
        SCOPED_TRACE("material " + x.name);
        EXPECT_EQ(x.name, y.name);
        EXPECT_TRUE(near(x.baseColor, y.baseColor));
        EXPECT_TRUE(near(x.emissive, y.emissive)) << x.emissive.x << " " << y.emissive.x;
        EXPECT_TRUE(near(x.albedo, y.albedo));
        EXPECT_EQ(x.metallic, y.metallic);
        EXPECT_EQ(x.roughness, y.roughness);
        EXPECT_EQ(x.alphaMode, y.alphaMode);
        if (x.alphaMode == AlphaMode::kMask) {
            EXPECT_EQ(x.alphaCutoff, y.alphaCutoff);
        }
        EXPECT_EQ(x.doubleSided, y.doubleSided);
        EXPECT_EQ(x.castsShadows, y.castsShadows);
        EXPECT_EQ(x.materialClass, y.materialClass);
        EXPECT_EQ(x.baseColorTexture == kNoIndex, y.baseColorTexture == kNoIndex);
        EXPECT_EQ(x.emissiveTexture == kNoIndex, y.emissiveTexture == kNoIndex);
    }
    ASSERT_EQ(a.lights.size(), b.lights.size());
    for (size_t i = 0; i < a.lights.size(); ++i) {
        const Light &x = a.lights[i], &y = b.lights[i];
        SCOPED_TRACE("light " + x.name);
        EXPECT_EQ(x.type, y.type);
        EXPECT_EQ(x.role, y.role);
        EXPECT_TRUE(near(x.color, y.color));
        EXPECT_TRUE(near(x.intensity, y.intensity));
        EXPECT_TRUE(near(x.range, y.range));
        if (x.type != LightType::kDirectional) {
            EXPECT_TRUE(near(x.position, y.position));
        }
        EXPECT_LT(glm::length(x.direction - y.direction), 1e-5f);
        if (x.type == LightType::kSpot) {
            EXPECT_TRUE(near(x.innerCone, y.innerCone));
            EXPECT_TRUE(near(x.outerCone, y.outerCone));
        }
    }
    ASSERT_EQ(a.cameras.size(), b.cameras.size());
    for (size_t i = 0; i < a.cameras.size(); ++i) {
        EXPECT_EQ(a.cameras[i].name, b.cameras[i].name);
        EXPECT_TRUE(near(a.cameras[i].position, b.cameras[i].position));
        EXPECT_GT(std::fabs(glm::dot(a.cameras[i].rotation, b.cameras[i].rotation)), 1.0f - 1e-6f);
        EXPECT_EQ(a.cameras[i].yfov, b.cameras[i].yfov);
    }
    EXPECT_TRUE(near(a.skyRadiance, b.skyRadiance));
}

TEST(LevelExport, AGeneratedLevelWrittenBackImportsAsTheSameStaticScene) {
    const std::filesystem::path folder = test::freshFolder("level_export_generated");
    test::GeneratedLevelOptions options;
    options.groundCells = 8;
    options.buildings = 4;
    options.buildingCells = 2;
    const std::string gltf = test::writeGeneratedLevel(folder, "generated", options);
    SourceLevel source = importLevel(gltf);
    ASSERT_FALSE(source.lights.empty());
    // What the glTF's own materials do not say: a surface light passes (a Quake 3 translucent
    // shader), an emitter brighter than 1 cd/m^2 (KHR_materials_emissive_strength), a cut-out.
    ASSERT_GE(source.materials.size(), 2u);
    source.materials[0].castsShadows = false;
    source.materials[1].emissive = glm::vec3(2000.0f, 1000.0f, 0.0f);
    source.materials[1].alphaMode = AlphaMode::kMask;
    source.materials[1].alphaCutoff = 0.25f;
    source.skyRadiance = glm::vec3(1.0f, 2.0f, 3.0f);
    const LevelExportStats stats =
        exportLevelGltf(source, folder, folder / "written", "generated_again");
    EXPECT_GT(stats.dynamicLeftOut, 0u);  // its crates
    const SourceLevel again = importLevel((folder / "written" / "generated_again.gltf").string());
    expectSameStaticScene(source, again);
    EXPECT_EQ(again.hasGridBounds, source.hasGridBounds);
    size_t probes = 0, probesAgain = 0;
    for (const Entity& e : source.entities) probes += (e.flags & kEntityProbe) ? 1 : 0;
    for (const Entity& e : again.entities) probesAgain += (e.flags & kEntityProbe) ? 1 : 0;
    EXPECT_EQ(probes, probesAgain);
}

// A map nobody here made: its TGA and JPEG textures become PNGs of the same texels, its lights
// (30 points and a sun) and its sky stay.
TEST(LevelExport, AQuake3MapWrittenBackKeepsItsTexturesLightsAndSky) {
    const char* const pk3 = "/usr/share/games/openarena/baseoa/pak1-maps.pk3";
    if (!std::filesystem::exists(pk3)) GTEST_SKIP() << pk3 << " is missing: install openarena-data";
    const std::filesystem::path folder = test::freshFolder("level_export_kaos");
    const SourceLevel source = importLevel("kaos");
    const LevelExportStats stats = exportLevelGltf(source, ".", folder, "kaos");
    EXPECT_EQ(stats.imagesMissing, 0u);
    EXPECT_EQ(stats.images, source.images.size());
    const SourceLevel again = importLevel((folder / "kaos.gltf").string());
    expectSameStaticScene(source, again);
    // Each static surface's base colour texels, from the map's TGA or JPEG and from the PNG.
    const std::vector<const MeshInstance*> ia = staticInstances(source),
                                           ib = staticInstances(again);
    ASSERT_EQ(ia.size(), ib.size());
    size_t textured = 0;
    for (size_t i = 0; i < ia.size(); ++i) {
        const Material &x = source.materials[ia[i]->material],
                       &y = again.materials[ib[i]->material];
        if (x.baseColorTexture == kNoIndex) continue;
        ++textured;
        const Image& sourceImage = source.images[source.textures[x.baseColorTexture].image];
        const DecodedImage expected =
            decodeImage(sourceImage.encodedBytes.data(), sourceImage.encodedBytes.size(), "source");
        const DecodedImage got = readImageFile(
            (folder / again.images[again.textures[y.baseColorTexture].image].uri).string());
        ASSERT_EQ(expected.width, got.width) << sourceImage.name;
        ASSERT_EQ(expected.height, got.height) << sourceImage.name;
        EXPECT_EQ(expected.rgba, got.rgba) << sourceImage.name;
    }
    EXPECT_GT(textured, 40u);
}

}  // namespace
}  // namespace onelight::world
