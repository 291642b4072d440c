// Hostile Quake 3 input: records whose sizes would make more than the level's limits, refused
// from their headers before anything is built, in one line naming the map and the place.
#include <chrono>
#include <string>

#include <gtest/gtest.h>

#include "tests/support/error_message.hpp"
#include "tests/world/q3_test_maps.hpp"
#include "tests/world/world_test_support.hpp"
#include "world/import/level_import.hpp"
#include "world/import/level_limits.hpp"

namespace onelight::test {
namespace {

using namespace world::q3;

// The error importing `bsp` as NAME.bsp gives, with how long it took.
std::string importError(const Quake3BspBuilder& bsp, const std::string& name, double& seconds,
                        uint32_t patchLevel = 4) {
    const std::string path = bsp.write(name, name);
    world::Quake3Options options = quake3GameIn(freshFolder(name + "_game"));
    options.patchLevel = patchLevel;
    const auto start = std::chrono::steady_clock::now();
    const std::string message = errorMessage([&] { (void)world::importLevel(path, options); });
    seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    return message;
}

TEST(HostileQuake3, AHugePatchIsRefusedFromItsSizeBeforeItIsTessellated) {
    // 255 x 255 controls, 127^2 pieces: at level 64, 2 x 64^2 triangles each, 132M in all, past
    // the level's 67M.
    Quake3BspBuilder bsp;
    bsp.vertices.assign(255 * 255, bsp.vertices[0]);
    for (uint32_t i = 0; i < 255 * 255; ++i) {
        bsp.vertices[i].position[0] = float(i % 255);
        bsp.vertices[i].position[1] = float(i / 255);
    }
    bsp.indices.clear();
    BspSurface& patch = bsp.surfaces[0];
    patch.type = kSurfacePatch;
    patch.vertexCount = 255 * 255;
    patch.indexCount = 0;
    patch.patchWidth = patch.patchHeight = 255;
    double seconds = 0.0;
    const std::string message = importError(bsp, "hugepatch", seconds, 64);
    EXPECT_NE(
        message.find("hugepatch.bsp: the surfaces would make 132128768 triangles and 68145025 "
                     "vertices"),
        std::string::npos)
        << message;
    EXPECT_NE(message.find("surface 0, a 255 x 255 patch at patch level 64"), std::string::npos)
        << message;
    EXPECT_NE(message.find("expected at most 67108864"), std::string::npos) << message;
    EXPECT_EQ(message.find('\n'), std::string::npos);
    EXPECT_LT(seconds, 5.0) << "refused from the header, not after building";
    // The same map at the default level imports (127^2 x 32 = 516128 triangles).
    EXPECT_EQ(importError(bsp, "hugepatch4", seconds, 4), "");
}

TEST(HostileQuake3, SurfacesSharingOneVertexRangeAreCountedBeforeTheyAreCopied) {
    // 2000 surfaces, each drawing one triangle but spanning the same 40000 vertices: 80M vertex
    // copies, past the 67M limit, in a 2 MB file.
    Quake3BspBuilder bsp;
    bsp.vertices.assign(40000, bsp.vertices[0]);
    for (uint32_t i = 0; i < 40000; ++i) bsp.vertices[i].position[0] = float(i);
    bsp.indices = {0, 1, 2};
    BspSurface f = bsp.surfaces[0];
    f.vertexCount = 40000;
    f.indexCount = 3;
    bsp.surfaces.assign(2000, f);
    double seconds = 0.0;
    const std::string message = importError(bsp, "sharedrange", seconds);
    EXPECT_NE(message.find("sharedrange.bsp: the surfaces would make 2000 triangles and 80000000 "
                           "vertices"),
              std::string::npos)
        << message;
    EXPECT_LT(seconds, 5.0);
}

// Imports PAK.pk3:maps/room.bsp from `pk3` alone, as its game; the error, with its time.
std::string importFromPk3(const std::filesystem::path& pk3, double& seconds) {
    const auto start = std::chrono::steady_clock::now();
    const std::string message = errorMessage([&] {
        (void)world::importLevel(pk3.string() + ":maps/room.bsp", quake3GameIn(pk3.parent_path()));
    });
    seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    return message;
}

TEST(HostileQuake3, APk3EntryWhoseBytesChangedIsRefusedByItsCrc) {
    const auto folder = freshFolder("crc");
    const std::string script = "textures/test/floor\n{\n\tsurfaceparm nolightmap\n}\n";
    writePk3(folder / "z.pk3",
             {{"maps/room.bsp", floorSquare(40).text()}, {"scripts/test.shader", script}}, true);
    double seconds = 0.0;
    ASSERT_EQ(importFromPk3(folder / "z.pk3", seconds), "") << "the archive as written imports";
    // One byte of the stored script changed: inflating still works, only the CRC can tell.
    std::string bytes = readFileText(folder / "z.pk3");
    const size_t at = bytes.find("nolightmap");
    ASSERT_NE(at, std::string::npos);
    bytes[at] = 'N';
    writeFile(folder / "z.pk3", bytes);
    const std::string message = importFromPk3(folder / "z.pk3", seconds);
    EXPECT_NE(message.find("z.pk3:scripts/test.shader: damaged in the archive (CRC"),
              std::string::npos)
        << message;
}

TEST(HostileQuake3, AnEntryThatInflatesPastItsDeclaredSizeIsRefused) {
    // The script's size in both headers edited from 64 to 16: 48 bytes more come out than the
    // archive declares, which must not be read into a 16-byte allocation or cut silently.
    const auto folder = freshFolder("liar");
    writePk3(folder / "z.pk3", {{"maps/room.bsp", floorSquare(40).text()},
                                {"scripts/liar.shader", std::string(64, '/')}});
    std::string bytes = readFileText(folder / "z.pk3");
    int edited = 0;
    for (const auto& [signature, sizeAt] :
         {std::pair{std::string("PK\x03\x04", 4), 22}, {std::string("PK\x01\x02", 4), 24}}) {
        for (size_t at = bytes.find(signature); at != std::string::npos;
             at = bytes.find(signature, at + 1)) {
            const size_t nameAt = signature[2] == 3 ? at + 30 : at + 46;
            if (bytes.compare(nameAt, 19, "scripts/liar.shader") != 0) continue;
            ASSERT_EQ(uint8_t(bytes[at + size_t(sizeAt)]), 64);
            bytes[at + size_t(sizeAt)] = 16;
            ++edited;
        }
    }
    ASSERT_EQ(edited, 2);
    writeFile(folder / "z.pk3", bytes);
    double seconds = 0.0;
    const std::string message = importFromPk3(folder / "z.pk3", seconds);
    EXPECT_NE(message.find("z.pk3:scripts/liar.shader: damaged in the archive ("),
              std::string::npos)
        << message;
}

TEST(HostileQuake3, AnEntryPastItsKindsLimitIsRefusedFromItsDeclaredSize) {
    // A shader script of 17 MiB deflates to about 17 KB: refused before it is inflated.
    const auto folder = freshFolder("zipbomb");
    writePk3(folder / "z.pk3", {{"maps/room.bsp", floorSquare(40).text()},
                                {"scripts/big.shader", std::string(size_t(17) << 20, ' ')}});
    double seconds = 0.0;
    const std::string message = importFromPk3(folder / "z.pk3", seconds);
    EXPECT_NE(message.find("z.pk3:scripts/big.shader: 17825792 bytes uncompressed; expected a "
                           "shader script of at most 16777216"),
              std::string::npos)
        << message;
    EXPECT_LT(seconds, 2.0);
}

TEST(HostileQuake3, LightsPastAFloatOrWithANegativeConeAreRefusedAtImport) {
    double seconds = 0.0;
    Quake3BspBuilder bsp = floorSquare(40);
    bsp.entities =
        "{\n\"classname\" \"worldspawn\"\n}\n"
        "{\n\"classname\" \"light\"\n\"origin\" \"32 32 64\"\n\"light\" \"1e38\"\n}\n";
    EXPECT_EQ(importError(bsp, "hotlight", seconds),
              freshFolder("hotlight").string() +
                  "/hotlight.bsp: entities line 4: light '1e38' makes an intensity past a "
                  "float's range; expected a value the engine can hold (at most about 4e37)");
    bsp.entities =
        "{\n\"classname\" \"worldspawn\"\n}\n"
        "{\n\"classname\" \"light\"\n\"origin\" \"32 32 64\"\n\"target\" \"t\"\n"
        "\"radius\" \"-1e30\"\n}\n"
        "{\n\"classname\" \"info_null\"\n\"targetname\" \"t\"\n\"origin\" \"32 32 0\"\n}\n";
    const std::string message = importError(bsp, "badspot", seconds);
    EXPECT_NE(message.find("badspot.bsp: entities line 4: spot light radius '-1e30'; expected >= "
                           "0 units"),
              std::string::npos)
        << message;
}

}  // namespace
}  // namespace onelight::test
