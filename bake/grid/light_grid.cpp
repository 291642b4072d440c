#include "bake/grid/light_grid.hpp"

#include "world/features/feature_analysis.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include <tbb/enumerable_thread_specific.h>

#include "bake/lighting/direct_light.hpp"
#include "bake/parallel_for.hpp"
#include "world/features/feature_analysis.hpp"

namespace onelight::bake {
namespace {

constexpr uint32_t kGridPass = 2;

const glm::vec3 kAxes[6] = {{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}};

world::LightGridCell bakeCell(const BakeScene& scene, const BakeLights& lights,
                              const GridSettings& settings, const glm::vec3& centre,
                              uint32_t cellIndex, RayCounts& rays) {
    world::LightGridCell cell;
    Rng rng{seedFrom(cellIndex, 0, 0, kGridPass)};
    const uint32_t count = std::max(1u, settings.samples);
    const float s0 = rng.next(), s1 = rng.next();
    std::array<glm::dvec3, 6> cube{};
    uint32_t backFaces = 0;
    const bool emission = samplesEmission(lights);
    const float kUniformPdf = 1.0f / (4.0f * glsl::PI);  // the directions' density
    for (uint32_t i = 0; i < count; ++i) {
        const glm::vec3 w = sampleUniformSphere(rotatedHammersley(i, count, s0, s1));
        FirstHit first;
        const glm::vec3 l = traceRadiance(scene, lights, settings.transport, centre, w,
                                          RayCone{0.0f, sampleSpread(4.0f * glsl::PI, count)}, rng,
                                          rays, &first, emission ? kUniformPdf : 0.0f);
        if (first.found && first.backFace) ++backFaces;
        for (size_t a = 0; a < 6; ++a)
            cube[a] += glm::dvec3(l) * double(std::max(0.0f, glm::dot(kAxes[a], w)));
        if (!emission) continue;
        // One emission sample per direction, in the same 4 pi / N scale: L_e w_e / (p_e 4 pi).
        const EmissionEstimate e =
            sampleEmission(scene, lights, centre, glm::vec3(0.0f), rng, rays);
        if (!(e.pdf > 0.0f)) continue;
        const glm::vec3 le = e.radianceOverPdf * (powerHeuristic(e.pdf, kUniformPdf) * kUniformPdf);
        for (size_t a = 0; a < 6; ++a)
            cube[a] += glm::dvec3(le) * double(std::max(0.0f, glm::dot(kAxes[a], e.direction)));
    }
    if (static_cast<float>(backFaces) > settings.insideFraction * static_cast<float>(count)) {
        cell.flags = world::kLightGridCellInsideSolid;
        return cell;
    }
    // Dominant primary and every light's shadowed direct irradiance at the centre: primaries
    // with their full shadow rays each (the dominant choice compares them), the other lights
    // sharing a budget by importance (direct_light.hpp).
    std::vector<LightTerm> terms;
    for (const uint32_t l : lightsNear(lights, centre)) {
        const BakeLight& light = lights.lights[l];
        const LightIncidence incidence = lightIncidence(light, centre);
        if (incidence.irradiance == glm::vec3(0.0f)) continue;
        terms.push_back(
            {l, incidence, luminance(incidence.irradiance),
             light.light.role == world::LightRole::kPrimary || !settings.transport.sampleLights});
    }
    estimateVisibilities(scene, lights, terms, centre, settings.shadowSamples, rng, rays);
    float bestScore = 0.0f;
    for (const LightTerm& t : terms) {
        const BakeLight& light = lights.lights[t.light];
        const float score = luminance(t.incidence.irradiance * t.visibility);
        if (light.light.role == world::LightRole::kPrimary && score > bestScore) {
            bestScore = score;
            cell.dominantPrimary = light.levelIndex;
            cell.primaryVisibility = t.visibility;
        }
    }
    const double scale = 4.0 * std::numbers::pi / count;
    for (size_t a = 0; a < 6; ++a) cube[a] *= scale;
    for (const LightTerm& t : terms) {
        if (!settings.punctualDirect) break;
        if (lights.lights[t.light].levelIndex == cell.dominantPrimary) continue;
        const glm::vec3 direct = t.incidence.irradiance * t.visibility;
        for (size_t a = 0; a < 6; ++a)
            cube[a] += glm::dvec3(direct) *
                       double(std::max(0.0f, glm::dot(kAxes[a], t.incidence.direction)));
    }
    for (size_t a = 0; a < 6; ++a) cell.ambientCube[a] = glm::max(glm::vec3(cube[a]), 0.0f);
    return cell;
}

}  // namespace

world::LightGrid layoutLightGrid(const world::CompiledLevel& level, const GridSettings& settings) {
    glm::vec3 lo = level.settings.boundsMin, hi = level.settings.boundsMax;
    if (level.features.flags & world::kFeatureAuthoredGrid) {
        lo = level.features.gridMin;
        hi = level.features.gridMax;
    } else {
        // Wherever a dynamic object goes too (a mover rising above an open floor).
        glm::vec3 reachMin, reachMax;
        if (world::dynamicObjectReach(level, reachMin, reachMax)) {
            lo = glm::min(lo, reachMin);
            hi = glm::max(hi, reachMax);
        }
    }
    return layoutLightGridOver(lo, hi, settings);
}

world::LightGrid layoutLightGridOver(glm::vec3 lo, glm::vec3 hi, const GridSettings& settings) {
    world::LightGrid grid;
    const float requested = std::max(settings.cellSize, 1e-3f);
    for (int c = 0; c < 3; ++c) {
        const float extent = std::max(0.0f, hi[c] - lo[c]);
        uint32_t n = static_cast<uint32_t>(std::ceil(extent / requested));
        n = std::clamp(n, 1u, std::max(1u, settings.maxCellsPerAxis));
        const float size = extent > 0.0f ? extent / static_cast<float>(n) : requested;
        grid.dims[c] = n;
        grid.cellSize[c] = size;
        grid.origin[c] = extent > 0.0f ? lo[c] : lo[c] - 0.5f * size;
    }
    grid.samples = settings.samples;
    grid.cells.resize(size_t(grid.dims.x) * grid.dims.y * grid.dims.z);
    return grid;
}

GridStats bakeLightGrid(const BakeScene& scene, const BakeLights& lights,
                        const GridSettings& settings, uint64_t cellBegin, uint64_t cellEnd,
                        world::LightGrid& grid, Progress* progress) {
    tbb::enumerable_thread_specific<RayCounts> rays;
    bake::parallelFor(tbb::blocked_range<uint64_t>(cellBegin, cellEnd, 4), [&](const auto& r) {
        RayCounts& local = rays.local();
        for (uint64_t i = r.begin(); i != r.end(); ++i) {
            const glm::vec3 centre = world::lightGridCellCentre(grid, i);
            grid.cells[i] =
                bakeCell(scene, lights, settings, centre, static_cast<uint32_t>(i), local);
        }
        if (progress) progress->advance(r.size());
    });
    GridStats stats;
    for (const RayCounts& r : rays) stats.rays += r;
    stats.cellsBaked = cellEnd - cellBegin;
    for (uint64_t i = cellBegin; i < cellEnd; ++i)
        stats.cellsInside += (grid.cells[i].flags & world::kLightGridCellInsideSolid) != 0;
    return stats;
}

glm::vec3 ambientCubeIrradiance(const world::LightGridCell& cell, const glm::vec3& n) {
    const glm::vec3 n2 = n * n;
    return n2.x * cell.ambientCube[n.x >= 0.0f ? 0 : 1] +
           n2.y * cell.ambientCube[n.y >= 0.0f ? 2 : 3] +
           n2.z * cell.ambientCube[n.z >= 0.0f ? 4 : 5];
}

}  // namespace onelight::bake
