#include "tests/world/level_generator.hpp"

#include <algorithm>
#include <cmath>

#include "tests/world/world_test_support.hpp"

namespace onelight::test {
namespace {

/// Numerical Recipes' LCG: deterministic on every platform.
struct Lcg {
    uint32_t state;
    double next() {
        state = state * 1664525u + 1013904223u;
        return static_cast<double>(state >> 8) / 16777216.0;
    }
};

constexpr double kGroundSize = 200.0;  // metres

}  // namespace

uint64_t generatedTriangleCount(const GeneratedLevelOptions& o) {
    return 2ull * o.groundCells * o.groundCells +
           10ull * static_cast<uint64_t>(o.buildings) * o.buildingCells * o.buildingCells;
}

GeneratedLevelOptions optionsForTriangles(uint64_t triangles) {
    GeneratedLevelOptions o;
    o.groundCells =
        std::max(2, static_cast<int>(std::sqrt(0.2 * static_cast<double>(triangles) / 2.0)));
    const double perBuilding = 0.8 * static_cast<double>(triangles) / o.buildings;
    o.buildingCells = std::max(1, static_cast<int>(std::lround(std::sqrt(perBuilding / 10.0))));
    return o;
}

std::string writeGeneratedLevel(const std::filesystem::path& folder, const std::string& name,
                                const GeneratedLevelOptions& o) {
    GltfBuilder gltf;
    Lcg random{o.seed};
    const int concrete = gltf.addMaterial({{"name", "concrete"},
                                           {"pbrMetallicRoughness",
                                            {{"baseColorFactor", {0.5, 0.5, 0.5, 1.0}},
                                             {"metallicFactor", 0.0},
                                             {"roughnessFactor", 0.8}}}});
    const int metal = gltf.addMaterial({{"name", "metal"},
                                        {"pbrMetallicRoughness",
                                         {{"baseColorFactor", {0.9, 0.8, 0.6, 1.0}},
                                          {"metallicFactor", 1.0},
                                          {"roughnessFactor", 0.3}}}});
    MeshData ground = gridMesh("ground", o.groundCells, kGroundSize, 0.0);
    ground.material = concrete;
    gltf.addNode({{"name", "ground"}, {"mesh", gltf.addMesh(ground)}});

    const int side = std::max(1, static_cast<int>(std::ceil(std::sqrt(o.buildings))));
    const double spacing = kGroundSize * 0.9 / side;
    for (int b = 0; b < o.buildings; ++b) {
        const double cx = -kGroundSize * 0.45 + spacing * (b % side + 0.5);
        const double cz = -kGroundSize * 0.45 + spacing * (b / side + 0.5);
        const double w = spacing * (0.35 + 0.3 * random.next());
        const double d = spacing * (0.35 + 0.3 * random.next());
        const double h = 5.0 + 25.0 * random.next();
        MeshData box =
            boxMesh("building_" + std::to_string(b),
                    glm::vec3(static_cast<float>(cx - w / 2), 0.0f, static_cast<float>(cz - d / 2)),
                    glm::vec3(static_cast<float>(cx + w / 2), static_cast<float>(h),
                              static_cast<float>(cz + d / 2)),
                    o.buildingCells, true);
        box.material = b % 7 == 3 ? metal : concrete;
        gltf.addNode({{"name", "building_" + std::to_string(b)}, {"mesh", gltf.addMesh(box)}});
    }
    MeshData crate =
        boxMesh("crate", glm::vec3(-0.5f, 0.0f, -0.5f), glm::vec3(0.5f, 1.0f, 0.5f), 2, false);
    crate.material = metal;
    const int crateMesh = gltf.addMesh(crate);
    for (int c = 0; c < o.dynamicCrates; ++c) {
        nlohmann::json extras = {{"dynamic", true}};
        if (c % 2 == 0) extras["mover"] = {{"offset", {0.0, 0.0, 4.0}}, {"period", 3.0 + c}};
        gltf.addNode({{"name", "crate_" + std::to_string(c)},
                      {"mesh", crateMesh},
                      {"translation", {-20.0 + 5.0 * c, 0.0, -3.0}},
                      {"extras", {{"onelight", extras}}}});
    }
    if (o.lights) {
        const int sun = gltf.addLight(
            {{"type", "directional"}, {"intensity", 10000.0}, {"color", {1.0, 0.95, 0.9}}});
        // Turned 60 degrees about x: the light travels down and towards -z.
        gltf.addNode({{"name", "sun"},
                      {"rotation", {-0.5, 0.0, 0.0, 0.8660254}},
                      {"extensions", {{"KHR_lights_punctual", {{"light", sun}}}}}});
        for (int p = 0; p < 6; ++p) {
            const int lamp =
                gltf.addLight({{"type", "point"}, {"intensity", 20000.0}, {"range", 40.0}});
            gltf.addNode({{"name", "lamp_" + std::to_string(p)},
                          {"translation", {-75.0 + 30.0 * p, 4.0, 10.0 * (p % 3) - 10.0}},
                          {"extensions", {{"KHR_lights_punctual", {{"light", lamp}}}}}});
        }
        const int spot =
            gltf.addLight({{"type", "spot"},
                           {"intensity", 50000.0},
                           {"spot", {{"innerConeAngle", 0.3}, {"outerConeAngle", 0.6}}}});
        gltf.addNode({{"name", "stage_spot"},
                      {"translation", {0.0, 12.0, 0.0}},
                      {"rotation", {-0.7071068, 0.0, 0.0, 0.7071068}},
                      {"extensions", {{"KHR_lights_punctual", {{"light", spot}}}}}});
        const int fill = gltf.addLight({{"type", "point"}, {"intensity", 500.0}});
        gltf.addNode({{"name", "fill"},
                      {"translation", {10.0, 3.0, 10.0}},
                      {"extensions", {{"KHR_lights_punctual", {{"light", fill}}}}},
                      {"extras", {{"onelight", {{"role", "baked"}}}}}});
        const int flashlight = gltf.addLight(
            {{"type", "spot"}, {"intensity", 800.0}, {"spot", {{"outerConeAngle", 0.5}}}});
        gltf.addNode({{"name", "flashlight"},
                      {"extensions", {{"KHR_lights_punctual", {{"light", flashlight}}}}},
                      {"extras", {{"onelight", {{"role", "effect"}}}}}});
        const int flash = gltf.addLight({{"type", "point"}, {"intensity", 300.0}});
        gltf.addNode({{"name", "gun_flash"},
                      {"extensions", {{"KHR_lights_punctual", {{"light", flash}}}}},
                      {"extras", {{"onelight", {{"role", "effect"}}}}}});
    }
    const int camera = gltf.addCamera(
        {{"type", "perspective"},
         {"perspective", {{"yfov", 1.0}, {"znear", 0.05}, {"aspectRatio", 1.7778}}}});
    gltf.addNode({{"name", "overview"},
                  {"camera", camera},
                  {"translation", {0.0, 60.0, 120.0}},
                  {"rotation", {-0.2588190, 0.0, 0.0, 0.9659258}},
                  {"extras", {{"onelight", {{"exposure", 12.0}}}}}});
    gltf.addNode({{"name", "player_start"},
                  {"translation", {0.0, 1.7, 30.0}},
                  {"extras", {{"onelight", {{"spawn", true}}}}}});
    gltf.addNode(
        {{"name", "plaza_probe"},
         {"translation", {0.0, 2.0, 0.0}},
         {"extras",
          {{"onelight",
            {{"probe", {{"box_min", {-20.0, 0.0, -20.0}}, {"box_max", {20.0, 10.0, 20.0}}}}}}}}});
    gltf.addNode({{"name", "level_settings"},
                  {"extras",
                   {{"onelight",
                     {{"grid", {{"min", {-100.0, -1.0, -100.0}}, {"max", {100.0, 40.0, 100.0}}}},
                      {"exposure", 11.0}}}}}});
    return gltf.write(folder, name);
}

}  // namespace onelight::test
