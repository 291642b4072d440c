#include "world/gltf/level_export.hpp"

#include <algorithm>
#include <cmath>
#include <vector>

#include <glm/gtc/matrix_inverse.hpp>
#include <glm/gtx/quaternion.hpp>
#include <nlohmann/json.hpp>

#include "world/error.hpp"
#include "world/file_read.hpp"
#include "world/file_write.hpp"
#include "world/gltf/gltf_builder.hpp"
#include "world/images/image_decode.hpp"
#include "world/images/image_files.hpp"

namespace onelight::world {
namespace {

using nlohmann::json;

json vec3(glm::vec3 v) {
    return json::array({v.x, v.y, v.z});
}

json quat(glm::quat q) {
    return json::array({q.x, q.y, q.z, q.w});  // glTF's order
}

// The image's bytes: embedded, or its uri under the source's folder (world::Error when that is
// not a readable regular file).
std::vector<uint8_t> imageBytes(const Image& image, const std::filesystem::path& sourceFolder) {
    if (!image.encodedBytes.empty()) return image.encodedBytes;
    if (image.uri.empty()) return {};
    return readRegularFile((sourceFolder / image.uri).string(), "an image");
}

// Each image the level uses, written under NAME_images/ as a PNG (the sky as .hdr); the uri the
// glTF gives it, or "" where it could not be decoded (its textures are then dropped).
std::vector<std::string> writeImages(const SourceLevel& level,
                                     const std::filesystem::path& sourceFolder,
                                     const std::filesystem::path& folder, const std::string& name,
                                     LevelExportStats& stats) {
    const std::string subfolder = name + "_images";
    std::filesystem::create_directories(folder / subfolder);
    std::vector<std::string> uris(level.images.size());
    for (size_t i = 0; i < level.images.size(); ++i) {
        const Image& image = level.images[i];
        const std::string where = image.name.empty() ? image.uri : image.name;
        // Read and decode: a source image that fails drops its textures (counted); writing
        // the copy is outside, so that a failed write fails the export.
        const bool hdr = i == level.skyImage || image.uri.ends_with(".hdr");
        HdrImage sky;
        DecodedImage decoded;
        try {
            const std::vector<uint8_t> bytes = imageBytes(image, sourceFolder);
            if (bytes.empty()) throw Error(where + ": no bytes");
            if (hdr)
                sky = decodeHdrImage(bytes.data(), bytes.size(), where);
            else
                decoded = decodeImage(bytes.data(), bytes.size(), where);
        } catch (const Error&) {
            ++stats.imagesMissing;
            continue;
        }
        uris[i] = subfolder + "/" + std::to_string(i) + (hdr ? ".hdr" : ".png");
        if (hdr)
            writeHdrFile((folder / uris[i]).string(), sky.width, sky.height, sky.rgb);
        else
            writePngFile((folder / uris[i]).string(), decoded.width, decoded.height, decoded.rgba);
        ++stats.images;
    }
    return uris;
}

// The glTF textures: one per level texture whose image was written (-1 for the others).
std::vector<int> addTextures(json& document, const SourceLevel& level,
                             const std::vector<std::string>& imageUris) {
    document["images"] = json::array();
    for (const std::string& uri : imageUris) document["images"].push_back({{"uri", uri}});
    document["samplers"] = json::array();
    document["textures"] = json::array();
    std::vector<int> index(level.textures.size(), -1);
    for (size_t t = 0; t < level.textures.size(); ++t) {
        const Texture& texture = level.textures[t];
        if (texture.image >= imageUris.size() || imageUris[texture.image].empty()) continue;
        json sampler = {{"wrapS", texture.sampler.wrapS}, {"wrapT", texture.sampler.wrapT}};
        if (texture.sampler.magFilter) sampler["magFilter"] = texture.sampler.magFilter;
        if (texture.sampler.minFilter) sampler["minFilter"] = texture.sampler.minFilter;
        document["samplers"].push_back(sampler);
        document["textures"].push_back(
            {{"sampler", document["samplers"].size() - 1}, {"source", texture.image}});
        index[t] = int(document["textures"].size() - 1);
    }
    return index;
}

json material(const Material& m, const std::vector<int>& textures) {
    const auto texture = [&](uint32_t t) { return t < textures.size() ? textures[t] : -1; };
    json pbr = {{"baseColorFactor", {m.baseColor.r, m.baseColor.g, m.baseColor.b, m.baseColor.a}},
                {"metallicFactor", m.metallic},
                {"roughnessFactor", m.roughness}};
    if (texture(m.baseColorTexture) >= 0)
        pbr["baseColorTexture"] = {{"index", texture(m.baseColorTexture)}};
    if (texture(m.metallicRoughnessTexture) >= 0)
        pbr["metallicRoughnessTexture"] = {{"index", texture(m.metallicRoughnessTexture)}};
    json out = {{"name", m.name}, {"pbrMetallicRoughness", pbr}};
    if (texture(m.normalTexture) >= 0)
        out["normalTexture"] = {{"index", texture(m.normalTexture)}, {"scale", m.normalScale}};
    if (texture(m.occlusionTexture) >= 0)
        out["occlusionTexture"] = {{"index", texture(m.occlusionTexture)},
                                   {"strength", m.occlusionStrength}};
    if (texture(m.emissiveTexture) >= 0)
        out["emissiveTexture"] = {{"index", texture(m.emissiveTexture)}};
    // cd/m^2 as a factor of at most 1 times KHR_materials_emissive_strength.
    const float peak = std::max({m.emissive.r, m.emissive.g, m.emissive.b});
    if (peak > 0.0f) {
        const float strength = std::max(peak, 1.0f);
        out["emissiveFactor"] = vec3(m.emissive / strength);
        if (strength > 1.0f)
            out["extensions"]["KHR_materials_emissive_strength"] = {{"emissiveStrength", strength}};
    }
    if (m.alphaMode != AlphaMode::kOpaque) {
        out["alphaMode"] = m.alphaMode == AlphaMode::kMask ? "MASK" : "BLEND";
        if (m.alphaMode == AlphaMode::kMask) out["alphaCutoff"] = m.alphaCutoff;
    }
    if (m.doubleSided) out["doubleSided"] = true;
    if (!m.castsShadows) out["extras"]["onelight"]["casts_shadows"] = false;
    return out;
}

const char* roleName(LightRole role) {
    return role == LightRole::kBaked ? "baked" : role == LightRole::kEffect ? "effect" : "primary";
}

// The rotation taking the node's -Z (where glTF's lights and cameras point) to `direction`.
glm::quat facing(glm::vec3 direction) {
    const float length = glm::length(direction);
    if (!(length > 0.0f)) return glm::quat(1.0f, 0.0f, 0.0f, 0.0f);
    return glm::rotation(glm::vec3(0.0f, 0.0f, -1.0f), direction / length);
}

void addLight(GltfBuilder& gltf, const Light& l) {
    json light = {{"name", l.name}, {"color", vec3(l.color)}, {"intensity", l.intensity}};
    light["type"] = l.type == LightType::kDirectional ? "directional"
                    : l.type == LightType::kSpot      ? "spot"
                                                      : "point";
    if (l.type != LightType::kDirectional && l.range > 0.0f) light["range"] = l.range;
    if (l.type == LightType::kSpot)
        light["spot"] = {{"innerConeAngle", l.innerCone}, {"outerConeAngle", l.outerCone}};
    const int index = gltf.addLight(light);
    json node = {{"name", l.name},
                 {"rotation", quat(facing(l.direction))},
                 {"extensions", {{"KHR_lights_punctual", {{"light", index}}}}},
                 {"extras", {{"onelight", {{"role", roleName(l.role)}}}}}};
    if (l.type != LightType::kDirectional) node["translation"] = vec3(l.position);
    gltf.addNode(node);
}

void addCamera(GltfBuilder& gltf, const Camera& c) {
    json camera;
    if (c.orthographic) {
        camera = {{"type", "orthographic"},
                  {"orthographic",
                   {{"xmag", c.xmag}, {"ymag", c.ymag}, {"znear", c.znear}, {"zfar", c.zfar}}}};
    } else {
        json perspective = {{"yfov", c.yfov}, {"znear", c.znear}};
        if (c.aspectRatio > 0.0f) perspective["aspectRatio"] = c.aspectRatio;
        if (c.zfar > 0.0f) perspective["zfar"] = c.zfar;
        camera = {{"type", "perspective"}, {"perspective", perspective}};
    }
    json node = {{"name", c.name},
                 {"camera", gltf.addCamera(camera)},
                 {"translation", vec3(c.position)},
                 {"rotation", quat(c.rotation)}};
    if (c.hasExposure) node["extras"]["onelight"]["exposure"] = c.exposureEv100;
    gltf.addNode(node);
}

// The level's own settings, on a node of their own (world/import/extras_import.cpp reads them
// from any node).
json levelExtras(const SourceLevel& level, const std::vector<std::string>& imageUris) {
    json o = json::object();
    if (level.skyImage < imageUris.size() && !imageUris[level.skyImage].empty())
        o["sky"] = {{"image", imageUris[level.skyImage]}, {"scale", vec3(level.skyRadiance)}};
    else if (glm::any(glm::greaterThan(level.skyRadiance, glm::vec3(0.0f))))
        o["sky"] = vec3(level.skyRadiance);
    if (level.texelsPerMetre > 0.0f) o["texels_per_metre"] = level.texelsPerMetre;
    if (level.probeSpacing > 0.0f) o["probe_spacing"] = level.probeSpacing;
    if (level.hasGridBounds)
        o["grid"] = {{"min", vec3(level.gridMin)}, {"max", vec3(level.gridMax)}};
    if (level.hasExposure) o["exposure"] = level.exposureEv100;
    o["diffuse"] = level.diffuseModel == DiffuseModel::kLambert ? "lambert" : "multiscatter";
    static const char* const kMips[] = {"blit", "black_ops", "wwii", "clean"};
    o["gloss_mips"] = kMips[std::min<size_t>(size_t(level.glossMips), 3)];
    return o;
}

// Probes and spawns, as nodes with their extras.
void addEntities(GltfBuilder& gltf, const SourceLevel& level) {
    for (const Entity& e : level.entities) {
        json o = json::object();
        if (e.flags & kEntitySpawn) o["spawn"] = true;
        if (e.flags & kEntityProbe) {
            if (glm::all(glm::lessThan(e.probeBoxMin, e.probeBoxMax)))
                o["probe"] = {{"box_min", vec3(e.probeBoxMin)}, {"box_max", vec3(e.probeBoxMax)}};
            else
                o["probe"] = true;
        }
        if (o.empty()) continue;  // dynamic objects are not written
        gltf.addNode({{"name", e.name},
                      {"translation", vec3(e.position)},
                      {"rotation", quat(e.rotation)},
                      {"extras", {{"onelight", o}}}});
    }
}

}  // namespace

LevelExportStats exportLevelGltf(const SourceLevel& level,
                                 const std::filesystem::path& sourceFolder,
                                 const std::filesystem::path& folder, const std::string& name) {
    LevelExportStats stats;
    std::filesystem::create_directories(folder);
    GltfBuilder gltf;
    const std::vector<std::string> imageUris =
        writeImages(level, sourceFolder, folder, name, stats);
    const std::vector<int> textures = addTextures(gltf.document(), level, imageUris);
    for (const Material& m : level.materials) gltf.addMaterial(material(m, textures));
    stats.materials = level.materials.size();
    bool emissiveStrength = false;
    for (const json& m : gltf.document()["materials"]) emissiveStrength |= m.contains("extensions");

    for (size_t i = 0; i < level.instances.size(); ++i) {
        const MeshInstance& instance = level.instances[i];
        if (instance.dynamic) {
            ++stats.dynamicLeftOut;
            continue;
        }
        // World space, in doubles until the end: the file's node carries no transform.
        const glm::dmat3 normalMatrix = glm::inverseTranspose(glm::dmat3(instance.worldFromLocal));
        MeshData mesh;
        mesh.name =
            instance.nodeName + "/" + instance.meshName + "#" + std::to_string(instance.primitive);
        mesh.material = instance.material < level.materials.size() ? int(instance.material) : -1;
        for (const Vertex& v : instance.vertices) {
            mesh.positions.push_back(
                glm::vec3(instance.worldFromLocal * glm::dvec4(glm::dvec3(v.position), 1.0)));
            const glm::dvec3 n = normalMatrix * glm::dvec3(v.normal);
            const double length = glm::length(n);
            mesh.normals.push_back(length > 0.0 ? glm::vec3(n / length) : v.normal);
            mesh.uv0.push_back(v.uv0);
            if (instance.hasUv1) mesh.uv1.push_back(v.uv1);
        }
        mesh.indices = instance.indices;
        stats.triangles += mesh.indices.size() / 3;
        ++stats.instances;
        json node = {{"name", instance.nodeName}, {"mesh", gltf.addMesh(mesh)}};
        if (instance.prop)
            node["extras"]["onelight"]["prop"] = {
                {"lighting_origin", vec3(glm::vec3(instance.lightingOrigin))}};
        gltf.addNode(node);
    }
    for (const Light& l : level.lights) addLight(gltf, l);
    stats.lights = level.lights.size();
    for (const Camera& c : level.cameras) addCamera(gltf, c);
    stats.cameras = level.cameras.size();
    addEntities(gltf, level);
    gltf.addNode({{"name", "level"}, {"extras", {{"onelight", levelExtras(level, imageUris)}}}});

    json& document = gltf.document();
    if (emissiveStrength) {
        json& used = document["extensionsUsed"];
        if (used.is_null()) used = json::array();
        used.push_back("KHR_materials_emissive_strength");
    }
    for (const char* key : {"images", "samplers", "textures"})
        if (document[key].empty()) document.erase(key);
    gltf.write(folder, name);
    return stats;
}

}  // namespace onelight::world
