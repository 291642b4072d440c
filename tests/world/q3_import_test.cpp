// Quake 3 maps: the BSP reader's checks on hand-made files, patch tessellation without cracks,
// the entity lump, the light mapping, the game's search path over pk3s (written here with
// libzip) and loose files, external and deluxe lightmaps, a computed view for a map without a
// spawn, and a real OpenArena map when the game's packages are installed (openarena-081-maps,
// openarena-081-textures, openarena-data).
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <limits>
#include <map>
#include <set>
#include <string>
#include <vector>

#include "tests/support/error_message.hpp"
#include "tests/world/q3_test_maps.hpp"
#include "tests/world/world_test_support.hpp"
#include "world/compile/compile_level.hpp"
#include "world/error.hpp"
#include "world/import/level_import.hpp"
#include "world/import/q3/bsp_file.hpp"
#include "world/import/q3/collision_import.hpp"
#include "world/import/q3/computed_view.hpp"
#include "world/import/q3/entity_lump.hpp"
#include "world/import/q3/patch_tessellation.hpp"
#include "world/import/q3/pk3_archive.hpp"
#include "world/import/q3/shader_script.hpp"
#include "world/light_model.hpp"
#include "world/package/collision_section.hpp"
#include "world/package/package_reader.hpp"

namespace onelight::world::q3 {
namespace {

using onelight::test::errorMessage;
using onelight::test::freshFolder;
using onelight::test::Quake3BspBuilder;
using onelight::test::tga;
using onelight::test::writeFile;
using onelight::test::writePk3;

// Import options whose only game folder is an empty one of its own: no game data is found.
Quake3Options withoutGame(const std::string& name) {
    Quake3Options options;
    options.gameFolders = {freshFolder("no_game_" + name).string()};
    return options;
}

std::string parseError(const std::vector<uint8_t>& bytes) {
    return errorMessage([&] { (void)parseBsp(bytes, "test.bsp"); });
}

TEST(Quake3Bsp, AHandMadeMapImportsInMetresWithYUp) {
    Quake3BspBuilder b;
    const SourceLevel level = importLevel(b.write("square", "square"), withoutGame("square"));
    ASSERT_EQ(level.instances.size(), 1u);
    const MeshInstance& mesh = level.instances[0];
    ASSERT_EQ(mesh.indices.size(), 6u);
    // (64, 64, 0) units is (2, 0, -2) m; the face's +z normal is +y.
    EXPECT_EQ(mesh.vertices[2].position, glm::vec3(2.0f, 0.0f, -2.0f));
    EXPECT_EQ(mesh.vertices[0].normal, glm::vec3(0.0f, 1.0f, 0.0f));
    // Wound counter-clockwise about +y.
    const glm::vec3 a = mesh.vertices[mesh.indices[0]].position,
                    c = mesh.vertices[mesh.indices[2]].position,
                    bb = mesh.vertices[mesh.indices[1]].position;
    EXPECT_GT(glm::cross(bb - a, c - a).y, 0.0f);
    // No image of the shader's name in any pk3: grey, counted as missing.
    ASSERT_EQ(level.materials.size(), 1u);
    EXPECT_EQ(level.materials[0].baseColorTexture, kNoIndex);
    EXPECT_EQ(level.materials[0].name, "textures/test/wall");
    EXPECT_FLOAT_EQ(level.texelsPerMetre, 2.0f);  // one luxel per 16 units
}

TEST(Quake3Bsp, BadFilesGiveOneLineNamingThePlace) {
    const std::vector<uint8_t> good = Quake3BspBuilder().bytes();
    EXPECT_NO_THROW((void)parseBsp(good, "test.bsp"));
    const auto expectError = [](const std::vector<uint8_t>& bytes, const std::string& fragment) {
        const std::string e = parseError(bytes);
        EXPECT_NE(e.find(fragment), std::string::npos) << "got: " << e;
        EXPECT_EQ(e.find('\n'), std::string::npos) << e;
        EXPECT_EQ(e.rfind("test.bsp", 0), 0u) << e;
    };
    expectError(std::vector<uint8_t>(good.begin(), good.begin() + 100), "expected a Quake 3 BSP");
    std::vector<uint8_t> magic = good;
    magic[0] = 'V';
    expectError(magic, "no IBSP magic");
    std::vector<uint8_t> version = good;
    version[4] = 47;
    expectError(version, "version 47");
    std::vector<uint8_t> truncated(good.begin(), good.end() - 50);
    expectError(truncated, "outside the file");
    {
        Quake3BspBuilder b;
        b.surfaces[0].vertexCount = -1;
        expectError(b.bytes(), "surface 0: vertices 0 + -1");
    }
    {
        Quake3BspBuilder b;
        b.indices[4] = 9;
        expectError(b.bytes(), "surface 0: index 4 is 9; expected 0 .. 3");
    }
    {
        Quake3BspBuilder b;
        b.surfaces[0].shader = 3;
        expectError(b.bytes(), "surface 0: shader 3 of 1");
    }
    {
        Quake3BspBuilder b;
        b.surfaces[0].type = kSurfacePatch;
        b.surfaces[0].patchWidth = 2;
        b.surfaces[0].patchHeight = 2;
        expectError(b.bytes(), "a patch of 2 x 2 controls");
    }
    {
        Quake3BspBuilder b;
        b.vertices[1].position[0] = std::nanf("");
        expectError(b.bytes(), "lump 10 (vertices): vertex 1 is NaN or Inf in its position");
    }
    {
        // Lightmap coordinates a surface reads on its page must be numbers.
        Quake3BspBuilder b;
        b.lightmaps.assign(kLightmapPageBytes, 0);
        b.surfaces[0].lightmap = 0;
        b.vertices[2].lightmap[1] = std::numeric_limits<float>::infinity();
        expectError(b.bytes(),
                    "lump 10 (vertices): vertex 2 is NaN or Inf in its lightmap coordinates, "
                    "which surface 0 reads on lightmap page 0");
    }
    {
        std::vector<uint8_t> odd = good;
        BspHeader h;
        std::memcpy(&h, odd.data(), sizeof h);
        h.lumps[kLumpDrawVerts].length -= 4;
        std::memcpy(odd.data(), &h, sizeof h);
        expectError(odd, "expected a multiple of its 44-byte records");
    }
    {
        Quake3BspBuilder b;
        b.lightmaps.assign(kLightmapPageBytes, 0);
        b.surfaces[0].lightmap = 2;
        expectError(b.bytes(), "surface 0: lightmap page 2 of 1");
    }
    {
        Quake3BspBuilder b;
        b.lightmaps.assign(100, 0);
        expectError(b.bytes(), "lump 14 (lightmaps) holds 100 bytes; expected whole pages");
    }
}

// q3map2's own light comes along for --view q3map2: each drawn triangle with its corners in the
// level, its lightmap coordinates and page, or its vertex light where it has no page.
TEST(Quake3Bsp, TheMapsOwnLightmapsAreKept) {
    Quake3BspBuilder b;
    b.lightmaps.assign(2 * kLightmapPageBytes, 7);
    b.surfaces[0].lightmap = 1;
    for (size_t v = 0; v < b.vertices.size(); ++v) {
        b.vertices[v].lightmap[0] = 0.25f * float(v);
        b.vertices[v].lightmap[1] = 0.5f;
        b.vertices[v].color[0] = uint8_t(10 * v);
    }
    b.surfaces.push_back(b.surfaces[0]);
    b.surfaces[1].lightmap = -3;  // vertex lit
    const SourceLevel level =
        importLevel(b.write("lightmaps", "lightmaps"), withoutGame("lightmaps"));
    const ImportedLightmap& l = level.importedLightmap;
    EXPECT_EQ(l.producer, "q3map2");
    EXPECT_EQ(l.pageSize, kLightmapPageSize);
    EXPECT_EQ(l.pages.size(), 2 * kLightmapPageBytes);
    ASSERT_EQ(l.triangles.size(), 4u);
    EXPECT_EQ(l.triangles[0].page, 1u);
    EXPECT_EQ(l.triangles[2].page, kNoIndex);
    // The first triangle is vertices 0 1 2 of the square: (0,0) (2,0) (2,-2) m in x and z.
    EXPECT_EQ(l.triangles[0].corners[1], glm::vec3(2.0f, 0.0f, 0.0f));
    EXPECT_EQ(l.triangles[0].uv[1], glm::vec2(0.25f, 0.5f));
    EXPECT_EQ(l.triangles[2].vertexLight[2], glm::vec3(20.0f, 0.0f, 0.0f));
}

TEST(Quake3Bsp, APk3ThatIsNotAZipIsNamed) {
    const auto folder = freshFolder("not_zip");
    const std::string pk3 = (folder / "broken.pk3").string();
    std::ofstream(pk3) << "not a zip at all";
    const std::string e = errorMessage([&] { (void)importLevel(pk3 + ":maps/x.bsp"); });
    EXPECT_NE(e.find("broken.pk3: not a readable pk3 (zip) archive"), std::string::npos) << e;
}

TEST(Quake3Entities, ParseKeysAndNameTheLineOfAFault) {
    const std::vector<MapEntity> e = parseEntities(
        "{\n\"classname\" \"worldspawn\"\n}\n{\n\"classname\" \"light\"\n\"light\" \"250\"\n"
        "\"_color\" \"1 0.5 0.25\"\n}\n",
        "t.bsp");
    ASSERT_EQ(e.size(), 2u);
    EXPECT_EQ(e[1].get("classname"), "light");
    EXPECT_EQ(e[1].line, 4);
    EXPECT_EQ(numberKey(e[1], "light", 0.0f, "t.bsp"), 250.0f);
    EXPECT_EQ(vectorKey(e[1], "_color", glm::vec3(0.0f), "t.bsp"), glm::vec3(1.0f, 0.5f, 0.25f));
    EXPECT_NE(errorMessage([] {
                  (void)parseEntities("{\n\"a\" \"b\"\n", "t.bsp");
              }).find("t.bsp: entities line 1: an entity is never closed"),
              std::string::npos);
    EXPECT_NE(errorMessage([] {
                  (void)parseEntities("{\n\"a\"\n\"b\" x }", "t.bsp");
              }).find("entities line 3: expected a quoted key"),
              std::string::npos);
    EXPECT_NE(errorMessage([&] {
                  (void)numberKey(e[1], "_color", 0.0f, "t.bsp");
              }).find("\"_color\" holds 3 numbers; expected one"),
              std::string::npos);
}

// Keys as real maps write them: an empty value is the key's default (Nexuiz's racetrack has
// "spawnflags" ""), and a light's intensity in the Half-Life form "R G B I" (Nexuiz's skyway
// source) is its first number, as q3map2's atof reads it, with a note.
TEST(Quake3Entities, EmptyValuesAndHalfLifeIntensitiesReadAsQ3map2Does) {
    const std::vector<MapEntity> e = parseEntities(
        "{\n\"classname\" \"worldspawn\"\n}\n{\n\"classname\" \"light\"\n\"spawnflags\" \"\"\n"
        "\"_color\" \" \"\n\"origin\" \"32 32 64\"\n\"_light\" \"255 128 64 500\"\n}\n",
        "t.bsp");
    ASSERT_EQ(e.size(), 2u);
    EXPECT_EQ(numberKey(e[1], "spawnflags", 7.0f, "t.bsp"), 7.0f);
    EXPECT_EQ(vectorKey(e[1], "_color", glm::vec3(1.0f), "t.bsp"), glm::vec3(1.0f));
    bool more = false;
    EXPECT_EQ(firstNumberKey(e[1], "_light", 300.0f, "t.bsp", &more), 255.0f);
    EXPECT_TRUE(more);
    Quake3BspBuilder b;
    b.entities =
        "{\n\"classname\" \"worldspawn\"\n}\n{\n\"classname\" \"light\"\n"
        "\"spawnflags\" \"\"\n\"origin\" \"32 32 64\"\n\"_light\" \"255 128 64 500\"\n}\n";
    const SourceLevel level = importLevel(b.write("half_life", "hl"), withoutGame("half_life"));
    ASSERT_EQ(level.lights.size(), 1u);
    EXPECT_NEAR(level.lights[0].intensity, 255.0 * kQuake3CandelaPerLight, 1e-3);
    bool noted = false;
    for (const std::string& note : level.importNotes)
        noted = noted || note.find("1 light(s) whose intensity key holds several numbers") !=
                             std::string::npos;
    EXPECT_TRUE(noted) << ::testing::PrintToString(level.importNotes);
}

// q3map2's units and spot cone (CreateEntityLights, LightContributionToSample): "light" 300 is
// 300 x 7500 / 32^2 cd; a light aimed at a target 256 units away with radius 64 has tan(outer)
// = (64 + 16) / 256, its light ramping down over the last 32 units of that radius (tan(inner) =
// 48 / 256); radius 0 is 64; a spot's linear flag is cleared (inverse-square, no range); and
// "_sun" 1 makes a sun along the axis, of the value itself in lux (no point scale), with a note.
TEST(Quake3Lights, PointsSpotsAndSpotSunsFollowQ3map2) {
    Quake3BspBuilder b;
    b.entities +=
        "{\n\"classname\" \"light\"\n\"origin\" \"0 0 128\"\n\"light\" \"300\"\n}\n"
        "{\n\"classname\" \"light\"\n\"origin\" \"0 0 256\"\n\"light\" \"600\"\n\"target\" "
        "\"spot1\"\n\"_color\" \"1 0.5 0\"\n}\n"
        "{\n\"classname\" \"light\"\n\"origin\" \"0 0 256\"\n\"light\" \"600\"\n\"target\" "
        "\"spot1\"\n\"radius\" \"0\"\n\"spawnflags\" \"1\"\n}\n"
        "{\n\"classname\" \"light\"\n\"origin\" \"0 0 512\"\n\"light\" \"80\"\n\"target\" "
        "\"spot1\"\n\"_sun\" \"1\"\n}\n"
        "{\n\"classname\" \"info_null\"\n\"targetname\" \"spot1\"\n\"origin\" \"0 0 0\"\n}\n";
    const SourceLevel level = importLevel(b.write("lights", "lights"), withoutGame("lights"));
    ASSERT_EQ(level.lights.size(), 4u);
    const Light& point = level.lights[0];
    EXPECT_EQ(point.type, LightType::kPoint);
    EXPECT_NEAR(point.intensity, 300.0 * 7500.0 / 1024.0, 1e-3);
    EXPECT_EQ(point.position, glm::vec3(0.0f, 4.0f, 0.0f));
    for (size_t i : {1u, 2u}) {  // the coloured spot, then the one of radius 0 and linear flag
        const Light& spot = level.lights[i];
        EXPECT_EQ(spot.type, LightType::kSpot);
        EXPECT_NEAR(spot.intensity, 600.0 * 7500.0 / 1024.0, 1e-3);
        EXPECT_EQ(spot.range, 0.0f);
        EXPECT_NEAR(std::tan(spot.outerCone), 80.0 / 256.0, 1e-6);
        EXPECT_NEAR(std::tan(spot.innerCone), 48.0 / 256.0, 1e-6);
        EXPECT_NEAR(spot.direction.y, -1.0f, 1e-6f);
    }
    EXPECT_EQ(level.lights[1].color, glm::vec3(1.0f, 0.5f, 0.0f));
    const Light& sun = level.lights[3];
    EXPECT_EQ(sun.type, LightType::kDirectional);
    EXPECT_NEAR(sun.intensity, 80.0f, 1e-6f);
    EXPECT_NEAR(sun.direction.y, -1.0f, 1e-6f);
    bool noted = false;
    for (const std::string& note : level.importNotes)
        noted =
            noted || note.find("1 spot light(s) with \"_sun\" 1 made suns") != std::string::npos;
    EXPECT_TRUE(noted) << ::testing::PrintToString(level.importNotes);
}

// A linear light (spawnflags 1) is an inverse-square light with q3map2's reach as its range,
// equal to q3map2's L 7500/8000 - d at half the reach (q3_import.hpp, "Linear lights"), and dark
// at the reach; the import says it approximated it. Worldspawn's ambient is reported as ignored.
TEST(Quake3Lights, LinearFalloffIsApproximatedAndAmbientIsReported) {
    Quake3BspBuilder b;
    b.entities =
        "{\n\"classname\" \"worldspawn\"\n\"ambient\" \"10\"\n}\n"
        "{\n\"classname\" \"light\"\n\"origin\" \"0 0 300\"\n\"light\" \"300\"\n"
        "\"spawnflags\" \"1\"\n\"fade\" \"0.5\"\n}\n"
        "{\n\"classname\" \"info_player_start\"\n\"origin\" \"32 32 24\"\n}\n";
    b.surfaces[0].lightmap = -3;  // vertex lit: no lightmap to miss
    const SourceLevel level = importLevel(b.write("linear", "linear"), withoutGame("linear"));
    ASSERT_EQ(level.lights.size(), 1u);
    const Light& l = level.lights[0];
    const double reach = 300.0 * 7500.0 / 8000.0 / 0.5;  // units: 562.5, 17.6 m
    EXPECT_NEAR(l.range, reach / 32.0, 1e-4);
    const glm::vec3 below = l.position - glm::vec3(0.0f, 1.0f, 0.0f);
    const auto luxAt = [&](double units) {
        return double(evaluateLight(l, l.position + (below - l.position) * float(units / 32.0))
                          .illuminance.x);
    };
    // q3map2 at half the reach: 300 x 7500/8000 - 281.25 x 0.5 = 140.625 lightmap units (lux).
    EXPECT_NEAR(luxAt(reach / 2.0), 140.625, 140.625 * 1e-4);
    EXPECT_EQ(luxAt(reach), 0.0);
    EXPECT_GT(luxAt(reach / 4.0), 140.625);
    ASSERT_EQ(level.importNotes.size(), 2u);
    EXPECT_NE(level.importNotes[0].find("1 light(s) with q3map2's linear falloff approximated"),
              std::string::npos)
        << level.importNotes[0];
    EXPECT_NE(level.importNotes[1].find("worldspawn 'ambient' 10 ignored"), std::string::npos)
        << level.importNotes[1];
}

// Primaries are the lights that are the brightest somewhere: over the 2 x 2 m square, a light
// 2 m above it wins everywhere; one 10 times as strong but 300 m away, nowhere; so only the
// first is a primary, even with room for four. Without the near one, the far one is.
TEST(Quake3Lights, PrimariesAreTheLightsThatAreTheBrightestSomewhere) {
    Quake3BspBuilder b;
    b.entities +=
        "{\n\"classname\" \"light\"\n\"origin\" \"32 32 64\"\n\"light\" \"300\"\n}\n"
        "{\n\"classname\" \"light\"\n\"origin\" \"9600 0 64\"\n\"light\" \"3000\"\n}\n";
    Quake3Options options = withoutGame("roles");
    options.primaryLights = 4;
    const SourceLevel level = importLevel(b.write("roles", "roles"), options);
    ASSERT_EQ(level.lights.size(), 2u);
    EXPECT_EQ(level.lights[0].role, LightRole::kPrimary);
    EXPECT_EQ(level.lights[1].role, LightRole::kBaked);
    Quake3BspBuilder far;
    far.entities += "{\n\"classname\" \"light\"\n\"origin\" \"9600 0 64\"\n\"light\" \"3000\"\n}\n";
    const SourceLevel alone = importLevel(far.write("roles_far", "roles"), options);
    ASSERT_EQ(alone.lights.size(), 1u);
    EXPECT_EQ(alone.lights[0].role, LightRole::kPrimary);
}

// Patches: every vertex a patch shares with a neighbour is bit-identical, whichever way the
// neighbour runs along the shared border and whether it is its row or its column.
TEST(Quake3Patches, SharedBordersAreBitIdentical) {
    // A curved 5 x 3 grid (two pieces side by side).
    std::vector<PatchPoint> grid;
    for (int y = 0; y < 3; ++y)
        for (int x = 0; x < 5; ++x)
            grid.push_back({glm::vec3(float(x) * 17.3f, float(y) * 11.1f,
                                      std::sin(float(x) * 1.3f + float(y)) * 9.7f),
                            glm::vec3(0, 0, 1), glm::vec2(float(x) * 0.31f, float(y) * 0.27f)});
    // The neighbour's first column is the first piece's top row (controls (0..2, 2)) reversed.
    std::vector<PatchPoint> neighbour(9);
    for (int j = 0; j < 3; ++j) {
        const PatchPoint& border = grid[size_t(2 * 5 + (2 - j))];
        neighbour[size_t(j) * 3] = border;
        for (int i = 1; i < 3; ++i)
            neighbour[size_t(j) * 3 + size_t(i)] = {
                border.position + glm::vec3(0.0f, float(i) * 13.0f, 1.0f), glm::vec3(0, 0, 1),
                glm::vec2(0.0f)};
    }
    for (uint32_t level : {1u, 3u, 4u, 7u}) {
        const PatchMesh a = tessellatePatch(grid, 5, 3, level);
        const PatchMesh b = tessellatePatch(neighbour, 3, 3, level);
        const uint32_t row = level + 1;
        ASSERT_EQ(a.vertices.size(), size_t(2 * row * row));
        ASSERT_EQ(a.triangles.size(), size_t(2 * level * level * 6));
        for (uint32_t k = 0; k <= level; ++k) {
            // Inside the grid: piece 0's right border is piece 1's left border.
            const PatchPoint& right = a.vertices[k * row + level];
            const PatchPoint& left = a.vertices[row * row + k * row];
            EXPECT_EQ(std::memcmp(&right.position, &left.position, sizeof(glm::vec3)), 0);
            // Across patches: piece 0's top row at i = k is the neighbour's column 0 at
            // j = level - k.
            const PatchPoint& top = a.vertices[level * row + k];
            const PatchPoint& side = b.vertices[(level - k) * row];
            EXPECT_EQ(std::memcmp(&top.position, &side.position, sizeof(glm::vec3)), 0)
                << "level " << level << ", k " << k;
            EXPECT_EQ(top.uv, side.uv);
        }
        // The corners are the controls themselves.
        EXPECT_EQ(a.vertices[0].position, grid[0].position);
        EXPECT_EQ(a.vertices[row * row + level * row + level].position, grid[14].position);
    }
    EXPECT_TRUE(tessellatePatch(grid, 4, 3, 4).vertices.empty());  // even width: nothing
}

// Shader scripts: stages, surfaceparms, the q3map keys, comments, keywords it skips, and the
// colour stage past an environment map and the lightmap.
TEST(Quake3Shaders, ScriptsParseWithTheirStagesAndQ3mapKeys) {
    const std::vector<ShaderScript> s = parseShaderScript(
        "// a comment\n"
        "textures/base_light/panel\n{\n  qer_editorimage textures/base_light/panel.tga\n"
        "  q3map_lightimage textures/base_light/panel.blend.tga\n  surfaceparm METALSTEPS\n"
        "  q3map_surfacelight 1000\n  deformVertexes wave 100 sin 0 1 0 1 /* skipped */\n"
        "  { map textures/effects/envmap2.tga\n tcGen environment }\n"
        "  {\n    map textures/base_light/panel.tga\n    blendFunc GL_ONE GL_ONE\n  }\n"
        "  { map $lightmap\n blendfunc filter }\n}\n"
        "textures/skies/night\n{\n surfaceparm sky\n surfaceparm noimpact\n"
        " q3map_sun 1 0.9 0.8 120 45 60\n q3map_skylight 80 3\n cull none\n}\n"
        "textures/grate\n{\n { map textures/grate.tga\n alphaFunc GE128 }\n}\n",
        "test.shader");
    ASSERT_EQ(s.size(), 3u);
    EXPECT_EQ(s[0].name, "textures/base_light/panel");
    EXPECT_EQ(s[0].line, 2);
    EXPECT_EQ(s[0].surfaceLight, 1000.0f);
    EXPECT_EQ(s[0].lightImage, "textures/base_light/panel.blend.tga");
    EXPECT_TRUE(s[0].surfaceParms.count("metalsteps"));
    ASSERT_EQ(s[0].stages.size(), 3u);
    ASSERT_NE(s[0].colorStage(), nullptr);
    EXPECT_EQ(s[0].colorStage()->map, "textures/base_light/panel.tga");
    EXPECT_EQ(s[0].colorStage()->blendFunc, "gl_one gl_one");
    ASSERT_TRUE(s[1].sun.has_value());
    EXPECT_EQ(s[1].sun->intensity, 120.0f);
    EXPECT_EQ(s[1].sun->elevation, 60.0f);
    EXPECT_EQ(s[1].skyLight, 80.0f);
    EXPECT_EQ(s[1].skyLightIterations, 3);
    // An iteration count past int's range, or not a number, is 0 (found by fuzz_q3_text: the
    // conversion was undefined).
    for (const char* count : {"1e30", "-7", "nan", "x"}) {
        const std::vector<ShaderScript> odd = parseShaderScript(
            std::string("textures/s\n{\n surfaceparm sky\n q3map_skylight 80 ") + count + "\n}\n",
            "odd.shader");
        ASSERT_EQ(odd.size(), 1u);
        EXPECT_EQ(odd[0].skyLightIterations, 0) << count;
    }
    EXPECT_TRUE(s[1].cullNone);
    EXPECT_EQ(s[1].colorStage(), nullptr);
    EXPECT_EQ(s[2].colorStage()->alphaFunc, "ge128");
}

TEST(Quake3Shaders, BrokenScriptsNameTheirFileAndLine) {
    const auto expectError = [](const std::string& text, const std::string& fragment) {
        const std::string e = errorMessage([&] { (void)parseShaderScript(text, "x.shader"); });
        EXPECT_NE(e.find(fragment), std::string::npos) << "got: " << e;
    };
    expectError("a\n{\n surfaceparm sky\n", "x.shader:2: shader 'a': its '{' is never closed");
    expectError("a\n{\n { map b.tga\n", "x.shader:3: a stage's '{' is never closed");
    expectError("}\n", "x.shader:1: a '}' closes nothing");
    expectError("a\nb\n{\n}\n", "x.shader:1: shader 'a' has no '{' after its name");
    expectError("a\n{\n q3map_sun 1 1 1 100\n}\n", "x.shader:3: q3map_sun has 4 values");
    expectError("a\n{\n /* never closed\n}\n", "x.shader:3: a /* comment is never closed");
    // A keyword it does not know is skipped, not an error (the game's renderer has hundreds),
    // and a number that is a word reads 0, as q3map2 reads it (the game's clown2.shader has one).
    EXPECT_EQ(parseShaderScript("a\n{\n frobnicate 1 2 3\n}\n", "x.shader").size(), 1u);
    EXPECT_EQ(parseShaderScript("a\n{\n q3map_surfacelight x.tga\n}\n", "x.shader")[0].surfaceLight,
              0.0f);
}

// Every script of the installed game parses.
TEST(Quake3Shaders, TheGamesScriptsAllParse) {
    if (defaultQuake3Folders().empty())
        GTEST_SKIP() << "OpenArena is not installed (openarena-data)";
    GameFiles files;
    for (const std::string& folder : defaultQuake3Folders())
        for (const auto& entry : std::filesystem::directory_iterator(folder))
            if (entry.path().extension() == ".pk3") files.add(entry.path().string());
    size_t scripts = 0, shaders = 0;
    for (const auto& [key, file] : files.files) {
        if (key.rfind("scripts/", 0) != 0 || key.size() < 7 ||
            key.compare(key.size() - 7, 7, ".shader") != 0)
            continue;
        const std::vector<uint8_t> bytes =
            *files.read(key, kMaxShaderScriptBytes, "a shader script");
        shaders +=
            parseShaderScript(std::string(bytes.begin(), bytes.end()), files.where(key)).size();
        ++scripts;
    }
    std::printf("[ shaders ] %zu scripts, %zu shaders\n", scripts, shaders);
    EXPECT_GT(scripts, 50u);
    EXPECT_GT(shaders, 1000u);
}

// A real map, when the game is installed: q3dm6ish imports with its textures, spawns (each
// with a camera at its eyes), lights (at most 4 primaries) and finite geometry of a sane size.
TEST(Quake3Maps, Q3dm6ishImportsWithTexturesSpawnsAndLights) {
    if (defaultQuake3Folders().empty())
        GTEST_SKIP() << "OpenArena is not installed (openarena-data, openarena-081-maps, "
                        "openarena-081-textures)";
    const SourceLevel level = importLevel("q3dm6ish");
    size_t triangles = 0, textured = 0;
    glm::vec3 lo(1e30f), hi(-1e30f);
    std::set<uint32_t> staticMaterials;
    for (const MeshInstance& m : level.instances) {
        if (m.dynamic) continue;  // the items' (q3_items_test.cpp)
        triangles += m.indices.size() / 3;
        staticMaterials.insert(m.material);
        for (const Vertex& v : m.vertices) {
            ASSERT_TRUE(std::isfinite(v.position.x) && std::isfinite(v.position.y) &&
                        std::isfinite(v.position.z));
            lo = glm::min(lo, v.position);
            hi = glm::max(hi, v.position);
        }
    }
    for (uint32_t m : staticMaterials) textured += level.materials[m].baseColorTexture != kNoIndex;
    const glm::vec3 size = hi - lo;
    std::printf(
        "[ q3dm6ish ] %zu triangles, %zu materials (%zu textured), %zu lights, %zu "
        "spawns, %.0f x %.0f x %.0f m\n",
        triangles, level.materials.size(), textured, level.lights.size(), level.cameras.size(),
        double(size.x), double(size.y), double(size.z));
    EXPECT_GT(triangles, 2000u);
    EXPECT_GE(textured * 10, staticMaterials.size() * 9);
    EXPECT_GT(level.lights.size(), 10u);
    size_t primaries = 0;
    for (const Light& l : level.lights) primaries += l.role == LightRole::kPrimary;
    std::printf("[ q3dm6ish ] %zu primaries\n", primaries);
    EXPECT_GE(primaries, 1u);
    EXPECT_LE(primaries, 8u);
    EXPECT_GE(level.cameras.size(), 4u);
    size_t spawns = 0;
    for (const Entity& e : level.entities) {
        EXPECT_TRUE(e.flags & (kEntitySpawn | kEntityItem));
        spawns += (e.flags & kEntitySpawn) != 0;
        EXPECT_GT(e.position.y, lo.y);  // above the map's lowest point
    }
    EXPECT_EQ(level.cameras.size(), spawns);
    EXPECT_GT(std::max(size.x, size.z), 20.0f);
    EXPECT_LT(std::max({size.x, size.y, size.z}), 300.0f);
    // q3map2's own light comes with it, for every drawn triangle.
    EXPECT_EQ(level.importedLightmap.triangles.size(), triangles);
    EXPECT_GT(level.importedLightmap.pages.size(), 0u);
}

// A pk3 named without its folder is looked for in the game folders; one that is nowhere is
// named in the error.
TEST(Quake3Maps, APk3NamedWithoutItsFolderIsFoundInTheGame) {
    if (defaultQuake3Folders().empty())
        GTEST_SKIP() << "OpenArena is not installed (openarena-data, openarena-081-maps)";
    const SourceLevel level = importLevel("pak1-maps.pk3:maps/aggressor.bsp");
    EXPECT_NE(level.sourcePath.find("/pak1-maps.pk3:maps/aggressor.bsp"), std::string::npos)
        << level.sourcePath;
    EXPECT_GT(level.lights.size(), 80u);  // the 0.8.1 BSP keeps its light entities
    const std::string e = errorMessage([] { (void)importLevel("pak9-none.pk3:maps/x.bsp"); });
    EXPECT_NE(e.find("pak9-none.pk3"), std::string::npos) << e;
}

}  // namespace
}  // namespace onelight::world::q3

namespace onelight::world::q3 {
namespace {

// oa_bases3's sky shader has no q3map_skylight but a q3map_surfacelight 50 (q3map2 makes its
// faces area lights): a uniform sky of 0.25 x 50 cd/m^2 at its brightest channel, in its light
// image's (reddish clouds) mean colour.
TEST(Quake3Maps, ASkyThatIsASurfaceLightIsAUniformSky) {
    if (defaultQuake3Folders().empty())
        GTEST_SKIP() << "OpenArena is not installed (openarena-data, openarena-088-data)";
    const SourceLevel level = importLevel("oa_bases3");
    const glm::vec3 sky = level.skyRadiance;
    EXPECT_FLOAT_EQ(std::max({sky.x, sky.y, sky.z}), 12.5f);
    EXPECT_GT(sky.x, sky.z);  // red clouds
}

}  // namespace
}  // namespace onelight::world::q3

namespace onelight::world::q3 {
namespace {

// Adds an axis-aligned box brush of `shader` (map units, Z up) and returns its index.
int32_t addBoxBrush(Quake3BspBuilder& b, glm::vec3 lo, glm::vec3 hi, int32_t shader) {
    const int32_t first = int32_t(b.brushSides.size());
    const float n[6][3] = {{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}};
    const float d[6] = {hi.x, -lo.x, hi.y, -lo.y, hi.z, -lo.z};
    for (int s = 0; s < 6; ++s) {
        b.brushSides.push_back({int32_t(b.planes.size()), shader});
        b.planes.push_back({{n[s][0], n[s][1], n[s][2]}, d[s]});
    }
    b.brushes.push_back({first, 6, shader});
    return int32_t(b.brushes.size()) - 1;
}

BspShader shaderWith(const char* name, int32_t contents, int32_t surfaceFlags = 0) {
    BspShader s{};
    std::strcpy(s.name, name);
    s.contentFlags = contents;
    s.surfaceFlags = surfaceFlags;
    return s;
}

// A floor (solid), a clip brush, a water and a trigger brush in the world, and one trigger
// model used by a jump pad, a teleporter and a hurt trigger.
Quake3BspBuilder mapWithCollision() {
    Quake3BspBuilder b;
    b.shaders[0].contentFlags = kContentsSolid;
    b.shaders.push_back(shaderWith("common/clip", kContentsPlayerClip, kSurfNoDraw));
    b.shaders.push_back(shaderWith("textures/liquids/water", kContentsWater));
    b.shaders.push_back(shaderWith("common/trigger", kContentsTrigger, kSurfNoDraw));
    addBoxBrush(b, {-256, -256, -16}, {256, 256, 0}, 0);  // the floor
    addBoxBrush(b, {0, 96, 0}, {64, 128, 128}, 1);        // a clip
    addBoxBrush(b, {-64, -64, 0}, {0, 0, 32}, 2);         // water: not solid
    addBoxBrush(b, {-32, -32, 0}, {32, 32, 8}, 3);        // a trigger brush in the world
    addBoxBrush(b, {64, 0, 0}, {128, 64, 16}, 3);         // the trigger model's brush
    b.models.push_back({{-256, -256, -16}, {256, 256, 128}, 0, 1, 0, 4});
    b.models.push_back({{64, 0, 0}, {128, 64, 16}, 0, 0, 4, 1});
    b.entities = R"({
"classname" "worldspawn"
}
{
"classname" "trigger_push"
"model" "*1"
"target" "apex"
}
{
"classname" "target_position"
"targetname" "apex"
"origin" "96 32 264"
}
{
"classname" "trigger_teleport"
"model" "*1"
"target" "exit"
}
{
"classname" "misc_teleporter_dest"
"targetname" "exit"
"origin" "-128 64 56"
"angle" "180"
}
{
"classname" "trigger_hurt"
"model" "*1"
}
)";
    return b;
}

}  // namespace

TEST(Quake3Collision, PlayerSolidBrushesAndTriggersImportInMetresWithYUp) {
    const SourceLevel level =
        importLevel(mapWithCollision().write("collision", "collision"), withoutGame("collision"));
    const LevelCollision& c = level.collision;
    // The floor and the clip; never the water or the trigger brushes.
    ASSERT_EQ(c.brushes.size(), 2u);
    EXPECT_EQ(c.brushes[0].contents, kContentsSolid);
    EXPECT_EQ(c.brushes[1].contents, kContentsPlayerClip);
    ASSERT_EQ(c.brushes[0].sideCount, 6u);
    // The floor's top, z <= 0 in units, is y <= 0 m; its +y side (y <= 256) is z >= -8 m.
    const CollisionPlane& top = c.planes[c.sidePlanes[c.brushes[0].firstSide + 4]];
    EXPECT_EQ(top.normal, glm::vec3(0, 1, 0));
    EXPECT_EQ(top.distance, 0.0f);
    const CollisionPlane& north = c.planes[c.sidePlanes[c.brushes[0].firstSide + 2]];
    EXPECT_EQ(north.normal, glm::vec3(0, 0, -1));
    EXPECT_EQ(north.distance, 8.0f);
    ASSERT_EQ(c.triggers.size(), 3u);
    const Trigger& push = c.triggers[0];
    EXPECT_EQ(push.kind, TriggerKind::kPush);
    EXPECT_EQ(push.boundsMin, glm::vec3(2, 0, -2));
    EXPECT_EQ(push.boundsMax, glm::vec3(4, 0.5f, 0));
    EXPECT_EQ(push.target, glm::vec3(3, 8.25f, -1));
    const Trigger& teleport = c.triggers[1];
    EXPECT_EQ(teleport.kind, TriggerKind::kTeleport);
    // The destination's origin + 1 - 24 units: the feet.
    EXPECT_EQ(teleport.target, glm::vec3(-4, 33.0f / 32.0f, -2));
    EXPECT_FLOAT_EQ(teleport.targetYaw, glm::radians(90.0f));  // Quake's -x is a left turn
    EXPECT_EQ(c.triggers[2].kind, TriggerKind::kHurt);
}

TEST(Quake3Collision, BrushesWithBadIndicesAreRefusedByTheBspReader) {
    Quake3BspBuilder b = mapWithCollision();
    b.brushSides[3].plane = 999;
    EXPECT_NE(parseError(b.bytes()).find("brush side 3: plane 999 of 30"), std::string::npos)
        << parseError(b.bytes());
    b = mapWithCollision();
    b.brushes[1].sideCount = 100;
    EXPECT_NE(parseError(b.bytes()).find("brush 1: sides 6 + 100 is outside the 30 brush sides"),
              std::string::npos)
        << parseError(b.bytes());
    b = mapWithCollision();
    b.planes[2].dist = std::nanf("");
    EXPECT_NE(parseError(b.bytes()).find("plane 2 is NaN or Inf"), std::string::npos);
    b = mapWithCollision();
    b.entities += "{\n\"classname\" \"trigger_hurt\"\n\"model\" \"*7\"\n}\n";
    const std::string message = errorMessage(
        [&] { (void)importLevel(b.write("badmodel", "badmodel"), withoutGame("badmodel")); });
    EXPECT_NE(message.find("trigger_hurt has model '*7'; expected *1 .. *1"), std::string::npos)
        << message;
}

TEST(Quake3Collision, TheSectionsRoundTripThroughAPackage) {
    SourceLevel source =
        importLevel(mapWithCollision().write("roundtrip", "roundtrip"), withoutGame("roundtrip"));
    const CompiledLevel level = compileLevel(source, CompileOptions{}).level;
    const package::PackageContents read =
        package::parsePackage(package::serializePackage(level), "roundtrip.olpak");
    const LevelCollision& c = read.level.collision;
    ASSERT_EQ(c.brushes.size(), source.collision.brushes.size());
    EXPECT_EQ(c.sidePlanes, source.collision.sidePlanes);
    for (size_t p = 0; p < c.planes.size(); ++p) {
        EXPECT_EQ(c.planes[p].normal, source.collision.planes[p].normal);
        EXPECT_EQ(c.planes[p].distance, source.collision.planes[p].distance);
    }
    ASSERT_EQ(c.triggers.size(), 3u);
    EXPECT_EQ(c.triggers[1].target, source.collision.triggers[1].target);
    EXPECT_TRUE(read.bakedSections.empty()) << "decoded into the level, not kept raw";
}

// A hostile package: the strict reader refuses every bad index and non-finite number.
TEST(Quake3Collision, TheSectionReaderRefusesBadIndicesAndNonFinitePlanes) {
    LevelCollision good;
    good.planes = {{{0, 1, 0}, 0.0f}, {{1, 0, 0}, 2.0f}};
    good.sidePlanes = {0, 1};
    good.brushes = {{0, 2, kContentsSolid}};
    Trigger t;
    t.kind = TriggerKind::kTeleport;
    t.boundsMax = glm::vec3(1.0f);
    good.triggers = {t};
    const auto decodeError = [](const std::vector<package::RawSection>& s) {
        return errorMessage(
            [&] { (void)package::decodeCollisionSections(&s[0], &s[1], 0, "hostile.olpak"); });
    };
    EXPECT_EQ(decodeError(package::encodeCollisionSections(good)), "");
    const auto expectRefused = [&](const LevelCollision& bad, const std::string& expected) {
        const std::string message = decodeError(package::encodeCollisionSections(bad));
        EXPECT_NE(message.find(expected), std::string::npos) << message;
    };
    LevelCollision bad = good;
    bad.sidePlanes[1] = 2;
    expectRefused(bad, "hostile.olpak: section collision: side 1 has plane 2; expected < 2");
    bad = good;
    bad.brushes[0].sideCount = 3;
    expectRefused(bad, "brush 0 has sides 0 + 3");
    bad = good;
    bad.brushes[0].contents = 0x20;
    expectRefused(bad, "brush 0 has contents 32");
    for (const float nonFinite : {std::nanf(""), INFINITY}) {
        bad = good;
        bad.planes[1].distance = nonFinite;
        expectRefused(bad, "plane 1 is NaN or Inf");
        bad = good;
        bad.triggers[0].target.x = nonFinite;
        expectRefused(bad, "section triggers: trigger 0 is NaN or Inf");
    }
    bad = good;
    bad.planes[0].normal = glm::vec3(0, 2, 0);
    expectRefused(bad, "plane 0 has a normal of length 2");
    bad = good;
    bad.triggers[0].kind = TriggerKind(9);
    expectRefused(bad, "trigger 0 has kind 9");
    // A header whose counts overrun the section.
    std::vector<package::RawSection> s = package::encodeCollisionSections(good);
    s[0].bytes[8] = 200;  // brushCount
    EXPECT_NE(decodeError(s).find("bytes; expected"), std::string::npos) << decodeError(s);
}

namespace {

// q3map2 leaves lightmap coordinates NaN on surfaces without a lightmap page (OpenArena's
// pul1ctf and oa_ctf2 have dozens): they are never read, so the map imports and compiles. A NaN
// normal is replaced by the face's plane and said.
TEST(Quake3Bsp, NaNLightmapCoordinatesWithoutAPageCompile) {
    Quake3BspBuilder b;
    b.surfaces[0].lightmap = -3;  // vertex lit
    for (BspVertex& v : b.vertices) v.lightmap[0] = v.lightmap[1] = std::nanf("");
    b.surfaces[0].lightmapVectors[2][2] = 1.0f;
    b.vertices[3].normal[0] = std::nanf("");
    const SourceLevel level =
        importLevel(b.write("nan_lightmap", "nan_lightmap"), withoutGame("nan_lightmap"));
    ASSERT_EQ(level.instances.size(), 1u);
    for (const Vertex& v : level.instances[0].vertices)
        EXPECT_EQ(v.normal, glm::vec3(0.0f, 1.0f, 0.0f));
    for (const ImportedLightmap::Triangle& t : level.importedLightmap.triangles)
        for (const glm::vec2& uv : t.uv) EXPECT_TRUE(std::isfinite(uv.x) && std::isfinite(uv.y));
    bool said = false;
    for (const std::string& note : level.importNotes)
        said |= note.find("1 vertex normal(s) NaN or Inf") != std::string::npos;
    EXPECT_TRUE(said);
    const CompileResult compiled = compileLevel(level, CompileOptions{});
    EXPECT_GT(compiled.stats.texels, 0u);
}

// q3map2 -external: the lightmaps are maps/NAME/lm_NNNN.tga (here a loose file of the game
// folder and, for a map beside no game, a NAME/ folder beside the .bsp), read for the q3map2 view
// at their own size.
TEST(Quake3Lightmaps, ExternalLightmapsAreRead) {
    const auto game = freshFolder("external_game");
    Quake3BspBuilder b;
    b.surfaces[0].lightmap = 0;
    for (BspVertex& v : b.vertices) v.lightmap[0] = v.lightmap[1] = 0.5f;
    Quake3Options options;
    options.gameFolders = {game.string()};
    writeFile(game / "maps" / "external.bsp", b.bytes());
    writeFile(game / "maps" / "external" / "lm_0000.tga", tga(8, {10, 20, 30}));
    const SourceLevel level = importLevel("external", options);
    const ImportedLightmap& l = level.importedLightmap;
    EXPECT_EQ(l.pageSize, 8u);
    ASSERT_EQ(l.pages.size(), 8u * 8u * 3u);
    EXPECT_EQ(l.pages[0], 10);
    EXPECT_EQ(l.pages[2], 30);
    EXPECT_TRUE(l.directionPages.empty());
    ASSERT_EQ(l.triangles.size(), 2u);
    EXPECT_EQ(l.triangles[0].page, 0u);

    // A .bsp outside any game folder, its lightmaps in a folder of its name beside it.
    const auto loose = freshFolder("external_loose");
    writeFile(loose / "outside.bsp", b.bytes());
    writeFile(loose / "outside" / "lm_0000.tga", tga(4, {200, 100, 50}));
    const SourceLevel outside =
        importLevel((loose / "outside.bsp").string(), withoutGame("external_loose"));
    EXPECT_EQ(outside.importedLightmap.pageSize, 4u);
    ASSERT_EQ(outside.importedLightmap.pages.size(), 4u * 4u * 3u);
    EXPECT_EQ(outside.importedLightmap.pages[0], 200);

    // Without them, the vertex light stands in, and the import says so.
    const auto none = freshFolder("external_none");
    writeFile(none / "bare.bsp", b.bytes());
    const SourceLevel bare = importLevel((none / "bare.bsp").string(), withoutGame("none"));
    EXPECT_TRUE(bare.importedLightmap.pages.empty());
    EXPECT_EQ(bare.importedLightmap.triangles[0].page, kNoIndex);
    ASSERT_FALSE(bare.importNotes.empty());
    EXPECT_NE(bare.importNotes[0].find("no external lightmaps"), std::string::npos)
        << bare.importNotes[0];
}

// q3map2 -deluxe interleaves colour and direction pages; surfaces name the colour ones (even).
// The colour pages are kept as the map's lightmap, the direction pages apart, in a lump or in
// external images.
TEST(Quake3Lightmaps, ADeluxeMappedLumpGivesColourPagesOnly) {
    Quake3BspBuilder b;
    b.entities =
        "{\n\"classname\" \"worldspawn\"\n\"_q3map2_cmdline\" \"-meta; -light -deluxe "
        "-samples 3\"\n}\n";
    for (uint8_t p = 0; p < 4; ++p) b.lightmaps.insert(b.lightmaps.end(), kLightmapPageBytes, p);
    b.surfaces[0].lightmap = 2;
    b.surfaces.push_back(b.surfaces[0]);
    b.surfaces[1].lightmap = 0;
    const SourceLevel level = importLevel(b.write("deluxe", "deluxe"), withoutGame("deluxe"));
    const ImportedLightmap& l = level.importedLightmap;
    ASSERT_EQ(l.pages.size(), 2 * kLightmapPageBytes);
    ASSERT_EQ(l.directionPages.size(), 2 * kLightmapPageBytes);
    EXPECT_EQ(l.pages[0], 0);
    EXPECT_EQ(l.pages[kLightmapPageBytes], 2);
    EXPECT_EQ(l.directionPages[0], 1);
    EXPECT_EQ(l.directionPages[kLightmapPageBytes], 3);
    ASSERT_EQ(l.triangles.size(), 4u);
    EXPECT_EQ(l.triangles[0].page, 1u);  // lump page 2
    EXPECT_EQ(l.triangles[2].page, 0u);  // lump page 0

    // The same without the command line: an even count of pages of which only even ones are
    // used is taken as deluxe (DarkPlaces' rule); one surface on an odd page says it is not.
    Quake3BspBuilder guessed = b;
    guessed.entities = "{\n\"classname\" \"worldspawn\"\n}\n";
    EXPECT_EQ(importLevel(guessed.write("deluxe_guess", "g"), withoutGame("g"))
                  .importedLightmap.pages.size(),
              2 * kLightmapPageBytes);
    guessed.surfaces[1].lightmap = 1;
    const SourceLevel plain = importLevel(guessed.write("deluxe_not", "n"), withoutGame("n"));
    EXPECT_EQ(plain.importedLightmap.pages.size(), 4 * kLightmapPageBytes);
    EXPECT_TRUE(plain.importedLightmap.directionPages.empty());
    EXPECT_EQ(plain.importedLightmap.triangles[2].page, 1u);

    // External deluxe pages, in a pk3 of the game (Nexuiz's way).
    const auto game = freshFolder("deluxe_external");
    Quake3BspBuilder external = b;
    external.lightmaps.clear();
    std::vector<std::pair<std::string, std::string>> files = {{"maps/dx.bsp", external.text()}};
    for (uint8_t p = 0; p < 4; ++p)
        files.emplace_back("maps/dx/lm_000" + std::to_string(p) + ".tga",
                           tga(16, {uint8_t(p * 50), 0, 0}));
    writePk3(game / "data.pk3", files);
    Quake3Options options;
    options.gameFolders = {game.string()};
    const SourceLevel dx = importLevel("dx", options);
    ASSERT_EQ(dx.importedLightmap.pageSize, 16u);
    ASSERT_EQ(dx.importedLightmap.pages.size(), 2u * 16u * 16u * 3u);
    EXPECT_EQ(dx.importedLightmap.pages[16 * 16 * 3], 100);  // lm_0002
    EXPECT_EQ(dx.importedLightmap.directionPages[0], 50);    // lm_0001
}

// The game's search path: a folder's pk3s in case-insensitive alphabetical order, a later one
// winning (B.pk3 after a.pk3, though 'B' < 'a' in ASCII), and its loose files winning over both.
TEST(Quake3SearchPath, LaterPk3sWinAndLooseFilesWinOverThem) {
    const auto game = freshFolder("search_path");
    Quake3BspBuilder b;
    for (const char* name : {"textures/test/floor", "textures/test/loose"}) {
        BspShader s{};
        std::strcpy(s.name, name);
        b.shaders.push_back(s);
    }
    for (int32_t shader : {1, 2}) {
        b.surfaces.push_back(b.surfaces[0]);
        b.surfaces.back().shader = shader;
    }
    const std::string red = tga(2, {255, 0, 0}), green = tga(2, {0, 255, 0}),
                      blue = tga(2, {0, 0, 255});
    writePk3(game / "a.pk3", {{"textures/test/wall.tga", red},
                              {"textures/test/floor.tga", red},
                              {"textures/test/loose.tga", red},
                              {"maps/searched.bsp", b.text()}});
    writePk3(game / "B.pk3",
             {{"textures/test/wall.tga", green}, {"Textures/Test/LOOSE.tga", green}});
    writeFile(game / "textures" / "test" / "loose.tga", blue);
    Quake3Options options;
    options.gameFolders = {game.string()};
    const auto imageOf = [](const SourceLevel& level, const std::string& material) {
        for (const Material& m : level.materials)
            if (m.name == material && m.baseColorTexture != kNoIndex)
                return level.images[level.textures[m.baseColorTexture].image].name;
        return std::string("(none)");
    };
    for (const std::string& spec :
         {std::string("searched"), (game / "a.pk3").string() + ":maps/searched.bsp"}) {
        const SourceLevel level = importLevel(spec, options);
        EXPECT_EQ(imageOf(level, "textures/test/wall"),
                  (game / "B.pk3").string() + ":textures/test/wall.tga")
            << spec;
        EXPECT_EQ(imageOf(level, "textures/test/floor"),
                  (game / "a.pk3").string() + ":textures/test/floor.tga")
            << spec;
        EXPECT_EQ(imageOf(level, "textures/test/loose"),
                  (game / "textures" / "test" / "loose.tga").string())
            << spec;
    }
    // A plain .bsp in GAME/maps/ reads the same game (its folder, holding maps/, is the game).
    writeFile(game / "maps" / "plain.bsp", b.bytes());
    const SourceLevel plain = importLevel((game / "maps" / "plain.bsp").string(), options);
    EXPECT_EQ(imageOf(plain, "textures/test/wall"),
              (game / "B.pk3").string() + ":textures/test/wall.tga");
}

// Hostile: a truncated pk3 in the game's search path is named, on one line.
TEST(Quake3SearchPath, ATruncatedPk3InTheSearchPathIsNamed) {
    const auto game = freshFolder("truncated_pk3");
    writePk3(game / "pak0.pk3", {{"maps/x.bsp", Quake3BspBuilder().text()}});
    const auto size = std::filesystem::file_size(game / "pak0.pk3");
    std::filesystem::resize_file(game / "pak0.pk3", size / 2);
    Quake3Options options;
    options.gameFolders = {game.string()};
    const std::string e = errorMessage([&] { (void)importLevel("x", options); });
    EXPECT_NE(e.find((game / "pak0.pk3").string() + ": not a readable pk3 (zip) archive"),
              std::string::npos)
        << e;
    EXPECT_EQ(e.find('\n'), std::string::npos) << e;
}

// A closed room (16 x 8 m, 4 m high, each wall a surface facing in) with no spawn: the import
// computes a view inside it, eyes above the floor, looking along the long axis, and says so.
TEST(Quake3Spawns, AMapWithoutASpawnGetsAViewInsideItsBounds) {
    Quake3BspBuilder b;
    b.vertices.clear();
    b.indices = {0, 1, 2, 0, 2, 3};
    b.surfaces.clear();
    const float x0 = 0, x1 = 512, y0 = 0, y1 = 256, z0 = 0, z1 = 128;
    const auto face = [&](glm::vec3 a, glm::vec3 c1, glm::vec3 c2, glm::vec3 c3, glm::vec3 in) {
        BspSurface f{};
        f.type = kSurfacePlanar;
        f.firstVertex = int32_t(b.vertices.size());
        f.vertexCount = 4;
        f.indexCount = 6;
        f.lightmap = -1;
        for (const glm::vec3& p : {a, c1, c2, c3}) {
            BspVertex v{};
            for (int k = 0; k < 3; ++k) {
                v.position[k] = p[k];
                v.normal[k] = in[k];
            }
            b.vertices.push_back(v);
        }
        b.surfaces.push_back(f);
    };
    face({x0, y0, z0}, {x1, y0, z0}, {x1, y1, z0}, {x0, y1, z0}, {0, 0, 1});   // floor
    face({x0, y0, z1}, {x1, y0, z1}, {x1, y1, z1}, {x0, y1, z1}, {0, 0, -1});  // ceiling
    face({x0, y0, z0}, {x1, y0, z0}, {x1, y0, z1}, {x0, y0, z1}, {0, 1, 0});
    face({x0, y1, z0}, {x1, y1, z0}, {x1, y1, z1}, {x0, y1, z1}, {0, -1, 0});
    face({x0, y0, z0}, {x0, y1, z0}, {x0, y1, z1}, {x0, y0, z1}, {1, 0, 0});
    face({x1, y0, z0}, {x1, y1, z0}, {x1, y1, z1}, {x1, y0, z1}, {-1, 0, 0});
    const SourceLevel level = importLevel(b.write("no_spawn", "no_spawn"), withoutGame("ns"));
    ASSERT_EQ(level.cameras.size(), 1u);
    ASSERT_EQ(level.entities.size(), 1u);
    EXPECT_TRUE(level.entities[0].flags & kEntitySpawn);
    const glm::vec3 eye = level.cameras[0].position;
    // The room is x 0 .. 16, y 0 .. 4, z -8 .. 0 m.
    EXPECT_GT(eye.x, 0.0f);
    EXPECT_LT(eye.x, 16.0f);
    EXPECT_LT(eye.z, 0.0f);
    EXPECT_GT(eye.z, -8.0f);
    EXPECT_NEAR(eye.y, kComputedViewEyeHeight, 0.02f);
    EXPECT_NEAR(level.entities[0].position.y, 0.0f, 0.02f);
    const glm::vec3 forward = level.cameras[0].rotation * glm::vec3(0.0f, 0.0f, -1.0f);
    EXPECT_NEAR(std::abs(forward.x), 1.0f, 1e-5f);  // along the 16 m side
    EXPECT_TRUE(insideLevel(level, eye));
    EXPECT_FALSE(insideLevel(level, glm::vec3(8.0f, 2.0f, 3.0f)));  // outside the walls
    bool said = false;
    for (const std::string& note : level.importNotes)
        said |= note.find("no player spawn: a view computed from the level's bounds") !=
                std::string::npos;
    EXPECT_TRUE(said);
}

}  // namespace
}  // namespace onelight::world::q3

namespace onelight::world::q3 {
namespace {

// Installed maps beyond the four the bake tests use: OpenArena's oa_ctf2 has NaN lightmap
// coordinates on vertex-lit surfaces; Nexuiz's bluesky keeps its textures in another pk3 and its
// deluxe lightmaps in maps/bluesky/lm_000[0-3].tga (512 x 512).
TEST(Quake3Maps, InstalledMapsWithUnsetFieldsAndExternalLightmapsImport) {
    if (defaultQuake3Folders().empty())
        GTEST_SKIP() << "OpenArena is not installed (openarena-081-maps)";
    const SourceLevel ctf = importLevel("oa_ctf2");
    EXPECT_FALSE(ctf.instances.empty());
    if (!std::filesystem::exists("/usr/share/games/nexuiz/data/data.pk3"))
        GTEST_SKIP() << "Nexuiz is not installed (nexuiz-data)";
    const SourceLevel level = importLevel("bluesky");
    EXPECT_NE(level.sourcePath.find("nexuiz/data/data.pk3:maps/bluesky.bsp"), std::string::npos)
        << level.sourcePath;
    size_t textured = 0;
    for (const Material& m : level.materials) textured += m.baseColorTexture != kNoIndex;
    std::printf("[ bluesky ] %zu materials (%zu textured), %zu spawns\n", level.materials.size(),
                textured, level.cameras.size());
    EXPECT_GE(textured * 10, level.materials.size() * 9);
    const ImportedLightmap& l = level.importedLightmap;
    EXPECT_EQ(l.pageSize, 512u);
    EXPECT_EQ(l.pages.size(), 2u * 512u * 512u * 3u);
    EXPECT_EQ(l.directionPages.size(), l.pages.size());
    size_t paged = 0;
    for (const ImportedLightmap::Triangle& t : l.triangles) paged += t.page != kNoIndex;
    EXPECT_GT(paged * 10, l.triangles.size() * 9);
}

// The world's BSP tree and its potentially visible set: a node's children must lie later in the
// lump or be leaves (so that a walk down the tree ends), a leaf's cluster inside the visibility
// lump's, whose rows must fit it.
TEST(Quake3Bsp, TheTreeAndThePotentiallyVisibleSetAreChecked) {
    const auto withTree = [] {
        Quake3BspBuilder b = mapWithCollision();
        b.nodes = {{0, {1, -1}, {0, 0, 0}, {0, 0, 0}}, {1, {-2, -3}, {0, 0, 0}, {0, 0, 0}}};
        b.leafs.assign(3, BspLeaf{});
        b.leafs[0].cluster = -1;
        b.leafs[1].cluster = 0;
        b.leafs[2].cluster = 1;
        const BspVisibilityHeader h{2, 1};
        b.visibility.resize(sizeof h);
        std::memcpy(b.visibility.data(), &h, sizeof h);
        b.visibility.insert(b.visibility.end(), {0x3, 0x3});
        return b;
    };
    const BspFile good = parseBsp(withTree().bytes(), "test.bsp");
    EXPECT_EQ(good.nodes.size(), 2u);
    EXPECT_EQ(good.leafs.size(), 3u);
    EXPECT_EQ(good.clusterCount, 2);
    EXPECT_EQ(good.visibility, (std::vector<uint8_t>{0x3, 0x3}));
    Quake3BspBuilder b = withTree();
    b.nodes[1].children[0] = 0;  // back to the root: a walk would never end
    EXPECT_EQ(parseError(b.bytes()),
              "test.bsp: node 1: child 0; expected a node after it (of 2) or a leaf -(l + 1) of 3");
    b = withTree();
    b.nodes[0].children[1] = -4;
    EXPECT_EQ(
        parseError(b.bytes()),
        "test.bsp: node 0: child -4; expected a node after it (of 2) or a leaf -(l + 1) of 3");
    b = withTree();
    b.nodes[0].plane = 999;
    EXPECT_EQ(parseError(b.bytes()),
              "test.bsp: node 0: plane 999 of 30; expected an index into the planes");
    b = withTree();
    b.leafs[2].cluster = 5;
    EXPECT_EQ(parseError(b.bytes()),
              "test.bsp: leaf 2: cluster 5 of 2; expected -1 (solid) or a cluster of the "
              "visibility lump");
    b = withTree();
    const BspVisibilityHeader tooMany{4, 1};
    std::memcpy(b.visibility.data(), &tooMany, sizeof tooMany);
    EXPECT_EQ(parseError(b.bytes()),
              "test.bsp: lump 16 (visibility): 4 clusters of 1 bytes in 2 bytes; expected rows "
              "of at least one bit a cluster inside the lump");
}

// Every installed map's tree and potentially visible set read, and every cluster sees itself.
TEST(Quake3Maps, EveryInstalledMapsTreeAndVisibilityRead) {
    std::vector<std::string> folders = defaultQuake3Folders();
    if (std::filesystem::exists("/usr/share/games/nexuiz/data"))
        folders.push_back("/usr/share/games/nexuiz/data");
    if (folders.empty()) GTEST_SKIP() << "OpenArena is not installed (openarena-data)";
    size_t maps = 0, withVisibility = 0, leafs = 0;
    for (const std::string& folder : folders) {
        GameFiles files;
        files.addGameFolder(folder);
        for (const auto& [key, file] : files.files) {
            if (key.rfind("maps/", 0) != 0 || key.size() < 9 ||
                key.compare(key.size() - 4, 4, ".bsp") != 0)
                continue;
            const std::vector<uint8_t> bytes = *files.read(key, kMaxMapBytes, "a map");
            if (bytes.size() < 8 || std::memcmp(bytes.data(), "IBSP\x2e\0\0\0", 8) != 0) continue;
            const BspFile bsp = parseBsp(bytes, files.where(key));
            ++maps;
            leafs += bsp.leafs.size();
            if (bsp.clusterCount == 0) continue;
            ++withVisibility;
            for (int32_t c = 0; c < bsp.clusterCount; ++c)
                EXPECT_TRUE(
                    (bsp.visibility[size_t(c) * size_t(bsp.bytesPerCluster) + size_t(c) / 8] >>
                     (c % 8)) &
                    1)
                    << files.where(key) << " cluster " << c;
        }
    }
    std::printf("[ bsp trees ] %zu maps, %zu with a potentially visible set, %zu leafs\n", maps,
                withVisibility, leafs);
    EXPECT_GT(maps, 50u);
    EXPECT_GT(withVisibility * 10, maps * 9);
}

// The map's own visible set in the level's space: a tree of one node whose plane is the map's
// y = 0 (the level's z = 0, facing -z), a leaf in front (cluster 0) and one behind (cluster 1)
// that cannot see each other.
TEST(Quake3Visibility, TheMapsOwnSetImportsInMetresWithYUp) {
    Quake3BspBuilder b = mapWithCollision();
    b.planes.push_back({{0.0f, 1.0f, 0.0f}, 0.0f});
    b.nodes = {{int32_t(b.planes.size() - 1), {-1, -2}, {0, 0, 0}, {0, 0, 0}}};
    b.leafs.assign(2, BspLeaf{});
    b.leafs[0] = {0, 0, {-256, 0, -16}, {256, 256, 128}, 0, 0, 0, 0};
    b.leafs[1] = {1, 0, {-256, -256, -16}, {256, 0, 128}, 0, 0, 0, 0};
    const BspVisibilityHeader h{2, 1};
    b.visibility.resize(sizeof h);
    std::memcpy(b.visibility.data(), &h, sizeof h);
    b.visibility.insert(b.visibility.end(), {0x1, 0x2});
    const SourceLevel level =
        importLevel(b.write("visibility", "visibility"), withoutGame("visibility"));
    const ImportedVisibility& v = level.importedVisibility;
    ASSERT_FALSE(v.empty());
    EXPECT_EQ(v.nodes[0].plane.normal, glm::vec3(0.0f, 0.0f, -1.0f));
    // Map y = +32 units is the level's z = -1 m: in front of the plane.
    EXPECT_EQ(importedLeafAt(v, {0.0f, 0.0f, -1.0f}), 0u);
    EXPECT_EQ(importedLeafAt(v, {0.0f, 0.0f, 1.0f}), 1u);
    EXPECT_EQ(v.leafs[0].boundsMin, glm::vec3(-8.0f, -0.5f, -8.0f));
    EXPECT_EQ(v.leafs[0].boundsMax, glm::vec3(8.0f, 4.0f, 0.0f));
    std::vector<uint32_t> leaves;
    importedLeavesIn(v, {-1.0f, 0.0f, -1.0f}, {1.0f, 1.0f, 1.0f}, leaves);
    EXPECT_EQ(leaves, (std::vector<uint32_t>{0, 1}));
    leaves.clear();
    importedLeavesIn(v, {-1.0f, 0.0f, 0.5f}, {1.0f, 1.0f, 1.0f}, leaves);
    EXPECT_EQ(leaves, (std::vector<uint32_t>{1}));
    EXPECT_TRUE(importedClusterSees(v, 0, 0));
    EXPECT_FALSE(importedClusterSees(v, 0, 1));
    EXPECT_TRUE(importedClusterSees(v, 1, 1));
}

// A real map's: every spawn stands in a leaf of a cluster (open space), which sees itself.
TEST(Quake3Visibility, EverySpawnOfARealMapStandsInAClusterOfItsSet) {
    if (defaultQuake3Folders().empty())
        GTEST_SKIP() << "OpenArena is not installed (openarena-data, openarena-081-maps)";
    for (const char* name : {"q3dm6ish", "kaos", "aggressor", "oa_bases3"}) {
        const SourceLevel level = importLevel(name);
        const ImportedVisibility& v = level.importedVisibility;
        ASSERT_FALSE(v.empty()) << name;
        size_t spawns = 0;
        for (const Camera& c : level.cameras) {
            const ImportedVisibility::Leaf& leaf = v.leafs[importedLeafAt(v, c.position)];
            EXPECT_GE(leaf.cluster, 0) << name << " " << c.name;
            if (leaf.cluster >= 0) {
                EXPECT_TRUE(importedClusterSees(v, uint32_t(leaf.cluster), uint32_t(leaf.cluster)));
                EXPECT_TRUE(glm::all(glm::greaterThanEqual(c.position, leaf.boundsMin - 0.05f)) &&
                            glm::all(glm::lessThanEqual(c.position, leaf.boundsMax + 0.05f)))
                    << name << " " << c.name;
            }
            ++spawns;
        }
        std::printf("[ %s ] %zu clusters, %zu leafs; %zu spawns, each in a cluster's leaf\n", name,
                    size_t(v.clusterCount), v.leafs.size(), spawns);
        EXPECT_GT(spawns, 0u);
    }
}

}  // namespace
}  // namespace onelight::world::q3
