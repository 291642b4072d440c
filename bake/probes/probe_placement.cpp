#include "probe_placement.hpp"

#include <algorithm>
#include <cassert>
#include <cmath>
#include <cstdio>
#include <numeric>

#include <tbb/enumerable_thread_specific.h>

#include "bake/lighting/sampling.hpp"
#include "bake/parallel_for.hpp"
#include "world/error.hpp"
#include "world/package/probe_section.hpp"

namespace onelight::bake {
namespace {

bool hasBox(glm::vec3 lo, glm::vec3 hi) {
    return lo.x < hi.x && lo.y < hi.y && lo.z < hi.z;
}

// The entities flagged kEntityProbe, each with its box when the box is non-empty.
std::vector<ProbePlacement> authoredProbes(const world::CompiledLevel& level) {
    std::vector<ProbePlacement> probes;
    for (uint32_t i = 0; i < level.entities.size(); ++i) {
        const world::Entity& e = level.entities[i];
        if (!(e.flags & world::kEntityProbe)) continue;
        ProbePlacement p;
        p.position = e.position;
        if (hasBox(e.probeBoxMin, e.probeBoxMax)) {
            p.boxMin = e.probeBoxMin;
            p.boxMax = e.probeBoxMax;
        }
        p.entity = i;
        probes.push_back(p);
    }
    return probes;
}

// Point i of an n-point Fibonacci sphere set: z uniform in equal-area bands, the azimuth
// turning by the golden angle. Fixed (no random rotation), so every point and every run casts
// the same directions, and not aligned with the axes that levels' walls usually follow.
glm::vec3 fibonacciDirection(uint32_t i, uint32_t n) {
    const float goldenAngle = glsl::PI * (3.0f - std::sqrt(5.0f));
    const float z = 1.0f - (2.0f * float(i) + 1.0f) / float(n);
    const float r = std::sqrt(std::max(0.0f, 1.0f - z * z));
    const float phi = goldenAngle * float(i);
    return {r * std::cos(phi), r * std::sin(phi), z};
}

// First hits around a point: how many rays hit something, how many of those a back face.
struct SolidTest {
    uint32_t hits = 0;
    uint32_t backFaces = 0;
    bool solid() const { return float(backFaces) > kProbeSolidFraction * float(hits); }
    // backFaces / hits < o.backFaces / o.hits without dividing (0 / 0 counts as 0).
    bool lessSolidThan(const SolidTest& o) const {
        return uint64_t(backFaces) * std::max(1u, o.hits) <
               uint64_t(o.backFaces) * std::max(1u, hits);
    }
};

SolidTest testSolid(const BakeScene& scene, glm::vec3 point, RayCounts& rays) {
    SolidTest t;
    for (uint32_t i = 0; i < kProbeSolidRays; ++i) {
        const SurfaceHit hit = scene.intersect(point, fibonacciDirection(i, kProbeSolidRays),
                                               scene.sceneDiameter(), rays.probe);
        t.hits += hit.found ? 1u : 0u;
        t.backFaces += hit.found && hit.backFace ? 1u : 0u;
    }
    return t;
}

struct Lattice {
    glm::vec3 origin{0.0f};  // first point
    glm::vec3 step{0.0f};    // metres between points per axis (0 on an axis of one point)
    glm::uvec3 dims{1u};
    float spacing = 0.0f;  // the requested step, grown by the cap

    uint32_t count() const { return dims.x * dims.y * dims.z; }
    glm::uvec3 coords(uint32_t i) const {
        return {i % dims.x, (i / dims.x) % dims.y, i / (dims.x * dims.y)};
    }
    glm::vec3 point(uint32_t i) const { return origin + glm::vec3(coords(i)) * step; }
};

// Cell centres over [lo, hi], as layoutLightGrid sizes its cells; the cap grows the spacing.
Lattice layLattice(glm::vec3 lo, glm::vec3 hi, float spacing) {
    const glm::vec3 extent = glm::max(hi - lo, glm::vec3(0.0f));
    double s = spacing;
    glm::uvec3 dims(1u);
    for (;;) {
        uint64_t total = 1;
        for (int c = 0; c < 3; ++c) {
            const double n = std::max(1.0, std::ceil(double(extent[c]) / s));
            dims[c] = uint32_t(std::min(n, double(kMaxProbeLatticePoints) + 1.0));
            total *= dims[c];
        }
        if (total <= kMaxProbeLatticePoints) break;
        s *= std::max(1.01, std::cbrt(double(total) / double(kMaxProbeLatticePoints)));
    }
    Lattice lattice;
    lattice.dims = dims;
    lattice.spacing = float(s);
    for (int c = 0; c < 3; ++c) {
        lattice.step[c] = extent[c] / float(dims[c]);
        lattice.origin[c] = lo[c] + 0.5f * lattice.step[c];
    }
    return lattice;
}

// Union-find whose root is always the lowest index of its set.
uint32_t findRoot(std::vector<uint32_t>& parent, uint32_t i) {
    while (parent[i] != i) {
        parent[i] = parent[parent[i]];
        i = parent[i];
    }
    return i;
}

void unite(std::vector<uint32_t>& parent, uint32_t a, uint32_t b) {
    a = findRoot(parent, a);
    b = findRoot(parent, b);
    if (a < b)
        parent[b] = a;
    else if (b < a)
        parent[a] = b;
}

/// The box of the walls around `point`, as engines fit reflection proxies: for each of the
/// six axis directions, kBoxFitRays x kBoxFitRays rays through a grid on that face of a cube
/// around the point; the face lies at the farthest hit's distance along the axis (an obstacle
/// in front of a wall shortens some rays, not the farthest). A face most of whose rays escape
/// (a doorway, the open sky) leaves the probe unboxed: false.
bool fitBox(const BakeScene& scene, glm::vec3 point, RayCounts& rays, glm::vec3& lo,
            glm::vec3& hi) {
    for (int axis = 0; axis < 3; ++axis)
        for (int sign = -1; sign <= 1; sign += 2) {
            glm::vec3 a(0.0f), t(0.0f), b(0.0f);
            a[axis] = float(sign);
            t[(axis + 1) % 3] = 1.0f;
            b[(axis + 2) % 3] = 1.0f;
            uint32_t hits = 0;
            float farthest = 0.0f;
            for (uint32_t i = 0; i < kBoxFitRays; ++i)
                for (uint32_t j = 0; j < kBoxFitRays; ++j) {
                    const float u = 1.6f * (float(i) + 0.5f) / float(kBoxFitRays) - 0.8f;
                    const float v = 1.6f * (float(j) + 0.5f) / float(kBoxFitRays) - 0.8f;
                    const glm::vec3 d = glm::normalize(a + u * t + v * b);
                    const SurfaceHit hit =
                        scene.intersect(point, d, scene.sceneDiameter(), rays.probe);
                    if (!hit.found) continue;
                    ++hits;
                    farthest = std::max(farthest, hit.distance * glm::dot(d, a));
                }
            if (float(hits) < kBoxFitHitFraction * float(kBoxFitRays * kBoxFitRays) ||
                !(farthest > 0.0f))
                return false;
            (sign > 0 ? hi : lo)[axis] = point[axis] + float(sign) * farthest;
        }
    return true;
}

/// Whether some specular surface of `scene` sees geometry in reflection: from the centres of
/// its specular triangles (every one, or an even stride through them past
/// kReflectorPoints), kProbeSolidRays directions over each front hemisphere (both sides when
/// double-sided), stopping at the first hit.
bool reflectorsSeeGeometry(const BakeScene& scene, RayCounts& rays) {
    std::vector<uint32_t> reflectors;
    for (uint32_t t = 0; t < scene.triangleCount(); ++t)
        if (scene.materialOf(t).materialClass != world::MaterialClass::kLambert)
            reflectors.push_back(t);
    const size_t stride = std::max<size_t>(1, reflectors.size() / kReflectorPoints);
    for (size_t k = 0; k < reflectors.size(); k += stride) {
        const uint32_t t = reflectors[k];
        const std::array<glm::vec3, 3> v = scene.triangleVertices(t);
        const glm::vec3 n = scene.triangleNormal(t);
        const glm::vec3 centre = (v[0] + v[1] + v[2]) / 3.0f;
        for (int side = 0; side < (scene.materialOf(t).doubleSided ? 2 : 1); ++side) {
            const glm::vec3 facing = side == 0 ? n : -n;
            const glm::vec3 origin = centre + facing * (4.0f * scene.rayOffset());
            for (uint32_t i = 0; i < kProbeSolidRays; ++i) {
                glm::vec3 d = fibonacciDirection(i, kProbeSolidRays);
                if (glm::dot(d, facing) < 0.0f) d = -d;
                if (scene.occluded(origin, d, scene.sceneDiameter(), rays.shadow)) return true;
            }
        }
    }
    return false;
}

}  // namespace

void checkProbeBudget(size_t probeCount, uint32_t faceSize) {
    if (probeCount <= kMaxBakedProbes) return;
    const double megabytes = double(probeCount) * double(world::probeTexelCount(faceSize)) *
                             double(sizeof(uint32_t)) * 1e-6;
    char message[256];
    std::snprintf(message, sizeof message,
                  "%zu environment probes of %u texels a face (%.0f MB of texels); expected at "
                  "most %u (6 cube layers each under the 2048 devices commonly allow): author "
                  "fewer probe entities",
                  probeCount, faceSize, megabytes, kMaxBakedProbes);
    throw world::Error(message);
}

std::vector<ProbePlacement> placeProbes(const world::CompiledLevel& level, const BakeScene& scene,
                                        const ProbePlacementSettings& settings,
                                        ProbePlacementStats* stats) {
    ProbePlacementStats local;
    ProbePlacementStats& out = stats ? *stats : local;
    out = ProbePlacementStats{};

    std::vector<ProbePlacement> probes = authoredProbes(level);
    for (ProbePlacement& p : probes) p.insideSolid = testSolid(scene, p.position, out.rays).solid();
    if (!probes.empty() || !(level.features.flags & world::kFeatureProbes)) return probes;
    // Nothing to reflect: when no specular surface sees any geometry, its reflections hold only
    // the uniform sky, which the runtime's probe-less path (a uniform normalised radiance)
    // gives exactly. A sky image varies, so it keeps the probes.
    if (scene.triangleCount() > 0 && level.settings.skyImage == world::kNoIndex &&
        !reflectorsSeeGeometry(scene, out.rays)) {
        out.nothingToReflect = true;
        return probes;
    }
    if (scene.triangleCount() == 0) {
        ProbePlacement centre;
        centre.position = 0.5f * (level.settings.boundsMin + level.settings.boundsMax);
        return {centre};
    }

    float spacing = level.settings.probeSpacing > 0.0f && !settings.overridesLevel
                        ? level.settings.probeSpacing
                        : settings.spacing;
    assert(std::isfinite(spacing) && spacing > 0.0f && "probe spacing must be metres > 0");
    // Without asserts, a bad spacing (0 would never let the cap's growth end) gets the default.
    if (!(std::isfinite(spacing) && spacing > 0.0f)) spacing = ProbePlacementSettings{}.spacing;
    // A flat level (a floor alone) would put its points on the floor, half their view in it.
    glm::vec3 top = level.settings.boundsMax;
    top.y = std::max(top.y, level.settings.boundsMin.y + kProbeMinLatticeHeight);
    const Lattice lattice = layLattice(level.settings.boundsMin, top, spacing);
    const uint32_t count = lattice.count();
    out.spacing = lattice.spacing;
    out.lattice = lattice.dims;
    out.latticePoints = count;

    // Each point's solid test, then its segments to its +x, +y, +z neighbours; every result
    // lands in its point's slot, so the threads' order does not matter.
    tbb::enumerable_thread_specific<RayCounts> rays;
    std::vector<SolidTest> tests(count);
    bake::parallelFor(tbb::blocked_range<uint32_t>(0, count, 16), [&](const auto& r) {
        RayCounts& mine = rays.local();
        for (uint32_t i = r.begin(); i != r.end(); ++i)
            tests[i] = testSolid(scene, lattice.point(i), mine);
    });
    std::vector<uint8_t> linked(count, 0);  // bit a: connected to the next point along axis a
    bake::parallelFor(tbb::blocked_range<uint32_t>(0, count, 16), [&](const auto& r) {
        RayCounts& mine = rays.local();
        for (uint32_t i = r.begin(); i != r.end(); ++i) {
            if (tests[i].solid()) continue;
            const glm::uvec3 at = lattice.coords(i);
            const uint32_t stride[3] = {1u, lattice.dims.x, lattice.dims.x * lattice.dims.y};
            for (int a = 0; a < 3; ++a) {
                if (at[a] + 1 >= lattice.dims[a] || tests[i + stride[a]].solid()) continue;
                const glm::vec3 from = lattice.point(i);
                const glm::vec3 to = lattice.point(i + stride[a]);
                const float length = glm::length(to - from);
                if (!scene.occluded(from, (to - from) / length, length, mine.shadow))
                    linked[i] |= uint8_t(1u << a);
            }
        }
    });
    for (const RayCounts& r : rays) out.rays += r;

    std::vector<uint32_t> parent(count);
    std::iota(parent.begin(), parent.end(), 0u);
    const uint32_t stride[3] = {1u, lattice.dims.x, lattice.dims.x * lattice.dims.y};
    for (uint32_t i = 0; i < count; ++i)
        for (int a = 0; a < 3; ++a)
            if (linked[i] & (1u << a)) unite(parent, i, i + stride[a]);

    // A root is its component's lowest index, so it comes before its other points: numbering
    // components as their roots come gives "lowest lattice index first".
    std::vector<uint32_t> component(count, world::kNoIndex);
    std::vector<std::vector<uint32_t>> members;
    for (uint32_t i = 0; i < count; ++i) {
        if (tests[i].solid()) continue;
        const uint32_t root = findRoot(parent, i);
        if (root == i) {
            component[i] = uint32_t(members.size());
            members.emplace_back();
        }
        members[component[root]].push_back(i);
        ++out.openPoints;
    }
    out.components = uint32_t(members.size());
    for (const std::vector<uint32_t>& points : members)
        for (uint32_t i : points) {
            ProbePlacement p;
            p.position = lattice.point(i);
            probes.push_back(p);
        }

    const float nearby = 0.5f * lattice.spacing;
    for (const world::Camera& camera : level.cameras) {
        bool near = false;
        for (const ProbePlacement& p : probes)
            near = near || glm::length(p.position - camera.position) <= nearby;
        if (near || testSolid(scene, camera.position, out.rays).solid()) continue;
        ProbePlacement p;
        p.position = camera.position;
        probes.push_back(p);
        ++out.cameraProbes;
    }

    // Box projection for every probe placed so far, where walls close it in on every side.
    for (ProbePlacement& p : probes)
        if (fitBox(scene, p.position, out.rays, p.boxMin, p.boxMax)) {
            ++out.boxed;
        } else {
            p.boxMin = p.boxMax = glm::vec3(0.0f);
        }

    if (probes.empty()) {
        uint32_t best = 0;
        for (uint32_t i = 1; i < count; ++i)
            if (tests[i].lessSolidThan(tests[best])) best = i;
        ProbePlacement p;
        p.position = lattice.point(best);
        probes.push_back(p);
        out.fallback = true;
    }
    return probes;
}

}  // namespace onelight::bake
