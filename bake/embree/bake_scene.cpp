#include "bake/embree/bake_scene.hpp"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>
#include <stdexcept>

namespace onelight::bake {
namespace {

/// Self-intersection offset relative to the scene's largest coordinate magnitude M. A hit
/// point computed by Embree carries an absolute error of a few ulps of M (float epsilon is
/// 1.2e-7), so 2e-5 M is ~170 ulps: far above the error, and for a 10 m level only 0.2 mm,
/// below any wall thickness the level compiler keeps. Wächter and Binder 2019, "A Fast and
/// Robust Method for Avoiding Self-Intersection", Ray Tracing Gems ch. 6, discuss the trade-off.
constexpr float kSelfIntersectionScale = 2e-5f;
/// The offset never goes below this (metres), for levels near the origin.
constexpr float kMinimumRayOffset = 1e-5f;

/// How rays meet a material's triangles.
enum class Coverage {
    kOpaque,    // every hit counts: the first geometry, no filter
    kFiltered,  // the alpha filter decides per hit: the second geometry
    kNone,      // no hit ever counts (alpha 0 everywhere): not given to Embree
};

/// The coverage of material `m`. One that casts no shadow (world::Material::castsShadows) is
/// never hit: light and view rays alike pass it. A material without a base colour texture has one
/// alpha (its factor), so MASK and BLEND are decided here once, exactly as the filter would decide
/// every hit (alpha >= cutoff; a uniform in [0, 1) below alpha), and the filter only runs where
/// alpha varies over the surface or BLEND's coin is needed.
Coverage coverageOf(const SceneMaterials& materials, uint32_t m) {
    if (m >= materials.materials.size()) return Coverage::kOpaque;
    const world::Material& material = materials.materials[m];
    if (!material.castsShadows) return Coverage::kNone;  // drawn, but light passes it
    if (material.alphaMode == world::AlphaMode::kOpaque) return Coverage::kOpaque;
    if (materials.textureSets[m].baseColor != world::kNoIndex) return Coverage::kFiltered;
    const float alpha = material.baseColor.w;
    if (material.alphaMode == world::AlphaMode::kMask)
        return alpha >= material.alphaCutoff ? Coverage::kOpaque : Coverage::kNone;
    if (alpha >= 1.0f) return Coverage::kOpaque;
    return alpha > 0.0f ? Coverage::kFiltered : Coverage::kNone;
}

uint32_t floatBits(float f) {
    uint32_t u;
    std::memcpy(&u, &f, sizeof u);
    return u;
}

/// MurmurHash3's 32-bit finaliser over a running combination: a well-mixed uniform in [0, 1)
/// from the ray and the triangle, so a BLEND decision needs no random-number state.
float coverageHash(uint32_t triangle, const glm::vec3& origin, const glm::vec3& dir) {
    uint32_t h = 0x9E3779B9u ^ triangle;
    for (float f : {origin.x, origin.y, origin.z, dir.x, dir.y, dir.z}) {
        h ^= floatBits(f) + 0x9E3779B9u + (h << 6) + (h >> 2);
        h ^= h >> 16;
        h *= 0x85EBCA6Bu;
        h ^= h >> 13;
        h *= 0xC2B2AE35u;
        h ^= h >> 16;
    }
    return float(h >> 8) * 0x1p-24f;
}

/// One Embree triangle geometry over the shared vertex buffer `vertices` (`vertexCount`
/// float3) with the triangles `triangles` of `indices`, attached to `scene`; its ID is returned.
unsigned attachTriangles(RTCDevice device, RTCScene scene, RTCBuffer vertices, size_t vertexCount,
                         const std::vector<uint32_t>& indices,
                         const std::vector<uint32_t>& triangles, RTCFilterFunctionN filter,
                         void* user) {
    RTCGeometry mesh = rtcNewGeometry(device, RTC_GEOMETRY_TYPE_TRIANGLE);
    rtcSetGeometryBuffer(mesh, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT3, vertices, 0,
                         3 * sizeof(float), vertexCount);
    auto* out = static_cast<uint32_t*>(rtcSetNewGeometryBuffer(
        mesh, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3, 3 * sizeof(uint32_t), triangles.size()));
    for (size_t t = 0; t < triangles.size(); ++t)
        for (int k = 0; k < 3; ++k) out[3 * t + k] = indices[3 * size_t(triangles[t]) + k];
    if (filter != nullptr) {
        rtcSetGeometryUserData(mesh, user);
        rtcSetGeometryIntersectFilterFunction(mesh, filter);
        rtcSetGeometryOccludedFilterFunction(mesh, filter);
    }
    rtcCommitGeometry(mesh);
    const unsigned id = rtcAttachGeometry(scene, mesh);
    rtcReleaseGeometry(mesh);
    return id;
}

}  // namespace

EmbreeDevice::EmbreeDevice() {
    device_ = rtcNewDevice(nullptr);
    if (device_ == nullptr)
        throw std::runtime_error("Embree: rtcNewDevice failed (" +
                                 std::to_string(static_cast<int>(rtcGetDeviceError(nullptr))) +
                                 ")");
    rtcSetDeviceErrorFunction(device_, &EmbreeDevice::onError, this);
}

EmbreeDevice::~EmbreeDevice() {
    rtcReleaseDevice(device_);
}

std::string EmbreeDevice::lastError() const {
    return lastError_;
}

void EmbreeDevice::onError(void* user, RTCError code, const char* message) {
    auto* self = static_cast<EmbreeDevice*>(user);
    self->lastError_ = "Embree error " + std::to_string(static_cast<int>(code)) + ": " +
                       (message ? message : "(no message)");
}

BakeScene::BakeScene(const EmbreeDevice& device, const world::StaticGeometry& geometry,
                     std::vector<world::Material> materials)
    : BakeScene(device, geometry, factorMaterials(std::move(materials))) {}

BakeScene::BakeScene(const EmbreeDevice& device, const world::StaticGeometry& geometry,
                     SceneMaterials materials)
    : materials_(std::move(materials)) {
    positions_.reserve(geometry.vertices.size());
    attributes_.reserve(geometry.vertices.size());
    for (const world::CompileVertex& v : geometry.vertices) {
        positions_.push_back(glm::vec3(v.position));
        attributes_.push_back({v.normal, v.tangent, v.uv0});
    }
    indices_.reserve(geometry.triangles.size() * 3);
    for (const world::StaticTriangle& t : geometry.triangles) {
        indices_.insert(indices_.end(), t.v.begin(), t.v.end());
        triangleMaterial_.push_back(t.material);
    }
    build(device);
}

BakeScene::BakeScene(const EmbreeDevice& device, const world::CompiledLevel& level)
    : materials_(factorMaterials(level.materials, level.settings.diffuseModel)) {
    positions_.reserve(level.vertices.size());
    attributes_.reserve(level.vertices.size());
    for (const world::Vertex& v : level.vertices) {
        positions_.push_back(v.position);
        attributes_.push_back({v.normal, v.tangent, v.uv0});
    }
    indices_ = level.indices;
    triangleMaterial_.assign(indices_.size() / 3, world::kNoIndex);
    for (const world::Surface& s : level.surfaces)
        for (uint32_t i = s.firstIndex / 3; i < (s.firstIndex + s.indexCount) / 3; ++i)
            triangleMaterial_[i] = s.material;
    build(device);
}

void BakeScene::build(const EmbreeDevice& device) {
    const size_t triangleCount = indices_.size() / 3;
    triangleNormal_.resize(triangleCount);
    uvDensityLog2_.resize(triangleCount);
    boundsMin_ = glm::vec3(std::numeric_limits<float>::max());
    boundsMax_ = glm::vec3(-std::numeric_limits<float>::max());
    for (size_t t = 0; t < triangleCount; ++t) {
        const glm::vec3 a = positions_[indices_[3 * t]], b = positions_[indices_[3 * t + 1]],
                        c = positions_[indices_[3 * t + 2]];
        const glm::dvec3 n = glm::cross(glm::dvec3(b - a), glm::dvec3(c - a));
        const double length = glm::length(n);
        triangleNormal_[t] = length > 0.0 ? glm::vec3(n / length) : glm::vec3(0.0f, 0.0f, 1.0f);
        const glm::vec2 ua = attributes_[indices_[3 * t]].uv,
                        ub = attributes_[indices_[3 * t + 1]].uv,
                        uc = attributes_[indices_[3 * t + 2]].uv;
        const double uvArea = std::fabs(double(ub.x - ua.x) * double(uc.y - ua.y) -
                                        double(uc.x - ua.x) * double(ub.y - ua.y));
        // A degenerate uv mapping reads the finest mip (no density information).
        uvDensityLog2_[t] =
            length > 0.0 && uvArea > 0.0 ? float(0.5 * std::log2(uvArea / length)) : -64.0f;
        for (const glm::vec3& p : {a, b, c}) {
            boundsMin_ = glm::min(boundsMin_, p);
            boundsMax_ = glm::max(boundsMax_, p);
        }
    }
    if (triangleCount == 0) boundsMin_ = boundsMax_ = glm::vec3(0.0f);
    const float magnitude =
        std::max(glm::length(glm::max(glm::abs(boundsMin_), glm::abs(boundsMax_))),
                 glm::length(boundsMax_ - boundsMin_));
    rayOffset_ = std::max(kMinimumRayOffset, kSelfIntersectionScale * magnitude);
    diameter_ = std::max(1.0f, 2.0f * glm::length(boundsMax_ - boundsMin_));

    std::vector<uint32_t> opaque, filtered;
    std::vector<Coverage> coverage(materials_.materials.size());
    for (uint32_t m = 0; m < coverage.size(); ++m) coverage[m] = coverageOf(materials_, m);
    for (uint32_t t = 0; t < triangleCount; ++t) {
        const uint32_t m = triangleMaterial_[t];
        const Coverage c = m < coverage.size() ? coverage[m] : Coverage::kOpaque;
        if (c != Coverage::kNone) (c == Coverage::kOpaque ? opaque : filtered).push_back(t);
    }
    if (!filtered.empty() &&
        !rtcGetDeviceProperty(device.handle(), RTC_DEVICE_PROPERTY_FILTER_FUNCTION_SUPPORTED))
        throw std::runtime_error(
            "Embree: filter functions are not supported by this build (EMBREE_FILTER_FUNCTION); "
            "the level's MASK and BLEND materials need them");
    scene_ = rtcNewScene(device.handle());
    rtcSetSceneBuildQuality(scene_, RTC_BUILD_QUALITY_HIGH);
    if (!opaque.empty() || !filtered.empty()) {
        // One vertex buffer shared by both geometries. Embree reads 16 bytes at the last
        // vertex: the buffer gets one float of slack.
        RTCBuffer vertices =
            rtcNewBuffer(device.handle(), (3 * positions_.size() + 1) * sizeof(float));
        auto* v = static_cast<float*>(rtcGetBufferData(vertices));
        for (size_t i = 0; i < positions_.size(); ++i) {
            v[3 * i] = positions_[i].x;
            v[3 * i + 1] = positions_[i].y;
            v[3 * i + 2] = positions_[i].z;
        }
        v[3 * positions_.size()] = 0.0f;
        // Geometry IDs follow attachment order; empty groups are not attached.
        for (std::vector<uint32_t>* group : {&opaque, &filtered}) {
            if (group->empty()) continue;
            const unsigned id =
                attachTriangles(device.handle(), scene_, vertices, positions_.size(), indices_,
                                *group, group == &filtered ? &alphaFilter : nullptr, this);
            if (id != geometryTriangles_.size()) {
                rtcReleaseBuffer(vertices);
                throw std::runtime_error("Embree: unexpected geometry ID " + std::to_string(id));
            }
            geometryTriangles_.push_back(std::move(*group));
        }
        rtcReleaseBuffer(vertices);
    }
    rtcCommitScene(scene_);
    if (!device.lastError().empty()) throw std::runtime_error(device.lastError());
}

BakeScene::~BakeScene() {
    rtcReleaseScene(scene_);
}

bool BakeScene::coverageAccepts(uint32_t triangle, glm::vec2 barycentric, const glm::vec3& origin,
                                const glm::vec3& dir) const {
    const uint32_t m = triangleMaterial_[triangle];
    if (m >= materials_.materials.size()) return true;
    const world::Material& material = materials_.materials[m];
    if (material.alphaMode == world::AlphaMode::kOpaque) return true;
    // The uv as attributesAt interpolates it (the same expression), without the other
    // attributes.
    const glm::vec2 a = attributes_[indices_[3 * size_t(triangle)]].uv;
    const glm::vec2 b = attributes_[indices_[3 * size_t(triangle) + 1]].uv;
    const glm::vec2 c = attributes_[indices_[3 * size_t(triangle) + 2]].uv;
    const float u = barycentric.x, v = barycentric.y, w = 1.0f - u - v;
    const float alpha = sampleAlpha(materials_, m, w * a + u * b + v * c);
    if (material.alphaMode == world::AlphaMode::kMask) return alpha >= material.alphaCutoff;
    return coverageHash(triangle, origin, dir) < alpha;
}

void BakeScene::alphaFilter(const RTCFilterFunctionNArguments* args) {
    const auto* self = static_cast<const BakeScene*>(args->geometryUserPtr);
    for (unsigned i = 0; i < args->N; ++i) {
        if (args->valid[i] != -1) continue;
        const uint32_t triangle = self->geometryTriangles_[RTCHitN_geomID(args->hit, args->N, i)]
                                                          [RTCHitN_primID(args->hit, args->N, i)];
        const glm::vec2 barycentric(RTCHitN_u(args->hit, args->N, i),
                                    RTCHitN_v(args->hit, args->N, i));
        const glm::vec3 origin(RTCRayN_org_x(args->ray, args->N, i),
                               RTCRayN_org_y(args->ray, args->N, i),
                               RTCRayN_org_z(args->ray, args->N, i));
        const glm::vec3 dir(RTCRayN_dir_x(args->ray, args->N, i),
                            RTCRayN_dir_y(args->ray, args->N, i),
                            RTCRayN_dir_z(args->ray, args->N, i));
        if (!self->coverageAccepts(triangle, barycentric, origin, dir)) args->valid[i] = 0;
    }
}

const world::Material& BakeScene::materialOf(uint32_t triangle) const {
    const uint32_t m = triangleMaterial_[triangle];
    return m < materials_.materials.size() ? materials_.materials[m] : defaultMaterial_;
}

SurfaceAttributes BakeScene::attributesAt(const SurfaceHit& hit) const {
    const VertexAttributes& a = attributes_[indices_[3 * hit.triangle]];
    const VertexAttributes& b = attributes_[indices_[3 * hit.triangle + 1]];
    const VertexAttributes& c = attributes_[indices_[3 * hit.triangle + 2]];
    const float u = hit.barycentric.x, v = hit.barycentric.y, w = 1.0f - u - v;
    SurfaceAttributes out;
    out.uv = w * a.uv + u * b.uv + v * c.uv;
    out.normal = w * a.normal + u * b.normal + v * c.normal;
    out.tangent = w * a.tangent + u * b.tangent + v * c.tangent;
    out.tangent.w = a.tangent.w;  // the bitangent sign is a triangle's, not interpolated
    out.uvDensityLog2 = uvDensityLog2_[hit.triangle];
    return out;
}

size_t BakeScene::memoryBytes() const {
    return positions_.size() * sizeof(glm::vec3) + indices_.size() * sizeof(uint32_t) +
           triangleNormal_.size() * sizeof(glm::vec3) + triangleMaterial_.size() * 4 +
           attributes_.size() * sizeof(VertexAttributes) + uvDensityLog2_.size() * sizeof(float) +
           triangleMaterial_.size() * sizeof(uint32_t) +  // geometryTriangles_
           textureBytes(materials_);
}

SurfaceHit BakeScene::intersect(const glm::vec3& origin, const glm::vec3& dir, float maxDistance,
                                uint64_t& counter) const {
    RTCIntersectContext context;
    rtcInitIntersectContext(&context);
    RTCRayHit query = embreeRay(origin, dir, maxDistance);
    rtcIntersect1(scene_, &context, &query);
    ++counter;
    if (observer_) observer_(observerUser_, {origin, maxDistance, dir, false});
    SurfaceHit hit;
    if (query.hit.geomID == RTC_INVALID_GEOMETRY_ID) return hit;
    hit.found = true;
    hit.distance = query.ray.tfar;
    hit.triangle = geometryTriangles_[query.hit.geomID][query.hit.primID];
    hit.normal = triangleNormal_[hit.triangle];
    // The hit point from the barycentrics (not origin + t dir): its error is relative to the
    // triangle's coordinates, not to the ray's length.
    const glm::vec3 a = positions_[indices_[3 * hit.triangle]];
    const glm::vec3 b = positions_[indices_[3 * hit.triangle + 1]];
    const glm::vec3 c = positions_[indices_[3 * hit.triangle + 2]];
    hit.position = a + query.hit.u * (b - a) + query.hit.v * (c - a);
    hit.backFace = glm::dot(dir, hit.normal) > 0.0f;
    hit.barycentric = {query.hit.u, query.hit.v};
    return hit;
}

bool BakeScene::occluded(const glm::vec3& origin, const glm::vec3& dir, float maxDistance,
                         uint64_t& counter) const {
    RTCIntersectContext context;
    rtcInitIntersectContext(&context);
    RTCRay ray = embreeRay(origin, dir, maxDistance).ray;
    rtcOccluded1(scene_, &context, &ray);
    ++counter;
    if (observer_) observer_(observerUser_, {origin, maxDistance, dir, true});
    return ray.tfar < 0.0f;  // Embree sets tfar to -inf on a hit
}

}  // namespace onelight::bake
