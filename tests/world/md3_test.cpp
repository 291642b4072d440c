// Quake 3 models (world/import/q3/md3_file.hpp): every MD3 the installed games ship reads, its
// frames' stored bounds holding their decoded vertices; a model built here reads back as
// written; and each kind of damage is refused in one line naming the file and the place.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <limits>

#include "world/error.hpp"
#include "world/import/q3/game_search_path.hpp"
#include "world/import/q3/md3_file.hpp"
#include "world/import/q3/md3_format.hpp"
#include "world/import/q3/pk3_archive.hpp"

namespace onelight::world::q3 {
namespace {

template <typename Record>
void put(std::vector<uint8_t>& bytes, size_t at, const Record& r) {
    std::memcpy(bytes.data() + at, &r, sizeof(Record));
}

template <size_t N>
void setName(char (&field)[N], const char* name) {
    std::memset(field, 0, N);
    std::strncpy(field, name, N - 1);
}

// One frame, one tag, one surface of one triangle over three vertices and one shader.
struct SmallModel {
    std::vector<uint8_t> bytes;
    size_t surface = 0;                          // the surface's offset
    size_t frame = 0, triangle = 0, vertex = 0;  // offsets of records the tests damage
};

SmallModel smallModel() {
    SmallModel m;
    Md3Header h{};
    std::memcpy(h.magic, kMd3Magic, 4);
    h.version = kMd3Version;
    setName(h.name, "models/test/tri.md3");
    h.frameCount = 1;
    h.tagCount = 1;
    h.surfaceCount = 1;
    h.framesOffset = int32_t(sizeof(Md3Header));
    h.tagsOffset = h.framesOffset + int32_t(sizeof(Md3Frame));
    h.surfacesOffset = h.tagsOffset + int32_t(sizeof(Md3Tag));
    Md3SurfaceHeader s{};
    std::memcpy(s.magic, kMd3Magic, 4);
    setName(s.name, "tri");
    s.frameCount = 1;
    s.shaderCount = 1;
    s.vertexCount = 3;
    s.triangleCount = 1;
    s.shadersOffset = int32_t(sizeof(Md3SurfaceHeader));
    s.trianglesOffset = s.shadersOffset + int32_t(sizeof(Md3Shader));
    s.texCoordsOffset = s.trianglesOffset + int32_t(sizeof(Md3Triangle));
    s.verticesOffset = s.texCoordsOffset + 3 * int32_t(sizeof(Md3TexCoord));
    s.endOffset = s.verticesOffset + 3 * int32_t(sizeof(Md3Vertex));
    h.endOffset = h.surfacesOffset + s.endOffset;
    m.bytes.assign(size_t(h.endOffset), 0);
    put(m.bytes, 0, h);
    Md3Frame f{};
    const float lo[3] = {0, 0, 0}, hi[3] = {1, 1, 0};
    std::memcpy(f.boundsMin, lo, sizeof lo);
    std::memcpy(f.boundsMax, hi, sizeof hi);
    f.radius = 1.5f;
    setName(f.name, "idle");
    m.frame = size_t(h.framesOffset);
    put(m.bytes, m.frame, f);
    Md3Tag t{};
    setName(t.name, "tag_weapon");
    t.origin[2] = 8.0f;
    for (int i = 0; i < 3; ++i) t.axis[i][i] = 1.0f;
    put(m.bytes, size_t(h.tagsOffset), t);
    m.surface = size_t(h.surfacesOffset);
    put(m.bytes, m.surface, s);
    Md3Shader shader{};
    setName(shader.name, "models/test/tri.tga");
    put(m.bytes, m.surface + size_t(s.shadersOffset), shader);
    m.triangle = m.surface + size_t(s.trianglesOffset);
    put(m.bytes, m.triangle, Md3Triangle{{0, 1, 2}});
    for (int v = 0; v < 3; ++v) {
        put(m.bytes, m.surface + size_t(s.texCoordsOffset) + size_t(v) * sizeof(Md3TexCoord),
            Md3TexCoord{{float(v), 0.5f}});
        // (0,0,0), (1,0,0), (0,1,0) in game units; normals up: latitude 0, longitude 0.
        const Md3Vertex vertex{{int16_t(v == 1 ? 64 : 0), int16_t(v == 2 ? 64 : 0), 0}, 0};
        put(m.bytes, m.surface + size_t(s.verticesOffset) + size_t(v) * sizeof(Md3Vertex), vertex);
    }
    m.vertex = m.surface + size_t(s.verticesOffset);
    return m;
}

std::string errorOf(const std::vector<uint8_t>& bytes) {
    try {
        (void)parseMd3(bytes, "tri.md3");
    } catch (const Error& e) {
        return e.what();
    }
    return "";
}

TEST(Md3Models, AModelBuiltHereReadsBackAsWritten) {
    const Md3Model m = parseMd3(smallModel().bytes, "tri.md3");
    EXPECT_EQ(m.name, "models/test/tri.md3");
    ASSERT_EQ(m.frames.size(), 1u);
    EXPECT_EQ(m.frames[0].name, "idle");
    ASSERT_EQ(m.tags.size(), 1u);
    EXPECT_EQ(m.tags[0].name, "tag_weapon");
    EXPECT_EQ(m.tags[0].origin, glm::vec3(0, 0, 8));
    ASSERT_EQ(m.surfaces.size(), 1u);
    const Md3Surface& s = m.surfaces[0];
    EXPECT_EQ(s.name, "tri");
    EXPECT_EQ(s.shaders, std::vector<std::string>{"models/test/tri.tga"});
    EXPECT_EQ(s.indices, (std::vector<uint32_t>{0, 1, 2}));
    ASSERT_EQ(s.positions.size(), 3u);
    EXPECT_EQ(s.positions[1], glm::vec3(1, 0, 0));
    EXPECT_EQ(s.positions[2], glm::vec3(0, 1, 0));
    EXPECT_EQ(s.texCoords[2], glm::vec2(2.0f, 0.5f));
    EXPECT_NEAR(s.normals[0].z, 1.0f, 1e-6f);
    EXPECT_EQ(checkedMd3Frame(m, 0, "tri.md3"), 0u);
}

// The stored normal's two angles: (cos a sin b, sin a sin b, cos b), a step 2 pi / 256.
TEST(Md3Models, NormalsDecodeFromTheirTwoAngles) {
    EXPECT_NEAR(md3Normal(0).z, 1.0f, 1e-6f);              // b = 0: up
    EXPECT_NEAR(md3Normal(int16_t(128)).z, -1.0f, 1e-6f);  // b = pi: down
    const glm::vec3 x = md3Normal(int16_t(64));            // a = 0, b = pi / 2: +x
    EXPECT_NEAR(x.x, 1.0f, 1e-6f);
    const glm::vec3 y = md3Normal(int16_t((64 << 8) | 64));  // a = pi / 2, b = pi / 2: +y
    EXPECT_NEAR(y.y, 1.0f, 1e-6f);
    for (int bits = 0; bits < 65536; bits += 97)
        EXPECT_NEAR(glm::length(md3Normal(int16_t(uint16_t(bits)))), 1.0f, 1e-5f);
}

TEST(Md3Models, DamageIsRefusedInOneLineNamingThePlace) {
    const SmallModel good = smallModel();
    // Truncated: the file ends inside its surface.
    std::vector<uint8_t> b(good.bytes.begin(), good.bytes.end() - 4);
    EXPECT_EQ(errorOf(b),
              "tri.md3: surface 0 ('tri'): ends at byte 512 of the file's 508; expected its end "
              "inside the file, after its header");
    b.assign(good.bytes.begin(), good.bytes.begin() + 50);
    EXPECT_EQ(errorOf(b), "tri.md3: 50 bytes; expected an MD3 of at least 108 (its header)");
    // Counts past the file: a surface claiming more vertices than its bytes hold.
    b = good.bytes;
    int32_t count = 4;
    std::memcpy(&b[good.surface + offsetof(Md3SurfaceHeader, vertexCount)], &count, 4);
    EXPECT_EQ(errorOf(b),
              "tri.md3: surface 0 ('tri'): vertices at byte 488, 4 of 8 bytes, reach past bytes "
              "276..512; expected them inside");
    b = good.bytes;
    count = 100000;
    std::memcpy(&b[offsetof(Md3Header, frameCount)], &count, 4);
    EXPECT_EQ(errorOf(b), "tri.md3: 100000 frames; expected 1..1024 (the games' limit)");
    // A triangle naming a vertex the surface does not have.
    b = good.bytes;
    put(b, good.triangle, Md3Triangle{{0, 1, 3}});
    EXPECT_EQ(errorOf(b),
              "tri.md3: surface 0 ('tri'): triangle 0 names vertex 3 of 3; expected an index "
              "into the surface's vertices");
    // NaN in a frame's bounds.
    b = good.bytes;
    const float nan = std::numeric_limits<float>::quiet_NaN();
    std::memcpy(&b[good.frame + offsetof(Md3Frame, boundsMax)], &nan, 4);
    EXPECT_EQ(errorOf(b), "tri.md3: frame 0: its bounds is NaN or Inf; expected finite numbers");
    // Not a model at all.
    b = good.bytes;
    b[0] = 'X';
    EXPECT_EQ(errorOf(b), "tri.md3: does not start with IDP3; expected a Quake 3 model (MD3)");
    // A frame index out of range, as an entity might ask for.
    const Md3Model m = parseMd3(good.bytes, "tri.md3");
    try {
        (void)checkedMd3Frame(m, 1, "tri.md3");
        ADD_FAILURE() << "frame 1 of 1 accepted";
    } catch (const Error& e) {
        EXPECT_STREQ(e.what(), "tri.md3: frame 1 of a model of 1 frames; expected 0..0");
    }
}

// Every MD3 of the installed games reads, and the decoded vertices lie inside their frames'
// stored bounds (to the 1/64-unit steps positions are stored in) in all but a few models, whose
// tools wrote bounds that miss their vertices: a wrong decode (scale, layout) would miss in
// nearly all. The engine computes its own bounds from the vertices.
TEST(Md3Models, EveryInstalledModelReadsAndMostKeepInsideTheirFramesBounds) {
    // Every installed game's models, each game's files as that game finds them: Nexuiz's too,
    // whose surfaces pass Quake 3's vertex limit.
    const std::vector<InstalledGame> games = installedGames();
    if (games.empty()) GTEST_SKIP() << "OpenArena is not installed (openarena-data)";
    size_t models = 0, triangles = 0, outside = 0;
    std::string firstOutside;
    for (const InstalledGame& game : games) {
        GameFiles files;
        files.addGameFolder(game.folder);
        for (const auto& [key, file] : files.files) {
            if (key.size() < 4 || key.compare(key.size() - 4, 4, ".md3") != 0) continue;
            const std::vector<uint8_t> bytes = *files.read(key, kMaxModelBytes, "a model");
            const Md3Model m = parseMd3(bytes, files.where(key));
            ++models;
            bool inside = true;
            for (const Md3Surface& s : m.surfaces) {
                triangles += s.indices.size() / 3;
                for (size_t k = 0; k < s.positions.size(); ++k) {
                    const Md3FrameInfo& f = m.frames[k / s.vertexCount];
                    inside &=
                        glm::all(
                            glm::greaterThanEqual(s.positions[k], f.boundsMin - 1.0f / 32.0f)) &&
                        glm::all(glm::lessThanEqual(s.positions[k], f.boundsMax + 1.0f / 32.0f));
                    EXPECT_NEAR(glm::length(s.normals[k]), 1.0f, 1e-5f);
                }
            }
            if (!inside && outside++ == 0) firstOutside = files.where(key);
        }
    }
    std::printf(
        "[ md3 ] %zu installed models, %zu triangles; %zu with vertices "
        "outside their frames' stored bounds (the first: %s)\n",
        models, triangles, outside, firstOutside.c_str());
    EXPECT_GT(models, 100u);
    EXPECT_LT(double(outside), 0.1 * double(models));
}

}  // namespace
}  // namespace onelight::world::q3
