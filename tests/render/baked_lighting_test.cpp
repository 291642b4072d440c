// Baked lighting at runtime: a small level baked in the test at draft quality (a floor, a static
// block, a point primary, a second point light with role "baked", a dynamic box) renders what its
// package says. A floor pixel's linear radiance equals the C++ evaluation from the package data
// at that pixel: the primary through the shared BRDF times the baked shadow mask, plus the
// secondary irradiance reconstructed from the lightmap texels (bilinear) times the albedo.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <utility>

#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/packing.hpp>

#include "env_brdf_table.hpp"
#include "render/scene.hpp"
#include "shading.hpp"
#include "test_scene.hpp"
#include "vk/context.hpp"
#include "world/baked_lighting.hpp"
#include "world/dynamic_primary.hpp"
#include "world/images/image_decode.hpp"
#include "world/images/image_files.hpp"
#include "world/light_grid_sample.hpp"
#include "world/package/probe_section.hpp"

namespace {

using namespace onelight;
namespace glsl = onelight::glsl;

constexpr uint32_t kWidth = 192, kHeight = 128;

// ---------------------------------------------------------------------------------------------
// The C++ side: what a pixel sees and what the package says about it.

struct Ray {
    glm::vec3 origin, direction;
};

// The camera ray through point (px, py) of the frame (pixel centres at + 0.5), as the GPU
// rasterises it.
Ray pixelRay(const render::Camera& camera, float px, float py) {
    const glm::mat4 viewProj =
        render::projectionMatrix(camera, float(kWidth) / float(kHeight), 1000.0f) *
        render::viewMatrix(camera);
    const glm::mat4 inv = glm::inverse(viewProj);
    const float ndcX = 2.0f * px / float(kWidth) - 1.0f;
    const float ndcY = 2.0f * py / float(kHeight) - 1.0f;
    const glm::vec4 far = inv * glm::vec4(ndcX, ndcY, 1.0f, 1.0f);
    return {camera.position, glm::normalize(glm::vec3(far) / far.w - camera.position)};
}

// Distance along the ray to an axis-aligned box (slab test), or infinity.
float hitBox(const Ray& r, glm::vec3 lo, glm::vec3 hi) {
    float t0 = 0.0f, t1 = 1e30f;
    for (int a = 0; a < 3; ++a) {
        const float inv = 1.0f / r.direction[a];
        float tn = (lo[a] - r.origin[a]) * inv, tf = (hi[a] - r.origin[a]) * inv;
        if (tn > tf) std::swap(tn, tf);
        t0 = std::max(t0, tn);
        t1 = std::min(t1, tf);
    }
    return t0 <= t1 ? t0 : 1e30f;
}

// What the ray meets first: 0 nothing, 1 the floor, 2 the block, 3 the dynamic box at `dynamic`.
int hitWhat(const Ray& r, glm::vec3 dynamic, float* distance = nullptr) {
    float best = 1e30f;
    int what = 0;
    const float tf = r.direction.y < 0.0f ? -r.origin.y / r.direction.y : 1e30f;
    const glm::vec3 pf = r.origin + tf * r.direction;
    if (tf < best && std::fabs(pf.x) <= 10.0f && std::fabs(pf.z) <= 10.0f) {
        best = tf;
        what = 1;
    }
    const float tb = hitBox(r, {1.0f, 0.0f, -1.0f}, {2.0f, 1.5f, 1.0f});
    if (tb < best) {
        best = tb;
        what = 2;
    }
    const float td = hitBox(r, dynamic - 0.3f, dynamic + 0.3f);
    if (td < best) {
        best = td;
        what = 3;
    }
    if (distance) *distance = best;
    return what;
}

// True when the pixel's centre and its four corners all see `what` (no silhouette inside).
bool pixelSees(const render::Camera& camera, uint32_t x, uint32_t y, int what, glm::vec3 dynamic) {
    const float offsets[5][2] = {
        {0.5f, 0.5f}, {0.0f, 0.0f}, {1.0f, 0.0f}, {0.0f, 1.0f}, {1.0f, 1.0f}};
    for (const auto& o : offsets)
        if (hitWhat(pixelRay(camera, float(x) + o[0], float(y) + o[1]), dynamic) != what)
            return false;
    return true;
}

// The lightmap and shadow mask at a static point: the triangle of the level holding it gives
// uv1 (barycentric), then bilinear filtering of the atlas texels as the sampler does it.
struct LightmapSample {
    bool found = false;
    uint32_t surface = 0;
    glm::vec4 coefficients[3];  // irradianceLinear per channel, lux
    float mask = 1.0f;          // [0, 1]
    float maskSpread = 0.0f;    // largest minus smallest of the four texels' masks
    // The baked direct light and its shadow edge, filtered as the GPU reads them (the edge's
    // distance in penumbra widths and its levels at the shadow mask's 8 bits).
    glm::vec3 direct{0.0f}, directLight{0.0f};
    float visibility = 0.0f, ramps = 0.0f, low = 0.0f, high = 0.0f;
};

// A texel's byte in the shadow mask's unorm channels (runtime/render/scene.cpp), read back.
float unorm8(float v) {
    return std::round(std::clamp(v, 0.0f, 1.0f) * 255.0f) / 255.0f;
}

LightmapSample sampleLightmap(const assets::LoadedLevel& loaded, glm::vec3 p, glm::vec3 n) {
    const world::CompiledLevel& level = loaded.level;
    LightmapSample out;
    for (uint32_t si = 0; si < level.surfaces.size() && !out.found; ++si) {
        const world::Surface& surface = level.surfaces[si];
        for (uint32_t i = surface.firstIndex; i < surface.firstIndex + surface.indexCount; i += 3) {
            const world::Vertex& a = level.vertices[level.indices[i]];
            const world::Vertex& b = level.vertices[level.indices[i + 1]];
            const world::Vertex& c = level.vertices[level.indices[i + 2]];
            const glm::vec3 normal = glm::cross(b.position - a.position, c.position - a.position);
            if (glm::dot(glm::normalize(normal), n) < 0.99f) continue;
            if (std::fabs(glm::dot(p - a.position, glm::normalize(normal))) > 1e-3f) continue;
            const float area = glm::dot(normal, normal);
            const float wa = glm::dot(glm::cross(b.position - p, c.position - p), normal) / area;
            const float wb = glm::dot(glm::cross(c.position - p, a.position - p), normal) / area;
            const float wc = 1.0f - wa - wb;
            if (wa < -1e-5f || wb < -1e-5f || wc < -1e-5f) continue;
            const glm::vec2 uv = wa * a.uv1 + wb * b.uv1 + wc * c.uv1;
            const world::Atlas& atlas = level.atlases.at(surface.atlas);
            const uint64_t first = world::atlasTexelOffset(level, surface.atlas);
            const glm::vec2 t = uv * glm::vec2(atlas.width, atlas.height) - 0.5f;
            const glm::vec2 f = glm::floor(t), frac = t - f;
            out = LightmapSample{};
            for (auto& k : out.coefficients) k = glm::vec4(0.0f);
            out.mask = 0.0f;
            float lowest = 1.0f, highest = 0.0f;
            for (int dy = 0; dy < 2; ++dy)
                for (int dx = 0; dx < 2; ++dx) {
                    const int x = std::clamp(int(f.x) + dx, 0, int(atlas.width) - 1);
                    const int y = std::clamp(int(f.y) + dy, 0, int(atlas.height) - 1);
                    const float w = (dx ? frac.x : 1.0f - frac.x) * (dy ? frac.y : 1.0f - frac.y);
                    const uint64_t texel = first + uint64_t(y) * atlas.width + uint64_t(x);
                    for (int ch = 0; ch < 3; ++ch)
                        out.coefficients[ch] +=
                            w * world::linearIrradianceCoefficients(loaded.baked.texels[texel], ch);
                    const world::LightmapTexel& k = loaded.baked.texels[texel];
                    out.direct += w * k.directIrradiance;
                    out.directLight += w * k.directLight;
                    out.visibility += w * k.directVisibility;
                    const render::DirectEdgeMask e = render::directEdgeMask(k);
                    out.ramps += w * (unorm8(e.ramps) * 2.0f - 1.0f) * glsl::DIRECT_EDGE_RAMPS;
                    out.low += w * unorm8(e.low);
                    out.high += w * unorm8(e.high);
                    const float m = float(loaded.baked.shadowMask[texel]) / 255.0f;
                    out.mask += w * m;
                    lowest = std::min(lowest, m);
                    highest = std::max(highest, m);
                }
            out.maskSpread = highest - lowest;
            out.found = true;
            out.surface = si;
            break;
        }
    }
    return out;
}

// Radiance (cd/m^2) of a Lambert point lit by `primary` (illuminance times shadow) and by the
// secondary irradiance `secondary`, through the shared shaders.
glm::vec3 lambertRadiance(const world::CompiledLevel& level, uint32_t material, uint32_t primary,
                          float shadow, glm::vec3 secondary, glm::vec3 p, glm::vec3 n,
                          glm::vec3 eye) {
    const world::Material& m = level.materials.at(material);
    EXPECT_EQ(m.materialClass, world::MaterialClass::kLambert);
    const glm::vec3 albedo = glsl::albedo_fromMetallic(glm::vec3(m.baseColor), m.metallic);
    const glm::vec3 v = glm::normalize(eye - p);
    glm::vec3 radiance(0.0f);
    if (primary != world::kNoIndex) {
        const world::Light& l = level.lights.at(primary);
        const glsl::LightSample s = glsl::evaluatePunctualLight(
            int(l.type), l.color * l.intensity, 1.0f, l.range, l.position,
            glm::normalize(l.direction), std::cos(l.innerCone), std::cos(l.outerCone), p);
        const glsl::BrdfDots d = glsl::brdfDots(n, v, s.l);
        if (glm::dot(n, s.l) > 0.0f && d.NoL > 0.0f)
            radiance += glsl::surfaceReflectance(MATERIAL_LAMBERT, DIFFUSE_LAMBERT, albedo,
                                                 glm::vec3(0.04f), 0.0f, glm::vec2(0.0f), 1.0f, d) *
                        s.illuminance * shadow;
    }
    return radiance + glsl::secondaryRadiance(MATERIAL_LAMBERT, albedo, glm::vec3(0.04f),
                                              glm::vec2(0.0f), secondary, 1.0f, 1.0f,
                                              glm::vec3(0.0f), secondary);
}

// The lightmap's irradiance at normal n, with the baked direct light's shadow edge drawn as the
// runtime draws it (directEdgeFactor; `pixelStep`: the edge distance's change over a pixel, in
// penumbra widths).
glm::vec3 lightmapIrradiance(const LightmapSample& s, glm::vec3 n, float pixelStep = 0.0f) {
    glm::vec3 e(glsl::irradianceLinear(s.coefficients[0], n),
                glsl::irradianceLinear(s.coefficients[1], n),
                glsl::irradianceLinear(s.coefficients[2], n));
    if (s.high > s.low) {
        const float g = glsl::directEdgeFactor(s.visibility, s.ramps, pixelStep, s.low, s.high);
        const float length = glm::length(s.directLight);
        const glm::vec3 l = length > 1e-4f ? s.directLight / length : glm::vec3(0.0f);
        e = glm::max(e + s.direct * ((g - 1.0f) * std::max(glm::dot(n, l), 0.0f)), glm::vec3(0.0f));
    }
    return e;
}

// ---------------------------------------------------------------------------------------------
// The GPU side.

test::Scene bakedScene() {
    test::Scene s;
    s.materials = {{{0.5f, 0.5f, 0.5f, 1.0f}, 0.0f, 1.0f},   // floor
                   {{0.6f, 0.6f, 0.6f, 1.0f}, 0.0f, 1.0f},   // block
                   {{0.7f, 0.7f, 0.7f, 1.0f}, 0.0f, 1.0f}};  // dynamic box
    test::addFloor(s, 0.0f, 0.0f, 10.0f, 0.0f, 0);
    test::addBox(s, {1.0f, 0.0f, -1.0f}, {2.0f, 1.5f, 1.0f}, 1);
    test::addBox(s, {-0.3f, -0.3f, -0.3f}, {0.3f, 0.3f, 0.3f}, 2, true);
    test::SceneLight primary;
    primary.type = 1;
    primary.intensity = 400.0f;
    primary.position = {-2.0f, 4.0f, 0.0f};
    s.lights.push_back(primary);
    test::SceneLight baked;
    baked.type = 1;
    baked.intensity = 300.0f;
    baked.color = {1.0f, 0.8f, 0.6f};
    baked.position = {5.0f, 1.5f, -5.0f};
    baked.role = "baked";
    s.lights.push_back(baked);
    return s;
}

// Each test bakes its own package (ctest may run them in parallel): ~1.5 s at draft quality.
assets::LoadedLevel bake(const std::string& name, const test::Scene& scene = bakedScene()) {
    const std::string gltf = test::outputDir() + "/" + name + ".gltf";
    test::writeGltf(scene, gltf);
    assets::LoadedLevel level = test::bakeAndLoad(gltf, test::outputDir() + "/" + name + ".olpak");
    EXPECT_TRUE(level.hasBakedLighting);
    return level;
}

render::Camera testCamera() {
    const glm::vec3 eye(-7.0f, 7.0f, 8.0f), target(2.0f, 0.0f, -2.0f);
    const glm::vec3 d = glm::normalize(target - eye);
    return render::cameraFromYawPitch(eye, glm::degrees(std::atan2(-d.x, -d.z)),
                                      glm::degrees(std::asin(d.y)));
}

render::RendererOptions options(float shadowRadius, float shadowBand) {
    render::RendererOptions o;
    o.width = kWidth;
    o.height = kHeight;
    o.shadowRadius = shadowRadius;
    o.shadowBand = shadowBand;
    return o;
}

// Renders and returns the linear frame through an EXR file, as a capture writes it.
std::vector<float> renderLinear(const assets::LoadedLevel& level, const render::RendererOptions& o,
                                const render::FrameInputs& inputs, const std::string& name) {
    const test::RenderedFrame r = test::renderOnce(level, o, inputs);
    EXPECT_EQ(r.validationErrors, 0u);
    const std::string exr = test::outputDir() + "/" + name + ".exr";
    world::writeExrFile(exr, kWidth, kHeight, r.frame.linearRgba);
    world::FloatImage image = world::readExrFile(exr);
    EXPECT_EQ(image.width, kWidth);
    EXPECT_EQ(image.height, kHeight);
    return std::move(image.rgba);
}

glm::vec3 pixel(const std::vector<float>& linear, uint32_t x, uint32_t y) {
    const size_t i = (size_t(y) * kWidth + x) * 4;
    return {linear[i], linear[i + 1], linear[i + 2]};
}

// The pixel whose centre ray meets the floor nearest to world point (x, 0, z).
glm::uvec2 floorPixelNear(const render::Camera& camera, glm::vec3 target) {
    const glm::mat4 viewProj =
        render::projectionMatrix(camera, float(kWidth) / float(kHeight), 1000.0f) *
        render::viewMatrix(camera);
    const glm::vec4 clip = viewProj * glm::vec4(target, 1.0f);
    const glm::vec2 ndc = glm::vec2(clip) / clip.w;
    const glm::vec2 at((ndc.x * 0.5f + 0.5f) * float(kWidth),
                       (ndc.y * 0.5f + 0.5f) * float(kHeight));
    EXPECT_TRUE(at.x >= 0.0f && at.y >= 0.0f && at.x < float(kWidth) && at.y < float(kHeight))
        << "point (" << target.x << ", " << target.y << ", " << target.z << ") is out of the frame";
    return {uint32_t(std::clamp(at.x, 0.0f, float(kWidth - 1))),
            uint32_t(std::clamp(at.y, 0.0f, float(kHeight - 1)))};
}

glm::vec3 floorPointOf(const render::Camera& camera, glm::uvec2 px) {
    const Ray r = pixelRay(camera, float(px.x) + 0.5f, float(px.y) + 0.5f);
    return r.origin + (-r.origin.y / r.direction.y) * r.direction;
}

constexpr glm::vec3 kUp(0.0f, 1.0f, 0.0f);
constexpr glm::vec3 kDynamicAtRest(0.0f);  // the dynamic box's entity sits at the origin

double relativeError(glm::vec3 got, glm::vec3 want, double floor) {
    double worst = 0.0;
    for (int c = 0; c < 3; ++c)
        worst = std::max(
            worst, std::fabs(double(got[c]) - double(want[c])) / std::max(double(want[c]), floor));
    return worst;
}

}  // namespace

namespace {

// Every floor pixel away from silhouettes, with the baked shadow mask in charge everywhere (a
// runtime-shadow radius of 1 cm): the linear EXR equals the C++ evaluation from the package.
// Tolerance: 1% relative (floor 1e-3 of the peak) for the RGBA16F lightmap coefficients and HDR
// target (both round at 2^-11), plus, where the four mask texels differ (penumbrae), 1/256 of
// their spread times the unshadowed primary: samplers weigh bilinear taps with 8 fractional bits
// (lavapipe's subTexelPrecisionBits, as most GPUs), and a hard shadow edge steps by up to 1; and
// where the baked light's shadow edge is drawn from its distance field, the change of that edge
// over half to twice the pixel's step of the distance (the GPU's fwidth is per 2x2 quad).
TEST(RenderBaked, FloorPixelsMatchPackageEvaluation) {
    const assets::LoadedLevel level = bake("baked_floor");
    const render::Camera camera = testCamera();
    render::FrameInputs inputs;
    inputs.camera = camera;
    const std::vector<float> gpu =
        renderLinear(level, options(0.01f, 0.005f), inputs, "baked_floor");
    ASSERT_EQ(gpu.size(), size_t(kWidth) * kHeight * 4);

    std::vector<glm::vec3> cpu(size_t(kWidth) * kHeight, glm::vec3(-1.0f));
    std::vector<float> penumbra(cpu.size(), 0.0f);  // the mask filtering's share of the bound
    double peak = 0.0;
    for (uint32_t y = 0; y < kHeight; ++y)
        for (uint32_t x = 0; x < kWidth; ++x) {
            if (!pixelSees(camera, x, y, 1, kDynamicAtRest)) continue;
            const glm::vec3 p = floorPointOf(camera, {x, y});
            const LightmapSample s = sampleLightmap(level, p, kUp);
            ASSERT_TRUE(s.found) << "no floor triangle at " << p.x << " " << p.z;
            const world::Surface& surface = level.level.surfaces[s.surface];
            // fwidth of the edge's distance, from the next pixels' floor points; the GPU's own
            // differences (per 2x2 quad) may be half or twice it: that range bounds the edge.
            const auto distanceAt = [&](uint32_t px, uint32_t py) {
                const LightmapSample o = sampleLightmap(level, floorPointOf(camera, {px, py}), kUp);
                return o.found ? o.ramps : s.ramps;
            };
            const float step = s.high > s.low ? std::fabs(distanceAt(x + 1, y) - s.ramps) +
                                                    std::fabs(distanceAt(x, y + 1) - s.ramps)
                                              : 0.0f;
            const glm::vec3 secondary = lightmapIrradiance(s, kUp, step);
            cpu[y * kWidth + x] =
                lambertRadiance(level.level, surface.material, surface.primaryLight, s.mask,
                                secondary, p, kUp, camera.position);
            const glm::vec3 edgeSpread =
                glm::max(glm::abs(lightmapIrradiance(s, kUp, 0.5f * step) - secondary),
                         glm::abs(lightmapIrradiance(s, kUp, 2.0f * step) - secondary));
            const glm::vec3 unshadowed =
                lambertRadiance(level.level, surface.material, surface.primaryLight, 1.0f,
                                glm::vec3(0.0f), p, kUp, camera.position);
            const glm::vec3 edge = lambertRadiance(level.level, surface.material, world::kNoIndex,
                                                   0.0f, edgeSpread, p, kUp, camera.position);
            penumbra[y * kWidth + x] =
                s.maskSpread / 256.0f * glm::max(unshadowed.x, unshadowed.y) +
                std::max({edge.x, edge.y, edge.z});
            for (int c = 0; c < 3; ++c) peak = std::max(peak, double(cpu[y * kWidth + x][c]));
        }
    ASSERT_GT(peak, 0.0);
    const double floor = 1e-3 * peak;
    double worst = 0.0, sum = 0.0;
    uint32_t tested = 0, failures = 0, shadowed = 0;
    for (uint32_t y = 0; y < kHeight; ++y)
        for (uint32_t x = 0; x < kWidth; ++x) {
            const glm::vec3 want = cpu[y * kWidth + x];
            if (want.x < 0.0f) continue;
            const glm::vec3 got = pixel(gpu, x, y);
            const double e = relativeError(got, want, floor);
            worst = std::max(worst, e);
            sum += e;
            ++tested;
            const glm::vec3 p = floorPointOf(camera, {x, y});
            if (sampleLightmap(level, p, kUp).mask < 0.5f) ++shadowed;
            bool bad = false;
            for (int c = 0; c < 3; ++c)
                bad = bad || std::fabs(double(got[c]) - double(want[c])) >
                                 0.01 * double(want[c]) + floor + double(penumbra[y * kWidth + x]);
            if (bad) {
                if (failures < 5)
                    ADD_FAILURE() << "pixel (" << x << ", " << y << ") at (" << p.x << ", " << p.z
                                  << "): gpu " << got.x << " " << got.y << " " << got.z << " cpu "
                                  << want.x << " " << want.y << " " << want.z << " mask "
                                  << sampleLightmap(level, p, kUp).mask;
                ++failures;
            }
        }
    std::printf(
        "[ baked ] floor: %u pixels (%u in the baked umbra), relative error max %.3e "
        "(penumbrae included), mean %.3e (peak %.3g cd/m^2)\n",
        tested, shadowed, worst, sum / std::max(tested, 1u), peak);
    EXPECT_GT(tested, kWidth * kHeight / 3);
    EXPECT_GT(shadowed, 50u);
    EXPECT_EQ(failures, 0u);
}

}  // namespace

namespace {

// The secondary is not a constant: two floor pixels, one near the baked light and one far
// from it, differ as their lightmap texels say (the primary's part, evaluated in C++, removed;
// the far one lies in the primary's umbra, so it is all secondary).
TEST(RenderBaked, SecondaryFollowsLightmap) {
    const assets::LoadedLevel level = bake("baked_secondary");
    const render::Camera camera = testCamera();
    render::FrameInputs inputs;
    inputs.camera = camera;
    const std::vector<float> gpu =
        renderLinear(level, options(0.01f, 0.005f), inputs, "baked_secondary");
    glm::vec3 secondary[2], measured[2];
    // Near the baked light, and in the primary's umbra behind the block (secondary only).
    const glm::vec3 targets[2] = {{4.0f, 0.0f, -4.0f}, {3.2f, 0.0f, 0.3f}};
    for (int i = 0; i < 2; ++i) {
        const glm::uvec2 px = floorPixelNear(camera, targets[i]);
        ASSERT_TRUE(pixelSees(camera, px.x, px.y, 1, kDynamicAtRest));
        const glm::vec3 p = floorPointOf(camera, px);
        const LightmapSample s = sampleLightmap(level, p, kUp);
        ASSERT_TRUE(s.found);
        const world::Surface& surface = level.level.surfaces[s.surface];
        const glm::vec3 primaryOnly =
            lambertRadiance(level.level, surface.material, surface.primaryLight, s.mask,
                            glm::vec3(0.0f), p, kUp, camera.position);
        secondary[i] = lambertRadiance(level.level, surface.material, world::kNoIndex, 0.0f,
                                       lightmapIrradiance(s, kUp), p, kUp, camera.position);
        measured[i] = pixel(gpu, px.x, px.y) - primaryOnly;
        std::printf(
            "[ baked ] floor (%.2f, %.2f): secondary %.4g %.4g %.4g cd/m^2 by the lightmap, "
            "%.4g %.4g %.4g rendered\n",
            double(p.x), double(p.z), double(secondary[i].x), double(secondary[i].y),
            double(secondary[i].z), double(measured[i].x), double(measured[i].y),
            double(measured[i].z));
        for (int c = 0; c < 3; ++c)
            EXPECT_NEAR(measured[i][c], secondary[i][c], 0.01f * secondary[i][c] + 1e-4f);
    }
    EXPECT_GT(secondary[0].x, 3.0f * secondary[1].x);  // the lightmap varies a lot here...
    for (int c = 0; c < 3; ++c)                        // ...and so does the frame, alike
        EXPECT_NEAR(measured[0][c] / measured[1][c], secondary[0][c] / secondary[1][c],
                    0.02f * secondary[0][c] / secondary[1][c]);
}

}  // namespace

namespace {

// A point of the primary's umbra behind the block, 14.6 m from the camera: beyond a runtime-shadow
// radius of 8 m it reads the baked mask (dark; lit once the mask is cleared in memory), inside a
// radius of 40 m the runtime shadow map darkens it whatever the mask says.
TEST(RenderBaked, FarUmbraReadsBakedMaskNearUsesShadowMap) {
    const assets::LoadedLevel level = bake("baked_umbra");
    assets::LoadedLevel cleared = level;
    std::fill(cleared.baked.shadowMask.begin(), cleared.baked.shadowMask.end(), uint8_t(255));
    const render::Camera camera = testCamera();
    render::FrameInputs inputs;
    inputs.camera = camera;
    const glm::uvec2 px = floorPixelNear(camera, {3.2f, 0.0f, 0.3f});
    ASSERT_TRUE(pixelSees(camera, px.x, px.y, 1, kDynamicAtRest));
    const glm::vec3 p = floorPointOf(camera, px);
    ASSERT_GT(glm::length(p - camera.position), 10.0f);
    const LightmapSample s = sampleLightmap(level, p, kUp);
    ASSERT_TRUE(s.found);
    ASSERT_LT(s.mask, 0.01f) << "expected the primary's baked umbra";
    const world::Surface& surface = level.level.surfaces[s.surface];
    ASSERT_EQ(surface.primaryLight, 0u);
    const glm::vec3 secondary = lightmapIrradiance(s, kUp);
    const glm::vec3 dark = lambertRadiance(level.level, surface.material, 0, s.mask, secondary, p,
                                           kUp, camera.position);
    const glm::vec3 lit =
        lambertRadiance(level.level, surface.material, 0, 1.0f, secondary, p, kUp, camera.position);

    const glm::vec3 far =
        pixel(renderLinear(level, options(8.0f, 2.0f), inputs, "baked_umbra_far"), px.x, px.y);
    const glm::vec3 farCleared = pixel(
        renderLinear(cleared, options(8.0f, 2.0f), inputs, "baked_umbra_far_cleared"), px.x, px.y);
    const glm::vec3 nearCleared =
        pixel(renderLinear(cleared, options(40.0f, 8.0f), inputs, "baked_umbra_near_cleared"), px.x,
              px.y);
    std::printf(
        "[ baked ] umbra (%.2f, %.2f), %.1f m away: baked mask %.3g; rendered %.4g (C++ "
        "%.4g); mask cleared: %.4g beyond the radius (C++ lit %.4g), %.4g inside it\n",
        double(p.x), double(p.z), double(glm::length(p - camera.position)), double(s.mask),
        double(far.x), double(dark.x), double(farCleared.x), double(lit.x), double(nearCleared.x));
    EXPECT_LT(relativeError(far, dark, 1e-4), 0.01);
    EXPECT_LT(relativeError(farCleared, lit, 1e-4), 0.01);
    EXPECT_GT(lit.x, 3.0f * dark.x);
    EXPECT_LT(relativeError(nearCleared, dark, 1e-4), 0.02);  // the shadow map's 4-tap PCF
}

// The light grid at the object's origin, read as the renderer must: trilinear between cell
// centres, cells inside solid skipped and the weights renormalised.
struct GridAt {
    glm::vec3 up{0.0f};  // ambient cube, +y face (lux)
    uint32_t dominant = world::kNoIndex;
    float visibility = 0.0f;  // of `dominant`, over the corners it dominates
    bool oneDominant = true;  // every used corner has the same dominant primary
};

GridAt gridAt(const world::LightGrid& g, glm::vec3 p) {
    const glm::vec3 f =
        glm::clamp((p - g.origin) / g.cellSize - 0.5f, glm::vec3(0.0f), glm::vec3(g.dims) - 1.0f);
    const glm::ivec3 lo(glm::floor(f));
    const glm::vec3 t = f - glm::vec3(lo);
    GridAt out;
    float total = 0.0f, dominantWeight = 0.0f;
    bool first = true;
    for (int k = 0; k < 8; ++k) {
        const glm::ivec3 c =
            glm::min(lo + glm::ivec3(k & 1, (k >> 1) & 1, (k >> 2) & 1), glm::ivec3(g.dims) - 1);
        const float w = ((k & 1) ? t.x : 1.0f - t.x) * ((k & 2) ? t.y : 1.0f - t.y) *
                        ((k & 4) ? t.z : 1.0f - t.z);
        const world::LightGridCell& cell =
            g.cells[size_t(c.x) +
                    size_t(g.dims.x) * (size_t(c.y) + size_t(g.dims.y) * size_t(c.z))];
        if (w <= 0.0f || (cell.flags & 1u)) continue;
        total += w;
        out.up += w * cell.ambientCube[2];
        if (first) out.dominant = cell.dominantPrimary;
        first = false;
        if (cell.dominantPrimary != out.dominant) out.oneDominant = false;
        dominantWeight += w;
        out.visibility += w * cell.primaryVisibility;
    }
    out.up /= total;
    out.visibility /= dominantWeight;
    return out;
}

// A dynamic box moved between a cell near the baked light and one far from it: its top face
// is lit by the grid's ambient cube (+y face) and by the grid's dominant primary times the
// grid's visibility (runtime-shadow radius 1 cm), as the C++ evaluation of the grid says.
TEST(RenderBaked, DynamicObjectFollowsGrid) {
    const assets::LoadedLevel level = bake("baked_dynamic");
    uint32_t entity = world::kNoIndex;
    for (uint32_t e = 0; e < level.level.entities.size(); ++e)
        if (level.level.entities[e].flags & world::kEntityDynamic) entity = e;
    ASSERT_NE(entity, world::kNoIndex);
    const render::Camera camera = testCamera();
    const glm::vec3 places[2] = {{4.3f, 0.5f, -3.6f}, {-3.4f, 0.5f, 1.6f}};
    glm::vec3 rendered[2], expected[2], secondary[2];

    render::RenderDeviceFeatures features;
    vk::Context ctx;
    vk::createContext(ctx, render::renderContextOptions(features, {}));
    {
        render::Renderer renderer;
        render::createRenderer(renderer, ctx, level, options(0.01f, 0.005f));
        std::vector<uint32_t> candidates;
        for (uint32_t l = 0; l < level.level.lights.size(); ++l)
            if (level.level.lights[l].role == world::LightRole::kPrimary) candidates.push_back(l);
        for (int i = 0; i < 2; ++i) {
            // The game's pick, by the grid's score, handed over with the transform.
            world::DynamicPrimary pick;
            const world::LightGridSample sample =
                world::sampleLightGrid(level.baked.grid, places[i]);
            world::updateDynamicPrimary(pick, places[i], candidates, [&](uint32_t l, glm::vec3 p) {
                return world::gridPrimaryScore(level.level.lights, level.baked.grid, sample, l, p);
            });
            render::DynamicTransform moved{entity, glm::translate(glm::mat4(1.0f), places[i]),
                                           pick.primary};
            render::FrameInputs inputs;
            inputs.camera = camera;
            inputs.dynamicTransforms = {&moved, 1};
            render::FrameOutput output;
            output.readback = true;
            render::drawFrame(renderer, inputs, output);
            const render::CapturedFrame& frame = render::capturedFrame(renderer);

            const glm::vec3 top = places[i] + glm::vec3(0.0f, 0.3f, 0.0f);
            const glm::uvec2 px = floorPixelNear(camera, top);
            ASSERT_TRUE(pixelSees(camera, px.x, px.y, 3, places[i]));
            const Ray r = pixelRay(camera, float(px.x) + 0.5f, float(px.y) + 0.5f);
            const glm::vec3 p = r.origin + ((top.y - r.origin.y) / r.direction.y) * r.direction;
            const GridAt g = gridAt(level.baked.grid, places[i]);
            ASSERT_TRUE(g.oneDominant);
            EXPECT_EQ(pick.primary, g.dominant);
            EXPECT_EQ(render::drawnPrimary(renderer, entity), pick.primary);
            const uint32_t material = level.level.dynamicMeshes.at(0).material;
            expected[i] = lambertRadiance(level.level, material, g.dominant, g.visibility, g.up, p,
                                          kUp, camera.position);
            secondary[i] = lambertRadiance(level.level, material, world::kNoIndex, 0.0f, g.up, p,
                                           kUp, camera.position);
            const size_t at = (size_t(px.y) * kWidth + px.x) * 4;
            rendered[i] = {frame.linearRgba[at], frame.linearRgba[at + 1],
                           frame.linearRgba[at + 2]};
            std::printf(
                "[ baked ] dynamic box at (%.1f, %.1f, %.1f): grid +y %.4g lux, primary %d "
                "visibility %.3f; top face %.4g %.4g %.4g rendered, %.4g %.4g %.4g by the "
                "grid\n",
                double(places[i].x), double(places[i].y), double(places[i].z), double(g.up.x),
                int(g.dominant), double(g.visibility), double(rendered[i].x), double(rendered[i].y),
                double(rendered[i].z), double(expected[i].x), double(expected[i].y),
                double(expected[i].z));
            EXPECT_LT(relativeError(rendered[i], expected[i], 1e-4), 0.01);
        }
        // Whatever the game hands over is what the renderer draws with.
        const uint32_t other =
            (render::drawnPrimary(renderer, entity) + 1) % uint32_t(level.level.lights.size());
        render::DynamicTransform given{entity, glm::translate(glm::mat4(1.0f), places[0])};
        given.primary = other;
        render::FrameInputs givenInputs;
        givenInputs.camera = camera;
        givenInputs.dynamicTransforms = {&given, 1};
        render::drawFrame(renderer, givenInputs, render::FrameOutput{});
        EXPECT_EQ(render::drawnPrimary(renderer, entity), other);
        render::destroyRenderer(renderer);
    }
    vk::destroyContext(ctx);
    EXPECT_EQ(ctx.validationCounts.errors.load(), 0u);
    EXPECT_GT(secondary[0].x, 3.0f * secondary[1].x);  // a bright cell and a dark one...
    EXPECT_GT(rendered[0].x - rendered[1].x, 0.5f * (secondary[0].x - secondary[1].x));  // ...seen
}

// A dynamic object's primary switch cross-fades (world::kPrimaryFadeSeconds): drawn with primary
// B fading from A at weight w, every pixel of the frame is (1 - w) x the frame lit by A plus w x
// the frame lit by B, the rest of its light being the same in all three (closed form, linear
// light). Tolerance: the RGBA16F target's step (2^-11 relative) on each of the three frames, and
// 1e-3 of the brightest channel for the half-float rounding of sums. With 15 steps of w (0.25 s
// at 60 Hz) the largest change between consecutive frames is a fifteenth of the switch's pop.
TEST(RenderBaked, APrimarySwitchCrossFadesLinearlyBetweenTheTwoLights) {
    test::Scene scene = bakedScene();
    scene.lights[1].role = nullptr;  // the second light a primary too
    const assets::LoadedLevel level = bake("baked_fade", scene);
    uint32_t entity = world::kNoIndex;
    for (uint32_t e = 0; e < level.level.entities.size(); ++e)
        if (level.level.entities[e].flags & world::kEntityDynamic) entity = e;
    ASSERT_NE(entity, world::kNoIndex);
    std::vector<uint32_t> primaries;
    for (uint32_t l = 0; l < level.level.lights.size(); ++l)
        if (level.level.lights[l].role == world::LightRole::kPrimary) primaries.push_back(l);
    ASSERT_GE(primaries.size(), 2u);
    const render::Camera camera = testCamera();
    const glm::vec3 place(0.5f, 0.5f, -1.0f);

    render::RenderDeviceFeatures features;
    vk::Context ctx;
    vk::createContext(ctx, render::renderContextOptions(features, {}));
    {
        render::Renderer renderer;
        render::createRenderer(renderer, ctx, level, options(40.0f, 8.0f));
        auto frameWith = [&](uint32_t primary, uint32_t from, float weight) {
            render::DynamicTransform t{entity, glm::translate(glm::mat4(1.0f), place), primary};
            t.fadingFrom = from;
            t.fadeWeight = weight;
            render::FrameInputs inputs;
            inputs.camera = camera;
            inputs.dynamicTransforms = {&t, 1};
            render::FrameOutput output;
            output.readback = true;
            render::drawFrame(renderer, inputs, output);
            return render::capturedFrame(renderer).linearRgba;
        };
        const std::vector<float> a = frameWith(primaries[0], world::kNoIndex, 1.0f);
        const std::vector<float> b = frameWith(primaries[1], world::kNoIndex, 1.0f);
        float pop = 0.0f, brightest = 0.0f;
        for (size_t i = 0; i < a.size(); ++i) {
            pop = std::max(pop, std::abs(a[i] - b[i]));
            brightest = std::max({brightest, a[i], b[i]});
        }
        std::printf("[ fade ] the switch's pop: %.4g (brightest %.4g)\n", double(pop),
                    double(brightest));
        ASSERT_GT(pop, 0.05f * brightest);  // the two lights light the object differently
        std::vector<float> previous = a;
        float worstStep = 0.0f;
        for (int k = 0; k <= 15; ++k) {
            const float w = float(k) / 15.0f;
            const std::vector<float> f = frameWith(primaries[1], primaries[0], w);
            float worst = 0.0f;
            for (size_t i = 0; i < f.size(); ++i) {
                const float expected = (1.0f - w) * a[i] + w * b[i];
                const float tolerance =
                    3.0f * std::ldexp(std::max({std::abs(a[i]), std::abs(b[i]), 1e-6f}), -11) +
                    1e-3f * brightest;
                worst = std::max(worst, std::abs(f[i] - expected) - tolerance);
                worstStep = std::max(worstStep, std::abs(f[i] - previous[i]));
            }
            EXPECT_LE(worst, 0.0f) << "at weight " << w;
            previous = f;
        }
        std::printf("[ fade ] worst step between consecutive frames: %.4g (%.3f of the pop)\n",
                    double(worstStep), double(worstStep / pop));
        EXPECT_LE(worstStep, pop / 15.0f + 2e-3f * brightest);
        render::destroyRenderer(renderer);
    }
    vk::destroyContext(ctx);
    EXPECT_EQ(ctx.validationCounts.errors.load(), 0u);
}

// The bar scenes' dynamic entities: the bar (the last one) and bakedScene's small box before it
// (kNoIndex where missing).
std::pair<uint32_t, uint32_t> barAndBox(const assets::LoadedLevel& level) {
    uint32_t bar = world::kNoIndex, box = world::kNoIndex;
    for (uint32_t e = 0; e < level.level.entities.size(); ++e)
        if (level.level.entities[e].flags & world::kEntityDynamic) {
            box = bar == world::kNoIndex ? box : bar;
            bar = e;
        }
    return {bar, box};
}

// Draws the bar at rest with primary `primary` and the small box moved to `boxAt`; the frame as
// read back.
const render::CapturedFrame& drawBarFrame(render::Renderer& renderer, const render::Camera& camera,
                                          uint32_t bar, uint32_t primary, uint32_t box,
                                          glm::vec3 boxAt) {
    std::vector<render::DynamicTransform> transforms = {{bar, glm::mat4(1.0f), primary}};
    if (box != world::kNoIndex)
        transforms.push_back({box, glm::translate(glm::mat4(1.0f), boxAt), world::kNoIndex});
    render::FrameInputs inputs;
    inputs.camera = camera;
    inputs.dynamicTransforms = transforms;
    render::FrameOutput output;
    output.readback = true;
    render::drawFrame(renderer, inputs, output);
    return render::capturedFrame(renderer);
}

// A dynamic bar 6 m long, longer than a grid cell, takes its secondary light from a lattice of
// grid samples over its bounds (a cell or less apart along it, on both faces across it), a pixel
// interpolating those around it. Along its top face the rendered radiance is within 5% of the
// grid sampled at each pixel's own point (what the lattice stands in for: the grid is trilinear
// over 1 m cells and the lattice's samples are up to a cell apart and not on the cells' centres,
// so the two interpolations differ where the light curves; measured 2.8%; and the RGBA16F target),
// where the one sample at its origin was several times off.
TEST(RenderBaked, ALongDynamicObjectTakesItsLightAlongItsLength) {
    test::Scene scene = bakedScene();
    scene.lights[1].role = nullptr;  // a second primary: the secondary light varies more
    // The bar's vertices are in the world (its node at the origin): from (-3, 0.3, -4.4) to
    // (3, 0.7, -3.6), its long axis from (-3, 0.5, -4) to (3, 0.5, -4).
    test::addBox(scene, {-3.0f, 0.3f, -4.4f}, {3.0f, 0.7f, -3.6f}, 2, true);
    const assets::LoadedLevel level = bake("baked_long", scene);
    const auto [bar, box] = barAndBox(level);
    ASSERT_NE(bar, world::kNoIndex);
    const render::Camera camera = render::cameraFromYawPitch({0.0f, 6.0f, 1.0f}, 0.0f, -45.0f);
    render::RenderDeviceFeatures features;
    vk::Context ctx;
    vk::createContext(ctx, render::renderContextOptions(features, {}));
    {
        render::Renderer renderer;
        render::createRenderer(renderer, ctx, level, options(40.0f, 8.0f));
        // The small box out of the way; no primary: the secondary alone.
        const render::CapturedFrame& frame =
            drawBarFrame(renderer, camera, bar, world::kNoIndex, box, {4.0f, 0.3f, 3.0f});
        const world::LightGrid& grid = level.baked.grid;
        auto upAt = [&](glm::vec3 p) { return world::sampleLightGrid(grid, p).ambientCube[2]; };
        const glm::vec3 origin = upAt({0.0f, 0.5f, -4.0f});
        const uint32_t material =
            level.level.dynamicMeshes.at(level.level.entities[bar].firstDynamicMesh).material;
        float worstSamples = 0.0f, worstOne = 0.0f;
        for (const float aim : {0.1f, 0.3f, 0.5f, 0.7f, 0.9f}) {
            const glm::uvec2 px = floorPixelNear(camera, {-3.0f + 6.0f * aim, 0.7f, -4.0f});
            // Where the pixel's centre meets the top face (y = 0.7).
            const Ray r = pixelRay(camera, float(px.x) + 0.5f, float(px.y) + 0.5f);
            const glm::vec3 top = r.origin + ((0.7f - r.origin.y) / r.direction.y) * r.direction;
            const size_t at = (size_t(px.y) * kWidth + px.x) * 4;
            const glm::vec3 rendered(frame.linearRgba[at], frame.linearRgba[at + 1],
                                     frame.linearRgba[at + 2]);
            auto radianceOf = [&](glm::vec3 up) {
                return lambertRadiance(level.level, material, world::kNoIndex, 0.0f, up, top, kUp,
                                       camera.position);
            };
            const glm::vec3 reference = radianceOf(upAt(top));
            const glm::vec3 oneSample = radianceOf(origin);
            worstSamples = std::max(worstSamples, float(relativeError(rendered, reference, 1e-4)));
            worstOne = std::max(worstOne, float(relativeError(oneSample, reference, 1e-4)));
            std::printf(
                "[ long ] x %+.2f: rendered %.4g, the grid there %.4g, one sample %.4g (red)\n",
                double(top.x), double(rendered.x), double(reference.x), double(oneSample.x));
        }
        std::printf(
            "[ long ] worst error against the grid at each pixel: the lattice %.3f, one sample "
            "%.3f\n",
            double(worstSamples), double(worstOne));
        EXPECT_LT(worstSamples, 0.05);
        EXPECT_LT(worstSamples, worstOne);
        render::destroyRenderer(renderer);
    }
    vk::destroyContext(ctx);
    EXPECT_EQ(ctx.validationCounts.errors.load(), 0u);
}

// The same 6 m bar, now a mover's stand-in lit as the game lights it (its primary, with a
// runtime shadow; the grid's secondary at its lattice), against the path tracer's image of the
// same scene with the bar standing there as static geometry (every light at full strength, the
// bar's own shadows and bounces included). Measured on the bar's top in six 1 m bands along it:
// each band's mean radiance, the frame's against the reference's. The secondary light changes
// several fold along the bar (the baked lamp stands 2.2 m from its end), which one sample at its
// origin cannot follow; the same bands evaluated on the CPU with the grid at the origin alone, and
// with the grid at each pixel's own point, give the error the lattice removes and the grid's own.
// Measured (2026-12-06): worst band 5.4% (the grid at each pixel: 1.8%; one sample at the
// origin: 54%; samples along the bar's axis only, before the lattice: 27%).
// Tolerance: the worst band under 10%: the reference's own noise at 256 paths per pixel over a
// band's ~100 pixels is under 1%, the grid's own error ~2% here, and the lattice's samples, up
// to a cell apart, interpolate a lamp's 1 / r^2 falloff 2 m away linearly (a few %).
TEST(RenderBaked, ALongDynamicObjectIsLitCloseToThePathTracer) {
    test::Scene scene = bakedScene();
    const glm::vec3 lo(-3.0f, 0.3f, -4.4f), hi(3.0f, 0.7f, -3.6f);
    test::addBox(scene, lo, hi, 2, true);
    const render::Camera camera = render::cameraFromYawPitch({0.0f, 6.0f, 1.0f}, 0.0f, -45.0f);
    scene.viewPosition = camera.position;
    scene.viewRotation = camera.rotation;
    scene.viewYfov = camera.yfov;
    scene.viewAspect = float(kWidth) / float(kHeight);
    const assets::LoadedLevel level = bake("baked_long_reference", scene);
    const auto [bar, box] = barAndBox(level);
    ASSERT_NE(bar, world::kNoIndex);

    // The reference: the bar static, the small dynamic box left out of both (moved away below).
    test::Scene still = scene;
    still.meshes.back().dynamic = false;
    for (size_t m = 0; m + 1 < still.meshes.size(); ++m)
        if (still.meshes[m].dynamic) still.meshes[m].positions.clear();
    std::erase_if(still.meshes, [](const test::SceneMesh& m) { return m.positions.empty(); });
    const std::string folder = test::outputDir();
    test::writeGltf(still, folder + "/long_reference.gltf");
    const std::string exr = folder + "/long_reference.exr";
    const world::ChildResult pathTraced = world::runChild(
        {ONELIGHT_BAKE_PATH, "reference", folder + "/long_reference.gltf", "--camera", "view",
         "--size", std::to_string(kWidth) + "x" + std::to_string(kHeight), "--spp", "256", "-o",
         exr});
    ASSERT_EQ(pathTraced.exitCode, 0) << pathTraced.err;
    const world::FloatImage reference = world::readExrFile(exr);
    ASSERT_EQ(reference.width, kWidth);
    ASSERT_EQ(reference.height, kHeight);

    vk::Context ctx;
    render::RenderDeviceFeatures features;
    vk::createContext(ctx, render::renderContextOptions(features, {}));
    {
        render::Renderer renderer;
        render::createRenderer(renderer, ctx, level, options(40.0f, 8.0f));
        const glm::vec3 centre = 0.5f * (lo + hi);
        uint32_t primary = world::kNoIndex;  // the scene's one primary: the game's pick
        for (uint32_t l = 0; l < level.level.lights.size(); ++l)
            if (level.level.lights[l].role == world::LightRole::kPrimary) primary = l;
        ASSERT_NE(primary, world::kNoIndex);
        // The small box far off the floor, out of the view.
        const render::CapturedFrame& frame =
            drawBarFrame(renderer, camera, bar, primary, box, {0.0f, -50.0f, 0.0f});
        world::writeExrFile(folder + "/long_frame.exr", kWidth, kHeight, frame.linearRgba);

        const world::LightGrid& grid = level.baked.grid;
        const uint32_t material =
            level.level.dynamicMeshes.at(level.level.entities[bar].firstDynamicMesh).material;
        const glm::vec3 atOrigin = world::sampleLightGrid(grid, centre).ambientCube[2];
        const auto luminance = [](glm::dvec3 c) {
            return 0.2126 * c.x + 0.7152 * c.y + 0.0722 * c.z;
        };
        constexpr int kBands = 6;
        glm::dvec3 rendered[kBands] = {}, traced[kBands] = {}, oneSample[kBands] = {},
                   atPixel[kBands] = {};
        int pixels[kBands] = {};
        for (uint32_t y = 0; y < kHeight; ++y)
            for (uint32_t x = 0; x < kWidth; ++x) {
                // Pixels whose whole footprint lies on the top face, 5 cm in from its edges.
                bool inside = true;
                glm::vec3 top(0.0f);
                for (const float o : {0.0f, 0.5f, 1.0f}) {
                    const Ray r = pixelRay(camera, float(x) + o, float(y) + o);
                    const glm::vec3 p =
                        r.origin + ((hi.y - r.origin.y) / r.direction.y) * r.direction;
                    inside = inside && p.x > lo.x + 0.05f && p.x < hi.x - 0.05f &&
                             p.z > lo.z + 0.05f && p.z < hi.z - 0.05f;
                    if (o == 0.5f) top = p;
                }
                if (!inside) continue;
                const int band = std::clamp(int(top.x - lo.x), 0, kBands - 1);
                const size_t at = (size_t(y) * kWidth + x) * 4;
                rendered[band] += glm::dvec3(frame.linearRgba[at], frame.linearRgba[at + 1],
                                             frame.linearRgba[at + 2]);
                traced[band] +=
                    glm::dvec3(reference.rgba[at], reference.rgba[at + 1], reference.rgba[at + 2]);
                oneSample[band] += glm::dvec3(lambertRadiance(level.level, material, primary, 1.0f,
                                                              atOrigin, top, kUp, camera.position));
                atPixel[band] += glm::dvec3(lambertRadiance(
                    level.level, material, primary, 1.0f,
                    world::sampleLightGrid(grid, top).ambientCube[2], top, kUp, camera.position));
                ++pixels[band];
            }
        double worstFrame = 0.0, worstOne = 0.0;
        for (int b = 0; b < kBands; ++b) {
            ASSERT_GT(pixels[b], 20) << "band " << b;
            const double want = luminance(traced[b]);
            const double frameError = std::fabs(luminance(rendered[b]) - want) / want;
            const double oneError = std::fabs(luminance(oneSample[b]) - want) / want;
            worstFrame = std::max(worstFrame, frameError);
            worstOne = std::max(worstOne, oneError);
            std::printf(
                "[ long/reference ] band x %+.0f..%+.0f m (%d px): reference %.4g, frame %.4g "
                "(%+.1f%%), the grid at each pixel %.4g (%+.1f%%), one grid sample at the origin "
                "%.4g (%+.1f%%) cd/m^2\n",
                double(lo.x) + b, double(lo.x) + b + 1, pixels[b], want / pixels[b],
                luminance(rendered[b]) / pixels[b], 100.0 * (luminance(rendered[b]) - want) / want,
                luminance(atPixel[b]) / pixels[b], 100.0 * (luminance(atPixel[b]) - want) / want,
                luminance(oneSample[b]) / pixels[b],
                100.0 * (luminance(oneSample[b]) - want) / want);
        }
        std::printf(
            "[ long/reference ] worst band against the path tracer: frame %.1f%%, one grid "
            "sample at the origin %.1f%%\n",
            100.0 * worstFrame, 100.0 * worstOne);
        EXPECT_LT(worstFrame, 0.10);
        EXPECT_LT(worstFrame, worstOne);
        render::destroyRenderer(renderer);
    }
    vk::destroyContext(ctx);
    EXPECT_EQ(ctx.validationCounts.errors.load(), 0u);
}

// A Lambert floor under a uniform sky of radiance L and nothing else sees sky over its whole
// upper hemisphere: E = pi L, so its radiance is albedo L (closed form; and noise-free, as
// every path escapes at its first ray). Where the frame shows no geometry it shows the sky, L.
// Tolerance 1%: RGBA16F lightmap coefficients and HDR target (2^-11 each), the readback's
// un-exposure.
TEST(RenderBaked, FloorUnderAUniformSkyIsAlbedoTimesSky) {
    test::Scene scene;
    scene.materials = {{{0.5f, 0.5f, 0.5f, 1.0f}, 0.0f, 1.0f}};  // Lambert
    test::addFloor(scene, 0.0f, 0.0f, 10.0f, 0.0f, 0);
    scene.sky = glm::vec3(1000.0f, 2000.0f, 3000.0f);
    const std::string gltf = test::outputDir() + "/sky_floor.gltf";
    test::writeGltf(scene, gltf);
    const assets::LoadedLevel level =
        test::bakeAndLoad(gltf, test::outputDir() + "/sky_floor.olpak");
    ASSERT_TRUE(level.hasBakedLighting);
    EXPECT_EQ(level.level.settings.skyRadiance, scene.sky);

    render::FrameInputs inputs;
    inputs.camera = render::cameraFromYawPitch({0.0f, 2.0f, 6.0f}, 0.0f, -10.0f);
    inputs.camera.hasExposure = true;
    inputs.camera.ev100 = 10.0f;
    const std::vector<float> linear =
        renderLinear(level, options(40.0f, 8.0f), inputs, "sky_floor");
    const glm::vec3 sky = pixel(linear, kWidth / 2, 2);
    EXPECT_LT(relativeError(sky, scene.sky, 1.0), 0.01) << sky.x << " " << sky.y << " " << sky.z;
    const glm::uvec2 at = floorPixelNear(inputs.camera, {0.0f, 0.0f, 2.0f});
    const glm::vec3 floor = pixel(linear, at.x, at.y);
    EXPECT_LT(relativeError(floor, 0.5f * scene.sky, 1.0), 0.01)
        << floor.x << " " << floor.y << " " << floor.z;
}

// An emissive surface shows its own radiance, pre-exposed like the rest of the frame: a black
// floor of emission 0.5 x strength 800 = 400 cd/m^2 reads 400 cd/m^2 in the linear capture at
// two exposures four stops apart (an exposure-relative emission would differ 16 times). No
// light and no sky: the floor pixel is the emission alone.
// Tolerance 1%: the HDR target's half floats and the readback's un-exposure.
TEST(RenderBaked, AnEmissiveSurfaceShowsItsLuminancePreExposed) {
    test::Scene scene;
    test::SceneMaterial glow{{0.0f, 0.0f, 0.0f, 1.0f}, 0.0f, 1.0f};
    glow.emissive = glm::vec3(0.5f);
    glow.emissiveStrength = 800.0f;
    scene.materials = {glow};
    test::addFloor(scene, 0.0f, 0.0f, 10.0f, 0.0f, 0);
    const std::string gltf = test::outputDir() + "/emissive_floor.gltf";
    test::writeGltf(scene, gltf);
    const assets::LoadedLevel level =
        test::bakeAndLoad(gltf, test::outputDir() + "/emissive_floor.olpak");
    ASSERT_EQ(level.level.materials.size(), 1u);
    EXPECT_EQ(level.level.materials[0].emissive, glm::vec3(400.0f));
    for (float ev100 : {6.0f, 10.0f}) {
        render::FrameInputs inputs;
        inputs.camera = render::cameraFromYawPitch({0.0f, 2.0f, 6.0f}, 0.0f, -10.0f);
        inputs.camera.hasExposure = true;
        inputs.camera.ev100 = ev100;
        const std::vector<float> linear = renderLinear(level, options(40.0f, 8.0f), inputs,
                                                       "emissive_ev" + std::to_string(int(ev100)));
        const glm::uvec2 at = floorPixelNear(inputs.camera, {0.0f, 0.0f, 2.0f});
        const glm::vec3 floor = pixel(linear, at.x, at.y);
        EXPECT_LT(relativeError(floor, glm::vec3(400.0f), 1.0), 0.01)
            << "EV " << ev100 << ": " << floor.x << " " << floor.y << " " << floor.z;
    }
}

// A sky image behind the level: every pixel the floor leaves to the sky shows the image along
// the pixel's ray (shaders/sky.glsl's mapping, bilinear between texel centres) times its scale,
// at two exposures and two headings (u varies with the heading, so a turned or mirrored
// mapping shows). Tolerance 1 %: the half-float texels and HDR target round at 2^-11, the
// sampler weighs with 8 fractional bits on a sky that changes by < 3 % between texels.
glm::vec3 equirectBilinear(const world::HdrImage& image, const glm::vec3& direction) {
    const glm::vec2 uv = glsl::equirectUv_fromDirection(direction);
    const float x = uv.x * float(image.width) - 0.5f, y = uv.y * float(image.height) - 0.5f;
    const int w = int(image.width), h = int(image.height);
    const int x0 = int(std::floor(x)), y0 = int(std::floor(y));
    const float fx = x - float(x0), fy = std::clamp(y - float(y0), 0.0f, 1.0f);
    const auto at = [&](int i, int j) {
        i = std::clamp(i, 0, h - 1);
        j = ((j % w) + w) % w;
        const size_t t = (size_t(i) * image.width + size_t(j)) * 3;
        return glm::vec3(image.rgb[t], image.rgb[t + 1], image.rgb[t + 2]);
    };
    return glm::mix(glm::mix(at(y0, x0), at(y0, x0 + 1), fx),
                    glm::mix(at(y0 + 1, x0), at(y0 + 1, x0 + 1), fx), fy);
}

TEST(RenderBaked, TheSkyImageShowsBehindTheLevel) {
    world::HdrImage sky;
    sky.width = 64;
    sky.height = 32;
    for (uint32_t i = 0; i < sky.height; ++i)
        for (uint32_t j = 0; j < sky.width; ++j) {
            const float v = (float(i) + 0.5f) / float(sky.height);
            const float u = (float(j) + 0.5f) / float(sky.width);
            // Neither symmetric in u nor about u = 1/2: a mirrored or turned mapping shows.
            const float around =
                1.0f + 0.3f * std::cos(6.2831853f * u) + 0.2f * std::sin(6.2831853f * u);
            sky.rgb.insert(sky.rgb.end(),
                           {(1.0f - 0.6f * v) * around, (1.0f - 0.5f * v) * around, 1.0f * around});
        }
    world::writeHdrFile(test::outputDir() + "/sky_image.hdr", sky.width, sky.height, sky.rgb);
    const world::HdrImage stored = world::readHdrFile(test::outputDir() + "/sky_image.hdr");
    test::Scene scene;
    scene.materials = {{{0.5f, 0.5f, 0.5f, 1.0f}, 0.0f, 1.0f}};
    test::addFloor(scene, 0.0f, 0.0f, 10.0f, 0.0f, 0);
    scene.sky = glm::vec3(2000.0f);
    scene.skyImage = "sky_image.hdr";
    const std::string gltf = test::outputDir() + "/sky_image.gltf";
    test::writeGltf(scene, gltf);
    const assets::LoadedLevel level =
        test::bakeAndLoad(gltf, test::outputDir() + "/sky_image.olpak");
    ASSERT_EQ(level.sky.width, sky.width);
    for (const float yaw : {0.0f, 120.0f})
        for (const float ev100 : {8.0f, 12.0f}) {
            render::FrameInputs inputs;
            inputs.camera = render::cameraFromYawPitch({0.0f, 2.0f, 0.0f}, yaw, 20.0f);
            inputs.camera.hasExposure = true;
            inputs.camera.ev100 = ev100;
            const std::string name =
                "sky_image_yaw" + std::to_string(int(yaw)) + "_ev" + std::to_string(int(ev100));
            const std::vector<float> linear =
                renderLinear(level, options(0.01f, 0.005f), inputs, name);
            int checked = 0;
            double worst = 0.0;
            for (uint32_t y = 0; y < kHeight; y += 3)
                for (uint32_t x = 0; x < kWidth; x += 3) {
                    const Ray r = pixelRay(inputs.camera, float(x) + 0.5f, float(y) + 0.5f);
                    if (r.direction.y < 0.05f) continue;  // the floor, its edge, the horizon
                    const glm::vec3 want = equirectBilinear(stored, r.direction) * 2000.0f;
                    worst = std::max(worst, relativeError(pixel(linear, x, y), want, 1.0));
                    ++checked;
                }
            std::printf("[ sky ] %s: %d sky pixels, worst %.3f %%\n", name.c_str(), checked,
                        100.0 * worst);
            EXPECT_GT(checked, 500);
            EXPECT_LT(worst, 0.01) << name;
        }
}

// The probe path of the forward shader against the C++ formula: a dielectric floor (dark, so
// the specular weighs) under a uniform grey sky L, its baked probes replaced in memory by one
// synthetic probe (and a decoy) whose mips are uniform and coloured apart (mip 0 red, 1 green, 2
// blue, normalised radiance 1 / pi). The floor's E(n) is pi L (it sees only sky), so a floor pixel
// is
//   (1 - (f0 A + B)) albedo L + (f0 A + B) c(lod) pi L,   lod = probeMipOfGloss(gloss, 3),
// c the trilinear mix of the two mips around lod and (A, B) the split-sum table at (NoV, gloss):
// the mip chosen by the gloss, the upload's mip order (per mip, every probe's faces), the
// de-normalisation by E(n), the environment "Fresnel" and the diffuse's energy-conservation
// weight all show in the colour. Tolerance 1.5% of the pixel: the GPU holds the table in half
// floats, RGB9E5 rounds at 1/512 and the mip lerp weight has 8 fractional bits.
TEST(RenderBaked, GlossyFloorReadsTheProbeMipOfItsGlossTimesItsIrradiance) {
    test::Scene scene;
    const float roughness = 0.4f;
    scene.materials = {{{0.05f, 0.05f, 0.05f, 1.0f}, 0.0f, roughness}};  // dielectric, f0 0.04
    test::addFloor(scene, 0.0f, 0.0f, 10.0f, 0.0f, 0);
    scene.sky = glm::vec3(1000.0f);
    const std::string gltf = test::outputDir() + "/probe_floor.gltf";
    test::writeGltf(scene, gltf);
    assets::LoadedLevel level = test::bakeAndLoad(gltf, test::outputDir() + "/probe_floor.olpak");
    ASSERT_TRUE(level.hasBakedLighting);

    // The coloured probe is boxed around the floor; a grey one without a box, 30 m away, comes
    // first in the package but last in blending order (larger influence volume) and in the cube
    // array: the floor reads only the coloured one, through the per-mip, per-probe upload.
    const glm::vec3 mipColour[3] = {
        {glsl::INV_PI, 0.0f, 0.0f}, {0.0f, glsl::INV_PI, 0.0f}, {0.0f, 0.0f, glsl::INV_PI}};
    world::EnvironmentProbe coloured, grey;
    coloured.position = glm::vec3(0.0f, 1.0f, 0.0f);
    coloured.boxMin = glm::vec3(-20.0f, -1.0f, -20.0f);
    coloured.boxMax = glm::vec3(20.0f, 10.0f, 20.0f);
    grey.position = glm::vec3(30.0f, 1.0f, 0.0f);
    for (world::EnvironmentProbe* probe : {&coloured, &grey}) {
        // Captured where the light equals the floor's: the floor reads the texels times its own
        // irradiance (shaders/probe.glsl, "Normalization").
        probe->irradianceCube.fill(probe->irradianceAverage);
        probe->faceSize = 4;
        probe->mipCount = 3;
        for (uint32_t m = 0; m < 3; ++m)
            for (uint32_t t = 0; t < 6 * (4u >> m) * (4u >> m); ++t)
                probe->texels.push_back(package::encodeRgb9e5(
                    probe == &coloured ? mipColour[m] : glm::vec3(0.5f * glsl::INV_PI)));
    }
    level.baked.probes = {grey, coloured};

    render::FrameInputs inputs;
    inputs.camera = render::cameraFromYawPitch({0.0f, 2.0f, 6.0f}, 0.0f, -20.0f);
    inputs.camera.hasExposure = true;
    inputs.camera.ev100 = 10.0f;
    const std::vector<float> linear =
        renderLinear(level, options(40.0f, 8.0f), inputs, "probe_floor");
    for (const glm::vec3 target : {glm::vec3(0.0f, 0.0f, 2.0f), glm::vec3(-1.5f, 0.0f, 0.0f)}) {
        const glm::uvec2 at = floorPixelNear(inputs.camera, target);
        const glm::vec3 p = floorPointOf(inputs.camera, at);
        const float NoV = glm::normalize(inputs.camera.position - p).y;
        const float gloss = glsl::gloss_fromRoughness(roughness);
        const float lod = glsl::probeMipOfGloss(gloss, 3);
        const int below = int(std::floor(lod));
        const float t = lod - float(below);
        const glm::vec3 c = (1.0f - t) * mipColour[below] + t * mipColour[std::min(below + 1, 2)];
        const glm::vec2 env = glsl::sampleEnvBrdfTable(glsl::envBrdfTableCoord(NoV, gloss));
        const float specularAlbedo = 0.04f * env.x + env.y;
        const glm::vec3 want =
            (1.0f - specularAlbedo) * 0.05f * scene.sky + specularAlbedo * c * glsl::PI * scene.sky;
        const glm::vec3 got = pixel(linear, at.x, at.y);
        const float tolerance = 0.015f * std::max({want.x, want.y, want.z});
        for (int ch = 0; ch < 3; ++ch)
            EXPECT_NEAR(got[ch], want[ch], tolerance)
                << "channel " << ch << " at (" << target.x << ", " << target.z << "), lod " << lod;
    }
}

}  // namespace

namespace {

/// A quad a b c d, counter-clockwise seen from the side it faces, as two triangles.
void addQuad(test::Scene& scene, glm::vec3 a, glm::vec3 b, glm::vec3 c, glm::vec3 d,
             uint32_t material) {
    test::SceneMesh mesh;
    const glm::vec3 n = glm::normalize(glm::cross(b - a, c - a));
    mesh.positions = {a, b, c, d};
    mesh.normals = {n, n, n, n};
    mesh.indices = {0, 1, 2, 0, 2, 3};
    mesh.material = material;
    scene.meshes.push_back(mesh);
}

// A 4 x 2.5 x 3 m room of single-sided quads (y up), lit by a high sun through a 1 x 1 m opening
// in its ceiling: outside the sunlit patch on the floor no point of the room sees the sun.
// Near the camera the primary's shadow comes from the runtime shadow map; far away from the
// baked mask. The two must agree off the patch: a frame drawn with the runtime shadows (radius
// 40 m) may not be sunlit where the baked-mask frame (radius 1 cm) is dim. Before the sun's map
// was fitted to the level (it spanned 100 m in 1024 texels, 10 cm each) and its slope bias
// clamped, bands a texel wide along every junction of walls, floor and ceiling were sunlit, up
// to 40 times the baked-mask frame: 6.3% of the dim pixels over 2x. Then 0.37%: lines a pixel
// wide at the junctions, where the map's filter reached past a wall's foot into texels that hold
// nothing. Now a static surface's mask vetoes a runtime lookup wherever it is umbra over its
// whole bilinear footprint: 1 pixel of 23771 (0.004%); the bound is 0.05%. Pixels counted: those
// whose baked-mask radiance is under a tenth of the patch's (off the patch and its penumbra).
TEST(RenderBaked, RuntimeSunShadowsDoNotLeakAlongTheJunctionsOfThinWalls) {
    test::Scene s;
    s.materials = {{{0.6f, 0.6f, 0.6f, 1.0f}, 0.0f, 1.0f}};
    const float x0 = -2.0f, x1 = 2.0f, z0 = -1.5f, z1 = 1.5f, h = 2.5f;
    addQuad(s, {x0, 0, z0}, {x0, 0, z1}, {x1, 0, z1}, {x1, 0, z0}, 0);  // floor, up
    addQuad(s, {x0, 0, z0}, {x1, 0, z0}, {x1, h, z0}, {x0, h, z0}, 0);  // z0 wall, +z
    addQuad(s, {x1, 0, z1}, {x0, 0, z1}, {x0, h, z1}, {x1, h, z1}, 0);  // z1 wall, -z
    addQuad(s, {x0, 0, z1}, {x0, 0, z0}, {x0, h, z0}, {x0, h, z1}, 0);  // x0 wall, +x
    addQuad(s, {x1, 0, z0}, {x1, 0, z1}, {x1, h, z1}, {x1, h, z0}, 0);  // x1 wall, -x
    const float ox0 = 0.3f, ox1 = 1.3f, oz0 = -0.5f, oz1 = 0.5f;
    const auto ceiling = [&](float ax, float az, float bx, float bz) {  // facing down
        addQuad(s, {ax, h, az}, {bx, h, az}, {bx, h, bz}, {ax, h, bz}, 0);
    };
    ceiling(x0, z0, ox0, z1);
    ceiling(ox1, z0, x1, z1);
    ceiling(ox0, z0, ox1, oz0);
    ceiling(ox0, oz1, ox1, z1);
    test::SceneLight sun;
    sun.type = 0;
    sun.intensity = 20000.0f;
    sun.direction = glm::normalize(glm::vec3(0.25f, -1.0f, -0.15f));
    s.lights.push_back(sun);
    const std::string gltf = test::outputDir() + "/thin_room.gltf";
    test::writeGltf(s, gltf);
    const assets::LoadedLevel level =
        test::bakeAndLoad(gltf, test::outputDir() + "/thin_room.olpak", "--texels-per-metre 6");

    render::FrameInputs inputs;
    const glm::vec3 eye(-1.85f, 1.75f, 1.35f), target(0.9f, 0.5f, -0.8f);
    const glm::vec3 d = glm::normalize(target - eye);
    inputs.camera = render::cameraFromYawPitch(eye, glm::degrees(std::atan2(-d.x, -d.z)),
                                               glm::degrees(std::asin(d.y)));
    const std::vector<float> runtime =
        renderLinear(level, options(40.0f, 8.0f), inputs, "thin_room_runtime");
    const std::vector<float> baked =
        renderLinear(level, options(0.01f, 0.005f), inputs, "thin_room_baked");
    const auto luminanceAt = [](const std::vector<float>& f, size_t i) {
        return 0.2126f * f[4 * i] + 0.7152f * f[4 * i + 1] + 0.0722f * f[4 * i + 2];
    };
    float patch = 0.0f;
    for (size_t i = 0; i < size_t(kWidth) * kHeight; ++i)
        patch = std::max(patch, luminanceAt(baked, i));
    size_t dim = 0, leaks = 0;
    for (size_t i = 0; i < size_t(kWidth) * kHeight; ++i) {
        const float b = luminanceAt(baked, i), r = luminanceAt(runtime, i);
        ASSERT_TRUE(std::isfinite(r) && std::isfinite(b));
        if (b <= 0.0f || b > 0.1f * patch) continue;
        ++dim;
        leaks += r > 2.0f * b;
    }
    std::printf("[ thin room ] %zu of %zu dim pixels sunlit by the runtime shadows\n", leaks, dim);
    ASSERT_GT(dim, size_t(kWidth) * kHeight / 2);
    EXPECT_LT(double(leaks), 0.0005 * double(dim));
}

// Culling by the potentially visible set changes no pixel: a 40 m hall cut into three rooms by
// two walls with offset doorways (a chicane), seen from the first room towards the doorway and
// from the middle room, with culling on and off, gives identical frames; from the first room
// the far room's surfaces are not drawn.
TEST(RenderBaked, CullingByTheVisibleSetChangesNoPixel) {
    test::Scene s;
    s.materials = {{{0.6f, 0.6f, 0.6f, 1.0f}, 0.0f, 0.6f}};
    test::addChicaneHall(s, 3);
    const std::string gltf = test::outputDir() + "/chicane.gltf";
    test::writeGltf(s, gltf);
    const assets::LoadedLevel level =
        test::bakeAndLoad(gltf, test::outputDir() + "/chicane.olpak", "--texels-per-metre 2");
    ASSERT_FALSE(level.baked.visibility.empty());

    struct View {
        glm::vec3 eye;
        float yaw, pitch;
        bool hidesSome;
    };
    for (const View& view : {View{{-14.0f, 1.7f, 3.0f}, -127.0f, -5.0f, true},
                             View{{-2.0f, 1.7f, 5.0f}, -63.0f, -5.0f, false}}) {
        render::FrameInputs inputs;
        inputs.camera = render::cameraFromYawPitch(view.eye, view.yaw, view.pitch);
        render::RendererOptions on = options(40.0f, 8.0f), off = on;
        off.visibilityCulling = false;
        const test::RenderedFrame culled = test::renderOnce(level, on, inputs);
        const test::RenderedFrame all = test::renderOnce(level, off, inputs);
        std::printf(
            "[ chicane ] from (%.0f, %.0f): %u surfaces drawn with culling, %u without; %u "
            "hidden by the visible set\n",
            double(view.eye.x), double(view.eye.z), culled.stats.surfacesDrawn,
            all.stats.surfacesDrawn, culled.stats.surfacesHidden);
        EXPECT_EQ(all.stats.surfacesHidden, 0u);
        // The level's one material is bound once, its one page of records with the frame's set;
        // a pipeline at most once a draw.
        EXPECT_EQ(culled.stats.materialBinds, 1u);
        EXPECT_EQ(culled.stats.frameSetBinds, 0u);
        EXPECT_GE(culled.stats.pipelineBinds, 1u);
        EXPECT_LE(culled.stats.pipelineBinds, culled.stats.draws);
        if (view.hidesSome) {
            EXPECT_GT(culled.stats.surfacesHidden, 20u);
        }
        ASSERT_EQ(culled.frame.rgba8.size(), all.frame.rgba8.size());
        size_t differing = 0;
        for (size_t i = 0; i < all.frame.rgba8.size(); ++i)
            differing += culled.frame.rgba8[i] != all.frame.rgba8[i];
        EXPECT_EQ(differing, 0u);
        EXPECT_TRUE(culled.frame.linearRgba == all.frame.linearRgba);
        if (differing) {
            world::writePngFile(test::outputDir() + "/chicane_culled.png", kWidth, kHeight,
                                culled.frame.rgba8);
            world::writePngFile(test::outputDir() + "/chicane_all.png", kWidth, kHeight,
                                all.frame.rgba8);
        }
    }
}

}  // namespace
