#include "test_scene.hpp"

#include <sys/wait.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <stdexcept>

#include <glm/gtc/quaternion.hpp>
#include <nlohmann/json.hpp>

#include "vk/context.hpp"
#include "world/images/image_files.hpp"

namespace onelight::test {

namespace {

std::string base64(const std::vector<uint8_t>& bytes) {
    static const char* const table =
        "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
    std::string out;
    size_t i = 0;
    for (; i + 2 < bytes.size(); i += 3) {
        const uint32_t v = uint32_t(bytes[i]) << 16 | uint32_t(bytes[i + 1]) << 8 | bytes[i + 2];
        out += table[v >> 18];
        out += table[(v >> 12) & 63];
        out += table[(v >> 6) & 63];
        out += table[v & 63];
    }
    if (i < bytes.size()) {
        uint32_t v = uint32_t(bytes[i]) << 16;
        if (i + 1 < bytes.size()) v |= uint32_t(bytes[i + 1]) << 8;
        out += table[v >> 18];
        out += table[(v >> 12) & 63];
        out += i + 1 < bytes.size() ? table[(v >> 6) & 63] : '=';
        out += '=';
    }
    return out;
}

template <typename T>
size_t append(std::vector<uint8_t>& buffer, const std::vector<T>& values) {
    while (buffer.size() % 4) buffer.push_back(0);
    const size_t offset = buffer.size();
    const auto* bytes = reinterpret_cast<const uint8_t*>(values.data());
    buffer.insert(buffer.end(), bytes, bytes + values.size() * sizeof(T));
    return offset;
}

void addQuadFace(SceneMesh& m, glm::vec3 a, glm::vec3 b, glm::vec3 c, glm::vec3 d, glm::vec3 n) {
    const uint32_t base = uint32_t(m.positions.size());
    for (glm::vec3 p : {a, b, c, d}) {
        m.positions.push_back(p);
        m.normals.push_back(n);
    }
    for (uint32_t i : {0u, 1u, 2u, 0u, 2u, 3u}) m.indices.push_back(base + i);
}

// The rotation taking the node's -Z to `direction`.
glm::quat lightRotation(glm::vec3 direction) {
    const glm::vec3 from(0.0f, 0.0f, -1.0f);
    const glm::vec3 to = glm::normalize(direction);
    const float c = glm::dot(from, to);
    if (c < -0.9999f) return glm::angleAxis(glm::pi<float>(), glm::vec3(0.0f, 1.0f, 0.0f));
    const glm::vec3 axis = glm::cross(from, to);
    const float s = std::sqrt((1.0f + c) * 2.0f);
    return glm::normalize(glm::quat(0.5f * s, axis.x / s, axis.y / s, axis.z / s));
}

}  // namespace

void addFloor(Scene& scene, float cx, float cz, float half, float height, uint32_t material) {
    SceneMesh m;
    m.material = material;
    // Counter-clockwise seen from +Y.
    addQuadFace(m, {cx - half, height, cz + half}, {cx + half, height, cz + half},
                {cx + half, height, cz - half}, {cx - half, height, cz - half}, {0, 1, 0});
    scene.meshes.push_back(m);
}

void addTiles(Scene& scene, glm::vec3 a, glm::vec3 b, glm::vec3 c, glm::vec3 d, int n, int m,
              uint32_t material) {
    const auto at = [&](float u, float v) {
        return glm::mix(glm::mix(a, b, u), glm::mix(d, c, u), v);
    };
    const glm::vec3 normal = glm::normalize(glm::cross(b - a, c - a));
    for (int j = 0; j < m; ++j)
        for (int i = 0; i < n; ++i) {
            const float u0 = float(i) / float(n), u1 = float(i + 1) / float(n);
            const float v0 = float(j) / float(m), v1 = float(j + 1) / float(m);
            SceneMesh q;
            q.material = material;
            q.positions = {at(u0, v0), at(u1, v0), at(u1, v1), at(u0, v1)};
            q.normals.assign(4, normal);
            q.indices = {0, 1, 2, 0, 2, 3};
            scene.meshes.push_back(std::move(q));
        }
}

void addChicaneHall(Scene& s, int rooms) {
    const float x0 = -20.0f, x1 = 12.0f * float(rooms) - 16.0f, z0 = 0.0f, z1 = 10.0f, h = 4.0f;
    const int along = int((x1 - x0) / 2.0f);
    addTiles(s, {x0, 0, z0}, {x0, 0, z1}, {x1, 0, z1}, {x1, 0, z0}, 5, along, 0);  // floor, up
    addTiles(s, {x0, h, z0}, {x1, h, z0}, {x1, h, z1}, {x0, h, z1}, along, 5, 0);  // ceiling
    addTiles(s, {x0, 0, z0}, {x1, 0, z0}, {x1, h, z0}, {x0, h, z0}, along, 2, 0);  // z0, +z
    addTiles(s, {x1, 0, z1}, {x0, 0, z1}, {x0, h, z1}, {x1, h, z1}, along, 2, 0);  // z1, -z
    addTiles(s, {x0, 0, z1}, {x0, 0, z0}, {x0, h, z0}, {x0, h, z1}, 5, 2, 0);      // x0, +x
    addTiles(s, {x1, 0, z0}, {x1, 0, z1}, {x1, h, z1}, {x1, h, z0}, 5, 2, 0);      // x1, -x
    for (int k = 0; k + 1 < rooms; ++k) {
        const float x = -6.0f + 12.0f * float(k);
        if (k % 2 == 0)
            addBox(s, {x - 1.0f, 0, 0}, {x + 1.0f, h, 8}, 0);  // doorway at z 8..10
        else
            addBox(s, {x - 1.0f, 0, 2}, {x + 1.0f, h, 10}, 0);  // doorway at z 0..2
    }
    for (int r = 0; r < rooms; ++r) {
        const float lo = r == 0 ? x0 : -5.0f + 12.0f * float(r - 1);
        const float hi = r + 1 == rooms ? x1 : -7.0f + 12.0f * float(r);
        const float x = 0.5f * (lo + hi);
        addBox(s, {x - 0.25f, 0, 4.75f}, {x + 0.25f, 0.5f, 5.25f}, 0);
        SceneLight lamp;
        lamp.type = 1;
        lamp.intensity = 300.0f;
        lamp.position = {x, 3.0f, 5.0f};
        s.lights.push_back(lamp);
    }
}

void addBox(Scene& scene, glm::vec3 lo, glm::vec3 hi, uint32_t material, bool dynamic) {
    SceneMesh m;
    m.material = material;
    m.dynamic = dynamic;
    const glm::vec3 p[8] = {{lo.x, lo.y, lo.z}, {hi.x, lo.y, lo.z}, {hi.x, hi.y, lo.z},
                            {lo.x, hi.y, lo.z}, {lo.x, lo.y, hi.z}, {hi.x, lo.y, hi.z},
                            {hi.x, hi.y, hi.z}, {lo.x, hi.y, hi.z}};
    addQuadFace(m, p[4], p[5], p[6], p[7], {0, 0, 1});   // +Z
    addQuadFace(m, p[1], p[0], p[3], p[2], {0, 0, -1});  // -Z
    addQuadFace(m, p[5], p[1], p[2], p[6], {1, 0, 0});   // +X
    addQuadFace(m, p[0], p[4], p[7], p[3], {-1, 0, 0});  // -X
    addQuadFace(m, p[7], p[6], p[2], p[3], {0, 1, 0});   // +Y
    addQuadFace(m, p[0], p[1], p[5], p[4], {0, -1, 0});  // -Y
    scene.meshes.push_back(m);
}

void addSphere(Scene& scene, glm::vec3 centre, float radius, uint32_t rings, uint32_t segments,
               uint32_t material) {
    SceneMesh m;
    m.material = material;
    for (uint32_t r = 0; r <= rings; ++r)
        for (uint32_t s = 0; s <= segments; ++s) {
            const float theta = glm::pi<float>() * float(r) / float(rings);
            const float phi = 2.0f * glm::pi<float>() * float(s) / float(segments);
            const glm::vec3 n(std::sin(theta) * std::cos(phi), std::cos(theta),
                              -std::sin(theta) * std::sin(phi));
            m.positions.push_back(centre + radius * n);
            m.normals.push_back(n);
        }
    for (uint32_t r = 0; r < rings; ++r)
        for (uint32_t s = 0; s < segments; ++s) {
            const uint32_t a = r * (segments + 1) + s, b = a + segments + 1;
            if (r > 0) {
                m.indices.push_back(a);
                m.indices.push_back(b);
                m.indices.push_back(a + 1);
            }
            if (r + 1 < rings) {
                m.indices.push_back(a + 1);
                m.indices.push_back(b);
                m.indices.push_back(b + 1);
            }
        }
    scene.meshes.push_back(m);
}

void writeGltf(const Scene& scene, const std::string& path) {
    using nlohmann::json;
    std::vector<uint8_t> buffer;
    json accessors = json::array(), views = json::array(), meshes = json::array(),
         nodes = json::array(), materials = json::array(), lights = json::array();
    auto addView = [&](size_t offset, size_t bytes, int target) {
        views.push_back(
            {{"buffer", 0}, {"byteOffset", offset}, {"byteLength", bytes}, {"target", target}});
        return views.size() - 1;
    };
    for (const SceneMesh& m : scene.meshes) {
        glm::vec3 lo(1e30f), hi(-1e30f);
        for (glm::vec3 p : m.positions) {
            lo = glm::min(lo, p);
            hi = glm::max(hi, p);
        }
        const size_t pos = addView(append(buffer, m.positions), m.positions.size() * 12, 34962);
        const size_t nor = addView(append(buffer, m.normals), m.normals.size() * 12, 34962);
        const size_t idx = addView(append(buffer, m.indices), m.indices.size() * 4, 34963);
        accessors.push_back({{"bufferView", pos},
                             {"componentType", 5126},
                             {"count", m.positions.size()},
                             {"type", "VEC3"},
                             {"min", {lo.x, lo.y, lo.z}},
                             {"max", {hi.x, hi.y, hi.z}}});
        accessors.push_back({{"bufferView", nor},
                             {"componentType", 5126},
                             {"count", m.normals.size()},
                             {"type", "VEC3"}});
        accessors.push_back({{"bufferView", idx},
                             {"componentType", 5125},
                             {"count", m.indices.size()},
                             {"type", "SCALAR"}});
        const size_t a = accessors.size() - 3;
        meshes.push_back({{"primitives",
                           {{{"attributes", {{"POSITION", a}, {"NORMAL", a + 1}}},
                             {"indices", a + 2},
                             {"material", m.material}}}}});
        json node = {{"mesh", meshes.size() - 1},
                     {"name", "mesh" + std::to_string(meshes.size() - 1)}};
        if (m.dynamic) node["extras"] = {{"onelight", {{"dynamic", true}}}};
        nodes.push_back(node);
    }
    for (const SceneMaterial& m : scene.materials) {
        json material = {
            {"pbrMetallicRoughness",
             {{"baseColorFactor", {m.baseColor.x, m.baseColor.y, m.baseColor.z, m.baseColor.w}},
              {"metallicFactor", m.metallic},
              {"roughnessFactor", m.roughness}}}};
        if (m.emissive != glm::vec3(0.0f))
            material["emissiveFactor"] = {m.emissive.x, m.emissive.y, m.emissive.z};
        if (m.emissiveStrength != 1.0f)
            material["extensions"] = {
                {"KHR_materials_emissive_strength", {{"emissiveStrength", m.emissiveStrength}}}};
        materials.push_back(material);
    }
    for (size_t i = 0; i < scene.lights.size(); ++i) {
        const SceneLight& l = scene.lights[i];
        static const char* const types[3] = {"directional", "point", "spot"};
        json light = {{"type", types[l.type]},
                      {"color", {l.color.x, l.color.y, l.color.z}},
                      {"intensity", l.intensity}};
        if (l.range > 0.0f) light["range"] = l.range;
        if (l.type == 2)
            light["spot"] = {{"innerConeAngle", l.innerCone}, {"outerConeAngle", l.outerCone}};
        lights.push_back(light);
        const glm::quat q = lightRotation(l.direction);
        json node = {{"name", "light" + std::to_string(i)},
                     {"translation", {l.position.x, l.position.y, l.position.z}},
                     {"rotation", {q.x, q.y, q.z, q.w}},
                     {"extensions", {{"KHR_lights_punctual", {{"light", i}}}}}};
        if (l.role) node["extras"] = {{"onelight", {{"role", l.role}}}};
        nodes.push_back(node);
    }
    const json sky = {scene.sky.x, scene.sky.y, scene.sky.z};
    if (!scene.skyImage.empty())
        nodes.push_back(
            {{"name", "level_settings"},
             {"extras", {{"onelight", {{"sky", {{"image", scene.skyImage}, {"scale", sky}}}}}}}});
    else if (scene.sky != glm::vec3(0.0f))
        nodes.push_back({{"name", "level_settings"}, {"extras", {{"onelight", {{"sky", sky}}}}}});
    if (scene.viewAspect > 0.0f) {
        const glm::vec3 t = scene.viewPosition;
        const glm::quat q = scene.viewRotation;
        nodes.push_back({{"name", "view"},
                         {"camera", 0},
                         {"translation", {t.x, t.y, t.z}},
                         {"rotation", {q.x, q.y, q.z, q.w}}});
    }
    json sceneNodes = json::array();
    for (size_t i = 0; i < nodes.size(); ++i) sceneNodes.push_back(i);
    json gltf = {{"asset", {{"version", "2.0"}}},
                 {"scene", 0},
                 {"scenes", {{{"nodes", sceneNodes}}}},
                 {"nodes", nodes},
                 {"meshes", meshes},
                 {"materials", materials},
                 {"accessors", accessors},
                 {"bufferViews", views},
                 {"buffers",
                  {{{"byteLength", buffer.size()},
                    {"uri", "data:application/octet-stream;base64," + base64(buffer)}}}}};
    if (scene.viewAspect > 0.0f)
        gltf["cameras"] = {
            {{"type", "perspective"},
             {"perspective",
              {{"yfov", scene.viewYfov}, {"aspectRatio", scene.viewAspect}, {"znear", 0.05}}}}};
    if (!scene.lights.empty()) {
        gltf["extensionsUsed"] = {"KHR_lights_punctual"};
        gltf["extensions"] = {{"KHR_lights_punctual", {{"lights", lights}}}};
    }
    std::ofstream out(path, std::ios::binary | std::ios::trunc);
    out << gltf.dump();
    if (!out) throw std::runtime_error(path + ": cannot write");
}

int compileLevel(const std::string& gltf, const std::string& package) {
    world::ChildOptions options;
    options.out = world::ChildStream::kDiscard;
    options.err = world::ChildStream::kInherit;
    return world::runChild({ONELIGHT_BAKE_PATH, "compile", gltf, "-o", package}, options).exitCode;
}

world::ChildResult runOnelight(const std::vector<std::string>& args) {
    std::vector<std::string> argv = {ONELIGHT_ONELIGHT_PATH};
    argv.insert(argv.end(), args.begin(), args.end());
    world::ChildOptions options;
    options.out = world::ChildStream::kDiscard;
    return world::runChild(argv, options);
}

assets::LoadedLevel compileAndLoad(const std::string& gltf, const std::string& package) {
    if (compileLevel(gltf, package) != 0)
        throw std::runtime_error(gltf + ": onelight-bake compile failed");
    return assets::loadLevel(package);
}

int bakeLevel(const std::string& gltf, const std::string& package,
              const std::string& extraArguments) {
    const std::string command = std::string("'") + ONELIGHT_BAKE_PATH + "' '" + gltf + "' -o '" +
                                package + "' --quality draft --quiet " + extraArguments +
                                " > /dev/null";
    const int status = std::system(command.c_str());
    return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

assets::LoadedLevel bakeAndLoad(const std::string& gltf, const std::string& package,
                                const std::string& extraArguments) {
    if (bakeLevel(gltf, package, extraArguments) != 0)
        throw std::runtime_error(gltf + ": onelight-bake failed");
    return assets::loadLevel(package);
}

std::string outputDir() {
    const std::string dir = ONELIGHT_TEST_OUTPUT_DIR;
    std::filesystem::create_directories(dir);
    return dir;
}

RenderedFrame renderOnce(const assets::LoadedLevel& level, const render::RendererOptions& options,
                         const render::FrameInputs& inputs, int frames) {
    render::RenderDeviceFeatures features;
    vk::Context ctx;
    vk::createContext(ctx, render::renderContextOptions(features, {}));
    RenderedFrame result;
    {
        render::Renderer renderer;
        try {
            render::createRenderer(renderer, ctx, level, options);
            render::FrameOutput output;
            output.readback = true;
            for (int i = 0; i < frames; ++i)
                result.stats = render::drawFrame(renderer, inputs, output);
            result.frame = render::capturedFrame(renderer);
            result.msaaInUse = render::rendererInfo(renderer).msaaInUse;
            result.permutations = render::rendererInfo(renderer).permutations;
        } catch (...) {
            render::destroyRenderer(renderer);
            vk::destroyContext(ctx);
            throw;
        }
        render::destroyRenderer(renderer);
    }
    vk::destroyContext(ctx);
    result.validationErrors = ctx.validationCounts.errors.load();
    return result;
}

void writeReferenceComparison(const std::string& path, uint32_t width, uint32_t height,
                              const std::vector<float>& reference,
                              const std::vector<const std::vector<float>*>& frames, float mean) {
    const size_t pixels = size_t(width) * height;
    const auto luminanceOf = [](const std::vector<float>& image, size_t pixel, size_t channels) {
        return 0.2126 * double(image[pixel * channels]) +
               0.7152 * double(image[pixel * channels + 1]) +
               0.0722 * double(image[pixel * channels + 2]);
    };
    double sum = 0.0;
    for (size_t i = 0; i < pixels; ++i) sum += luminanceOf(reference, i, 3);
    const float scale = float(double(mean) / std::max(sum / double(pixels), 1e-9));
    const uint32_t columns = uint32_t(frames.size() + 1);
    std::vector<uint8_t> rgba(size_t(columns) * pixels * 4, 255);
    for (uint32_t k = 0; k < columns; ++k) {
        const std::vector<float>& image = k == 0 ? reference : *frames[k - 1];
        const size_t channels = k == 0 ? 3 : 4;
        for (uint32_t y = 0; y < height; ++y)
            for (uint32_t x = 0; x < width; ++x)
                for (size_t c = 0; c < 3; ++c) {
                    const float v = image[(size_t(y) * width + x) * channels + c] * scale;
                    const float display = std::pow(v / (1.0f + v), 1.0f / 2.2f);
                    rgba[((size_t(y) * columns * width) + size_t(k) * width + x) * 4 + c] =
                        uint8_t(std::lround(255.0f * std::clamp(display, 0.0f, 1.0f)));
                }
    }
    world::writePngFile(path, columns * width, height, rgba);
}

bool anyNamed(const std::vector<std::string>& names, const char* part) {
    for (const std::string& n : names)
        if (n.find(part) != std::string::npos) return true;
    return false;
}

int worstChannelDifference(const std::vector<uint8_t>& a, const std::vector<uint8_t>& b,
                           size_t pixel) {
    int worst = 0;
    for (size_t k = 0; k < 3; ++k)
        worst = std::max(worst, std::abs(int(a[4 * pixel + k]) - int(b[4 * pixel + k])));
    return worst;
}

double shareOfPixelsOff(const std::vector<uint8_t>& a, const std::vector<uint8_t>& b,
                        int threshold) {
    const size_t pixels = std::min(a.size(), b.size()) / 4;
    size_t off = 0;
    for (size_t p = 0; p < pixels; ++p) off += worstChannelDifference(a, b, p) > threshold ? 1 : 0;
    return pixels == 0 ? 0.0 : double(off) / double(pixels);
}

}  // namespace onelight::test
