// The Embree 3 scene of a level's static world, built once and shared by every bake stage
// (dominant primaries, lightmaps, the light grid, the reference path tracer). Dynamic objects
// are not in it. Follows Embree's tutorials/minimal: one device with one error callback;
// geometry new -> fill buffers -> commit -> attach -> release; the scene committed before use.
#pragma once

#include <array>
#include <atomic>
#include <cstdint>
#include <string>
#include <vector>

#include <embree3/rtcore.h>
#include <glm/glm.hpp>

#include "bake/materials/scene_materials.hpp"
#include "bake/materials/surface_point.hpp"
#include "world/compiled_level.hpp"
#include "world/static_geometry.hpp"

namespace onelight::bake {

/// Owns an RTCDevice whose error callback records the last error (no global state).
class EmbreeDevice {
public:
    EmbreeDevice();
    ~EmbreeDevice();
    EmbreeDevice(const EmbreeDevice&) = delete;
    EmbreeDevice& operator=(const EmbreeDevice&) = delete;

    RTCDevice handle() const { return device_; }  // owned
    /// The message of the last error Embree reported, "" when none.
    std::string lastError() const;

private:
    static void onError(void* user, RTCError code, const char* message);
    RTCDevice device_ = nullptr;
    std::string lastError_;
};

/// Ray counts by kind, per thread, summed when a stage ends (integer sums: order-free).
struct RayCounts {
    uint64_t shadow = 0;  // rtcOccluded1 towards lights
    uint64_t bounce = 0;  // rtcIntersect1 of indirect paths (and camera rays)
    uint64_t probe = 0;   // rtcIntersect1 that look for geometry around a sample point
    RayCounts& operator+=(const RayCounts& o) {
        shadow += o.shadow;
        bounce += o.bounce;
        probe += o.probe;
        return *this;
    }
    uint64_t total() const { return shadow + bounce + probe; }
};

/// An Embree query from `origin` along unit `dir` over (0, maxDistance], with no hit recorded
/// yet: every field that rtcIntersect1 and rtcOccluded1 read is set.
[[nodiscard]] inline RTCRayHit embreeRay(const glm::vec3& origin, const glm::vec3& dir,
                                         float maxDistance) {
    RTCRayHit q;
    q.ray.org_x = origin.x;
    q.ray.org_y = origin.y;
    q.ray.org_z = origin.z;
    q.ray.tnear = 0.0f;
    q.ray.dir_x = dir.x;
    q.ray.dir_y = dir.y;
    q.ray.dir_z = dir.z;
    q.ray.time = 0.0f;
    q.ray.tfar = maxDistance;
    q.ray.mask = 0xFFFFFFFFu;
    q.ray.id = 0;
    q.ray.flags = 0;
    q.hit.Ng_x = q.hit.Ng_y = q.hit.Ng_z = 0.0f;
    q.hit.u = q.hit.v = 0.0f;
    q.hit.primID = RTC_INVALID_GEOMETRY_ID;
    q.hit.geomID = RTC_INVALID_GEOMETRY_ID;
    q.hit.instID[0] = RTC_INVALID_GEOMETRY_ID;
    return q;
}

/// What a ray found.
struct SurfaceHit {
    bool found = false;
    float distance = 0.0f;        // metres along the unit ray direction
    uint32_t triangle = 0;        // into BakeScene triangles
    glm::vec3 position{0.0f};     // metres, world
    glm::vec3 normal{0.0f};       // unit geometric normal of the front face (winding order)
    bool backFace = false;        // the ray arrived on the side opposite `normal`
    glm::vec2 barycentric{0.0f};  // Embree's (u, v): position = a + u (b - a) + v (c - a)
};

/// A ray as a BakeScene traced it, for tools that replay the baker's rays (the benchmark
/// times them against raw rtcIntersect1 / rtcOccluded1).
struct TracedRay {
    glm::vec3 origin{0.0f};
    float maxDistance = 0.0f;  // metres
    glm::vec3 dir{0.0f};       // unit
    bool occlusion = false;    // rtcOccluded1 (else rtcIntersect1)
};
/// Receives every ray a BakeScene traces, from any thread (the callee synchronises).
using RayObserver = void (*)(void* user, const TracedRay& ray);

/// The static world in Embree, plus the per-triangle data hits are shaded with.
/*
   Alpha: triangles of MASK and BLEND materials sit in a second Embree geometry whose filter
   functions (intersect and occluded) see every candidate hit:
     MASK   rejected where alpha(uv) < alphaCutoff (glTF), for every ray: the holes of a grate
            let light and view rays through;
     BLEND  accepted with probability alpha(uv), decided by a hash of the ray and the triangle
            (stochastic coverage): on average a fraction 1 - alpha goes through, so shadows
            and views through the surface see it as a transmitter of (1 - alpha) without
            refraction. The hash makes the decision the same on every thread and every call
            (Embree may test a primitive twice under spatial splits).
   Opaque triangles stay in the first geometry, with no filter, at full Embree speed.
*/
class BakeScene {
public:
    /// Builds from the static triangles of a level (world space), shaded with `materials`
    /// (the level's, with their textures: loadSceneMaterials).
    BakeScene(const EmbreeDevice& device, const world::StaticGeometry& geometry,
              SceneMaterials materials);
    /// The same with the materials' factors alone.
    BakeScene(const EmbreeDevice& device, const world::StaticGeometry& geometry,
              std::vector<world::Material> materials);
    /// Builds from a compiled level's static vertices and indices (factors alone).
    BakeScene(const EmbreeDevice& device, const world::CompiledLevel& level);
    ~BakeScene();
    BakeScene(const BakeScene&) = delete;
    BakeScene& operator=(const BakeScene&) = delete;

    /// Closest hit along origin + t dir, t in (0, maxDistance]. `dir` is unit.
    SurfaceHit intersect(const glm::vec3& origin, const glm::vec3& dir, float maxDistance,
                         uint64_t& counter) const;
    /// True when anything lies along origin + t dir, t in (0, maxDistance].
    bool occluded(const glm::vec3& origin, const glm::vec3& dir, float maxDistance,
                  uint64_t& counter) const;

    /// Self-intersection offset (metres): a ray leaving a surface starts this far along the
    /// surface normal. kSelfIntersectionScale times the scene's coordinate magnitude, i.e. a
    /// few hundred float ulps of the largest coordinate (see the .cpp for the derivation).
    float rayOffset() const { return rayOffset_; }
    /// Largest distance any ray needs to travel (the bounding box diagonal plus margin).
    float sceneDiameter() const { return diameter_; }
    glm::vec3 boundsMin() const { return boundsMin_; }
    glm::vec3 boundsMax() const { return boundsMax_; }

    /// Calls `observer(user, ray)` for every ray traced from now on; null stops it.
    void observeRays(RayObserver observer, void* user) {
        observer_ = observer;
        observerUser_ = user;
    }
    RTCScene embreeScene() const { return scene_; }  // borrowed, committed

    /// The corners of `triangle` (world metres) and its unit front-face normal (winding order).
    [[nodiscard]] std::array<glm::vec3, 3> triangleVertices(uint32_t triangle) const {
        return {positions_[indices_[3 * size_t(triangle)]],
                positions_[indices_[3 * size_t(triangle) + 1]],
                positions_[indices_[3 * size_t(triangle) + 2]]};
    }
    [[nodiscard]] glm::vec3 triangleNormal(uint32_t triangle) const {
        return triangleNormal_[triangle];
    }

    const world::Material& materialOf(uint32_t triangle) const;
    /// The index of `triangle`'s material in materials() (kNoIndex: the default).
    [[nodiscard]] uint32_t materialIndexOf(uint32_t triangle) const {
        return triangleMaterial_[triangle];
    }
    [[nodiscard]] const SceneMaterials& materials() const { return materials_; }
    /// The interpolated vertex attributes where `hit` landed.
    [[nodiscard]] SurfaceAttributes attributesAt(const SurfaceHit& hit) const;
    uint32_t triangleCount() const { return static_cast<uint32_t>(triangleMaterial_.size()); }
    size_t memoryBytes() const;

    /// Whether the alpha filter lets a ray (origin, dir) hit `triangle` at `barycentric`.
    [[nodiscard]] bool coverageAccepts(uint32_t triangle, glm::vec2 barycentric,
                                       const glm::vec3& origin, const glm::vec3& dir) const;

private:
    void build(const EmbreeDevice& device);
    static void alphaFilter(const RTCFilterFunctionNArguments* args);

    RTCScene scene_ = nullptr;  // owned
    std::vector<glm::vec3> positions_;
    std::vector<uint32_t> indices_;           // 3 per triangle
    std::vector<glm::vec3> triangleNormal_;   // unit, from the winding
    std::vector<uint32_t> triangleMaterial_;  // into materials_
    // Embree geometry ID -> primID -> triangle: the opaque group, then the alpha-filtered.
    std::vector<std::vector<uint32_t>> geometryTriangles_;
    SceneMaterials materials_;
    world::Material defaultMaterial_;
    struct VertexAttributes {
        glm::vec3 normal{0.0f, 0.0f, 1.0f};
        glm::vec4 tangent{1.0f, 0.0f, 0.0f, 1.0f};
        glm::vec2 uv{0.0f};
    };
    std::vector<VertexAttributes> attributes_;  // per vertex
    std::vector<float> uvDensityLog2_;          // per triangle: 0.5 log2(uv area / world area)
    glm::vec3 boundsMin_{0.0f}, boundsMax_{0.0f};
    float rayOffset_ = 1e-4f;
    float diameter_ = 1.0f;
    RayObserver observer_ = nullptr;
    void* observerUser_ = nullptr;  // borrowed
};

}  // namespace onelight::bake
