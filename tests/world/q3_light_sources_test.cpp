// Where a Quake 3 map's light comes from when q3map2 has stripped its light entities: the map's
// source .map (beside the BSP or in its pk3), else q3map2's own lightmaps; a map with no light
// at all is marked for the bake to refuse; the .map parser against hostile text; the colour of a
// surface light (q3map2's display-referred light-image mean); the light scales and lightmap
// encoding of q3map2's recorded command line.
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <filesystem>
#include <string>
#include <tuple>
#include <utility>
#include <vector>

#include "tests/support/error_message.hpp"
#include "tests/world/q3_test_maps.hpp"
#include "tests/world/world_test_support.hpp"
#include "world/error.hpp"
#include "world/import/level_import.hpp"
#include "world/import/q3/bsp_file.hpp"
#include "world/import/q3/map_source.hpp"
#include "world/import/q3/q3map2_command_line.hpp"

namespace onelight::world::q3 {
namespace {

using onelight::test::errorMessage;
using onelight::test::floorSquare;
using onelight::test::freshFolder;
using onelight::test::Quake3BspBuilder;
using onelight::test::quake3GameIn;
using onelight::test::tgaImage;
using onelight::test::writeFile;
using onelight::test::writePk3;

// A source .map as Radiant writes it: worldspawn with an old-format brush, a brushDef and a
// patchDef2 (braces, comments and parentheses the parser must skip), a point light, a coloured
// spot aimed at an info_null, and a linear light.
const char* kSourceMap = R"(// entity 0
{
"classname" "worldspawn"
"message" "http://example.org/ { not a brace }"
// brush 0
{
( 0 0 0 ) ( 256 0 0 ) ( 0 256 0 ) test/floor 0 0 0 0.5 0.5 0 0 0
( 0 0 -16 ) ( 0 256 -16 ) ( 256 0 -16 ) test/floor 0 0 0 0.5 0.5 0 0 0
}
// brush 1
{
brushDef
{
( 0 0 1 0 ) ( ( 0.03125 0 0 ) ( 0 0.03125 0 ) ) test/floor 0 0 0
}
}
// brush 2
{
patchDef2
{
test/floor
( 3 3 0 0 0 )
(
( ( 0 0 0 0 0 ) ( 0 64 0 0 1 ) ( 0 128 0 0 2 ) )
( ( 64 0 0 1 0 ) ( 64 64 0 1 1 ) ( 64 128 0 1 2 ) )
( ( 128 0 0 2 0 ) ( 128 64 0 2 1 ) ( 128 128 0 2 2 ) )
)
}
}
}
// entity 1
{
"classname" "light"
"origin" "32 64 128"
"light" "300"
}
// entity 2
{
"classname" "light"
"origin" "128 128 256"
"light" "600"
"target" "spot1"
"_color" "1 0.5 0"
}
{
"classname" "info_null"
"targetname" "spot1"
"origin" "128 128 0"
}
{
"classname" "light"
"origin" "64 64 64"
"light" "200"
"spawnflags" "1"
}
)";

bool mentions(const std::vector<std::string>& lines, const std::string& text) {
    for (const std::string& line : lines)
        if (line.find(text) != std::string::npos) return true;
    return false;
}

void expectTheSourceLights(const SourceLevel& level) {
    ASSERT_EQ(level.lights.size(), 3u);
    // As the BSP path gives them: (32, 64, 128) units is (1, 4, -2) m, 7.32 cd per "light".
    const Light& point = level.lights[0];
    EXPECT_EQ(point.type, LightType::kPoint);
    EXPECT_EQ(point.position, glm::vec3(1.0f, 4.0f, -2.0f));
    EXPECT_NEAR(point.intensity, 300.0 * 7500.0 / 1024.0, 1e-3);
    const Light& spot = level.lights[1];
    EXPECT_EQ(spot.type, LightType::kSpot);
    EXPECT_NEAR(std::tan(spot.outerCone), 80.0 / 256.0, 1e-6);
    EXPECT_NEAR(spot.direction.y, -1.0f, 1e-6f);
    EXPECT_EQ(spot.color, glm::vec3(1.0f, 0.5f, 0.0f));
    EXPECT_GT(level.lights[2].range, 0.0f);  // linear: a range
    EXPECT_FALSE(level.lightmapIsImported);
    EXPECT_TRUE(level.lightless.empty());
}

TEST(Quake3LightSources, ASourceMapBesideTheBspGivesItsLights) {
    const auto folder = freshFolder("beside");
    Quake3BspBuilder bsp = floorSquare(40);
    writeFile(folder / "room.bsp", bsp.text());
    writeFile(folder / "room.map", kSourceMap);
    const SourceLevel level =
        importLevel((folder / "room.bsp").string(), quake3GameIn(freshFolder("beside_game")));
    expectTheSourceLights(level);
    EXPECT_TRUE(mentions(level.lightSources, "light entities: 3 from the source .map "))
        << level.lightSources[0];
    EXPECT_TRUE(mentions(level.lightSources, "room.map")) << level.lightSources[0];
    EXPECT_TRUE(mentions(level.lightSources, "surface lights: none"));
}

TEST(Quake3LightSources, ASourceMapInThePk3GivesItsLights) {
    const auto folder = freshFolder("pk3");
    Quake3BspBuilder bsp = floorSquare(0);
    writePk3(folder / "room.pk3",
             {{"maps/room.bsp", bsp.text()}, {"sources/maps/room.map", kSourceMap}});
    const SourceLevel level = importLevel((folder / "room.pk3").string() + ":maps/room.bsp",
                                          quake3GameIn(freshFolder("pk3_game")));
    expectTheSourceLights(level);
    EXPECT_TRUE(mentions(level.lightSources, "room.pk3:sources/maps/room.map"))
        << level.lightSources[0];
}

// The BSP's own light entities win over a source (they are what q3map2 lit with).
TEST(Quake3LightSources, TheBspsOwnLightsWin) {
    const auto folder = freshFolder("own");
    Quake3BspBuilder bsp = floorSquare(0);
    bsp.entities += "{\n\"classname\" \"light\"\n\"origin\" \"0 0 64\"\n}\n";
    writeFile(folder / "room.bsp", bsp.text());
    writeFile(folder / "room.map", kSourceMap);
    const SourceLevel level =
        importLevel((folder / "room.bsp").string(), quake3GameIn(freshFolder("own_game")));
    ASSERT_EQ(level.lights.size(), 1u);
    EXPECT_TRUE(mentions(level.lightSources, "light entities: 1 from the BSP's entities"));
}

// The lights q3map2 bakes, read as its CreateEntityLights reads them: "_light" before "light",
// 300 where neither gives a non-zero value; a source .map's named (switched) light and a
// "noradiosity" 1 light left out, each kind with a note; a named light in the BSP kept.
TEST(Quake3LightSources, LightsAreTakenAndLeftOutAsQ3map2Does) {
    const auto folder = freshFolder("q3map2_keys");
    Quake3BspBuilder bsp = floorSquare(0);
    writeFile(folder / "room.bsp", bsp.text());
    writeFile(folder / "room.map",
              std::string(kSourceMap) +
                  "{\n\"classname\" \"light\"\n\"origin\" \"0 0 64\"\n\"_light\" \"100\"\n"
                  "\"light\" \"400\"\n}\n"
                  "{\n\"classname\" \"light\"\n\"origin\" \"0 0 96\"\n\"light\" \"0\"\n}\n"
                  "{\n\"classname\" \"light\"\n\"origin\" \"0 0 32\"\n\"light\" \"500\"\n"
                  "\"targetname\" \"switch1\"\n}\n"
                  "{\n\"classname\" \"light\"\n\"origin\" \"0 0 48\"\n\"light\" \"500\"\n"
                  "\"noradiosity\" \"1\"\n}\n"
                  // Any class named "light..." is a light to q3map2: a light_spot with no target
                  // is a point light; lightJunior lights only the grid.
                  "{\n\"classname\" \"light_spot\"\n\"origin\" \"0 0 80\"\n\"light\" \"150\"\n"
                  "\"_cone\" \"30\"\n\"pitch\" \"-90\"\n}\n"
                  "{\n\"classname\" \"Light\"\n\"origin\" \"0 0 88\"\n\"light\" \"50\"\n}\n"
                  "{\n\"classname\" \"lightJunior\"\n\"origin\" \"0 0 72\"\n\"light\" \"500\"\n}\n"
                  "{\n\"classname\" \"misc_lighthouse\"\n\"origin\" \"0 0 72\"\n\"light\" "
                  "\"500\"\n}\n");
    const SourceLevel level =
        importLevel((folder / "room.bsp").string(), quake3GameIn(freshFolder("keys_game")));
    ASSERT_EQ(level.lights.size(), 7u);
    EXPECT_NEAR(level.lights[3].intensity, 100.0 * 7500.0 / 1024.0, 1e-3);  // "_light" first
    EXPECT_NEAR(level.lights[4].intensity, 300.0 * 7500.0 / 1024.0, 1e-3);  // 0: q3map2's 300
    EXPECT_EQ(level.lights[5].type, LightType::kPoint);  // light_spot without a target
    EXPECT_NEAR(level.lights[5].intensity, 150.0 * 7500.0 / 1024.0, 1e-3);
    EXPECT_NEAR(level.lights[6].intensity, 50.0 * 7500.0 / 1024.0, 1e-3);  // the class's case
    EXPECT_TRUE(mentions(level.importNotes, "1 lightJunior light(s) left out"));
    EXPECT_TRUE(mentions(level.importNotes, "1 light(s) with a targetname left out"));
    EXPECT_TRUE(mentions(level.importNotes, "1 light(s) with \"noradiosity\" 1 left out"));

    // In the BSP (q3map2's -light reads its entities), a named light is baked.
    const auto inBsp = freshFolder("q3map2_named_bsp");
    Quake3BspBuilder named = floorSquare(0);
    named.entities +=
        "{\n\"classname\" \"light\"\n\"origin\" \"0 0 64\"\n\"targetname\" "
        "\"switch1\"\n}\n";
    writeFile(inBsp / "room.bsp", named.text());
    const SourceLevel kept =
        importLevel((inBsp / "room.bsp").string(), quake3GameIn(freshFolder("named_game")));
    ASSERT_EQ(kept.lights.size(), 1u);
    EXPECT_NEAR(kept.lights[0].intensity, 300.0 * 7500.0 / 1024.0, 1e-3);
}

TEST(Quake3LightSources, WithoutASourceQ3map2sLightmapsAreTheLevels) {
    const auto folder = freshFolder("recovered");
    Quake3BspBuilder bsp = floorSquare(40);
    writePk3(folder / "room.pk3", {{"maps/room.bsp", bsp.text()}});
    const SourceLevel level = importLevel((folder / "room.pk3").string() + ":maps/room.bsp",
                                          quake3GameIn(freshFolder("recovered_game")));
    EXPECT_TRUE(level.lights.empty());
    EXPECT_TRUE(level.lightmapIsImported);
    EXPECT_TRUE(level.lightless.empty());
    EXPECT_TRUE(mentions(level.lightSources, "light entities: none"));
    EXPECT_TRUE(mentions(level.lightSources, "lightmaps: recovered from q3map2's own"));
}

// No lights, no source, no sun, sky or surface lights and no lightmaps: the import still reads
// the geometry, but the level is marked lightless with a message naming the map, which the bake
// refuses with (bake_level.cpp startReport) instead of baking black.
TEST(Quake3LightSources, AMapWithNoLightIsNotBakedBlackInSilence) {
    const auto folder = freshFolder("dark");
    writeFile(folder / "dark.bsp", floorSquare(0).text());
    const SourceLevel level =
        importLevel((folder / "dark.bsp").string(), quake3GameIn(freshFolder("dark_game")));
    EXPECT_FALSE(level.lightmapIsImported);
    EXPECT_NE(level.lightless.find("dark.bsp: no light source"), std::string::npos)
        << level.lightless;
    EXPECT_NE(level.lightless.find("a bake would be black"), std::string::npos);
    EXPECT_TRUE(mentions(level.lightSources, "no light at all"));
}

// A placeholder map with nothing to draw (Nexuiz's _init: one caulk brush for a dedicated
// server) has no light either, but nothing is lost by baking it: it is not lightless.
TEST(Quake3LightSources, AMapWithNothingToDrawIsNotRefusedForItsDark) {
    const auto folder = freshFolder("placeholder");
    writeFile(folder / "init.bsp", Quake3BspBuilder(8.0f, "common/caulk").text());
    const SourceLevel level =
        importLevel((folder / "init.bsp").string(), quake3GameIn(freshFolder("placeholder_game")));
    EXPECT_TRUE(level.instances.empty());
    EXPECT_TRUE(level.lightless.empty()) << level.lightless;
    EXPECT_TRUE(mentions(level.lightSources, "nothing drawn")) << level.lightSources.back();
}

TEST(Quake3MapSource, HostileTextGivesOneLineNamingTheLine) {
    const auto parse = [](const std::string& text) {
        return errorMessage([&] { (void)parseMapSource(text, "bad.map"); });
    };
    EXPECT_EQ(parse("{\n\"classname\" \"light\"\n"),
              "bad.map: line 1: an entity opened here is never closed with '}'");
    EXPECT_EQ(parse("{\n{\n( 0 0 0 ) ( 1 0 0 ) ( 0 1 0 ) x 0 0 0 1 1 0 0 0\n"),
              "bad.map: line 2: a brush or patch opened here is never closed with '}'");
    EXPECT_EQ(parse("{\n\"classname\" \"light\n}\n"), "bad.map: line 2: a quote is never closed");
    EXPECT_EQ(parse("{\n\"classname\"\n}\n"),
              "bad.map: line 2: key \"classname\" has no quoted value");
    EXPECT_EQ(parse("}\n"), "bad.map: line 1: expected '{' to open an entity");
    EXPECT_EQ(parse("{\nclassname light\n}\n"),
              "bad.map: line 2: expected a quoted key, a brush or '}'");
    const std::string deep = "{\n" + std::string(100000, '{');
    EXPECT_NE(parse(deep).find("bad.map: line 2: blocks nested deeper than"), std::string::npos);
    // Comments and empty text are fine.
    EXPECT_TRUE(parseMapSource("// nothing\n", "empty.map").empty());
}

// A source whose values are not finite (huge or NaN) or that does not parse is ignored with one
// warning naming it; the map still imports, on q3map2's lightmaps. A light far outside the map
// is left out with a note.
TEST(Quake3MapSource, HostileSourcesAreIgnoredWithAWarning) {
    for (const std::string& source :
         {std::string("{\n\"classname\" \"light\"\n\"origin\" \"1e999 0 0\"\n}\n"),
          std::string("{\n\"classname\" \"light\"\n\"origin\" \"0 0 64\"\n\"light\" \"nan\"\n}\n"),
          std::string("{\n\"classname\" \"light\"\n\"origin\" \"0 0 64\"\n")}) {
        const auto folder = freshFolder("hostile");
        Quake3BspBuilder bsp = floorSquare(40);
        writeFile(folder / "room.bsp", bsp.text());
        writeFile(folder / "room.map", source);
        const SourceLevel level =
            importLevel((folder / "room.bsp").string(), quake3GameIn(freshFolder("hostile_game")));
        EXPECT_TRUE(level.lights.empty());
        EXPECT_TRUE(level.lightmapIsImported);
        // One note names the source (the others say the map has no spawn, a view computed).
        std::vector<std::string> aboutSource;
        for (const std::string& note : level.importNotes)
            if (note.find("room.map") != std::string::npos) aboutSource.push_back(note);
        ASSERT_EQ(aboutSource.size(), 1u) << ::testing::PrintToString(level.importNotes);
        EXPECT_NE(aboutSource[0].find("room.map: "), std::string::npos) << aboutSource[0];
        EXPECT_NE(aboutSource[0].find("the map's source is ignored"), std::string::npos)
            << aboutSource[0];
    }
    const auto folder = freshFolder("far");
    Quake3BspBuilder bsp = floorSquare(0);
    writeFile(folder / "room.bsp", bsp.text());
    writeFile(folder / "room.map",
              "{\n\"classname\" \"light\"\n\"origin\" \"1e30 0 0\"\n}\n"
              "{\n\"classname\" \"light\"\n\"origin\" \"0 0 64\"\n}\n");
    const SourceLevel level =
        importLevel((folder / "room.bsp").string(), quake3GameIn(freshFolder("far_game")));
    ASSERT_EQ(level.lights.size(), 1u);
    // Exactly one note about the far light (another says the view was computed: no spawn).
    size_t farNotes = 0;
    for (const std::string& note : level.importNotes)
        farNotes +=
            note.find("1 light(s) far outside the map's geometry left out") != std::string::npos;
    EXPECT_EQ(farNotes, 1u) << ::testing::PrintToString(level.importNotes);
}

// q3map2 lights a surface light with its light image's mean bytes (display-referred, not
// linearised) scaled to a brightest channel of 1; the engine's emission, the factor times the
// sRGB-decoded texture, averages to 0.25 S times that colour.
TEST(Quake3LightSources, ASurfaceLightHasQ3map2sColour) {
    const auto game = freshFolder("lamp_game");
    const std::vector<glm::u8vec3> pixels = {{255, 200, 120}, {235, 220, 140}};
    writePk3(game / "lamp.pk3",
             {{"scripts/lamp.shader",
               "textures/test/lamp\n{\n q3map_surfacelight 1000\n q3map_lightimage "
               "textures/test/lamp.tga\n {\n  map textures/test/lamp.tga\n }\n}\n"},
              {"textures/test/lamp.tga", tgaImage(2, pixels)}});
    const auto folder = freshFolder("lamp");
    Quake3BspBuilder bsp = floorSquare(0);
    std::strcpy(bsp.shaders[0].name, "textures/test/lamp");
    writeFile(folder / "lamp.bsp", bsp.text());
    const SourceLevel level = importLevel((folder / "lamp.bsp").string(), quake3GameIn(game));
    ASSERT_EQ(level.materials.size(), 1u);
    const glm::vec3 bytes = glm::vec3(245.0f, 210.0f, 130.0f) / 255.0f;  // the mean bytes
    const glm::vec3 q3map2Colour = bytes / bytes.x;
    const auto decode = [](float v) {
        return v <= 0.04045f ? v / 12.92f : std::pow((v + 0.055f) / 1.055f, 2.4f);
    };
    for (int c = 0; c < 3; ++c) {
        const float meanLinear =
            0.5f * (decode(float(pixels[0][c]) / 255.0f) + decode(float(pixels[1][c]) / 255.0f));
        EXPECT_NEAR(level.materials[0].emissive[c] * meanLinear, 250.0f * q3map2Colour[c], 0.05f)
            << "channel " << c;
    }
    EXPECT_TRUE(mentions(level.lightSources, "surface lights: 1 shader(s), 2 triangles"));
}

// q3map2 traces no translucent surface (surfaceparm trans, water and the other parms its game
// table marks translucent) unless it is alphashadow or lightfilter: such a material casts no
// shadow, from its script or, without one, from the contents q3map2 compiled into the BSP.
TEST(Quake3LightSources, TranslucentSurfacesCastNoShadowAsInQ3map2) {
    const auto game = freshFolder("trans_game");
    const auto shader = [](const std::string& name, const std::string& parms) {
        return "textures/test/" + name + "\n{\n" + parms +
               " {\n  map textures/test/glow.tga\n  blendFunc add\n }\n}\n";
    };
    writePk3(game / "trans.pk3",
             {{"scripts/trans.shader",
               shader("glow", " surfaceparm trans\n") + shader("pool", " surfaceparm water\n") +
                   shader("grate", " surfaceparm trans\n surfaceparm alphashadow\n") +
                   shader("tinted", " surfaceparm trans\n surfaceparm lightfilter\n") +
                   shader("plain", " surfaceparm nomarks\n")},
              {"textures/test/glow.tga", tgaImage(1, {{200, 200, 200}})}});
    const std::vector<std::pair<std::string, bool>> cases = {
        {"glow", false}, {"pool", false}, {"grate", true}, {"tinted", true}, {"plain", true}};
    for (const auto& [name, casts] : cases) {
        const auto folder = freshFolder("trans_" + name);
        Quake3BspBuilder bsp = floorSquare(0);
        std::strcpy(bsp.shaders[0].name, ("textures/test/" + name).c_str());
        writeFile(folder / "room.bsp", bsp.text());
        const SourceLevel level = importLevel((folder / "room.bsp").string(), quake3GameIn(game));
        ASSERT_EQ(level.materials.size(), 1u) << name;
        EXPECT_EQ(level.materials[0].castsShadows, casts) << name;
        EXPECT_EQ(mentions(level.lightSources,
                           "translucent: 1 shader(s), 2 triangles, cast no "
                           "shadow"),
                  !casts)
            << name;
    }
    // No script: the BSP's contents (CONTENTS_TRANSLUCENT, a liquid), and SURF_ALPHASHADOW.
    const std::vector<std::tuple<int32_t, int32_t, bool>> flags = {
        {0x20000000, 0, false}, {0x20, 0, false}, {0x20000000, 0x10000, true}, {0x1, 0, true}};
    for (const auto& [contents, surface, casts] : flags) {
        const auto folder = freshFolder("trans_flags");
        Quake3BspBuilder bsp = floorSquare(0);
        bsp.shaders[0].contentFlags = contents;
        bsp.shaders[0].surfaceFlags = surface;
        writeFile(folder / "room.bsp", bsp.text());
        const SourceLevel level =
            importLevel((folder / "room.bsp").string(), quake3GameIn(freshFolder("flags_game")));
        ASSERT_EQ(level.materials.size(), 1u);
        EXPECT_EQ(level.materials[0].castsShadows, casts) << contents << " " << surface;
    }
}

// q3map_skylight V n is q3map2's dome of suns (light.c CreateSkyLights): each of its suns
// gives V / (number of suns) lux at normal incidence, so an open floor gets V times the mean
// sine of their elevations. The import's uniform sky gives the floor as much (pi L), in the light
// image's normalised mean colour; below 2 iterations q3map2 makes no sky light, nor the import.
TEST(Quake3LightSources, ASkyLightGivesAnOpenFloorWhatQ3map2sSunsGiveIt) {
    // The dome, sun by sun, as q3map2 steps through it.
    const auto floorLux = [](double value, int n) {
        const int rings = n - 1, perRing = 4 * rings;
        const double pi = 3.14159265358979323846;
        double sum = 1.0, elevation = 0.5 * (0.5 * pi / n);  // the zenith's sun, then the rings
        int suns = 1;
        for (int i = 0; i < rings; ++i, elevation += 0.5 * pi / n)
            for (int j = 0; j < perRing; ++j, ++suns) sum += std::max(0.0, std::sin(elevation));
        return value * sum / suns;
    };
    const auto game = freshFolder("skylight_game");
    writePk3(game / "sky.pk3",
             {{"scripts/sky.shader",
               "textures/test/sky2\n{\n surfaceparm sky\n q3map_skylight 100 2\n"
               " q3map_lightimage textures/test/blue.tga\n}\n"
               "textures/test/sky8\n{\n surfaceparm sky\n q3map_skylight 180 8\n}\n"
               "textures/test/sky1\n{\n surfaceparm sky\n q3map_skylight 180 1\n}\n"},
              {"textures/test/blue.tga", tgaImage(1, {{128, 160, 255}})}});
    const auto skyOf = [&](const std::string& name, SourceLevel* out = nullptr) {
        const auto folder = freshFolder("skylight_" + name);
        Quake3BspBuilder bsp = floorSquare(0);
        world::q3::BspShader sky = bsp.shaders[0];
        std::strcpy(sky.name, ("textures/test/" + name).c_str());
        bsp.shaders.push_back(sky);
        writeFile(folder / "room.bsp", bsp.text());
        SourceLevel level = importLevel((folder / "room.bsp").string(), quake3GameIn(game));
        if (out) *out = level;
        return level.skyRadiance;
    };
    const double pi = 3.14159265358979323846;
    // Two iterations: one ring of 4 suns at 22.5 degrees and the zenith's, 0.506 of the value.
    EXPECT_NEAR(floorLux(1.0, 2), (4.0 * std::sin(pi / 8.0) + 1.0) / 5.0, 1e-12);
    const glm::vec3 two = skyOf("sky2");
    EXPECT_NEAR(pi * double(two.z), floorLux(100.0, 2), 1e-3);  // blue, the brightest channel
    EXPECT_NEAR(two.x / two.z, 128.0 / 255.0, 1e-4);            // the light image's mean bytes
    EXPECT_NEAR(two.y / two.z, 160.0 / 255.0, 1e-4);
    const glm::vec3 eight = skyOf("sky8");  // no light image: white
    EXPECT_NEAR(pi * double(eight.x), floorLux(180.0, 8), 1e-3);
    EXPECT_NEAR(floorLux(1.0, 8), 0.588, 0.001);  // not the whole value
    SourceLevel none;
    EXPECT_EQ(skyOf("sky1", &none), glm::vec3(0.0f));
    EXPECT_TRUE(mentions(none.importNotes, "q3map_skylight with 1 iteration(s): q3map2 makes no"));
}

// The BSP's entities: worldspawn with `worldspawnKeys`, and the source map's three lights (a
// point light of 300, a spot of 600 aimed at an info_null, a linear light of 200).
std::string entitiesWithLights(const std::string& worldspawnKeys) {
    return "{\n\"classname\" \"worldspawn\"\n" + worldspawnKeys +
           "}\n"
           "{\n\"classname\" \"light\"\n\"origin\" \"32 64 128\"\n\"light\" \"300\"\n}\n"
           "{\n\"classname\" \"light\"\n\"origin\" \"128 128 256\"\n\"light\" \"600\"\n"
           "\"target\" \"spot1\"\n}\n"
           "{\n\"classname\" \"info_null\"\n\"targetname\" \"spot1\"\n\"origin\" \"128 128 0\"\n}\n"
           "{\n\"classname\" \"light\"\n\"origin\" \"64 64 64\"\n\"light\" \"200\"\n"
           "\"spawnflags\" \"1\"\n}\n";
}

SourceLevel importWithEntities(const std::string& name, const std::string& entities) {
    const auto folder = freshFolder(name);
    Quake3BspBuilder bsp = floorSquare(40);
    bsp.entities = entities;
    writeFile(folder / "room.bsp", bsp.text());
    return importLevel((folder / "room.bsp").string(), quake3GameIn(freshFolder(name + "_game")));
}

TEST(Quake3Q3map2Options, TheLightStagesScalesLightTheMapAndItsEncodingDecodesTheLightmaps) {
    // -scale in the BSP stage is not the light stage's (it scales the geometry there).
    const SourceLevel level = importWithEntities(
        "cmdline", entitiesWithLights("\"_q3map2_cmdline\" \"-meta -scale 9; -vis; -light -fast "
                                      "-pointscale 2 -spot 3 -gamma 1.5 -compensate 2 -bounce 8 "
                                      "-dirty\"\n"));
    ASSERT_EQ(level.lights.size(), 3u);
    const double candela = 7500.0 / 1024.0;
    EXPECT_NEAR(level.lights[0].intensity, 300.0 * 2.0 * candela, 1e-2);  // -pointscale
    EXPECT_EQ(level.lights[1].type, LightType::kSpot);
    EXPECT_NEAR(level.lights[1].intensity, 600.0 * 6.0 * candela, 1e-2);  // -pointscale, -spot
    // The linear light's reach doubles with its value: 0.9375 x 400 units.
    EXPECT_NEAR(level.lights[2].range, 0.9375 * 400.0 / 32.0, 1e-3);
    const ImportedLightEncoding& e = level.importedLightmap.encoding;
    EXPECT_EQ(e.gamma, 1.5f);
    EXPECT_EQ(e.compensate, 2.0f);
    EXPECT_EQ(e.exposure, 0.0f);
    EXPECT_TRUE(mentions(level.lightSources, "8 bounces")) << level.lightSources.back();
    EXPECT_TRUE(mentions(level.lightSources, "dirt")) << level.lightSources.back();
    EXPECT_TRUE(mentions(level.lightSources, "gamma 1.5")) << level.lightSources.back();
}

// A "-scale S" stage after -light (q3map2's ScaleBSP, Nexuiz's aggressor records 1.25) scaled
// the lit map's geometry and origins but not its light values: q3map2's distances were 1/S of
// the stored ones, so a point or spot light is S^2 as intense, a spot's cone is as wide as q3map2
// saw it, and a linear light reaches S as far. A scale before -light, or one that is not
// uniform, changes nothing (the latter with a note).
TEST(Quake3Q3map2Options, AMapScaledAfterItWasLitIsLitAsItWasThen) {
    const double candela = 7500.0 / 1024.0, s = 1.25;
    const SourceLevel level = importWithEntities(
        "scaled", entitiesWithLights("\"_q3map2_cmdline\" \"-meta; -light -fast; -scale 1.25\"\n"));
    ASSERT_EQ(level.lights.size(), 3u);
    EXPECT_NEAR(level.lights[0].intensity, 300.0 * candela * s * s, 1e-2);
    ASSERT_EQ(level.lights[1].type, LightType::kSpot);
    EXPECT_NEAR(level.lights[1].intensity, 600.0 * candela * s * s, 1e-2);
    // The spot's target is 256 units away as stored, 204.8 as lit; radius 64 (+ 16).
    EXPECT_NEAR(level.lights[1].outerCone, std::atan(80.0 / (256.0 / s)), 1e-5);
    EXPECT_NEAR(level.lights[2].range, 0.9375 * 200.0 * s / 32.0, 1e-3);
    EXPECT_TRUE(mentions(level.lightSources, "the map scaled 1.25x after it was lit"))
        << level.lightSources.back();

    const SourceLevel before = importWithEntities(
        "scaled_before", entitiesWithLights("\"_q3map2_cmdline\" \"-scale 2; -light -fast\"\n"));
    ASSERT_EQ(before.lights.size(), 3u);
    EXPECT_NEAR(before.lights[0].intensity, 300.0 * candela, 1e-2);
    const SourceLevel skewed = importWithEntities(
        "scaled_skewed",
        entitiesWithLights("\"_q3map2_cmdline\" \"-light -fast; -scale 1 1 2\"\n"));
    ASSERT_EQ(skewed.lights.size(), 3u);
    EXPECT_NEAR(skewed.lights[0].intensity, 300.0 * candela, 1e-2);
    EXPECT_TRUE(mentions(skewed.importNotes, "the stage '-scale 1 1 2' after -light ignored"));
}

TEST(Quake3Q3map2Options, WithoutACommandLineQ3map2sDefaultsAreAssumedAndSaid) {
    const SourceLevel level = importWithEntities("nocmdline", entitiesWithLights(""));
    ASSERT_EQ(level.lights.size(), 3u);
    EXPECT_NEAR(level.lights[0].intensity, 300.0 * 7500.0 / 1024.0, 1e-2);
    EXPECT_EQ(level.importedLightmap.encoding.gamma, 1.0f);
    EXPECT_TRUE(mentions(level.lightSources, "not recorded")) << level.lightSources.back();
}

TEST(Quake3Q3map2Options, ALightsOwnScaleKeyMultipliesItAsQ3map2s) {
    const std::string entities =
        "{\n\"classname\" \"worldspawn\"\n}\n"
        "{\n\"classname\" \"light\"\n\"origin\" \"32 64 128\"\n\"light\" \"300\"\n"
        "\"scale\" \"1.5\"\n}\n";
    const SourceLevel level = importWithEntities("scalekey", entities);
    ASSERT_EQ(level.lights.size(), 1u);
    EXPECT_NEAR(level.lights[0].intensity, 450.0 * 7500.0 / 1024.0, 1e-2);
}

TEST(Quake3Q3map2Options, AValueThatIsNotANumberIsIgnoredWithANote) {
    const SourceLevel level = importWithEntities(
        "badcmdline", entitiesWithLights("\"_q3map2_cmdline\" \"-light -gamma abc -bounce 2.5 "
                                         "-exposure\"\n"));
    EXPECT_EQ(level.importedLightmap.encoding.gamma, 1.0f);
    EXPECT_EQ(level.importedLightmap.encoding.exposure, 0.0f);
    EXPECT_TRUE(mentions(level.importNotes, "-gamma 'abc' ignored: expected a number"));
    EXPECT_TRUE(mentions(level.importNotes, "-bounce '2.5' ignored: expected a whole number"));
    EXPECT_TRUE(mentions(level.importNotes, "-exposure (nothing) ignored"));
    EXPECT_TRUE(mentions(level.importNotes, "room.bsp")) << "the note names the map";
}

// Pages holding `texels` texels whose three channels are each value of `values` in turn.
std::vector<uint8_t> pagesOf(const std::vector<std::pair<uint8_t, size_t>>& values) {
    std::vector<uint8_t> rgb;
    for (const auto& [value, texels] : values)
        for (size_t i = 0; i < texels; ++i) rgb.insert(rgb.end(), {value, uint8_t(value / 2), 0});
    return rgb;
}

TEST(Quake3Q3map2Options, APileUpBelow255ShowsQ3map2sCompensate) {
    // -compensate 2: clamped at 255, halved: the brightest pile up at 127.
    EXPECT_EQ(compensateShownByPages(pagesOf({{10, 500}, {126, 5}, {127, 100}})), 2.0f);
    // -compensate 3: at 85.
    EXPECT_EQ(compensateShownByPages(pagesOf({{10, 500}, {84, 2}, {85, 40}})), 3.0f);
    // No pile-up: a map that is simply dim, or one that clamps at 255 (no compensate).
    EXPECT_EQ(compensateShownByPages(pagesOf({{10, 500}, {126, 30}, {127, 1}})), 1.0f);
    EXPECT_EQ(compensateShownByPages(pagesOf({{10, 500}, {127, 10}})), 1.0f);  // too few
    EXPECT_EQ(compensateShownByPages(pagesOf({{10, 500}, {254, 5}, {255, 100}})), 1.0f);
    EXPECT_EQ(compensateShownByPages({}), 1.0f);
    // Off the quarters: 255 / 100.5.
    EXPECT_NEAR(compensateShownByPages(pagesOf({{10, 50}, {100, 50}})), 255.0 / 100.5, 1e-5);
}

TEST(Quake3Q3map2Options, AnUnrecordedMapsLightmapsDecodeWithTheCompensateTheyShow) {
    const auto folder = freshFolder("inferred");
    Quake3BspBuilder bsp = floorSquare(127);  // every byte 127: a pile-up and nothing above
    writeFile(folder / "room.bsp", bsp.text());
    const SourceLevel level =
        importLevel((folder / "room.bsp").string(), quake3GameIn(freshFolder("inferred_game")));
    EXPECT_EQ(level.importedLightmap.encoding.compensate, 2.0f);
    EXPECT_TRUE(mentions(level.lightSources, "clamp at 127, as -compensate 2 makes them"))
        << level.lightSources.back();
    // A recorded command line is the record: nothing is inferred.
    const auto recorded = freshFolder("recorded");
    bsp.entities = "{\n\"classname\" \"worldspawn\"\n\"_q3map2_cmdline\" \"-light -fast\"\n}\n";
    writeFile(recorded / "room.bsp", bsp.text());
    const SourceLevel kept =
        importLevel((recorded / "room.bsp").string(), quake3GameIn(freshFolder("recorded_game")));
    EXPECT_EQ(kept.importedLightmap.encoding.compensate, 1.0f);
}

}  // namespace
}  // namespace onelight::world::q3
