// The light transport sees the real material: textures reach every ray hit of the reference path
// tracer and of the baker's bounces (bake/materials), against closed forms.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>

#include <glm/gtc/quaternion.hpp>

#include "bake/embree/bake_scene.hpp"
#include "bake/lighting/radiance.hpp"
#include "bake/materials/bake_textures.hpp"
#include "bake/reference/path_tracer.hpp"
#include "bake_scenes.hpp"
#include "env_brdf_table.hpp"
#include "shading.hpp"
#include "world/compile/static_split.hpp"

namespace onelight::bake {
namespace {

std::string outputFolder() {
    const std::filesystem::path dir = std::filesystem::temp_directory_path() / "onelight_materials";
    std::filesystem::create_directories(dir);
    return dir.string();
}

// IEC 61966-2-1, the linear value of an 8-bit sRGB code.
float linearOf(uint8_t code) {
    const float c = float(code) / 255.0f;
    return c <= 0.04045f ? c / 12.92f : std::pow((c + 0.055f) / 1.055f, 2.4f);
}

// An 8x8 checker of 2x2-texel blocks, codes `a` and `b` (grey).
std::vector<uint8_t> checker(uint8_t a, uint8_t b) {
    std::vector<uint8_t> rgba;
    for (int y = 0; y < 8; ++y)
        for (int x = 0; x < 8; ++x) {
            const uint8_t c = ((x / 2 + y / 2) % 2) ? b : a;
            rgba.insert(rgba.end(), {c, c, c, 255});
        }
    return rgba;
}

constexpr uint8_t kLight = 220, kDark = 50;

// A 2 x 2 m Lambert plane at y = 0 whose uv covers [0, 1]^2 once (u along +x, v along +z),
// textured with the checker, under a uniform sky; a camera 2 m above looks straight down.
world::SourceLevel checkerPlane(float sky) {
    world::SourceLevel level;
    const uint32_t m = test::addLambertMaterial(level, 1.0f);
    world::Sampler nearest;
    nearest.magFilter = 9728;
    level.materials[m].baseColorTexture = test::addImageTexture(
        level, outputFolder() + "/checker.png", 8, 8, checker(kLight, kDark), nearest);
    world::MeshInstance plane;
    plane.nodeName = plane.meshName = "plane";
    plane.material = m;
    for (int i = 0; i < 4; ++i) {
        world::Vertex v;
        const float x = (i == 1 || i == 2) ? 1.0f : -1.0f, z = (i >= 2) ? 1.0f : -1.0f;
        v.position = {x, 0.0f, z};
        v.normal = {0.0f, 1.0f, 0.0f};
        v.uv0 = {0.5f * (x + 1.0f), 0.5f * (z + 1.0f)};
        plane.vertices.push_back(v);
    }
    plane.indices = {0, 2, 1, 0, 3, 2};  // counter-clockwise seen from +y
    level.instances.push_back(plane);
    world::Camera camera;
    camera.name = "down";
    camera.position = {0.0f, 2.0f, 0.0f};
    camera.rotation = glm::angleAxis(-0.5f * 3.14159265f, glm::vec3(1.0f, 0.0f, 0.0f));
    camera.yfov = 0.8f;
    level.cameras.push_back(camera);
    level.skyRadiance = glm::vec3(sky);
    return level;
}

// The checker's linear albedo at plane point (x, z), or -1 within `margin` (uv) of a block edge.
float checkerAlbedoAt(float x, float z, float margin) {
    const float u = 0.5f * (x + 1.0f), v = 0.5f * (z + 1.0f);
    const float bu = u * 4.0f, bv = v * 4.0f;  // 4 x 4 blocks
    const auto nearEdge = [&](float b) {
        const float f = b - std::floor(b);
        return f < margin * 4.0f || f > 1.0f - margin * 4.0f;
    };
    if (u <= 0.0f || u >= 1.0f || v <= 0.0f || v >= 1.0f || nearEdge(bu) || nearEdge(bv))
        return -1.0f;
    return linearOf(((int(bu) + int(bv)) % 2) ? kDark : kLight);
}

// Under a uniform sky L an open Lambert plane reflects albedo x L (every path escapes after its
// first bounce, so each sample is exact): the reference shows each checker texel's albedo x L,
// and the lightmap's irradiance stays pi L: the texture reaches the frame through the
// renderer, not through the bake.
TEST(MaterialTransport, ACheckerUnderAUniformSkyShowsEachTexelsAlbedo) {
    const float sky = 1000.0f;
    const world::SourceLevel level = checkerPlane(sky);
    const test::LevelScene built(level);
    const BakeScene& scene = built.scene;
    const BakeLights& lights = built.lights;
    RayCounts rays;
    const uint32_t size = 64;
    const ReferenceImage image =
        renderReference(scene, lights, level.cameras[0], size, size, 4, {}, nullptr, rays);
    const glm::mat3 rotation = glm::mat3_cast(level.cameras[0].rotation);
    const float tanHalf = std::tan(0.5f * level.cameras[0].yfov);
    int checked[2] = {0, 0};
    for (uint32_t y = 0; y < size; ++y)
        for (uint32_t x = 0; x < size; ++x) {
            const float sx = (float(x) + 0.5f) / float(size) * 2.0f - 1.0f;
            const float sy = 1.0f - (float(y) + 0.5f) / float(size) * 2.0f;
            const glm::vec3 d = rotation * glm::vec3(sx * tanHalf, sy * tanHalf, -1.0f);
            const glm::vec3 p = level.cameras[0].position + d * (2.0f / -d.y);
            // A pixel spans 2 tan(0.4) 2 / 64 = 0.053 m = 0.013 uv: stay 0.02 uv inside blocks.
            const float albedo = checkerAlbedoAt(p.x, p.z, 0.02f);
            if (albedo < 0.0f) continue;
            const float rendered = image.rgb[(size_t(y) * size + x) * 3];
            ASSERT_NEAR(rendered, albedo * sky, 0.01f * albedo * sky) << "pixel " << x << ", " << y;
            ++checked[albedo > 0.5f ? 1 : 0];
        }
    EXPECT_GT(checked[0], 200);
    EXPECT_GT(checked[1], 200);

    BakeOptions options = test::testOptions(8.0f);
    options.indirectSamples = 64;
    const BakeResult baked = bakeLevel(level, options);
    ASSERT_FALSE(baked.baked.texels.empty());
    int sampled = 0;
    for (const world::LightmapTexel& t : baked.baked.texels) {
        if (!(t.flags & world::kLightmapTexelSampled)) continue;
        ASSERT_NEAR(t.irradiance.x, 3.14159265f * sky, 0.01f * 3.14159265f * sky);
        ++sampled;
    }
    EXPECT_GT(sampled, 100);
}

// An integrating sphere: a closed Lambert sphere with a point light at its centre. Direct light
// E_d = I / R^2 lands evenly, and every reflection spreads evenly over a Lambert sphere, so the
// irradiance anywhere is E_d (1 + rho + rho^2 + ...) = E_d / (1 - rho) with rho the wall's
// mean albedo. The wall is textured with stripes of two albedos: only their mean makes the
// closed form (the material's factor, white, would not converge at all).
TEST(MaterialTransport, AnIntegratingSphereSeesItsTexturesMeanAlbedo) {
    world::SourceLevel level;
    const uint32_t m = test::addLambertMaterial(level, 1.0f);
    std::vector<uint8_t> stripes;
    const uint8_t codes[2] = {240, 150};
    for (int x = 0; x < 16; ++x)
        stripes.insert(stripes.end(), {codes[x % 2], codes[x % 2], codes[x % 2], 255});
    level.materials[m].baseColorTexture =
        test::addImageTexture(level, outputFolder() + "/stripes.png", 16, 1, stripes);
    const float radius = 2.0f, candela = 100.0f;
    test::addInwardSphere(level, glm::vec3(0.0f), radius, 64, 128, m);
    level.lights.push_back(test::pointLight(glm::vec3(0.0f), candela, world::LightRole::kBaked));
    const test::LevelScene built(level);
    const BakeScene& scene = built.scene;
    const BakeLights& lights = built.lights;
    TransportSettings transport;
    transport.maxDepth = 200;
    RayCounts rays;
    const double rho = 0.5 * (double(linearOf(codes[0])) + double(linearOf(codes[1])));
    // A point 2 cm inside the wall, looking in: the direct light there is I / d^2 (the light
    // straight ahead), the indirect light the wall's, uniform inside the sphere.
    const float phi = 2.0f * 3.14159265f * 0.5f / 128.0f;
    const float theta = 3.14159265f * 32.5f / 64.0f;
    const glm::vec3 out(std::sin(theta) * std::cos(phi), std::sin(theta) * std::sin(phi),
                        std::cos(theta));
    const float d = 0.99f * radius;
    const glm::vec3 e =
        referenceIrradiance(scene, lights, out * d, -out, 40000, 7, transport, rays);
    const double wall = double(candela) / (double(radius) * double(radius));
    const double expected = double(candela) / (double(d) * double(d)) + wall * rho / (1.0 - rho);
    std::printf(
        "[ sphere ] mean albedo %.4f: irradiance %.3f lux, closed form %.3f (the white "
        "factor alone: unbounded)\n",
        rho, double(e.x), expected);
    EXPECT_NEAR(double(e.x), expected, 0.02 * expected);
}

// A normal-mapped white Lambert floor under the sun: the reference shows, pixel by pixel, the
// sun's E max(0, n . l) / pi with n the normal map read at full resolution (bilinear between
// texel centres, wrapping, renormalised) through the tangent frame, brute-forced over 8 x 8
// points of each pixel's footprint. The map tilts the normal along the tangent only,
// a(u) = 0.5 sin(8 pi u) rad (4 periods across 64 texels), whatever way the bitangent points;
// the sun comes from +x, so the slopes facing it are brighter. A pixel spans 0.4 texel
// (level of detail 0). Tolerance 2 %: 8-bit normals (0.4 % in the cosine) and 8 x 8 points
// against the reference's 64 jittered paths per pixel on a field that changes by < 6 % across a
// pixel. Shaded with the geometric normal (the map ignored) the slopes would match nowhere.
constexpr int kBumpTexels = 64;
float bumpAngle(float u) {
    return 0.5f * std::sin(2.0f * 3.14159265f * 4.0f * u);
}

std::vector<uint8_t> bumpNormalMap() {
    std::vector<uint8_t> rgba;
    for (int y = 0; y < 4; ++y)
        for (int x = 0; x < kBumpTexels; ++x) {
            const float a = bumpAngle((float(x) + 0.5f) / float(kBumpTexels));
            const glm::vec3 n(std::sin(a), 0.0f, std::cos(a));
            const auto code = [](float c) {
                return uint8_t(std::lround((c * 0.5f + 0.5f) * 255.0f));
            };
            rgba.insert(rgba.end(), {code(n.x), code(n.y), code(n.z), 255});
        }
    return rgba;
}

// The normal map's tangent-space normal at u (bilinear between the 8-bit texel centres along u,
// wrapping; constant along v), decoded as 2 c - 1 and renormalised.
glm::vec3 bumpNormalAt(const std::vector<uint8_t>& map, float u) {
    const float x = u * float(kBumpTexels) - 0.5f;
    const int x0 = int(std::floor(x));
    const float f = x - float(x0);
    const auto texel = [&](int i) {
        i = ((i % kBumpTexels) + kBumpTexels) % kBumpTexels;
        const uint8_t* c = &map[size_t(i) * 4];
        return glm::vec3(c[0], c[1], c[2]) / 255.0f * 2.0f - 1.0f;
    };
    return glm::normalize(glm::mix(texel(x0), texel(x0 + 1), f));
}

struct FloorAgreement {
    int checked = 0;
    double mean = 0.0, rms = 0.0, worst = 0.0;  // rendered / brute force - 1
    double worstFlat = 0.0;                     // the same with the geometric normal
};

// The floor under the sun from +x, rendered by the reference and brute-forced pixel by pixel:
// Lambert (albedo 1) or glossy (a dielectric: base colour 0.5, f0 0.04, roughness 0.5, its
// specular lobe the transport's: brdf.glsl's GGX, correlated Smith, Schlick).
FloorAgreement normalMappedFloor(bool glossy) {
    world::SourceLevel level = checkerPlane(0.0f);
    world::Material& material = level.materials[0];
    material.baseColorTexture = world::kNoIndex;
    if (glossy) {
        material.materialClass = world::MaterialClass::kDielectric;
        material.baseColor = glm::vec4(0.5f, 0.5f, 0.5f, 1.0f);
        material.metallic = 0.0f;
        material.roughness = 0.5f;
        material.specularColor = glm::vec3(0.04f);
    }
    const std::vector<uint8_t> map = bumpNormalMap();
    material.normalTexture =
        test::addImageTexture(level, outputFolder() + "/bumps.png", kBumpTexels, 4, map);
    for (world::Vertex& v : level.instances[0].vertices) v.tangent = {1.0f, 0.0f, 0.0f, 1.0f};
    const glm::vec3 toSun = glm::normalize(glm::vec3(0.6f, 0.8f, 0.0f));
    world::Light sun;
    sun.type = world::LightType::kDirectional;
    sun.role = world::LightRole::kBaked;
    sun.intensity = 10000.0f;
    sun.direction = -toSun;
    level.lights.push_back(sun);

    const test::LevelScene built(level);
    const BakeScene& scene = built.scene;
    const BakeLights& lights = built.lights;
    RayCounts rays;
    const uint32_t size = 128;
    const world::Camera& camera = level.cameras[0];
    const ReferenceImage image =
        renderReference(scene, lights, camera, size, size, 64, {}, nullptr, rays);
    const glm::mat3 rotation = glm::mat3_cast(camera.rotation);
    const float tanHalf = std::tan(0.5f * camera.yfov);
    const auto floorPoint = [&](float px, float py) {
        const float sx = px / float(size) * 2.0f - 1.0f, sy = 1.0f - py / float(size) * 2.0f;
        const glm::vec3 d = rotation * glm::vec3(sx * tanHalf, sy * tanHalf, -1.0f);
        return camera.position + d * (camera.position.y / -d.y);
    };
    // Brute force: the tangent frame is (+x, -z, +y) for tangent +x, w = 1 and normal +y.
    const glm::vec3 t(1, 0, 0), n(0, 1, 0), b = glm::cross(n, t);
    const float albedo = glossy ? 0.5f : 1.0f;
    const float f0 = glossy ? 0.04f : 0.0f;
    const float gloss = glsl::gloss_fromRoughness(0.5f);
    const auto radianceAt = [&](const glm::vec3& p, const glm::vec3& shading) {
        const glsl::BrdfDots d =
            glsl::brdfDots(shading, glm::normalize(camera.position - p), toSun);
        if (!(glm::dot(shading, toSun) > 0.0f)) return 0.0;
        const float specular =
            glossy ? glsl::specularLobe(glsl::RUNTIME_NDF, glsl::RUNTIME_VIS, glsl::RUNTIME_FRESNEL,
                                        glm::vec3(f0), gloss, d)
                         .x
                   : 0.0f;
        // The diffuse weighted for energy conservation by the split-sum table (lighting.glsl).
        const glm::vec2 env = glsl::sampleEnvBrdfTable(glsl::envBrdfTableCoord(d.NoV, gloss));
        const float weight = glossy ? std::max(0.0f, 1.0f - (f0 * env.x + env.y)) : 1.0f;
        return double(sun.intensity) * (double(albedo * weight * d.NoL) / M_PI + double(specular));
    };
    FloorAgreement out;
    for (uint32_t y = 0; y < size; ++y)
        for (uint32_t x = 0; x < size; ++x) {
            const glm::vec3 centre = floorPoint(float(x) + 0.5f, float(y) + 0.5f);
            if (std::fabs(centre.x) > 0.95f || std::fabs(centre.z) > 0.95f) continue;
            double expected = 0.0, flat = 0.0;
            for (int j = 0; j < 8; ++j)
                for (int i = 0; i < 8; ++i) {
                    const glm::vec3 p = floorPoint(float(x) + (float(i) + 0.5f) / 8.0f,
                                                   float(y) + (float(j) + 0.5f) / 8.0f);
                    const glm::vec3 ts = bumpNormalAt(map, 0.5f * (p.x + 1.0f));
                    expected += radianceAt(p, glm::normalize(t * ts.x + b * ts.y + n * ts.z));
                    flat += radianceAt(p, n);
                }
            expected /= 64.0;
            flat /= 64.0;
            const double rendered = image.rgb[(size_t(y) * size + x) * 3];
            const double error = rendered / expected - 1.0;
            out.worst = std::max(out.worst, std::fabs(error));
            out.mean += error;
            out.rms += error * error;
            out.worstFlat = std::max(out.worstFlat, std::fabs(flat / expected - 1.0));
            ++out.checked;
        }
    out.mean /= std::max(1, out.checked);
    out.rms = std::sqrt(out.rms / std::max(1, out.checked));
    std::printf(
        "[ normal map ] %s: %d pixels off the brute force: mean %+.3f %%, RMS %.3f %%, worst "
        "%.2f %% (the flat normal: worst %.1f %%)\n",
        glossy ? "glossy" : "Lambert", out.checked, 100.0 * out.mean, 100.0 * out.rms,
        100.0 * out.worst, 100.0 * out.worstFlat);
    return out;
}

TEST(MaterialTransport, ANormalMappedFloorShowsItsFullResolutionNormals) {
    const FloorAgreement lambert = normalMappedFloor(false);
    EXPECT_GT(lambert.checked, 8000);
    EXPECT_LT(lambert.worst, 0.02);
    EXPECT_GT(lambert.worstFlat, 0.2);
}

// The glossy floor: the sun's glint on each bump's slope (the flat floor would show one broad
// highlight, 116 % off somewhere). The same 2 % per pixel: the lobe (GGX alpha 0.25) changes
// by < 10 % across a pixel, and 8 x 8 points against 64 paths resolve it.
TEST(MaterialTransport, AGlossyNormalMappedFloorShowsTheGlintOfEachBump) {
    const FloorAgreement glossy = normalMappedFloor(true);
    EXPECT_GT(glossy.checked, 8000);
    EXPECT_LT(glossy.worst, 0.02);
    EXPECT_GT(glossy.worstFlat, 0.2);
}

// The baker's own mips of a cut-out grate (what the reference reads along wide ray cones): the
// bars' colour at every level of detail, the alpha their coverage. A plain mean averaged the
// holes' black into the bars, and the box behind the textured room's grate, lit by light the
// bars reflect, read 14% under Cycles (2.41 against 2.74 cd/m^2; 2.75 with the fix).
TEST(MaterialTransport, ACutOutGratesBarsKeepTheirColourAtEveryLevelOfDetail) {
    world::DecodedImage grate;
    grate.width = grate.height = 64;
    grate.rgba.assign(64 * 64 * 4, 0);
    for (int y = 0; y < 64; ++y)
        for (int x = 0; x < 64; ++x)
            if (x % 32 < 8 || y % 32 < 8) {
                uint8_t* t = &grate.rgba[size_t(y * 64 + x) * 4];
                t[0] = 150, t[1] = 150, t[2] = 160, t[3] = 255;
            }
    const BakeTexture texture = makeBakeTexture(grate, true, true, world::Sampler{});
    const float bar = linearOf(150), blue = linearOf(160);
    // Each level read at its first texel's centre, where its bars cross (the filter reads that
    // texel alone): a plain mean was 56% under at the coarsest levels.
    for (uint32_t level = 1; level < texture.mipCount; ++level) {
        const float centre = 0.5f / float(64u >> level);
        const glm::vec4 t = sampleTexture(texture, glm::vec2(centre), float(level));
        ASSERT_GT(t.w, 0.0f) << "level " << level;
        EXPECT_NEAR(t.x, bar, 1e-4f) << "level " << level;
        EXPECT_NEAR(t.z, blue, 1e-4f) << "level " << level;
    }
    EXPECT_NEAR(sampleTexture(texture, glm::vec2(0.5f), 6.0f).w, 0.4375f, 1e-4f);  // coverage
    // Across a bar's edge at mip 0 (texels 7 and 8 of the first row of holes, half way): the
    // bar's colour, at half coverage, where the holes' black made a dark fringe of 0.5 bar.
    const glm::vec4 edge = sampleTexture(texture, glm::vec2(8.0f / 64.0f, 20.5f / 64.0f), 0.0f);
    EXPECT_NEAR(edge.w, 0.5f, 1e-4f);
    EXPECT_NEAR(edge.x, bar, 1e-4f);
    EXPECT_NEAR(edge.z, blue, 1e-4f);
}

// The directional albedo of the engine's GGX layer at cosine NoV (GGX D, height-correlated Smith,
// Schlick's Fresnel: shaders/brdf.glsl's terms, written here from their papers), by a midpoint
// quadrature over half vectors sampled from D: an integral independent of the split-sum table.
float ggxLayerAlbedo(float NoV, float alpha, float f0) {
    const int n = 256;
    const float a2 = alpha * alpha;
    const glm::vec3 v(std::sqrt(std::max(0.0f, 1.0f - NoV * NoV)), 0.0f, NoV);
    const auto lambda = [a2](float c) { return std::sqrt(a2 + (1.0f - a2) * c * c); };
    double sum = 0.0;
    for (int i = 0; i < n; ++i)
        for (int j = 0; j < n; ++j) {
            const float u1 = (float(i) + 0.5f) / float(n), u2 = (float(j) + 0.5f) / float(n);
            const float NoH = std::sqrt((1.0f - u1) / (1.0f + (a2 - 1.0f) * u1));
            const float sinH = std::sqrt(std::max(0.0f, 1.0f - NoH * NoH));
            const float phi = 2.0f * 3.14159265f * u2;
            const glm::vec3 h(sinH * std::cos(phi), sinH * std::sin(phi), NoH);
            const float VoH = glm::dot(v, h);
            const float NoL = 2.0f * VoH * NoH - NoV;
            if (VoH <= 0.0f || NoL <= 0.0f) continue;
            const float vis = 0.5f / (NoL * lambda(NoV) + NoV * lambda(NoL));
            const float fresnel = f0 + (1.0f - f0) * std::pow(1.0f - VoH, 5.0f);
            sum += double(vis * fresnel * NoL * 4.0f * VoH /
                          NoH);  // f cos / pdf, pdf = D NoH / (4 VoH)
        }
    return float(sum / (double(n) * n));
}

// A glossy dielectric floor under a uniform sky L, seen from 1.7 m up out to grazing angles: every
// path leaves after one bounce, so a pixel that sees the floor at cosine NoV is, in closed form,
// L (albedo w(NoV) + E(NoV)), with w the diffuse's energy weight of the engine's model
// (1 - E_spec from the split-sum table, diffuseEnergyWeight) and E the GGX layer's directional
// albedo by quadrature. The reference at 256 paths gives each image row's mean within 1% of it
// (0.6% at worst, in the grazing rows, where a path's specular estimate f cos / pdf varies most;
// 0.2% elsewhere) and the whole within 0.25%. Cycles' GGX layer (another Fresnel,
// separable Smith) is up to 7% off it per row: scripts/cycles-check.py.
TEST(MaterialTransport, AGlossyFloorUnderAUniformSkyIsItsLayersClosedForm) {
    const float sky = 1000.0f, albedo = 0.2f, f0 = 0.04f, roughness = 0.2f;
    world::SourceLevel level;
    world::Material m;
    m.name = "glossy";
    m.baseColor = glm::vec4(albedo, albedo, albedo, 1.0f);
    m.metallic = 0.0f;
    m.roughness = roughness;
    m.albedo = glm::vec3(albedo);
    m.specularColor = glm::vec3(f0);
    m.gloss = glsl::gloss_fromRoughness(roughness);
    m.materialClass = world::MaterialClass::kDielectric;
    level.materials.push_back(m);
    const float half = 500.0f;  // its edge far beyond the rows checked
    test::addQuad(level, {-half, 0.0f, half}, {half, 0.0f, half}, {half, 0.0f, -half},
                  {-half, 0.0f, -half}, 0, "floor");
    world::Camera camera;
    camera.name = "view";
    camera.position = {0.0f, 1.7f, 0.0f};
    camera.rotation = glm::angleAxis(-0.45f, glm::vec3(1.0f, 0.0f, 0.0f));  // 26 degrees down
    camera.yfov = 1.0f;
    level.cameras.push_back(camera);
    level.skyRadiance = glm::vec3(sky);
    const test::LevelScene built(level);
    RayCounts rays;
    const uint32_t size = 48, spp = 256;
    const ReferenceImage image =
        renderReference(built.scene, built.lights, camera, size, size, spp, {}, nullptr, rays);

    const float alpha = roughness * roughness;  // glTF's GGX alpha
    std::vector<float> table(257);
    for (size_t i = 0; i < table.size(); ++i)
        table[i] = ggxLayerAlbedo(std::max(float(i) / 256.0f, 1e-3f), alpha, f0);
    const auto layerAlbedo = [&](float NoV) {
        const float x = std::clamp(NoV, 0.0f, 1.0f) * 256.0f;
        const size_t i = std::min(size_t(x), table.size() - 2);
        return table[i] + (table[i + 1] - table[i]) * (x - float(i));
    };
    const glm::mat3 rotation = glm::mat3_cast(camera.rotation);
    const float tanHalf = std::tan(0.5f * camera.yfov);
    int rowsChecked = 0;
    float grazing = 1.0f;
    double allRendered = 0.0, allExpected = 0.0;
    for (uint32_t y = 0; y < size; ++y) {
        double rendered = 0.0, expected = 0.0;
        int pixels = 0;
        for (uint32_t x = 0; x < size; ++x) {
            const float sx = (float(x) + 0.5f) / float(size) * 2.0f - 1.0f;
            const float sy = 1.0f - (float(y) + 0.5f) / float(size) * 2.0f;
            const glm::vec3 d =
                glm::normalize(rotation * glm::vec3(sx * tanHalf, sy * tanHalf, -1.0f));
            const float NoV = -d.y;
            const size_t at = (size_t(y) * size + x) * 3;
            ASSERT_TRUE(std::isfinite(image.rgb[at])) << "pixel " << x << ", " << y;
            // Rows whose every pixel sees the floor well inside its edge, at least 0.05 down.
            if (NoV < 0.05f) break;
            const float w = glsl::diffuseEnergyWeight(
                                MATERIAL_DIELECTRIC, glm::vec3(f0),
                                glsl::sampleEnvBrdfTable(glsl::envBrdfTableCoord(NoV, m.gloss)))
                                .x;
            rendered += double(image.rgb[at]);
            expected += double(sky * (albedo * w + layerAlbedo(NoV)));
            grazing = std::min(grazing, NoV);
            ++pixels;
        }
        if (pixels < int(size)) continue;
        EXPECT_NEAR(rendered / expected, 1.0, 0.01) << "row " << y;
        allRendered += rendered;
        allExpected += expected;
        ++rowsChecked;
    }
    EXPECT_GT(rowsChecked, 24);
    EXPECT_NEAR(allRendered / allExpected, 1.0, 0.0025);
    EXPECT_LT(grazing, 0.1f);  // down to grazing view
}

}  // namespace
}  // namespace onelight::bake
