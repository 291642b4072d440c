#include <cmath>
#include <filesystem>
#include <fstream>
#include <string>

#include <gtest/gtest.h>

#include <tuple>

#include "shading.hpp"
#include "tests/world/world_test_support.hpp"
#include "world/error.hpp"
#include "world/import/gltf_import.hpp"
#include "world/import/material_import.hpp"

namespace onelight::test {
namespace {

using world::Error;
using world::importGltf;

MeshData oneTriangle(const std::string& name) {
    MeshData mesh;
    mesh.name = name;
    mesh.positions = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
    mesh.uv0 = {{0, 0}, {1, 0}, {0, 1}};
    mesh.indices = {0, 1, 2};
    return mesh;
}

TEST(Import, HierarchyComposesTransforms) {
    GltfBuilder gltf;
    const int mesh = gltf.addMesh(oneTriangle("tri"));
    const int child =
        gltf.addNode({{"name", "child"}, {"mesh", mesh}, {"translation", {0.0, 0.0, 5.0}}}, false);
    gltf.addNode({{"name", "parent"},
                  {"translation", {10.0, 0.0, 0.0}},
                  {"scale", {2.0, 2.0, 2.0}},
                  {"children", {child}}});
    const world::SourceLevel level = importGltf(gltf.write(freshFolder("hierarchy"), "hierarchy"));
    ASSERT_EQ(level.instances.size(), 1u);
    const glm::dvec4 p = level.instances[0].worldFromLocal * glm::dvec4(1.0, 0.0, 0.0, 1.0);
    EXPECT_NEAR(p.x, 10.0 + 2.0, 1e-12);
    EXPECT_NEAR(p.z, 10.0, 1e-12);
}

TEST(Import, GeneratesUnitTangentsOrthogonalToNormals) {
    GltfBuilder gltf;
    gltf.addNode({{"name", "floor"}, {"mesh", gltf.addMesh(gridMesh("floor", 2, 2.0, 0.0))}});
    const world::SourceLevel level = importGltf(gltf.write(freshFolder("tangents"), "tangents"));
    ASSERT_EQ(level.instances.size(), 1u);
    for (const world::Vertex& v : level.instances[0].vertices) {
        EXPECT_NEAR(glm::length(glm::vec3(v.tangent)), 1.0f, 1e-5f);
        EXPECT_NEAR(glm::dot(glm::vec3(v.tangent), v.normal), 0.0f, 1e-5f);
        EXPECT_EQ(std::abs(v.tangent.w), 1.0f);
        EXPECT_NEAR(v.tangent.x, 1.0f, 1e-5f);  // u grows along +x on the grid
    }
}

TEST(Import, FlatNormalsWhenMissingAndTexcoord1Kept) {
    GltfBuilder gltf;
    MeshData mesh = oneTriangle("tri");
    mesh.uv1 = {{0.1f, 0.1f}, {0.9f, 0.1f}, {0.1f, 0.9f}};
    gltf.addNode({{"name", "n"}, {"mesh", gltf.addMesh(mesh)}});
    const world::SourceLevel level = importGltf(gltf.write(freshFolder("flat"), "flat"));
    ASSERT_EQ(level.instances.size(), 1u);
    EXPECT_TRUE(level.instances[0].hasUv1);
    for (const world::Vertex& v : level.instances[0].vertices)
        EXPECT_EQ(v.normal, glm::vec3(0, 0, 1));
    EXPECT_FLOAT_EQ(level.instances[0].vertices[1].uv1.x, 0.9f);
}

TEST(Import, GlossFormulaInvertsTheEngineGgxAlpha) {
    for (float r = 0.1f; r <= 1.0f; r += 0.01f) {
        const float gloss = world::glossFromRoughness(r);
        ASSERT_GE(gloss, 0.0f);
        ASSERT_LE(gloss, 1.0f);
        EXPECT_NEAR(glsl::ggxAlpha_fromGloss(gloss), r * r, 2e-4f * std::max(1.0f, 1.0f / (r * r)))
            << r;
    }
    EXPECT_EQ(world::glossFromRoughness(1.0f), 0.0f);
    EXPECT_EQ(world::glossFromRoughness(0.0f), 1.0f);
}

TEST(Import, MetallicRoughnessBecomesAlbedoSpecularGloss) {
    GltfBuilder gltf;
    MeshData mesh = oneTriangle("tri");
    mesh.material = gltf.addMaterial({{"name", "gold"},
                                      {"pbrMetallicRoughness",
                                       {{"baseColorFactor", {1.0, 0.8, 0.4, 1.0}},
                                        {"metallicFactor", 0.25},
                                        {"roughnessFactor", 0.5}}}});
    gltf.addMaterial({{"name", "unused"}});
    gltf.addNode({{"name", "n"}, {"mesh", gltf.addMesh(mesh)}});
    const world::SourceLevel level = importGltf(gltf.write(freshFolder("material"), "material"));
    ASSERT_EQ(level.materials.size(), 1u) << "unused materials are dropped";
    const world::Material& m = level.materials[0];
    EXPECT_EQ(m.name, "gold");
    EXPECT_NEAR(m.albedo.g, 0.8f * 0.75f, 1e-6f);
    EXPECT_NEAR(m.specularColor.r, 0.04f * 0.75f + 1.0f * 0.25f, 1e-6f);
    EXPECT_NEAR(m.gloss, std::log2(2.0 / std::pow(0.5, 4.0) - 1.0) / 18.0, 1e-6);
    EXPECT_EQ(m.materialClass, world::MaterialClass::kFull);
}

// Emission in cd/m^2: emissiveFactor x KHR_materials_emissive_strength (world/import/README.md).
TEST(Import, EmissionIsFactorTimesStrengthInNits) {
    GltfBuilder gltf;
    MeshData panel = oneTriangle("panel"), dim = oneTriangle("dim");
    panel.material = gltf.addMaterial(
        {{"name", "panel"},
         {"emissiveFactor", {1.0, 0.5, 0.25}},
         {"extensions", {{"KHR_materials_emissive_strength", {{"emissiveStrength", 400.0}}}}}});
    dim.material = gltf.addMaterial({{"name", "dim"}, {"emissiveFactor", {0.5, 0.5, 0.5}}});
    gltf.addNode({{"name", "a"}, {"mesh", gltf.addMesh(panel)}});
    gltf.addNode({{"name", "b"}, {"mesh", gltf.addMesh(dim)}});
    const world::SourceLevel level = importGltf(gltf.write(freshFolder("emission"), "emission"));
    ASSERT_EQ(level.materials.size(), 2u);
    const world::Material& a =
        level.materials[0].name == "panel" ? level.materials[0] : level.materials[1];
    const world::Material& b =
        level.materials[0].name == "panel" ? level.materials[1] : level.materials[0];
    EXPECT_EQ(a.emissive, glm::vec3(400.0f, 200.0f, 100.0f));
    EXPECT_EQ(b.emissive, glm::vec3(0.5f));
}

TEST(Import, LightsKeepUnitsRolesAndDirections) {
    GltfBuilder gltf;
    const int sun = gltf.addLight({{"type", "directional"}, {"intensity", 100000.0}});
    const int spot = gltf.addLight({{"type", "spot"},
                                    {"intensity", 400.0},
                                    {"spot", {{"innerConeAngle", 0.2}, {"outerConeAngle", 0.5}}}});
    const int lamp = gltf.addLight({{"type", "point"}, {"intensity", 50.0}, {"range", 9.0}});
    gltf.addNode({{"name", "sun"},
                  {"rotation", {-0.7071068, 0.0, 0.0, 0.7071068}},
                  {"extensions", {{"KHR_lights_punctual", {{"light", sun}}}}}});
    gltf.addNode({{"name", "torch"},
                  {"translation", {1.0, 2.0, 3.0}},
                  {"extensions", {{"KHR_lights_punctual", {{"light", spot}}}}},
                  {"extras", {{"onelight", {{"role", "effect"}}}}}});
    gltf.addNode({{"name", "lamp"},
                  {"extensions", {{"KHR_lights_punctual", {{"light", lamp}}}}},
                  {"extras", {{"onelight", {{"role", "baked"}}}}}});
    const world::SourceLevel level = importGltf(gltf.write(freshFolder("lights"), "lights"));
    ASSERT_EQ(level.lights.size(), 3u);
    EXPECT_EQ(level.lights[0].type, world::LightType::kDirectional);
    EXPECT_EQ(level.lights[0].role, world::LightRole::kPrimary);
    EXPECT_FLOAT_EQ(level.lights[0].intensity, 100000.0f);  // lux
    EXPECT_NEAR(level.lights[0].direction.y, -1.0f, 1e-6f);
    EXPECT_EQ(level.lights[1].role, world::LightRole::kEffect);
    EXPECT_EQ(level.lights[1].name, "torch");
    EXPECT_FLOAT_EQ(level.lights[1].outerCone, 0.5f);
    EXPECT_EQ(level.lights[1].position, glm::vec3(1, 2, 3));
    EXPECT_EQ(level.lights[2].role, world::LightRole::kBaked);
    EXPECT_FLOAT_EQ(level.lights[2].range, 9.0f);
}

TEST(Import, CamerasAreNamedByTheirNode) {
    GltfBuilder gltf;
    const int camera =
        gltf.addCamera({{"type", "perspective"}, {"perspective", {{"yfov", 0.9}, {"znear", 0.1}}}});
    gltf.addNode({{"name", "courtyard"},
                  {"camera", camera},
                  {"translation", {0.0, 2.0, 0.0}},
                  {"extras", {{"onelight", {{"exposure", 9.5}}}}}});
    const world::SourceLevel level = importGltf(gltf.write(freshFolder("camera"), "camera"));
    ASSERT_EQ(level.cameras.size(), 1u);
    EXPECT_EQ(level.cameras[0].name, "courtyard");
    EXPECT_FLOAT_EQ(level.cameras[0].yfov, 0.9f);
    EXPECT_TRUE(level.cameras[0].hasExposure);
    EXPECT_FLOAT_EQ(level.cameras[0].exposureEv100, 9.5f);
    EXPECT_FALSE(level.hasExposure) << "a camera's exposure is its own";
}

TEST(Import, ExtrasMarkDynamicMoversSpawnsProbesGrid) {
    GltfBuilder gltf;
    const int mesh = gltf.addMesh(oneTriangle("tri"));
    gltf.addNode(
        {{"name", "door"},
         {"mesh", mesh},
         {"extras", {{"onelight", {{"mover", {{"offset", {0.0, 3.0, 0.0}}, {"period", 4.0}}}}}}}});
    gltf.addNode({{"name", "start"}, {"extras", {{"onelight", {{"spawn", true}}}}}});
    gltf.addNode({{"name", "probe"}, {"extras", {{"onelight", {{"probe", true}}}}}});
    gltf.addNode({{"name", "settings"},
                  {"extras",
                   {{"onelight",
                     {{"grid", {{"min", {-1, -1, -1}}, {"max", {1, 1, 1}}}},
                      {"exposure", 10.0},
                      {"texels_per_metre", 6.0}}}}}});
    const world::SourceLevel level = importGltf(gltf.write(freshFolder("extras"), "extras"));
    ASSERT_EQ(level.entities.size(), 3u);
    EXPECT_EQ(level.entities[0].flags, world::kEntityDynamic | world::kEntityMover);
    ASSERT_EQ(level.movers.movers.size(), 1u);
    EXPECT_EQ(level.movers.movers[0].entity, 0u);
    EXPECT_EQ(level.movers.movers[0].kind, world::MoverKind::kShuttle);
    EXPECT_FLOAT_EQ(level.movers.movers[0].period, 4.0f);
    EXPECT_EQ(level.movers.movers[0].pos2 - level.movers.movers[0].pos1, glm::vec3(0, 3, 0));
    EXPECT_TRUE(level.instances[0].dynamic);
    EXPECT_EQ(level.entities[1].flags, world::kEntitySpawn);
    EXPECT_EQ(level.entities[2].flags, world::kEntityProbe);
    EXPECT_TRUE(level.hasGridBounds);
    EXPECT_EQ(level.gridMax, glm::vec3(1.0f));
    EXPECT_TRUE(level.hasExposure);
    EXPECT_FLOAT_EQ(level.texelsPerMetre, 6.0f);
    // The level's density drives the charts unless the command line gave one.
    world::CompileOptions options;
    EXPECT_FLOAT_EQ(world::compileLevel(level, options).level.settings.texelsPerMetre, 6.0f);
    options.charts.densityFromCommandLine = true;
    EXPECT_FLOAT_EQ(world::compileLevel(level, options).level.settings.texelsPerMetre, 16.0f);
}

TEST(Import, ProbeSpacingIsTheLevels) {
    GltfBuilder gltf;
    gltf.addNode({{"name", "tri"}, {"mesh", gltf.addMesh(oneTriangle("tri"))}});
    gltf.addNode({{"name", "settings"}, {"extras", {{"onelight", {{"probe_spacing", 3.5}}}}}});
    const world::SourceLevel level = importGltf(gltf.write(freshFolder("spacing_ok"), "spacing"));
    EXPECT_FLOAT_EQ(level.probeSpacing, 3.5f);
    world::CompileOptions options;
    EXPECT_FLOAT_EQ(world::compileLevel(level, options).level.settings.probeSpacing, 3.5f);
}

// The material models are the level's, through the compile and the package records.
TEST(Import, MaterialModelsAreTheLevels) {
    GltfBuilder gltf;
    gltf.addNode({{"name", "tri"}, {"mesh", gltf.addMesh(oneTriangle("tri"))}});
    gltf.addNode(
        {{"name", "settings"},
         {"extras", {{"onelight", {{"diffuse", "multiscatter"}, {"gloss_mips", "black_ops"}}}}}});
    const world::SourceLevel level = importGltf(gltf.write(freshFolder("models_ok"), "models"));
    EXPECT_EQ(level.diffuseModel, world::DiffuseModel::kMultiscatter);
    EXPECT_EQ(level.glossMips, world::GlossMipMethod::kBlackOps);
    world::CompileOptions options;
    const world::LevelSettings settings = world::compileLevel(level, options).level.settings;
    EXPECT_EQ(settings.diffuseModel, world::DiffuseModel::kMultiscatter);
    EXPECT_EQ(settings.glossMips, world::GlossMipMethod::kBlackOps);
    // Without the keys: Lambert and CLEAN.
    GltfBuilder plain;
    plain.addNode({{"name", "tri"}, {"mesh", plain.addMesh(oneTriangle("tri"))}});
    const world::SourceLevel defaults = importGltf(plain.write(freshFolder("models_default"), "m"));
    EXPECT_EQ(defaults.diffuseModel, world::DiffuseModel::kLambert);
    EXPECT_EQ(defaults.glossMips, world::GlossMipMethod::kClean);
}

// The level's sky: one number (grey) or [r, g, b], cd/m^2, through the compile.
TEST(Import, SkyIsTheLevels) {
    for (const auto& [sky, expected] : {std::pair{nlohmann::json(1200.0), glm::vec3(1200.0f)},
                                        std::pair{nlohmann::json::array({4000.0, 5000.0, 6500.0}),
                                                  glm::vec3(4000, 5000, 6500)}}) {
        GltfBuilder gltf;
        gltf.addNode({{"name", "tri"}, {"mesh", gltf.addMesh(oneTriangle("tri"))}});
        gltf.addNode({{"name", "settings"}, {"extras", {{"onelight", {{"sky", sky}}}}}});
        const world::SourceLevel level = importGltf(gltf.write(freshFolder("sky_ok"), "sky"));
        EXPECT_EQ(level.skyRadiance, expected);
        world::CompileOptions options;
        EXPECT_EQ(world::compileLevel(level, options).level.settings.skyRadiance, expected);
    }
}

// An image sky: "file.hdr", or {"image": ..., "scale": s or [r, g, b]}; the image joins the
// level's images as a file reference beside the glTF, and its scale is the sky radiance.
TEST(Import, SkyImageJoinsTheImages) {
    for (const auto& [sky, scale] :
         {std::pair{nlohmann::json("sky.hdr"), glm::vec3(1.0f)},
          std::pair{nlohmann::json({{"image", "sky.hdr"}, {"scale", 2500.0}}), glm::vec3(2500.0f)},
          std::pair{nlohmann::json({{"image", "sky.hdr"}, {"scale", {1.0, 2.0, 3.0}}}),
                    glm::vec3(1, 2, 3)}}) {
        GltfBuilder gltf;
        gltf.addNode({{"name", "tri"}, {"mesh", gltf.addMesh(oneTriangle("tri"))}});
        gltf.addNode({{"name", "settings"}, {"extras", {{"onelight", {{"sky", sky}}}}}});
        const std::string folder = freshFolder("sky_image");
        const world::SourceLevel level = importGltf(gltf.write(folder, "sky"));
        EXPECT_EQ(level.skyRadiance, scale);
        ASSERT_LT(level.skyImage, level.images.size());
        EXPECT_EQ(level.images[level.skyImage].uri,
                  (std::filesystem::path(folder) / "sky.hdr").lexically_normal().string());
        world::CompileOptions options;
        const world::CompiledLevel compiled = world::compileLevel(level, options).level;
        EXPECT_EQ(compiled.settings.skyImage, level.skyImage);
        EXPECT_EQ(compiled.settings.skyRadiance, scale);
    }
}

TEST(Import, ImagesAreFileReferencesOrEncodedBytes) {
    GltfBuilder gltf;
    MeshData mesh = oneTriangle("tri");
    mesh.material =
        gltf.addMaterial({{"name", "painted"},
                          {"pbrMetallicRoughness", {{"baseColorTexture", {{"index", 0}}}}},
                          {"normalTexture", {{"index", 1}}}});
    gltf.document()["textures"] = {{{"source", 0}, {"sampler", 0}}, {{"source", 1}}};
    gltf.document()["samplers"] = {{{"wrapS", 33071}, {"wrapT", 33648}, {"magFilter", 9728}}};
    // "AQID" is base64 for bytes 1 2 3: never decoded as pixels, kept as they are.
    gltf.document()["images"] = {{{"uri", "data:image/png;base64,AQID"}}, {{"uri", "normal.png"}}};
    gltf.addNode({{"name", "n"}, {"mesh", gltf.addMesh(mesh)}});
    const world::SourceLevel level = importGltf(gltf.write(freshFolder("images"), "images"));
    ASSERT_EQ(level.textures.size(), 2u);
    EXPECT_EQ(level.textures[0].sampler.wrapS, 33071);
    EXPECT_EQ(level.textures[0].sampler.wrapT, 33648);
    EXPECT_EQ(level.textures[0].sampler.magFilter, 9728);
    ASSERT_EQ(level.images.size(), 2u);
    EXPECT_EQ(level.images[0].encodedBytes, (std::vector<uint8_t>{1, 2, 3}));
    EXPECT_TRUE(level.images[0].uri.empty());
    EXPECT_NE(level.images[1].uri.find("normal.png"), std::string::npos);
    EXPECT_TRUE(level.images[1].encodedBytes.empty());
}

/// Expects import to throw a Error whose message contains every fragment.
void expectError(const std::string& path, std::initializer_list<const char*> fragments) {
    try {
        (void)importGltf(path);
        FAIL() << "expected a world::Error for " << path;
    } catch (const Error& e) {
        const std::string message = e.what();
        EXPECT_EQ(message.find('\n'), std::string::npos) << message;
        for (const char* f : fragments) EXPECT_NE(message.find(f), std::string::npos) << message;
    }
}

TEST(ImportErrors, NanPositionNamesTheMesh) {
    GltfBuilder gltf;
    MeshData mesh = oneTriangle("broken_wall");
    mesh.positions[1].y = std::nanf("");
    gltf.addNode({{"name", "n"}, {"mesh", gltf.addMesh(mesh)}});
    expectError(gltf.write(freshFolder("nan"), "nan"),
                {"nan.gltf", "broken_wall", "POSITION", "NaN or Inf"});
}

TEST(ImportErrors, InfPositionNamesTheMesh) {
    GltfBuilder gltf;
    MeshData mesh = oneTriangle("sky");
    mesh.positions[2].x = INFINITY;
    gltf.addNode({{"name", "n"}, {"mesh", gltf.addMesh(mesh)}});
    expectError(gltf.write(freshFolder("inf"), "inf"), {"sky", "NaN or Inf"});
}

TEST(ImportErrors, IndexOutOfRange) {
    GltfBuilder gltf;
    MeshData mesh = oneTriangle("tri");
    mesh.indices = {0, 1, 7};
    gltf.addNode({{"name", "n"}, {"mesh", gltf.addMesh(mesh)}});
    expectError(gltf.write(freshFolder("index"), "index"), {"tri", "index 2 is 7"});
}

TEST(ImportErrors, AccessorPastItsBuffer) {
    GltfBuilder gltf;
    gltf.addNode({{"name", "n"}, {"mesh", gltf.addMesh(oneTriangle("tri"))}});
    gltf.document()["accessors"][0]["count"] = 1000;
    expectError(gltf.write(freshFolder("accessor"), "accessor"), {"tri", "POSITION"});
}

TEST(ImportErrors, BadTexelDensity) {
    GltfBuilder gltf;
    gltf.addNode({{"name", "settings"}, {"extras", {{"onelight", {{"texels_per_metre", -2.0}}}}}});
    expectError(gltf.write(freshFolder("density"), "density"), {"settings", "texels_per_metre"});
}

TEST(ImportErrors, BadProbeSpacing) {
    for (double spacing : {0.0, -2.0}) {
        GltfBuilder gltf;
        gltf.addNode(
            {{"name", "settings"}, {"extras", {{"onelight", {{"probe_spacing", spacing}}}}}});
        expectError(gltf.write(freshFolder("spacing"), "spacing"),
                    {"settings", "probe_spacing", "expected metres > 0"});
    }
}

TEST(ImportErrors, BadMaterialModels) {
    for (const auto& [key, value, expected] :
         {std::tuple{"diffuse", nlohmann::json("phong"),
                     "expected \"lambert\" or \"multiscatter\""},
          std::tuple{"diffuse", nlohmann::json(1), "must be a string"},
          std::tuple{"gloss_mips", nlohmann::json("toksvig"),
                     "\"blit\", \"black_ops\", \"wwii\" or \"clean\""}}) {
        GltfBuilder gltf;
        gltf.addNode({{"name", "settings"}, {"extras", {{"onelight", {{key, value}}}}}});
        expectError(gltf.write(freshFolder("models_bad"), "models"), {"settings", key, expected});
    }
}

TEST(ImportErrors, BadSky) {
    GltfBuilder gltf;
    gltf.addNode({{"name", "settings"},
                  {"extras", {{"onelight", {{"sky", nlohmann::json::array({1.0, -2.0, 3.0})}}}}}});
    expectError(gltf.write(freshFolder("sky"), "sky"), {"settings", "sky", "cd/m^2 >= 0"});
    GltfBuilder words;
    words.addNode({{"name", "settings"}, {"extras", {{"onelight", {{"sky", "blue"}}}}}});
    expectError(words.write(freshFolder("sky_words"), "sky"), {"settings", "sky"});
    GltfBuilder png;
    png.addNode({{"name", "settings"}, {"extras", {{"onelight", {{"sky", "sky.png"}}}}}});
    expectError(png.write(freshFolder("sky_png"), "sky"), {"settings", "sky.png", ".hdr"});
    GltfBuilder noImage;
    noImage.addNode(
        {{"name", "settings"}, {"extras", {{"onelight", {{"sky", {{"scale", 2.0}}}}}}}});
    expectError(noImage.write(freshFolder("sky_object"), "sky"), {"settings", "\"image\""});
    GltfBuilder badScale;
    badScale.addNode(
        {{"name", "settings"},
         {"extras", {{"onelight", {{"sky", {{"image", "a.hdr"}, {"scale", -1.0}}}}}}}});
    expectError(badScale.write(freshFolder("sky_scale"), "sky"), {"sky.scale", "cd/m^2 >= 0"});
}

TEST(ImportErrors, UnknownRole) {
    GltfBuilder gltf;
    const int lamp = gltf.addLight({{"type", "point"}});
    gltf.addNode({{"name", "lamp"},
                  {"extensions", {{"KHR_lights_punctual", {{"light", lamp}}}}},
                  {"extras", {{"onelight", {{"role", "sometimes"}}}}}});
    expectError(gltf.write(freshFolder("role"), "role"), {"lamp", "role", "\"baked\""});
}

TEST(ImportErrors, MissingFileAndNotJson) {
    expectError("/nonexistent/level.gltf", {"/nonexistent/level.gltf", "cannot open"});
    const auto folder = freshFolder("garbage");
    std::ofstream(folder / "garbage.gltf") << "{ this is not json";
    expectError((folder / "garbage.gltf").string(), {"garbage.gltf", "not a valid glTF"});
}

TEST(ImportAssets, NormalTangentTest) {
    const std::string path = sharedAsset("NormalTangentTest/glTF/NormalTangentTest.gltf");
    if (path.empty()) GTEST_SKIP() << "shared assets absent";
    const world::SourceLevel level = importGltf(path);
    size_t triangles = 0;
    for (const world::MeshInstance& i : level.instances) triangles += i.indices.size() / 3;
    EXPECT_EQ(triangles, 7774u);
    ASSERT_EQ(level.materials.size(), 1u);
    EXPECT_NE(level.materials[0].normalTexture, world::kNoIndex);
    EXPECT_NE(level.materials[0].baseColorTexture, world::kNoIndex);
    ASSERT_EQ(level.images.size(), 3u);
    for (const world::Image& image : level.images)
        EXPECT_TRUE(std::filesystem::exists(image.uri)) << image.uri;
    for (const world::Vertex& v : level.instances[0].vertices)
        ASSERT_NEAR(glm::dot(glm::vec3(v.tangent), v.normal), 0.0f, 1e-4f);
}

TEST(ImportAssets, TextureSettingsTestSamplers) {
    const std::string path = sharedAsset("TextureSettingsTest/glTF/TextureSettingsTest.gltf");
    if (path.empty()) GTEST_SKIP() << "shared assets absent";
    const world::SourceLevel level = importGltf(path);
    EXPECT_EQ(level.materials.size(), 10u);
    bool clamp = false, mirror = false;
    for (const world::Texture& t : level.textures) {
        clamp |= t.sampler.wrapT == 33071 || t.sampler.wrapS == 33071;
        mirror |= t.sampler.wrapT == 33648 || t.sampler.wrapS == 33648;
    }
    EXPECT_TRUE(clamp);
    EXPECT_TRUE(mirror);
}

}  // namespace
}  // namespace onelight::test
