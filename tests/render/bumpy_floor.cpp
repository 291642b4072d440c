// The bumpy glossy floor of tests/render/bumpy_floor.hpp.
#include "bumpy_floor.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <vector>

#include <glm/gtc/quaternion.hpp>
#include <nlohmann/json.hpp>

#include "world/gltf/gltf_builder.hpp"
#include "world/images/image_files.hpp"

namespace onelight::test {
namespace {

using nlohmann::json;

json vec(glm::vec3 v) {
    return json::array({v.x, v.y, v.z});
}

// Egg-crate bumps, one period per tile: slopes (dh/dx, dh/dy) = s (cos 2 pi u sin 2 pi v,
// sin 2 pi u cos 2 pi v) with s = 0.5 (up to 27 degrees), as a tangent-space normal map.
void writeBumpNormalMap(const std::string& path) {
    std::vector<uint8_t> rgba(size_t(kBumpTexels) * kBumpTexels * 4, 255);
    constexpr double kSlope = 0.5;
    for (uint32_t y = 0; y < kBumpTexels; ++y)
        for (uint32_t x = 0; x < kBumpTexels; ++x) {
            const double u = 2.0 * M_PI * (double(x) + 0.5) / kBumpTexels;
            const double v = 2.0 * M_PI * (double(y) + 0.5) / kBumpTexels;
            const glm::dvec3 n = glm::normalize(glm::dvec3(
                -kSlope * std::cos(u) * std::sin(v), -kSlope * std::sin(u) * std::cos(v), 1.0));
            uint8_t* p = &rgba[(size_t(y) * kBumpTexels + x) * 4];
            for (int c = 0; c < 3; ++c)
                p[c] = uint8_t(std::lround(std::clamp(0.5 + 0.5 * n[c], 0.0, 1.0) * 255.0));
        }
    world::writePngFile(path, kBumpTexels, kBumpTexels, rgba);
}

}  // namespace

std::string writeBumpyGlossyFloor(const std::string& folder, const char* glossMips, float aspect) {
    writeBumpNormalMap(folder + "/bumps.png");
    world::GltfBuilder g;
    g.document()["images"] = json::array({{{"uri", "bumps.png"}}});
    g.document()["textures"] = json::array({{{"source", 0}}});
    const int floorMaterial = g.addMaterial({{"name", "glossy_bumps"},
                                             {"pbrMetallicRoughness",
                                              {{"baseColorFactor", {0.1f, 0.1f, 0.1f, 1.0f}},
                                               {"metallicFactor", 0.0f},
                                               {"roughnessFactor", 0.2f}}},
                                             {"normalTexture", {{"index", 0}}}});
    world::MeshData floor;
    floor.name = "floor";
    const float x0 = -150.0f, x1 = 150.0f, z0 = -500.0f, z1 = 10.0f;
    floor.positions = {{x0, 0.0f, z0}, {x1, 0.0f, z0}, {x1, 0.0f, z1}, {x0, 0.0f, z1}};
    floor.normals.assign(4, glm::vec3(0.0f, 1.0f, 0.0f));
    for (const glm::vec3& p : floor.positions)
        floor.uv0.push_back({p.x / kTileMetres, p.z / kTileMetres});
    floor.indices = {0, 2, 1, 0, 3, 2};
    floor.material = floorMaterial;
    g.addNode({{"name", "floor"}, {"mesh", g.addMesh(floor)}});
    // The sun 8 degrees above the horizon, ahead of the camera: its light travels towards +z.
    const float elevation = glm::radians(8.0f);
    const int sun = g.addLight({{"type", "directional"}, {"intensity", 20000.0f}});
    // -z (a light's forward) turned about +x by pi + elevation: (0, -sin e, cos e).
    const glm::quat sunTurn = glm::angleAxis(float(M_PI) + elevation, glm::vec3(1.0f, 0.0f, 0.0f));
    g.addNode({{"name", "sun"},
               {"rotation", {sunTurn.x, sunTurn.y, sunTurn.z, sunTurn.w}},
               {"extensions", {{"KHR_lights_punctual", {{"light", sun}}}}}});
    g.addNode({{"name", "settings"}, {"extras", {{"onelight", {{"gloss_mips", glossMips}}}}}});
    const int camera = g.addCamera(
        {{"name", "view"},
         {"type", "perspective"},
         {"perspective",
          {{"yfov", 0.25f}, {"znear", 0.05f}, {"zfar", 1000.0f}, {"aspectRatio", aspect}}}});
    const glm::quat look = glm::angleAxis(glm::radians(-6.5f), glm::vec3(1.0f, 0.0f, 0.0f));
    g.addNode({{"name", "view"},
               {"translation", vec({0.0f, kCameraHeight, 5.0f})},
               {"rotation", {look.x, look.y, look.z, look.w}},
               {"camera", camera},
               {"extras", {{"onelight", {{"exposure", 9.0f}}}}}});
    return g.write(folder, std::string("floor_") + glossMips);
}

}  // namespace onelight::test
