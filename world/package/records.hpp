// One toDisk / fromDisk pair per .olpak record (format.hpp): the one place that maps each
// field between an in-memory type (compiled_level.hpp, baked_lighting.hpp, visibility.hpp,
// processed_textures.hpp) and its on-disk twin. The writers call toDisk; the readers check a record
// first (every index, range and float, with errors naming the field) and then call fromDisk.
// fromDisk never reads outside what it is given: a string or byte range that does not fit comes
// back empty.
#pragma once

#include <cstdint>
#include <cstring>
#include <span>
#include <string>
#include <vector>

#include "world/baked_lighting.hpp"
#include "world/compiled_level.hpp"
#include "world/package/format.hpp"
#include "world/processed_textures.hpp"
#include "world/visibility.hpp"

namespace onelight::package {

// The helpers and the pairs live in `records`; the pairs are brought into package below.
namespace records {

// Flags are stored as they are in memory.
static_assert(uint32_t(world::kLightmapTexelSampled) == uint32_t(kLightmapTexelSampled));
static_assert(uint32_t(world::kLightmapTexelDilated) == uint32_t(kLightmapTexelDilated));
static_assert(uint32_t(world::kLightGridCellInsideSolid) == uint32_t(kLightGridCellInsideSolid));

/// Copies `v` into the array field `dst`.
inline void put(float (&dst)[2], const glm::vec2& v) {
    for (int i = 0; i < 2; ++i) dst[i] = v[i];
}
/// Copies `v` into the array field `dst`.
inline void put(float (&dst)[3], const glm::vec3& v) {
    for (int i = 0; i < 3; ++i) dst[i] = v[i];
}
/// Copies `v` into the array field `dst`.
inline void put(float (&dst)[4], const glm::vec4& v) {
    for (int i = 0; i < 4; ++i) dst[i] = v[i];
}
/// Copies `v` into the array field `dst`.
inline void put(double (&dst)[3], const glm::dvec3& v) {
    for (int i = 0; i < 3; ++i) dst[i] = v[i];
}
/// Copies `q` into the array field `dst` as x, y, z, w.
inline void put(float (&dst)[4], const glm::quat& q) {
    dst[0] = q.x;
    dst[1] = q.y;
    dst[2] = q.z;
    dst[3] = q.w;
}

/// The array field `v` as a vector.
[[nodiscard]] inline glm::vec2 vec(const float (&v)[2]) {
    return glm::vec2(v[0], v[1]);
}
/// The array field `v` as a vector.
[[nodiscard]] inline glm::vec3 vec(const float (&v)[3]) {
    return glm::vec3(v[0], v[1], v[2]);
}
/// The array field `v` as a vector.
[[nodiscard]] inline glm::vec4 vec(const float (&v)[4]) {
    return glm::vec4(v[0], v[1], v[2], v[3]);
}
/// The array field `v` as a vector.
[[nodiscard]] inline glm::dvec3 vec(const double (&v)[3]) {
    return glm::dvec3(v[0], v[1], v[2]);
}
/// The array field `v` (x, y, z, w) as a quaternion.
[[nodiscard]] inline glm::quat quat(const float (&v)[4]) {
    return glm::quat(v[3], v[0], v[1], v[2]);
}

/// Bytes [first, first + count) of `bytes`, or none when they do not fit.
[[nodiscard]] inline std::span<const uint8_t> slice(std::span<const uint8_t> bytes, uint64_t first,
                                                    uint64_t count) {
    if (first > bytes.size() || count > bytes.size() - first) return {};
    return bytes.subspan(first, count);
}

}  // namespace records

/// The byte sections that records refer into (strings, image bytes), as a writer fills them.
struct BlobWriter {
    std::vector<uint8_t> strings;     // kSectionStrings
    std::vector<uint8_t> imageBytes;  // kSectionImageBytes

    /// Appends `s` to the strings and returns its reference.
    StringRef addString(const std::string& s) {
        const StringRef ref{static_cast<uint32_t>(strings.size()), static_cast<uint32_t>(s.size())};
        strings.insert(strings.end(), s.begin(), s.end());
        return ref;
    }
};

/// The same byte sections as a reader sees them.
struct BlobReader {
    std::span<const uint8_t> strings;     // kSectionStrings
    std::span<const uint8_t> imageBytes;  // kSectionImageBytes

    /// The string `ref` refers to; "" when it runs outside the strings.
    std::string string(const StringRef& ref) const {
        const std::span<const uint8_t> s = records::slice(strings, ref.offset, ref.length);
        return std::string(s.begin(), s.end());
    }
};

namespace records {

/// Level settings -> DiskLevel.
[[nodiscard]] inline DiskLevel toDisk(const world::LevelSettings& s) {
    DiskLevel d{};
    d.exposureEv100 = s.exposureEv100;
    d.hasExposure = s.hasExposure ? 1 : 0;
    d.texelsPerMetre = s.texelsPerMetre;
    put(d.boundsMin, s.boundsMin);
    put(d.boundsMax, s.boundsMax);
    d.probeSpacing = s.probeSpacing;
    put(d.skyRadiance, s.skyRadiance);
    d.skyImage = s.skyImage;
    d.diffuseModel = uint8_t(s.diffuseModel);
    d.glossMips = uint8_t(s.glossMips);
    return d;
}

/// DiskLevel -> level settings.
[[nodiscard]] inline world::LevelSettings fromDisk(const DiskLevel& d) {
    world::LevelSettings s;
    s.exposureEv100 = d.exposureEv100;
    s.hasExposure = d.hasExposure != 0;
    s.texelsPerMetre = d.texelsPerMetre;
    s.boundsMin = vec(d.boundsMin);
    s.boundsMax = vec(d.boundsMax);
    s.probeSpacing = d.probeSpacing;
    s.skyRadiance = vec(d.skyRadiance);
    s.skyImage = d.skyImage;
    s.diffuseModel = world::DiffuseModel(d.diffuseModel);
    s.glossMips = world::GlossMipMethod(d.glossMips);
    return s;
}

/// Material -> DiskMaterial; appends the name to `blobs`.
[[nodiscard]] inline DiskMaterial toDisk(const world::Material& m, BlobWriter& blobs) {
    DiskMaterial d{};
    d.name = blobs.addString(m.name);
    put(d.baseColor, m.baseColor);
    d.metallic = m.metallic;
    d.roughness = m.roughness;
    put(d.albedo, m.albedo);
    put(d.specularColor, m.specularColor);
    d.gloss = m.gloss;
    put(d.emissive, m.emissive);
    d.alphaCutoff = m.alphaCutoff;
    d.normalScale = m.normalScale;
    d.occlusionStrength = m.occlusionStrength;
    d.baseColorTexture = m.baseColorTexture;
    d.metallicRoughnessTexture = m.metallicRoughnessTexture;
    d.normalTexture = m.normalTexture;
    d.occlusionTexture = m.occlusionTexture;
    d.emissiveTexture = m.emissiveTexture;
    d.alphaMode = static_cast<uint8_t>(m.alphaMode);
    d.doubleSided = m.doubleSided ? 1 : 0;
    d.materialClass = static_cast<uint8_t>(m.materialClass);
    d.flags = m.castsShadows ? 0 : kMaterialFlagNoShadows;
    return d;
}

/// DiskMaterial -> material, the name read from `blobs`.
[[nodiscard]] inline world::Material fromDisk(const DiskMaterial& d, const BlobReader& blobs) {
    world::Material m;
    m.name = blobs.string(d.name);
    m.baseColor = vec(d.baseColor);
    m.metallic = d.metallic;
    m.roughness = d.roughness;
    m.albedo = vec(d.albedo);
    m.specularColor = vec(d.specularColor);
    m.gloss = d.gloss;
    m.emissive = vec(d.emissive);
    m.alphaCutoff = d.alphaCutoff;
    m.normalScale = d.normalScale;
    m.occlusionStrength = d.occlusionStrength;
    m.baseColorTexture = d.baseColorTexture;
    m.metallicRoughnessTexture = d.metallicRoughnessTexture;
    m.normalTexture = d.normalTexture;
    m.occlusionTexture = d.occlusionTexture;
    m.emissiveTexture = d.emissiveTexture;
    m.alphaMode = static_cast<world::AlphaMode>(d.alphaMode);
    m.doubleSided = d.doubleSided != 0;
    m.materialClass = static_cast<world::MaterialClass>(d.materialClass);
    m.castsShadows = (d.flags & kMaterialFlagNoShadows) == 0;
    return m;
}

/// Texture -> DiskTexture.
[[nodiscard]] inline DiskTexture toDisk(const world::Texture& t) {
    DiskTexture d{};
    d.image = t.image;
    d.magFilter = t.sampler.magFilter;
    d.minFilter = t.sampler.minFilter;
    d.wrapS = t.sampler.wrapS;
    d.wrapT = t.sampler.wrapT;
    return d;
}

/// DiskTexture -> texture.
[[nodiscard]] inline world::Texture fromDisk(const DiskTexture& d) {
    world::Texture t;
    t.image = d.image;
    t.sampler.magFilter = d.magFilter;
    t.sampler.minFilter = d.minFilter;
    t.sampler.wrapS = d.wrapS;
    t.sampler.wrapT = d.wrapT;
    return t;
}

/// Image -> DiskImage; appends the strings and the encoded bytes to `blobs`.
[[nodiscard]] inline DiskImage toDisk(const world::Image& image, BlobWriter& blobs) {
    DiskImage d{};
    d.name = blobs.addString(image.name);
    d.uri = blobs.addString(image.uri);
    d.mimeType = blobs.addString(image.mimeType);
    d.firstByte = static_cast<uint32_t>(blobs.imageBytes.size());
    d.byteCount = static_cast<uint32_t>(image.encodedBytes.size());
    blobs.imageBytes.insert(blobs.imageBytes.end(), image.encodedBytes.begin(),
                            image.encodedBytes.end());
    return d;
}

/// DiskImage -> image, strings and encoded bytes read from `blobs`.
[[nodiscard]] inline world::Image fromDisk(const DiskImage& d, const BlobReader& blobs) {
    world::Image image;
    image.name = blobs.string(d.name);
    image.uri = blobs.string(d.uri);
    image.mimeType = blobs.string(d.mimeType);
    const std::span<const uint8_t> bytes = slice(blobs.imageBytes, d.firstByte, d.byteCount);
    image.encodedBytes.assign(bytes.begin(), bytes.end());
    return image;
}

/// Light -> DiskLight; appends the name to `blobs`.
[[nodiscard]] inline DiskLight toDisk(const world::Light& l, BlobWriter& blobs) {
    DiskLight d{};
    d.name = blobs.addString(l.name);
    d.type = static_cast<uint8_t>(l.type);
    d.role = static_cast<uint8_t>(l.role);
    put(d.color, l.color);
    d.intensity = l.intensity;
    d.range = l.range;
    d.innerCone = l.innerCone;
    d.outerCone = l.outerCone;
    put(d.position, l.position);
    put(d.direction, l.direction);
    return d;
}

/// DiskLight -> light, the name read from `blobs`.
[[nodiscard]] inline world::Light fromDisk(const DiskLight& d, const BlobReader& blobs) {
    world::Light l;
    l.name = blobs.string(d.name);
    l.type = static_cast<world::LightType>(d.type);
    l.role = static_cast<world::LightRole>(d.role);
    l.color = vec(d.color);
    l.intensity = d.intensity;
    l.range = d.range;
    l.innerCone = d.innerCone;
    l.outerCone = d.outerCone;
    l.position = vec(d.position);
    l.direction = vec(d.direction);
    return l;
}

/// Camera -> DiskCamera; appends the name to `blobs`.
[[nodiscard]] inline DiskCamera toDisk(const world::Camera& c, BlobWriter& blobs) {
    DiskCamera d{};
    d.name = blobs.addString(c.name);
    d.orthographic = c.orthographic ? 1 : 0;
    d.yfov = c.yfov;
    d.aspectRatio = c.aspectRatio;
    d.znear = c.znear;
    d.zfar = c.zfar;
    d.xmag = c.xmag;
    d.ymag = c.ymag;
    put(d.position, c.position);
    put(d.rotation, c.rotation);
    d.exposureEv100 = c.exposureEv100;
    d.hasExposure = c.hasExposure ? 1 : 0;
    return d;
}

/// DiskCamera -> camera, the name read from `blobs`.
[[nodiscard]] inline world::Camera fromDisk(const DiskCamera& d, const BlobReader& blobs) {
    world::Camera c;
    c.name = blobs.string(d.name);
    c.orthographic = d.orthographic != 0;
    c.yfov = d.yfov;
    c.aspectRatio = d.aspectRatio;
    c.znear = d.znear;
    c.zfar = d.zfar;
    c.xmag = d.xmag;
    c.ymag = d.ymag;
    c.position = vec(d.position);
    c.rotation = quat(d.rotation);
    c.exposureEv100 = d.exposureEv100;
    c.hasExposure = d.hasExposure != 0;
    return c;
}

/// Vertex (static or dynamic) -> DiskVertex.
[[nodiscard]] inline DiskVertex toDisk(const world::Vertex& v) {
    DiskVertex d{};
    put(d.position, v.position);
    put(d.normal, v.normal);
    put(d.tangent, v.tangent);
    put(d.uv0, v.uv0);
    put(d.uv1, v.uv1);
    return d;
}

/// DiskVertex -> vertex.
[[nodiscard]] inline world::Vertex fromDisk(const DiskVertex& d) {
    world::Vertex v;
    v.position = vec(d.position);
    v.normal = vec(d.normal);
    v.tangent = vec(d.tangent);
    v.uv0 = vec(d.uv0);
    v.uv1 = vec(d.uv1);
    return v;
}

/// Surface -> DiskSurface.
[[nodiscard]] inline DiskSurface toDisk(const world::Surface& s) {
    DiskSurface d{};
    d.firstIndex = s.firstIndex;
    d.indexCount = s.indexCount;
    d.material = s.material;
    d.primaryLight = s.primaryLight;
    d.chart = s.chart;
    d.atlas = s.atlas;
    d.lightmapX = s.lightmapX;
    d.lightmapY = s.lightmapY;
    d.lightmapWidth = s.lightmapWidth;
    d.lightmapHeight = s.lightmapHeight;
    d.firstGivenUp = s.firstGivenUp;
    d.givenUpCount = s.givenUpCount;
    d.leaf = s.leaf;
    put(d.boundsMin, s.boundsMin);
    put(d.boundsMax, s.boundsMax);
    return d;
}

/// DiskSurface -> surface.
[[nodiscard]] inline world::Surface fromDisk(const DiskSurface& d) {
    world::Surface s;
    s.firstIndex = d.firstIndex;
    s.indexCount = d.indexCount;
    s.material = d.material;
    s.primaryLight = d.primaryLight;
    s.chart = d.chart;
    s.atlas = d.atlas;
    s.lightmapX = d.lightmapX;
    s.lightmapY = d.lightmapY;
    s.lightmapWidth = d.lightmapWidth;
    s.lightmapHeight = d.lightmapHeight;
    s.firstGivenUp = d.firstGivenUp;
    s.givenUpCount = d.givenUpCount;
    s.leaf = d.leaf;
    s.boundsMin = vec(d.boundsMin);
    s.boundsMax = vec(d.boundsMax);
    return s;
}

/// Chart -> DiskChart.
[[nodiscard]] inline DiskChart toDisk(const world::Chart& c) {
    DiskChart d{};
    d.atlas = c.atlas;
    d.x = c.x;
    d.y = c.y;
    d.width = c.width;
    d.height = c.height;
    d.padding = c.padding;
    d.texelsPerMetre = c.texelsPerMetre;
    d.authored = c.authored ? 1 : 0;
    put(d.origin, c.origin);
    put(d.axisU, c.axisU);
    put(d.axisV, c.axisV);
    return d;
}

/// DiskChart -> chart.
[[nodiscard]] inline world::Chart fromDisk(const DiskChart& d) {
    world::Chart c;
    c.atlas = d.atlas;
    c.x = d.x;
    c.y = d.y;
    c.width = d.width;
    c.height = d.height;
    c.padding = d.padding;
    c.texelsPerMetre = d.texelsPerMetre;
    c.authored = d.authored != 0;
    c.origin = vec(d.origin);
    c.axisU = vec(d.axisU);
    c.axisV = vec(d.axisV);
    return c;
}

/// Atlas -> DiskAtlas.
[[nodiscard]] inline DiskAtlas toDisk(const world::Atlas& a) {
    return DiskAtlas{a.width, a.height};
}

/// DiskAtlas -> atlas.
[[nodiscard]] inline world::Atlas fromDisk(const DiskAtlas& d) {
    return world::Atlas{d.width, d.height};
}

/// BSP plane -> DiskBspPlane.
[[nodiscard]] inline DiskBspPlane toDisk(const world::BspPlane& p) {
    DiskBspPlane d{};
    put(d.normal, p.normal);
    d.distance = p.distance;
    return d;
}

/// DiskBspPlane -> BSP plane.
[[nodiscard]] inline world::BspPlane fromDisk(const DiskBspPlane& d) {
    return world::BspPlane{vec(d.normal), d.distance};
}

/// BSP node -> DiskBspNode.
[[nodiscard]] inline DiskBspNode toDisk(const world::BspNode& n) {
    DiskBspNode d{};
    d.plane = n.plane;
    d.front = n.front;
    d.back = n.back;
    put(d.boundsMin, n.boundsMin);
    put(d.boundsMax, n.boundsMax);
    return d;
}

/// DiskBspNode -> BSP node.
[[nodiscard]] inline world::BspNode fromDisk(const DiskBspNode& d) {
    world::BspNode n;
    n.plane = d.plane;
    n.front = d.front;
    n.back = d.back;
    n.boundsMin = vec(d.boundsMin);
    n.boundsMax = vec(d.boundsMax);
    return n;
}

/// BSP leaf -> DiskBspLeaf.
[[nodiscard]] inline DiskBspLeaf toDisk(const world::BspLeaf& l) {
    DiskBspLeaf d{};
    d.firstTriangle = l.firstTriangle;
    d.triangleCount = l.triangleCount;
    d.firstSurface = l.firstSurface;
    d.surfaceCount = l.surfaceCount;
    put(d.boundsMin, l.boundsMin);
    put(d.boundsMax, l.boundsMax);
    return d;
}

/// DiskBspLeaf -> BSP leaf.
[[nodiscard]] inline world::BspLeaf fromDisk(const DiskBspLeaf& d) {
    world::BspLeaf l;
    l.firstTriangle = d.firstTriangle;
    l.triangleCount = d.triangleCount;
    l.firstSurface = d.firstSurface;
    l.surfaceCount = d.surfaceCount;
    l.boundsMin = vec(d.boundsMin);
    l.boundsMax = vec(d.boundsMax);
    return l;
}

/// Dynamic mesh -> DiskDynamicMesh; appends the name to `blobs`.
[[nodiscard]] inline DiskDynamicMesh toDisk(const world::DynamicMesh& m, BlobWriter& blobs) {
    DiskDynamicMesh d{};
    d.name = blobs.addString(m.name);
    d.material = m.material;
    d.firstVertex = m.firstVertex;
    d.vertexCount = m.vertexCount;
    d.firstIndex = m.firstIndex;
    d.indexCount = m.indexCount;
    return d;
}

/// DiskDynamicMesh -> dynamic mesh, the name read from `blobs`.
[[nodiscard]] inline world::DynamicMesh fromDisk(const DiskDynamicMesh& d,
                                                 const BlobReader& blobs) {
    world::DynamicMesh m;
    m.name = blobs.string(d.name);
    m.material = d.material;
    m.firstVertex = d.firstVertex;
    m.vertexCount = d.vertexCount;
    m.firstIndex = d.firstIndex;
    m.indexCount = d.indexCount;
    return m;
}

/// Entity -> DiskEntity; appends the name to `blobs`.
[[nodiscard]] inline DiskEntity toDisk(const world::Entity& e, BlobWriter& blobs) {
    DiskEntity d{};
    d.name = blobs.addString(e.name);
    d.flags = e.flags;
    d.firstDynamicMesh = e.firstDynamicMesh;
    d.dynamicMeshCount = e.dynamicMeshCount;
    put(d.position, e.position);
    put(d.rotation, e.rotation);
    put(d.scale, e.scale);
    put(d.probeBoxMin, e.probeBoxMin);
    put(d.probeBoxMax, e.probeBoxMax);
    d.itemRespawn = e.itemRespawn;
    return d;
}

/// DiskEntity -> entity, the name read from `blobs`.
[[nodiscard]] inline world::Entity fromDisk(const DiskEntity& d, const BlobReader& blobs) {
    world::Entity e;
    e.name = blobs.string(d.name);
    e.flags = d.flags;
    e.firstDynamicMesh = d.firstDynamicMesh;
    e.dynamicMeshCount = d.dynamicMeshCount;
    e.position = vec(d.position);
    e.rotation = quat(d.rotation);
    e.scale = vec(d.scale);
    e.probeBoxMin = vec(d.probeBoxMin);
    e.probeBoxMax = vec(d.probeBoxMax);
    e.itemRespawn = d.itemRespawn;
    return e;
}

[[nodiscard]] inline DiskMover toDisk(const world::Mover& m) {
    DiskMover d{};
    d.entity = m.entity;
    d.kind = uint32_t(m.kind);
    d.flags = m.flags;
    put(d.pos1, m.pos1);
    put(d.pos2, m.pos2);
    put(d.amplitude, m.amplitude);
    put(d.axis, m.axis);
    d.speed = m.speed;
    d.period = m.period;
    d.phase = m.phase;
    d.travelSeconds = m.travelSeconds;
    d.wait = m.wait;
    d.teamMaster = m.teamMaster;
    d.name = m.name;
    d.target = m.target;
    d.firstPoint = m.firstPoint;
    d.pointCount = m.pointCount;
    return d;
}

[[nodiscard]] inline world::Mover fromDisk(const DiskMover& d) {
    world::Mover m;
    m.entity = d.entity;
    m.kind = world::MoverKind(d.kind);
    m.flags = d.flags;
    m.pos1 = vec(d.pos1);
    m.pos2 = vec(d.pos2);
    m.amplitude = vec(d.amplitude);
    m.axis = vec(d.axis);
    m.speed = d.speed;
    m.period = d.period;
    m.phase = d.phase;
    m.travelSeconds = d.travelSeconds;
    m.wait = d.wait;
    m.teamMaster = d.teamMaster;
    m.name = d.name;
    m.target = d.target;
    m.firstPoint = d.firstPoint;
    m.pointCount = d.pointCount;
    return m;
}

[[nodiscard]] inline DiskMoverPoint toDisk(const world::MoverPoint& p) {
    DiskMoverPoint d{};
    put(d.position, p.position);
    d.wait = p.wait;
    d.legSeconds = p.legSeconds;
    return d;
}

[[nodiscard]] inline world::MoverPoint fromDisk(const DiskMoverPoint& d) {
    return {vec(d.position), d.wait, d.legSeconds};
}

/// Features -> DiskFeatures.
[[nodiscard]] inline DiskFeatures toDisk(const world::Features& f) {
    DiskFeatures d{};
    d.flags = f.flags;
    d.materialClasses = f.materialClasses;
    d.primaryLightTypes = f.primaryLightTypes;
    d.bakedLightTypes = f.bakedLightTypes;
    d.primaryCount = f.primaryCount;
    d.bakedLightCount = f.bakedLightCount;
    d.effectOmniCount = f.effectOmniCount;
    d.effectSpotCount = f.effectSpotCount;
    d.probeCount = f.probeCount;
    put(d.gridMin, f.gridMin);
    put(d.gridMax, f.gridMax);
    return d;
}

/// DiskFeatures -> features.
[[nodiscard]] inline world::Features fromDisk(const DiskFeatures& d) {
    world::Features f;
    f.flags = d.flags;
    f.materialClasses = d.materialClasses;
    f.primaryLightTypes = d.primaryLightTypes;
    f.bakedLightTypes = d.bakedLightTypes;
    f.primaryCount = d.primaryCount;
    f.bakedLightCount = d.bakedLightCount;
    f.effectOmniCount = d.effectOmniCount;
    f.effectSpotCount = d.effectSpotCount;
    f.probeCount = d.probeCount;
    f.gridMin = vec(d.gridMin);
    f.gridMax = vec(d.gridMax);
    return f;
}

/// Lightmap texel -> DiskLightmapTexel.
[[nodiscard]] inline DiskLightmapTexel toDisk(const world::LightmapTexel& t) {
    DiskLightmapTexel d{};
    put(d.irradiance, t.irradiance);
    put(d.direction, t.direction);
    d.normalWeight = t.normalWeight;
    d.flags = t.flags;
    put(d.directIrradiance, t.directIrradiance);
    put(d.directLight, t.directLight);
    put(d.indirectIrradiance, t.indirectIrradiance);
    d.directVisibility = t.directVisibility;
    d.directEdgeDistance = t.directEdgeDistance;
    d.directEdgeWidth = t.directEdgeWidth;
    d.directEdgeLow = t.directEdgeLow;
    d.directEdgeHigh = t.directEdgeHigh;
    d.directEdgeSharpness = t.directEdgeSharpness;
    return d;
}

/// DiskLightmapTexel -> lightmap texel.
[[nodiscard]] inline world::LightmapTexel fromDisk(const DiskLightmapTexel& d) {
    world::LightmapTexel t;
    t.irradiance = vec(d.irradiance);
    t.direction = vec(d.direction);
    t.normalWeight = d.normalWeight;
    t.flags = d.flags;
    t.directIrradiance = vec(d.directIrradiance);
    t.directLight = vec(d.directLight);
    t.indirectIrradiance = vec(d.indirectIrradiance);
    t.directVisibility = d.directVisibility;
    t.directEdgeDistance = d.directEdgeDistance;
    t.directEdgeWidth = d.directEdgeWidth;
    t.directEdgeLow = d.directEdgeLow;
    t.directEdgeHigh = d.directEdgeHigh;
    t.directEdgeSharpness = d.directEdgeSharpness;
    return t;
}

/// The light grid's layout and the bake's shard -> DiskLightGridHeader (cellCount from the cells).
[[nodiscard]] inline DiskLightGridHeader toDiskGridHeader(const world::BakedLighting& baked) {
    DiskLightGridHeader d{};
    put(d.origin, baked.grid.origin);
    put(d.cellSize, baked.grid.cellSize);
    for (int a = 0; a < 3; ++a) d.dims[a] = baked.grid.dims[a];
    d.cellCount = static_cast<uint32_t>(baked.grid.cells.size());
    d.shardIndex = baked.shardIndex;
    d.shardCount = baked.shardCount;
    d.samples = baked.grid.samples;
    return d;
}

/// DiskLightGridHeader -> the grid's origin, cell size, dims and samples and the shard in
/// `baked` (its cells untouched).
inline void fromDiskGridHeader(const DiskLightGridHeader& d, world::BakedLighting& baked) {
    baked.grid.origin = vec(d.origin);
    baked.grid.cellSize = vec(d.cellSize);
    baked.grid.dims = glm::uvec3(d.dims[0], d.dims[1], d.dims[2]);
    baked.grid.samples = d.samples;
    baked.shardIndex = d.shardIndex;
    baked.shardCount = d.shardCount;
}

/// Light grid cell -> DiskLightGridCell.
[[nodiscard]] inline DiskLightGridCell toDisk(const world::LightGridCell& c) {
    DiskLightGridCell d{};
    for (size_t f = 0; f < 6; ++f) put(d.ambientCube[f], c.ambientCube[f]);
    d.dominantPrimary = c.dominantPrimary == world::kNoIndex ? kNoIndex : c.dominantPrimary;
    d.primaryVisibility = c.primaryVisibility;
    d.flags = c.flags;
    return d;
}

/// DiskLightGridCell -> light grid cell.
[[nodiscard]] inline world::LightGridCell fromDisk(const DiskLightGridCell& d) {
    world::LightGridCell c;
    for (size_t f = 0; f < 6; ++f) c.ambientCube[f] = vec(d.ambientCube[f]);
    c.dominantPrimary = d.dominantPrimary == kNoIndex ? world::kNoIndex : d.dominantPrimary;
    c.primaryVisibility = d.primaryVisibility;
    c.flags = d.flags;
    return c;
}

/// Lightmap texel -> DiskImportedTexel: a level's own (imported) lightmap keeps only the
/// irradiance.
[[nodiscard]] inline DiskImportedTexel toDiskImported(const world::LightmapTexel& t) {
    DiskImportedTexel d{};
    put(d.irradiance, t.irradiance);
    return d;
}

/// DiskImportedTexel -> lightmap texel: no direction (normalWeight 0.5, all ambient, all of it
/// indirect), the `flags` of the baked texel at the same place.
[[nodiscard]] inline world::LightmapTexel fromDisk(const DiskImportedTexel& d, uint32_t flags) {
    world::LightmapTexel t;
    t.irradiance = vec(d.irradiance);
    t.direction = glm::vec3(0.0f);
    t.normalWeight = 0.5f;
    t.flags = flags;
    t.indirectIrradiance = t.irradiance;
    return t;
}

/// Visibility -> DiskVisibilityHeader (counts from its arrays).
[[nodiscard]] inline DiskVisibilityHeader toDiskVisibilityHeader(const world::Visibility& v) {
    DiskVisibilityHeader d{};
    put(d.origin, v.origin);
    d.cellSize = v.cellSize;
    for (int a = 0; a < 3; ++a) d.dims[a] = v.dims[a];
    d.cellCount = static_cast<uint32_t>(v.cellRow.size());
    d.surfaceCount = static_cast<uint32_t>(v.surfaceCluster.size());
    d.clusterCount = v.clusterCount;
    d.rowCount = v.rowCount();
    return d;
}

/// DiskVisibilityHeader -> the grid's origin, cell size, dims and cluster count in `v` (its
/// arrays untouched).
inline void fromDiskVisibilityHeader(const DiskVisibilityHeader& d, world::Visibility& v) {
    v.origin = vec(d.origin);
    v.cellSize = d.cellSize;
    v.dims = glm::uvec3(d.dims[0], d.dims[1], d.dims[2]);
    v.clusterCount = d.clusterCount;
}

/// Error budget choices -> DiskErrorBudget.
[[nodiscard]] inline DiskErrorBudget toDisk(const world::ErrorBudgetChoices& c) {
    DiskErrorBudget d{};
    d.budget = c.budget;
    d.flags = c.flags;
    d.probeError = c.probeError;
    d.probesPlaced = c.probesPlaced;
    d.densityTolerance = c.densityTolerance;
    d.lightmapError = c.lightmapError;
    d.texelsRequested = c.texelsRequested;
    d.texelsSampled = c.texelsSampled;
    d.gridCellsFull = c.gridCellsFull;
    d.gridCells = c.gridCells;
    d.viewsPredicted = c.viewsPredicted;
    d.predictedError = c.predictedError;
    return d;
}

/// DiskErrorBudget -> error budget choices.
[[nodiscard]] inline world::ErrorBudgetChoices fromDisk(const DiskErrorBudget& d) {
    world::ErrorBudgetChoices c;
    c.budget = d.budget;
    c.flags = d.flags;
    c.probeError = d.probeError;
    c.probesPlaced = d.probesPlaced;
    c.densityTolerance = d.densityTolerance;
    c.lightmapError = d.lightmapError;
    c.texelsRequested = d.texelsRequested;
    c.texelsSampled = d.texelsSampled;
    c.gridCellsFull = d.gridCellsFull;
    c.gridCells = d.gridCells;
    c.viewsPredicted = d.viewsPredicted;
    c.predictedError = d.predictedError;
    return c;
}

/// Shard range -> DiskShardRange.
[[nodiscard]] inline DiskShardRange toDisk(const world::ShardRange& r) {
    DiskShardRange d{};
    d.chartBegin = r.chartBegin;
    d.chartEnd = r.chartEnd;
    d.cellBegin = r.cellBegin;
    d.cellEnd = r.cellEnd;
    d.probeBegin = r.probeBegin;
    d.probeEnd = r.probeEnd;
    d.probeTotal = r.probeTotal;
    return d;
}

/// DiskShardRange -> shard range.
[[nodiscard]] inline world::ShardRange fromDisk(const DiskShardRange& d) {
    world::ShardRange r;
    r.chartBegin = d.chartBegin;
    r.chartEnd = d.chartEnd;
    r.cellBegin = d.cellBegin;
    r.cellEnd = d.cellEnd;
    r.probeBegin = d.probeBegin;
    r.probeEnd = d.probeEnd;
    r.probeTotal = d.probeTotal;
    return r;
}

/// Processed texture -> DiskProcessedTexture, its name placed at `nameOffset` of the section's
/// names and its texels at `firstByte` of the section.
[[nodiscard]] inline DiskProcessedTexture toDisk(const world::ProcessedTexture& t,
                                                 uint32_t nameOffset, uint64_t firstByte) {
    DiskProcessedTexture d{};
    d.nameOffset = nameOffset;
    d.nameLength = static_cast<uint32_t>(t.name.size());
    d.format = static_cast<uint8_t>(t.format);
    d.width = t.width;
    d.height = t.height;
    d.mipCount = t.mipCount;
    d.magFilter = t.sampler.magFilter;
    d.minFilter = t.sampler.minFilter;
    d.wrapS = t.sampler.wrapS;
    d.wrapT = t.sampler.wrapT;
    d.firstByte = firstByte;
    d.byteCount = t.texels.size();
    return d;
}

/// DiskProcessedTexture -> processed texture, its name read from `names` (the section's names)
/// and its texels from `section` (the whole section).
[[nodiscard]] inline world::ProcessedTexture fromDisk(const DiskProcessedTexture& d,
                                                      std::span<const uint8_t> names,
                                                      std::span<const uint8_t> section) {
    world::ProcessedTexture t;
    const std::span<const uint8_t> name = slice(names, d.nameOffset, d.nameLength);
    t.name.assign(name.begin(), name.end());
    t.format = static_cast<world::TexelFormat>(d.format);
    t.width = d.width;
    t.height = d.height;
    t.mipCount = d.mipCount;
    t.sampler.magFilter = d.magFilter;
    t.sampler.minFilter = d.minFilter;
    t.sampler.wrapS = d.wrapS;
    t.sampler.wrapT = d.wrapT;
    const std::span<const uint8_t> texels = slice(section, d.firstByte, d.byteCount);
    t.texels.assign(texels.begin(), texels.end());
    return t;
}

/// A material's texture slots -> DiskMaterialTextureSlots.
[[nodiscard]] inline DiskMaterialTextureSlots toDisk(const world::MaterialTextureSlots& s) {
    DiskMaterialTextureSlots d{};
    d.baseColor = s.baseColor;
    d.metallicRoughness = s.metallicRoughness;
    d.normal = s.normal;
    d.occlusion = s.occlusion;
    d.emissive = s.emissive;
    d.cavity = s.cavity;
    d.facets = s.facets;
    d.factorsFolded = s.factorsFolded ? 1 : 0;
    d.baseRoughnessInAlpha = s.baseRoughnessInAlpha ? 1 : 0;
    d.slopeKurtosisInNormalAlpha = s.slopeKurtosisInNormalAlpha ? 1 : 0;
    return d;
}

/// DiskMaterialTextureSlots -> a material's texture slots.
[[nodiscard]] inline world::MaterialTextureSlots fromDisk(const DiskMaterialTextureSlots& d) {
    world::MaterialTextureSlots s;
    s.baseColor = d.baseColor;
    s.metallicRoughness = d.metallicRoughness;
    s.normal = d.normal;
    s.occlusion = d.occlusion;
    s.emissive = d.emissive;
    s.cavity = d.cavity;
    s.facets = d.facets;
    s.factorsFolded = d.factorsFolded != 0;
    s.baseRoughnessInAlpha = d.baseRoughnessInAlpha != 0;
    s.slopeKurtosisInNormalAlpha = d.slopeKurtosisInNormalAlpha != 0;
    return s;
}

/// Environment probe -> DiskProbe, its texels placed at `firstTexel` of the section's texels.
[[nodiscard]] inline DiskProbe toDisk(const world::EnvironmentProbe& p, uint32_t firstTexel) {
    DiskProbe d{};
    put(d.position, p.position);
    put(d.boxMin, p.boxMin);
    put(d.boxMax, p.boxMax);
    put(d.irradianceAverage, p.irradianceAverage);
    for (size_t f = 0; f < 6; ++f) put(d.irradianceCube[f], p.irradianceCube[f]);
    d.faceSize = p.faceSize;
    d.mipCount = p.mipCount;
    d.firstTexel = firstTexel;
    d.texelCount = static_cast<uint32_t>(p.texels.size());
    d.entity = p.entity == world::kNoIndex ? kNoIndex : p.entity;
    return d;
}

/// DiskProbe -> environment probe, its texels copied from `texelBytes` (all of the section's
/// texels, 4 bytes each).
[[nodiscard]] inline world::EnvironmentProbe fromDisk(const DiskProbe& d,
                                                      std::span<const uint8_t> texelBytes) {
    world::EnvironmentProbe p;
    p.position = vec(d.position);
    p.boxMin = vec(d.boxMin);
    p.boxMax = vec(d.boxMax);
    p.irradianceAverage = vec(d.irradianceAverage);
    for (size_t f = 0; f < 6; ++f) p.irradianceCube[f] = vec(d.irradianceCube[f]);
    p.faceSize = d.faceSize;
    p.mipCount = d.mipCount;
    p.entity = d.entity == kNoIndex ? world::kNoIndex : d.entity;
    const std::span<const uint8_t> bytes =
        slice(texelBytes, uint64_t(d.firstTexel) * 4, uint64_t(d.texelCount) * 4);
    p.texels.resize(bytes.size() / 4);
    if (!bytes.empty()) std::memcpy(p.texels.data(), bytes.data(), bytes.size());
    return p;
}

}  // namespace records

using records::fromDisk;
using records::fromDiskGridHeader;
using records::fromDiskVisibilityHeader;
using records::toDisk;
using records::toDiskGridHeader;
using records::toDiskImported;
using records::toDiskVisibilityHeader;

}  // namespace onelight::package
