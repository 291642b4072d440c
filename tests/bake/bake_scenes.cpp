#include "bake_scenes.hpp"

#include <cmath>

#include "world/compile/static_split.hpp"
#include "world/images/image_files.hpp"

namespace onelight::bake::test {

uint32_t addLambertMaterial(world::SourceLevel& level, float albedo) {
    world::Material m;
    m.name = "lambert" + std::to_string(level.materials.size());
    m.baseColor = glm::vec4(albedo, albedo, albedo, 1.0f);
    m.metallic = 0.0f;
    m.roughness = 1.0f;
    m.albedo = glm::vec3(albedo);
    m.specularColor = glm::vec3(0.0f);
    m.gloss = 0.0f;
    m.materialClass = world::MaterialClass::kLambert;
    level.materials.push_back(m);
    return static_cast<uint32_t>(level.materials.size() - 1);
}

namespace {

void addTriangles(world::SourceLevel& level, std::vector<glm::vec3> positions,
                  std::vector<uint32_t> indices, uint32_t material, const std::string& name) {
    world::MeshInstance instance;
    instance.nodeName = name;
    instance.meshName = name;
    instance.material = material;
    for (const glm::vec3& p : positions) {
        world::Vertex v;
        v.position = p;
        instance.vertices.push_back(v);
    }
    // Vertex normals from the faces (flat per vertex: each shape gives its vertices one face).
    for (size_t i = 0; i + 2 < indices.size(); i += 3) {
        const glm::vec3 n =
            glm::normalize(glm::cross(positions[indices[i + 1]] - positions[indices[i]],
                                      positions[indices[i + 2]] - positions[indices[i]]));
        for (int k = 0; k < 3; ++k) instance.vertices[indices[i + k]].normal = n;
    }
    instance.indices = std::move(indices);
    level.instances.push_back(std::move(instance));
}

}  // namespace

void addQuad(world::SourceLevel& level, glm::vec3 p0, glm::vec3 p1, glm::vec3 p2, glm::vec3 p3,
             uint32_t material, const std::string& name) {
    addTriangles(level, {p0, p1, p2, p3}, {0, 1, 2, 0, 2, 3}, material, name);
}

void addBox(world::SourceLevel& level, glm::vec3 lo, glm::vec3 hi, uint32_t material, bool inward,
            const std::string& name) {
    const glm::vec3 c[8] = {{lo.x, lo.y, lo.z}, {hi.x, lo.y, lo.z}, {hi.x, hi.y, lo.z},
                            {lo.x, hi.y, lo.z}, {lo.x, lo.y, hi.z}, {hi.x, lo.y, hi.z},
                            {hi.x, hi.y, hi.z}, {lo.x, hi.y, hi.z}};
    // Outward-facing quads (counter-clockwise from outside).
    const int faces[6][4] = {{0, 3, 2, 1}, {4, 5, 6, 7}, {0, 1, 5, 4},
                             {2, 3, 7, 6}, {1, 2, 6, 5}, {0, 4, 7, 3}};
    for (int f = 0; f < 6; ++f) {
        const int* q = faces[f];
        if (inward)
            addQuad(level, c[q[3]], c[q[2]], c[q[1]], c[q[0]], material,
                    name + "_" + std::to_string(f));
        else
            addQuad(level, c[q[0]], c[q[1]], c[q[2]], c[q[3]], material,
                    name + "_" + std::to_string(f));
    }
}

void addInwardSphere(world::SourceLevel& level, glm::vec3 centre, float radius, uint32_t rings,
                     uint32_t segments, uint32_t material) {
    std::vector<glm::vec3> positions;
    std::vector<uint32_t> indices;
    const float pi = 3.14159265358979f;
    for (uint32_t r = 0; r <= rings; ++r) {
        const float theta = pi * float(r) / float(rings);
        for (uint32_t s = 0; s <= segments; ++s) {
            const float phi = 2.0f * pi * float(s) / float(segments);
            positions.push_back(centre + radius * glm::vec3(std::sin(theta) * std::cos(phi),
                                                            std::sin(theta) * std::sin(phi),
                                                            std::cos(theta)));
        }
    }
    const uint32_t row = segments + 1;
    for (uint32_t r = 0; r < rings; ++r) {
        for (uint32_t s = 0; s < segments; ++s) {
            const uint32_t a = r * row + s, b = a + 1, c = a + row, d = c + 1;
            // inward: clockwise seen from outside
            if (r != 0) indices.insert(indices.end(), {a, b, d});
            if (r + 1 != rings) indices.insert(indices.end(), {a, d, c});
        }
    }
    world::MeshInstance instance;
    instance.nodeName = "sphere";
    instance.meshName = "sphere";
    instance.material = material;
    for (size_t i = 0; i < positions.size(); ++i) {
        world::Vertex v;
        v.position = positions[i];
        v.normal = glm::normalize(centre - positions[i]);
        // Longitude and latitude: u around the axis, v from the +z pole.
        v.uv0 = {float(i % row) / float(segments), float(i / row) / float(rings)};
        instance.vertices.push_back(v);
    }
    instance.indices = std::move(indices);
    level.instances.push_back(std::move(instance));
}

uint32_t addImageTexture(world::SourceLevel& level, const std::string& pngPath, uint32_t width,
                         uint32_t height, const std::vector<uint8_t>& rgba,
                         const world::Sampler& sampler) {
    world::writePngFile(pngPath, width, height, rgba);
    world::Image image;
    image.name = pngPath;
    image.uri = pngPath;
    level.images.push_back(image);
    world::Texture texture;
    texture.image = uint32_t(level.images.size() - 1);
    texture.sampler = sampler;
    level.textures.push_back(texture);
    return uint32_t(level.textures.size() - 1);
}

LevelScene::LevelScene(const world::SourceLevel& level)
    : scene(device, world::splitStaticDynamic(level).staticGeometry, loadSceneMaterials(level)),
      lights(makeBakeLights(scene, level.lights, {}, level.skyRadiance)) {}

void setSkyImage(world::SourceLevel& level, const std::string& hdrPath, const world::HdrImage& sky,
                 glm::vec3 scale) {
    world::writeHdrFile(hdrPath, sky.width, sky.height, sky.rgb);
    world::Image image;
    image.name = "sky";
    image.mimeType = "image/vnd.radiance";
    image.uri = hdrPath;
    level.skyImage = uint32_t(level.images.size());
    level.images.push_back(image);
    level.skyRadiance = scale;
}

world::Light pointLight(glm::vec3 position, float candela, world::LightRole role) {
    world::Light l;
    l.name = "point";
    l.type = world::LightType::kPoint;
    l.role = role;
    l.intensity = candela;
    l.position = position;
    return l;
}

world::Light spotLight(glm::vec3 position, glm::vec3 direction, float candela, float inner,
                       float outer, world::LightRole role) {
    world::Light l = pointLight(position, candela, role);
    l.name = "spot";
    l.type = world::LightType::kSpot;
    l.direction = glm::normalize(direction);
    l.innerCone = inner;
    l.outerCone = outer;
    return l;
}

world::SourceLevel agreementRoom() {
    world::SourceLevel level;
    const uint32_t walls = addLambertMaterial(level, 0.6f);
    const uint32_t block = addLambertMaterial(level, 0.3f);
    addBox(level, {-2.0f, -1.5f, 0.0f}, {2.0f, 1.5f, 2.5f}, walls, true, "room");
    addBox(level, {-0.4f, -0.4f, 0.0f}, {0.4f, 0.4f, 0.8f}, block, false, "block");
    level.lights.push_back(pointLight({-1.0f, 0.5f, 2.0f}, 60.0f, world::LightRole::kPrimary));
    level.lights.push_back(spotLight({1.5f, -1.0f, 2.2f}, {-0.5f, 0.4f, -1.0f}, 150.0f, 0.4f, 0.7f,
                                     world::LightRole::kBaked));
    return level;
}

world::SourceLevel roofOpeningRoom() {
    world::SourceLevel level;
    const uint32_t walls = addLambertMaterial(level, 0.6f);
    const uint32_t block = addLambertMaterial(level, 0.3f);
    const float x0 = -2.0f, x1 = 2.0f, y0 = -1.5f, y1 = 1.5f, h = 2.5f;
    // Floor and four walls (inward), then the ceiling around the opening (facing down).
    const glm::vec3 c[8] = {{x0, y0, 0}, {x1, y0, 0}, {x1, y1, 0}, {x0, y1, 0},
                            {x0, y0, h}, {x1, y0, h}, {x1, y1, h}, {x0, y1, h}};
    const int faces[5][4] = {{0, 3, 2, 1}, {0, 1, 5, 4}, {2, 3, 7, 6}, {1, 2, 6, 5}, {0, 4, 7, 3}};
    for (int f = 0; f < 5; ++f)
        addQuad(level, c[faces[f][3]], c[faces[f][2]], c[faces[f][1]], c[faces[f][0]], walls,
                "room_" + std::to_string(f));
    const float ox0 = 0.3f, ox1 = 1.3f, oy0 = -0.5f, oy1 = 0.5f;
    const auto ceiling = [&](float ax, float ay, float bx, float by, const char* name) {
        addQuad(level, {ax, ay, h}, {ax, by, h}, {bx, by, h}, {bx, ay, h}, walls, name);
    };
    ceiling(x0, y0, ox0, y1, "ceiling_west");
    ceiling(ox1, y0, x1, y1, "ceiling_east");
    ceiling(ox0, y0, ox1, oy0, "ceiling_south");
    ceiling(ox0, oy1, ox1, y1, "ceiling_north");
    addBox(level, {-1.2f, -0.6f, 0.0f}, {-0.4f, 0.2f, 0.9f}, block, false, "block");
    level.lights.push_back(sunLight({0.25f, 0.15f, -1.0f}, 20000.0f));
    return level;
}

world::Light sunLight(glm::vec3 direction, float lux) {
    world::Light sun;
    sun.name = "sun";
    sun.type = world::LightType::kDirectional;
    sun.role = world::LightRole::kPrimary;
    sun.intensity = lux;
    sun.direction = glm::normalize(direction);
    return sun;
}

BakeOptions testOptions(float texelsPerMetre, BakeQuality quality) {
    BakeOptions o;
    o.quality = quality;
    o.showProgress = false;
    o.compile.charts.texelsPerMetre = texelsPerMetre;
    o.compile.charts.atlasSize = 512;
    o.gridCellSize = 1.0f;
    return o;
}

bool allFiniteNonNegative(const world::BakedLighting& baked) {
    const auto good = [](const glm::vec3& v) {
        return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z) && v.x >= 0.0f &&
               v.y >= 0.0f && v.z >= 0.0f;
    };
    for (const world::LightmapTexel& t : baked.texels)
        if (!good(t.irradiance) || !std::isfinite(t.normalWeight) ||
            !std::isfinite(glm::length(t.direction)))
            return false;
    for (const world::LightGridCell& c : baked.grid.cells)
        for (const glm::vec3& f : c.ambientCube)
            if (!good(f) || !std::isfinite(c.primaryVisibility)) return false;
    return true;
}

world::SourceLevel smallRoom() {
    world::SourceLevel level;
    const uint32_t m = addLambertMaterial(level, 0.6f);
    addBox(level, {-1.5f, -1.0f, 0.0f}, {1.5f, 1.0f, 2.0f}, m, true, "room");
    addBox(level, {-0.3f, -0.3f, 0.0f}, {0.3f, 0.3f, 0.5f}, m, false, "block");
    level.lights.push_back(pointLight({-0.8f, 0.2f, 1.6f}, 40.0f, world::LightRole::kPrimary));
    level.lights.push_back(pointLight({0.9f, -0.3f, 1.5f}, 30.0f, world::LightRole::kPrimary));
    return level;
}

world::SourceLevel smallRoomWithProbes() {
    world::SourceLevel level = smallRoom();
    world::Material glossy = level.materials[0];
    glossy.name = "glossy";
    glossy.materialClass = world::MaterialClass::kDielectric;
    glossy.specularColor = glm::vec3(0.04f);
    glossy.gloss = 0.8f;
    level.materials.push_back(glossy);
    for (world::MeshInstance& m : level.instances)
        if (m.nodeName == "block") m.material = 1;
    for (const glm::vec3 p :
         {glm::vec3(-1.0f, 0.0f, 1.0f), glm::vec3(0.0f, 0.5f, 1.2f), glm::vec3(1.0f, 0.0f, 0.8f)}) {
        world::Entity e;
        e.name = "probe" + std::to_string(level.entities.size());
        e.flags = world::kEntityProbe;
        e.position = p;
        if (level.entities.empty()) {
            e.probeBoxMin = {-1.5f, -1.0f, 0.0f};
            e.probeBoxMax = {1.5f, 1.0f, 2.0f};
        }
        level.entities.push_back(e);
    }
    return level;
}

world::SourceLevel texturedRoomWithProbes(const std::string& folder) {
    world::SourceLevel level = smallRoomWithProbes();
    std::vector<uint8_t> checker, bumps, holes;
    for (int y = 0; y < 8; ++y)
        for (int x = 0; x < 8; ++x) {
            const uint8_t c = ((x + y) % 2) ? 230 : 60;
            checker.insert(checker.end(), {c, uint8_t(c * 3 / 4), uint8_t(c / 2), 255});
            const float a = 0.4f * std::sin(0.785398f * float(x));
            bumps.insert(bumps.end(), {uint8_t(127.5f + 127.5f * std::sin(a)), 128,
                                       uint8_t(127.5f + 127.5f * std::cos(a)), 255});
            holes.insert(holes.end(), {200, 200, 200, uint8_t((x % 4 < 2) ? 255 : 0)});
        }
    level.materials[0].baseColorTexture =
        addImageTexture(level, folder + "/room_checker.png", 8, 8, checker);
    level.materials[1].normalTexture =
        addImageTexture(level, folder + "/room_bumps.png", 8, 8, bumps);
    world::Material glow = level.materials[0];
    glow.name = "glow";
    glow.baseColorTexture = world::kNoIndex;
    glow.emissive = glm::vec3(300.0f, 250.0f, 200.0f);
    level.materials.push_back(glow);
    addQuad(level, {1.2f, -0.2f, 1.9f}, {1.4f, -0.2f, 1.9f}, {1.4f, 0.2f, 1.9f}, {1.2f, 0.2f, 1.9f},
            uint32_t(level.materials.size() - 1), "panel");
    world::Material grate = level.materials[0];
    grate.name = "grate";
    grate.alphaMode = world::AlphaMode::kMask;
    grate.doubleSided = true;
    grate.baseColorTexture = addImageTexture(level, folder + "/room_holes.png", 8, 8, holes);
    level.materials.push_back(grate);
    addQuad(level, {-1.2f, -0.8f, 0.7f}, {-0.4f, -0.8f, 0.7f}, {-0.4f, 0.0f, 0.7f},
            {-1.2f, 0.0f, 0.7f}, uint32_t(level.materials.size() - 1), "grate");
    for (world::MeshInstance& m : level.instances)
        for (world::Vertex& v : m.vertices) v.uv0 = {v.position.x + v.position.z, v.position.y};
    return level;
}

world::SourceLevel manyLightsFloor(uint32_t n) {
    world::SourceLevel level;
    const uint32_t floor = addLambertMaterial(level, 0.5f);
    addQuad(level, {-4, -4, 0}, {4, -4, 0}, {4, 4, 0}, {-4, 4, 0}, floor, "floor");
    addBox(level, {-2.2f, -1.5f, 0}, {-1.2f, 1.5f, 0.6f}, floor, false, "block_a");
    addBox(level, {0.8f, -2.5f, 0}, {2.6f, -1.6f, 0.9f}, floor, false, "block_b");
    addBox(level, {0.9f, 1.0f, 0}, {1.5f, 2.8f, 0.4f}, floor, false, "block_c");
    const float step = 8.0f / float(n);
    for (uint32_t y = 0; y < n; ++y)
        for (uint32_t x = 0; x < n; ++x) {
            world::Light l = pointLight(
                {-4.0f + (float(x) + 0.5f) * step, -4.0f + (float(y) + 0.5f) * step, 1.2f},
                2.0f + float((x * 7 + y * 3) % 5), world::LightRole::kBaked);
            l.range = (x + y) % 3 == 0 ? 4.0f : 0.0f;
            level.lights.push_back(l);
        }
    return level;
}

BakeOptions fastBakeOptions() {
    BakeOptions o = testOptions(4.0f);
    o.indirectSamples = 16;
    o.shadowSamples = 4;
    o.gridSamples = 16;
    o.gridCellSize = 0.75f;
    o.probeFaceSize = 8;
    o.probeSamples = 4;
    return o;
}

}  // namespace onelight::bake::test
