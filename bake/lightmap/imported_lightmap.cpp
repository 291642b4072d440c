#include "bake/lightmap/imported_lightmap.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "bake/embree/bake_scene.hpp"
#include "bake/parallel_for.hpp"

namespace onelight::bake {
namespace {

// The imported triangles as one Embree scene; released with it.
class ImportedScene {
public:
    ImportedScene(RTCDevice device, const world::ImportedLightmap& imported) {
        scene_ = rtcNewScene(device);
        RTCGeometry mesh = rtcNewGeometry(device, RTC_GEOMETRY_TYPE_TRIANGLE);
        const size_t count = imported.triangles.size();
        auto* vertices = static_cast<float*>(rtcSetNewGeometryBuffer(
            mesh, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT3, 3 * sizeof(float), 3 * count));
        auto* indices = static_cast<uint32_t*>(rtcSetNewGeometryBuffer(
            mesh, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3, 3 * sizeof(uint32_t), count));
        if (!vertices || !indices) {
            rtcReleaseGeometry(mesh);
            rtcReleaseScene(scene_);
            throw std::runtime_error("Embree: could not allocate the imported lightmap's scene");
        }
        for (size_t t = 0; t < count; ++t)
            for (int k = 0; k < 3; ++k) {
                const glm::vec3& p = imported.triangles[t].corners[k];
                vertices[9 * t + 3 * size_t(k)] = p.x;
                vertices[9 * t + 3 * size_t(k) + 1] = p.y;
                vertices[9 * t + 3 * size_t(k) + 2] = p.z;
                indices[3 * t + size_t(k)] = uint32_t(3 * t + size_t(k));
            }
        rtcCommitGeometry(mesh);
        rtcAttachGeometry(scene_, mesh);
        rtcReleaseGeometry(mesh);
        rtcCommitScene(scene_);
    }
    ~ImportedScene() { rtcReleaseScene(scene_); }
    ImportedScene(const ImportedScene&) = delete;
    ImportedScene& operator=(const ImportedScene&) = delete;

    // The triangle and Embree's barycentrics (u, v) where the ray meets one, if any.
    bool intersect(glm::vec3 origin, glm::vec3 dir, float maxDistance, uint32_t& triangle,
                   glm::vec2& uv) const {
        RTCIntersectContext context;
        rtcInitIntersectContext(&context);
        RTCRayHit q = embreeRay(origin, dir, maxDistance);
        rtcIntersect1(scene_, &context, &q);
        if (q.hit.geomID == RTC_INVALID_GEOMETRY_ID) return false;
        triangle = q.hit.primID;
        uv = {q.hit.u, q.hit.v};
        return true;
    }

private:
    RTCScene scene_ = nullptr;
};

// Bilinear read of `page` at coordinates `uv` (texel centres at (i + 1/2) / size), of the
// decoded values.
glm::vec3 readPage(const world::ImportedLightmap& imported, uint32_t page, glm::vec2 uv) {
    const uint32_t size = imported.pageSize;
    const uint8_t* texels = imported.pages.data() + size_t(page) * size * size * 3;
    const float x = std::clamp(uv.x * float(size) - 0.5f, 0.0f, float(size - 1));
    const float y = std::clamp(uv.y * float(size) - 0.5f, 0.0f, float(size - 1));
    const uint32_t x0 = uint32_t(x), y0 = uint32_t(y);
    const uint32_t x1 = std::min(x0 + 1, size - 1), y1 = std::min(y0 + 1, size - 1);
    const float fx = x - float(x0), fy = y - float(y0);
    const auto at = [&](uint32_t i, uint32_t j) {
        const uint8_t* p = texels + (size_t(j) * size + i) * 3;
        return decodeImportedValue(glm::vec3(p[0], p[1], p[2]), imported.encoding);
    };
    return glm::mix(glm::mix(at(x0, y0), at(x1, y0), fx), glm::mix(at(x0, y1), at(x1, y1), fx), fy);
}

float srgbToLinear(float c) {
    return c <= 0.04045f ? c / 12.92f : std::pow((c + 0.055f) / 1.055f, 2.4f);
}

}  // namespace

glm::vec3 decodeImportedValue(glm::vec3 stored, const world::ImportedLightEncoding& encoding) {
    glm::vec3 s = glm::clamp(stored, glm::vec3(0.0f), glm::vec3(255.0f));
    if (encoding.srgb)
        for (int c = 0; c < 3; ++c) s[c] = 255.0f * srgbToLinear(s[c] / 255.0f);
    if (encoding.contrast > 0.0f && encoding.contrast != 1.0f)
        s = glm::max((s - 128.0f) / encoding.contrast + 128.0f, glm::vec3(0.0f));
    if (encoding.compensate > 0.0f) s *= encoding.compensate;
    if (encoding.exposure > 0.0f) {
        const float peak = std::max({s.x, s.y, s.z});
        if (peak > 0.0f) {
            const float exposed = std::min(peak, 254.5f);
            s *= -encoding.exposure * std::log1p(-exposed / 255.0f) / peak;
        }
    }
    if (encoding.gamma > 0.0f && encoding.gamma != 1.0f)
        for (int c = 0; c < 3; ++c) s[c] = 255.0f * std::pow(s[c] / 255.0f, encoding.gamma);
    if (encoding.brightness > 0.0f) s /= encoding.brightness;
    for (int c = 0; c < 3; ++c)
        if (!std::isfinite(s[c]) || s[c] < 0.0f) s[c] = 0.0f;
    return s;
}

std::vector<world::LightmapTexel> resampleImportedLightmap(
    RTCDevice device, const world::CompiledLevel& level, const std::vector<TexelSample>& samples,
    const world::ImportedLightmap& imported) {
    if (imported.triangles.empty()) return {};
    std::vector<world::LightmapTexel> texels(totalTexels(level), world::LightmapTexel{});
    const size_t pages = imported.pageSize ? imported.pages.size() /
                                                 (size_t(imported.pageSize) * imported.pageSize * 3)
                                           : 0;
    const ImportedScene scene(device, imported);
    const float lift = 0.01f;  // metres
    bake::parallelFor(size_t(0), samples.size(), [&](size_t i) {
        const TexelSample& s = samples[i];
        uint32_t triangle = 0;
        glm::vec2 b(0.0f);
        if (!scene.intersect(s.position + s.normal * lift, -s.normal, 2.0f * lift, triangle, b) &&
            !scene.intersect(s.position - s.normal * lift, s.normal, 2.0f * lift, triangle, b))
            return;
        const world::ImportedLightmap::Triangle& t = imported.triangles[triangle];
        const float w0 = 1.0f - b.x - b.y;
        glm::vec3 value;
        if (t.page < pages) {
            value = readPage(imported, t.page, w0 * t.uv[0] + b.x * t.uv[1] + b.y * t.uv[2]);
        } else {
            const auto corner = [&](int k) {
                return decodeImportedValue(t.vertexLight[k], imported.encoding);
            };
            value = w0 * corner(0) + b.x * corner(1) + b.y * corner(2);
        }
        world::LightmapTexel& out = texels[s.texel];
        out.irradiance = glm::max(value * imported.luxPerValue, glm::vec3(0.0f));
        out.direction = glm::vec3(0.0f);
        out.normalWeight = 0.5f;
        out.flags = world::kLightmapTexelSampled;
        out.indirectIrradiance = out.irradiance;  // no part of it held apart
    });
    return texels;
}

}  // namespace onelight::bake
