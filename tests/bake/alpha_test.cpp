// Alpha in the light transport (bake/embree/bake_scene.hpp): a MASK grate lets shadow rays, view
// rays and the light grid's visibility rays through its holes, and a BLEND sheet transmits
// 1 - alpha, against the grate's geometry traced by hand.
#include <gtest/gtest.h>
#include <tbb/global_control.h>
#include <tbb/parallel_for.h>

#include <cmath>
#include <cstdio>
#include <filesystem>

#include <glm/gtc/quaternion.hpp>

#include "bake/embree/bake_scene.hpp"
#include "bake/lightmap/texel_placement.hpp"
#include "bake/reference/path_tracer.hpp"
#include "bake_scenes.hpp"
#include "world/compile/static_split.hpp"

namespace onelight::bake {
namespace {

constexpr float kPi = 3.14159265358979f;

std::string outputFolder() {
    const std::filesystem::path dir = std::filesystem::temp_directory_path() / "onelight_alpha";
    std::filesystem::create_directories(dir);
    return dir.string();
}

// The grate's alpha texture: 8 x 8 texels of 4 x 4 cells, each a 2 x 2 hole (alpha 0) framed
// by two-texel bars (alpha 1) on its low sides: open fraction 1 / 4.
constexpr double kOpenFraction = 1.0 / 4.0;
std::vector<uint8_t> grateTexture() {
    std::vector<uint8_t> rgba;
    for (int y = 0; y < 8; ++y)
        for (int x = 0; x < 8; ++x) {
            const bool bar = x % 4 < 2 || y % 4 < 2;
            rgba.insert(rgba.end(), {255, 255, 255, uint8_t(bar ? 255 : 0)});
        }
    return rgba;
}

// Grate: 2 x 2 m at y = kGrateHeight, uv = 2 (x + 1), 2 (z + 1): the texture repeats every
// 0.5 m, so a texel is 1/16 m and the hole pattern's period 0.25 m.
constexpr float kGrateHeight = 1.0f;
constexpr glm::vec3 kLight{0.0f, 3.0f, 0.0f};
constexpr float kCandela = 100.0f, kFloorAlbedo = 0.5f;

// Whether grate point (x, z) is open (1), a bar (0), or within `margin` texels of an edge or
// outside the grate (-1).
int grateOpenAt(float x, float z, float margin) {
    if (std::fabs(x) >= 1.0f || std::fabs(z) >= 1.0f) return -1;
    int open = 1;
    for (float c : {x, z}) {
        const float texel = 16.0f * (c + 1.0f);  // texel coordinate along the grate
        const float inCell = texel - 4.0f * std::floor(texel / 4.0f);  // [0, 4): bar is [0, 2)
        for (float edge : {0.0f, 2.0f, 4.0f})
            if (std::fabs(inCell - edge) < margin) return -1;
        if (inCell < 2.0f) open = 0;
    }
    return open;
}

// Where the segment from the light to floor/space point p crosses the grate's plane.
glm::vec3 grateCrossing(const glm::vec3& from, const glm::vec3& p) {
    return from + (p - from) * ((from.y - kGrateHeight) / (from.y - p.y));
}

// A 3 x 3 m Lambert floor at y = 0 under the grate, a primary point light above both.
world::SourceLevel grateLevel(world::AlphaMode mode, float blendAlpha) {
    world::SourceLevel level;
    const uint32_t floor = test::addLambertMaterial(level, kFloorAlbedo);
    test::addQuad(level, {-1.5f, 0.0f, 1.5f}, {1.5f, 0.0f, 1.5f}, {1.5f, 0.0f, -1.5f},
                  {-1.5f, 0.0f, -1.5f}, floor, "floor");
    const uint32_t grate = test::addLambertMaterial(level, 0.0f);
    world::Material& g = level.materials[grate];
    g.alphaMode = mode;
    g.doubleSided = true;
    if (mode == world::AlphaMode::kMask) {
        world::Sampler nearest;
        nearest.magFilter = 9728;
        g.baseColorTexture = test::addImageTexture(level, outputFolder() + "/grate.png", 8, 8,
                                                   grateTexture(), nearest);
    } else {
        g.baseColor.w = blendAlpha;
    }
    world::MeshInstance mesh;
    mesh.nodeName = mesh.meshName = "grate";
    mesh.material = grate;
    for (int i = 0; i < 4; ++i) {
        world::Vertex v;
        const float x = (i == 1 || i == 2) ? 1.0f : -1.0f, z = (i >= 2) ? 1.0f : -1.0f;
        v.position = {x, kGrateHeight, z};
        v.normal = {0.0f, 1.0f, 0.0f};
        v.uv0 = {2.0f * (x + 1.0f), 2.0f * (z + 1.0f)};
        mesh.vertices.push_back(v);
    }
    mesh.indices = {0, 2, 1, 0, 3, 2};
    level.instances.push_back(mesh);
    level.lights.push_back(test::pointLight(kLight, kCandela, world::LightRole::kPrimary));
    world::Camera camera;
    camera.name = "down";
    camera.position = {0.0f, 2.5f, 0.0f};
    camera.rotation = glm::angleAxis(-0.5f * kPi, glm::vec3(1.0f, 0.0f, 0.0f));
    camera.yfov = 0.8f;
    level.cameras.push_back(camera);
    return level;
}

// The floor's unshadowed radiance at p: albedo / pi x I cos / d^2.
float floorRadiance(const glm::vec3& p) {
    const glm::vec3 toLight = kLight - p;
    const float d2 = glm::dot(toLight, toLight);
    return kFloorAlbedo / kPi * kCandela * (toLight.y / std::sqrt(d2)) / d2;
}

struct FloorTexel {
    glm::vec3 position;
    float mask;  // the baked shadow mask, [0, 1]
};

std::vector<FloorTexel> floorTexels(const BakeResult& result) {
    std::vector<FloorTexel> out;
    for (const TexelSample& s : placeTexels(result.level)) {
        if (!s.centreInside || s.normal.y < 0.99f || std::fabs(s.position.y) > 1e-3f) continue;
        out.push_back({s.position, float(result.baked.shadowMask[s.texel]) / 255.0f});
    }
    return out;
}

BakeOptions grateOptions() {
    BakeOptions options = test::testOptions(48.0f);
    options.compile.charts.atlasSize = 1024;
    options.shadowSamples = 16;
    options.indirectSamples = 4;
    options.gridSamples = 4;
    options.gridCellSize = 0.05f;
    options.probeSamples = 1;
    options.probeFaceSize = 4;
    return options;
}

// The floor region whose light paths cross the grate's central [-0.75, 0.75]^2: six whole
// periods of the hole pattern each way, so its mean openness is the texture's.
bool underCentralGrate(const glm::vec3& p) {
    const glm::vec3 q = grateCrossing(kLight, p);
    return std::fabs(q.x) < 0.75f && std::fabs(q.z) < 0.75f;
}

TEST(AlphaTransport, AMaskGrateCastsItsHolesPatternIntoTheShadowMaskAndTheGrid) {
    const world::SourceLevel level = grateLevel(world::AlphaMode::kMask, 1.0f);
    const BakeResult result = bakeLevel(level, grateOptions());
    ASSERT_TRUE(test::allFiniteNonNegative(result.baked));

    // Shadow mask: each texel clear of an edge is open or shut as its light path through the
    // grate is (the light's 5 cm radius blurs 0.27 texels of the grate: margin 0.45).
    double sum = 0.0;
    int inside = 0, checked = 0, wrong = 0;
    for (const FloorTexel& t : floorTexels(result)) {
        if (!underCentralGrate(t.position)) continue;
        sum += double(t.mask);
        ++inside;
        const glm::vec3 q = grateCrossing(kLight, t.position);
        const int open = grateOpenAt(q.x, q.z, 0.45f);
        if (open < 0) continue;
        ++checked;
        if (std::fabs(t.mask - float(open)) > 0.05f) ++wrong;
    }
    const double meanOpen = sum / inside;
    std::printf(
        "[ grate ] shadow mask: %d texels, mean openness %.4f (texture %.4f), %d of %d "
        "off the pattern\n",
        inside, meanOpen, kOpenFraction, wrong, checked);
    EXPECT_GT(checked, 3000);
    EXPECT_EQ(wrong, 0);
    EXPECT_NEAR(meanOpen, kOpenFraction, 0.02 * kOpenFraction);

    // The light grid: the dominant primary's visibility at each cell centre below the grate.
    const world::LightGrid& grid = result.baked.grid;
    double gridSum = 0.0;
    int cells = 0, gridChecked = 0, gridWrong = 0;
    for (uint32_t z = 0; z < grid.dims.z; ++z)
        for (uint32_t y = 0; y < grid.dims.y; ++y)
            for (uint32_t x = 0; x < grid.dims.x; ++x) {
                const glm::vec3 c = grid.origin + (glm::vec3(x, y, z) + 0.5f) * grid.cellSize;
                if (c.y <= 0.0f || c.y >= kGrateHeight - 0.1f || !underCentralGrate(c)) continue;
                const world::LightGridCell& cell =
                    grid.cells[(size_t(z) * grid.dims.y + y) * grid.dims.x + x];
                const float v = cell.dominantPrimary == 0 ? cell.primaryVisibility : 0.0f;
                gridSum += double(v);
                ++cells;
                const glm::vec3 q = grateCrossing(kLight, c);
                const int open = grateOpenAt(q.x, q.z, 0.45f);
                if (open < 0) continue;
                ++gridChecked;
                if (std::fabs(v - float(open)) > 0.05f) ++gridWrong;
            }
    const double gridOpen = gridSum / cells;
    std::printf(
        "[ grate ] light grid: %d cells, mean visibility %.4f, %d of %d off the "
        "pattern\n",
        cells, gridOpen, gridWrong, gridChecked);
    EXPECT_GT(gridChecked, 5000);
    EXPECT_EQ(gridWrong, 0);
    EXPECT_NEAR(gridOpen, kOpenFraction, 0.02 * kOpenFraction);
}

// View rays: from above the grate, the reference sees the lit floor through the holes, lit
// where its own light path is open too, and the black grate elsewhere.
TEST(AlphaTransport, TheReferenceSeesTheFloorThroughTheGratesHoles) {
    const world::SourceLevel level = grateLevel(world::AlphaMode::kMask, 1.0f);
    const test::LevelScene built(level);
    const BakeScene& scene = built.scene;
    const BakeLights& lights = built.lights;
    RayCounts rays;
    const uint32_t size = 192;
    const world::Camera& camera = level.cameras[0];
    const ReferenceImage image =
        renderReference(scene, lights, camera, size, size, 4, {}, nullptr, rays);
    const glm::mat3 rotation = glm::mat3_cast(camera.rotation);
    const float tanHalf = std::tan(0.5f * camera.yfov);
    int counted[2] = {0, 0};
    for (uint32_t y = 0; y < size; ++y)
        for (uint32_t x = 0; x < size; ++x) {
            const float sx = (float(x) + 0.5f) / float(size) * 2.0f - 1.0f;
            const float sy = 1.0f - (float(y) + 0.5f) / float(size) * 2.0f;
            const glm::vec3 d = rotation * glm::vec3(sx * tanHalf, sy * tanHalf, -1.0f);
            // A pixel spans 0.006 m = 0.1 texels of the grate: margin 0.45 texels.
            const glm::vec3 atGrate =
                camera.position + d * ((camera.position.y - kGrateHeight) / -d.y);
            const int viewOpen = grateOpenAt(atGrate.x, atGrate.z, 0.45f);
            if (viewOpen < 0) continue;
            const glm::vec3 p = camera.position + d * (camera.position.y / -d.y);
            const glm::vec3 q = grateCrossing(kLight, p);
            const int lightOpen = viewOpen ? grateOpenAt(q.x, q.z, 0.45f) : 0;
            if (lightOpen < 0) continue;
            const float expected = float(viewOpen * lightOpen) * floorRadiance(p);
            const float rendered = image.rgb[(size_t(y) * size + x) * 3];
            ASSERT_NEAR(rendered, expected, 0.01f * floorRadiance(p)) << "pixel " << x << ", " << y;
            ++counted[viewOpen * lightOpen];
        }
    EXPECT_GT(counted[0], 2000);
    EXPECT_GT(counted[1], 400);
}

// A BLEND sheet of alpha 0.3 stops 30% of every ray on average: the floor's shadow mask below
// reads 0.7, and the reference, whose view rays cross the sheet once and whose shadow rays
// cross it again, shows 0.49 of the open floor's radiance.
TEST(AlphaTransport, ABlendSheetTransmitsOneMinusAlpha) {
    const float alpha = 0.3f;
    const world::SourceLevel level = grateLevel(world::AlphaMode::kBlend, alpha);
    BakeOptions options = grateOptions();
    options.compile.charts.texelsPerMetre = 16.0f;
    options.shadowSamples = 64;
    options.gridCellSize = 0.25f;
    options.gridSamples = 4;
    const BakeResult result = bakeLevel(level, options);
    double sum = 0.0;
    int inside = 0;
    for (const FloorTexel& t : floorTexels(result))
        if (underCentralGrate(t.position)) {
            sum += double(t.mask);
            ++inside;
        }
    ASSERT_GT(inside, 500);
    const double transmitted = sum / inside;

    const test::LevelScene built(level);
    const BakeScene& scene = built.scene;
    const BakeLights& lights = built.lights;
    RayCounts rays;
    const uint32_t size = 64;
    const world::Camera& camera = level.cameras[0];
    const ReferenceImage image =
        renderReference(scene, lights, camera, size, size, 64, {}, nullptr, rays);
    const glm::mat3 rotation = glm::mat3_cast(camera.rotation);
    const float tanHalf = std::tan(0.5f * camera.yfov);
    double rendered = 0.0, open = 0.0;
    for (uint32_t y = 0; y < size; ++y)
        for (uint32_t x = 0; x < size; ++x) {
            const float sx = (float(x) + 0.5f) / float(size) * 2.0f - 1.0f;
            const float sy = 1.0f - (float(y) + 0.5f) / float(size) * 2.0f;
            const glm::vec3 d = rotation * glm::vec3(sx * tanHalf, sy * tanHalf, -1.0f);
            const glm::vec3 p = camera.position + d * (camera.position.y / -d.y);
            if (!underCentralGrate(p)) continue;
            rendered += double(image.rgb[(size_t(y) * size + x) * 3]);
            open += double(floorRadiance(p));
        }
    const double seen = rendered / open;
    const double t = 1.0 - double(alpha);
    std::printf(
        "[ blend ] shadow mask %.4f (1 - alpha = %.2f); reference %.4f ((1 - alpha)^2 "
        "= %.2f)\n",
        transmitted, t, seen, t * t);
    EXPECT_NEAR(transmitted, t, 0.02 * t);
    EXPECT_NEAR(seen, t * t, 0.02 * t * t);
}

// Ray by ray, against BakeScene itself: the shadow rays of `count` floor points whose paths to
// the light's centre cross the grate's central 1.5 x 1.5 m (six whole periods each way) at the
// points of an R2 low-discrepancy sequence (Roberts 2018), so their open fraction converges to
// the texture's like 1 / count.
struct ShadowRay {
    glm::vec3 origin, dir;
    float distance;
    glm::vec3 crossing;  // where the ray meets the grate's plane
};
std::vector<ShadowRay> shadowRaysThroughTheGrate(const BakeScene& scene, uint32_t count) {
    std::vector<ShadowRay> rays;
    for (uint32_t i = 0; i < count; ++i) {
        const double a = 0.5 + 0.7548776662466927 * i, b = 0.5 + 0.5698402909980532 * i;
        const glm::vec3 q(float(1.5 * (a - std::floor(a)) - 0.75), kGrateHeight,
                          float(1.5 * (b - std::floor(b)) - 0.75));
        const glm::vec3 p = kLight + (q - kLight) * (kLight.y / (kLight.y - kGrateHeight));
        const glm::vec3 origin(p.x, scene.rayOffset(), p.z);
        const glm::vec3 to = kLight - origin;
        rays.push_back({origin, glm::normalize(to), glm::length(to), q});
    }
    return rays;
}

// 1 where BakeScene::occluded stops `ray`, traced on the threads of a parallel loop.
std::vector<uint8_t> blocked(const BakeScene& scene, const std::vector<ShadowRay>& rays) {
    std::vector<uint8_t> out(rays.size());
    tbb::parallel_for(tbb::blocked_range<size_t>(0, rays.size(), 256), [&](const auto& r) {
        uint64_t counter = 0;
        for (size_t i = r.begin(); i != r.end(); ++i)
            out[i] = scene.occluded(rays[i].origin, rays[i].dir, rays[i].distance, counter);
    });
    return out;
}

double openFraction(const std::vector<uint8_t>& blockedRays) {
    size_t open = 0;
    for (uint8_t b : blockedRays) open += b == 0;
    return double(open) / double(blockedRays.size());
}

using test::LevelScene;

// Shadow rays: the open ones are the texture's open fraction, and each one clear of an edge is
// open exactly where it crosses a hole. With the grate's material OPAQUE (what every triangle
// was before the alpha filter) not one ray passes, so these checks and those of the shadow
// mask and the grid above fail without the filter.
TEST(AlphaTransport, ShadowRaysPassTheGrateInItsOpenFraction) {
    world::SourceLevel level = grateLevel(world::AlphaMode::kMask, 1.0f);
    const uint32_t count = 100000;
    {
        const LevelScene s(level);
        const std::vector<ShadowRay> rays = shadowRaysThroughTheGrate(s.scene, count);
        const std::vector<uint8_t> stopped = blocked(s.scene, rays);
        int checked = 0, wrong = 0;
        for (size_t i = 0; i < rays.size(); ++i) {
            const int open = grateOpenAt(rays[i].crossing.x, rays[i].crossing.z, 0.01f);
            if (open < 0) continue;
            ++checked;
            wrong += (stopped[i] == 0) != (open == 1);
        }
        const double measured = openFraction(stopped);
        std::printf(
            "[ grate ] %u shadow rays: open %.5f (texture %.5f); %d of %d off the "
            "pattern\n",
            count, measured, kOpenFraction, wrong, checked);
        EXPECT_NEAR(measured, kOpenFraction, 0.02 * kOpenFraction);
        EXPECT_GT(checked, 90000);
        EXPECT_EQ(wrong, 0);
    }
    level.materials[1].alphaMode = world::AlphaMode::kOpaque;
    const LevelScene opaque(level);
    const double measured =
        openFraction(blocked(opaque.scene, shadowRaysThroughTheGrate(opaque.scene, count)));
    std::printf("[ grate ] the same grate OPAQUE: open %.5f\n", measured);
    EXPECT_EQ(measured, 0.0);

    // And the bake: the shadow mask under an OPAQUE grate is black.
    const BakeResult result = bakeLevel(level, grateOptions());
    double sum = 0.0;
    int inside = 0;
    for (const FloorTexel& t : floorTexels(result))
        if (underCentralGrate(t.position)) {
            sum += double(t.mask);
            ++inside;
        }
    ASSERT_GT(inside, 1000);
    EXPECT_EQ(sum, 0.0);
}

// View rays (BakeScene::intersect) straight down through each texel centre of the grate find
// the floor below a hole and the grate on a bar; straight up from below they escape through a
// hole and meet the grate's back face on a bar. The hit's triangle is the scene's own (its
// material and its interpolated uv are the grate's at the hit).
TEST(AlphaTransport, ViewRaysSeeThroughTheHolesAndStopAtTheBars) {
    const world::SourceLevel level = grateLevel(world::AlphaMode::kMask, 1.0f);
    const LevelScene s(level);
    const BakeScene& scene = s.scene;
    const uint32_t floorMaterial = 0, grateMaterial = 1;
    int holes = 0, bars = 0;
    uint64_t counter = 0;
    for (int tz = 0; tz < 32; ++tz)
        for (int tx = 0; tx < 32; ++tx) {
            const float x = -1.0f + (float(tx) + 0.5f) / 16.0f;
            const float z = -1.0f + (float(tz) + 0.5f) / 16.0f;
            const int open = grateOpenAt(x, z, 0.45f);
            ASSERT_GE(open, 0);
            const SurfaceHit down =
                scene.intersect({x, 2.5f, z}, {0.0f, -1.0f, 0.0f}, 10.0f, counter);
            const SurfaceHit up = scene.intersect({x, 0.5f, z}, {0.0f, 1.0f, 0.0f}, 10.0f, counter);
            ASSERT_TRUE(down.found);
            if (open) {
                ++holes;
                EXPECT_EQ(scene.materialIndexOf(down.triangle), floorMaterial) << tx << ", " << tz;
                EXPECT_NEAR(down.distance, 2.5f, 1e-4f);
                EXPECT_NEAR(down.position.y, 0.0f, 1e-5f);
                EXPECT_FALSE(up.found) << tx << ", " << tz;
            } else {
                ++bars;
                EXPECT_EQ(scene.materialIndexOf(down.triangle), grateMaterial) << tx << ", " << tz;
                EXPECT_NEAR(down.distance, 2.5f - kGrateHeight, 1e-4f);
                EXPECT_FALSE(down.backFace);
                const glm::vec2 uv = scene.attributesAt(down).uv;
                EXPECT_NEAR(uv.x, 2.0f * (x + 1.0f), 1e-4f);
                EXPECT_NEAR(uv.y, 2.0f * (z + 1.0f), 1e-4f);
                ASSERT_TRUE(up.found);
                EXPECT_EQ(scene.materialIndexOf(up.triangle), grateMaterial);
                EXPECT_TRUE(up.backFace);
                EXPECT_NEAR(up.distance, kGrateHeight - 0.5f, 1e-4f);
            }
        }
    EXPECT_EQ(holes, 256);  // 1/4 of 32 x 32
    EXPECT_EQ(bars, 768);
}

// BLEND alpha 0.3: a shadow ray passes the sheet with probability 0.7 and a view ray sees it
// with probability 0.3; every decision is a function of the ray and the triangle alone, so the
// same rays give the same answers on every run and at any thread count, and a bake gives the
// same bytes on one thread and on two.
TEST(AlphaTransport, BlendCoverageIsAlphaAndTheSameOnEveryRunAndThread) {
    const float alpha = 0.3f;
    const world::SourceLevel level = grateLevel(world::AlphaMode::kBlend, alpha);
    const LevelScene s(level);
    const uint32_t count = 200000;
    const std::vector<ShadowRay> rays = shadowRaysThroughTheGrate(s.scene, count);
    std::vector<uint8_t> serial, parallel;
    {
        tbb::global_control limit(tbb::global_control::max_allowed_parallelism, 1);
        serial = blocked(s.scene, rays);
    }
    {
        tbb::global_control limit(tbb::global_control::max_allowed_parallelism, 2);
        parallel = blocked(s.scene, rays);
    }
    const double transmitted = openFraction(serial);
    EXPECT_TRUE(serial == parallel);
    EXPECT_TRUE(blocked(s.scene, rays) == serial);

    uint64_t counter = 0;
    uint32_t seen = 0;
    for (const ShadowRay& r : rays) {  // down through the same crossings
        const SurfaceHit hit = s.scene.intersect(r.crossing + glm::vec3(0.0f, 1.0f, 0.0f),
                                                 {0.0f, -1.0f, 0.0f}, 10.0f, counter);
        seen += hit.found && s.scene.materialIndexOf(hit.triangle) == 1;
    }
    const double seenFraction = double(seen) / double(count);
    std::printf(
        "[ blend ] %u shadow rays: transmitted %.5f (1 - alpha = %.2f); view rays see the "
        "sheet %.5f (alpha = %.2f)\n",
        count, transmitted, 1.0 - double(alpha), seenFraction, double(alpha));
    EXPECT_NEAR(transmitted, 1.0 - double(alpha), 0.02 * (1.0 - double(alpha)));
    EXPECT_NEAR(seenFraction, double(alpha), 0.02 * double(alpha));

    BakeOptions options = grateOptions();
    options.compile.charts.texelsPerMetre = 16.0f;
    options.gridCellSize = 0.25f;
    std::vector<uint8_t> one, two;
    {
        tbb::global_control limit(tbb::global_control::max_allowed_parallelism, 1);
        const BakeResult r = bakeLevel(level, options);
        one = packageBytes(r.level, r.baked, r.textures);
    }
    {
        tbb::global_control limit(tbb::global_control::max_allowed_parallelism, 2);
        const BakeResult r = bakeLevel(level, options);
        two = packageBytes(r.level, r.baked, r.textures);
    }
    EXPECT_TRUE(one == two);
}

// A material whose alpha is its factor alone (no base colour texture) is decided when the scene
// is built, as the filter would decide each hit: MASK at or above the cutoff and BLEND at 1 are
// opaque, MASK below the cutoff and BLEND at 0 are never hit.
TEST(AlphaTransport, AConstantAlphaIsDecidedOnceAsTheFilterWould) {
    struct Case {
        world::AlphaMode mode;
        float alpha;
        double open;
    };
    for (const Case& c :
         {Case{world::AlphaMode::kMask, 0.5f, 0.0}, Case{world::AlphaMode::kMask, 0.49f, 1.0},
          Case{world::AlphaMode::kBlend, 1.0f, 0.0}, Case{world::AlphaMode::kBlend, 0.0f, 1.0}}) {
        world::SourceLevel level = grateLevel(world::AlphaMode::kBlend, c.alpha);
        level.materials[1].alphaMode = c.mode;
        const LevelScene s(level);
        EXPECT_EQ(openFraction(blocked(s.scene, shadowRaysThroughTheGrate(s.scene, 1000))), c.open)
            << "mode " << int(c.mode) << ", alpha " << c.alpha;
        uint64_t counter = 0;
        const SurfaceHit hit =
            s.scene.intersect({0.1f, 2.0f, 0.1f}, {0.0f, -1.0f, 0.0f}, 10.0f, counter);
        ASSERT_TRUE(hit.found);
        EXPECT_EQ(s.scene.materialIndexOf(hit.triangle), c.open > 0.5 ? 0u : 1u);
    }
}

// A material that casts no shadow (world::Material::castsShadows false: a Quake 3 translucent
// surface) is never hit, whatever its alpha: every shadow ray passes it and a view ray finds the
// floor below it; with the flag set again the OPAQUE sheet stops them all.
TEST(AlphaTransport, AMaterialThatCastsNoShadowIsPassedByEveryRay) {
    world::SourceLevel level = grateLevel(world::AlphaMode::kOpaque, 1.0f);
    for (const bool casts : {false, true}) {
        level.materials[1].castsShadows = casts;
        const LevelScene s(level);
        EXPECT_EQ(openFraction(blocked(s.scene, shadowRaysThroughTheGrate(s.scene, 1000))),
                  casts ? 0.0 : 1.0);
        uint64_t counter = 0;
        const SurfaceHit hit =
            s.scene.intersect({0.1f, 2.0f, 0.1f}, {0.0f, -1.0f, 0.0f}, 10.0f, counter);
        ASSERT_TRUE(hit.found);
        EXPECT_EQ(s.scene.materialIndexOf(hit.triangle), casts ? 1u : 0u);
    }
}

}  // namespace
}  // namespace onelight::bake
