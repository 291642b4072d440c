// What a frame sees and draws, worked out on the CPU before recording: the camera and exposure,
// the dynamic objects' transforms and the primaries the game handed over, the culled and sorted
// draw list, the dynamic objects' grid lighting and the frame's uniforms.
#include "render/frame_view.hpp"

#include <algorithm>
#include <cmath>
#include <set>
#include <tuple>

#include "render/pipelines.hpp"
#include "shading.hpp"
#include "world/entity_transform.hpp"
#include "world/light_grid_sample.hpp"

namespace onelight::render {

namespace {

// How far around a dynamic object the static surfaces that stand for it in the potentially
// visible set reach (metres): an item's floor, a door's frame, a plat's shaft.
constexpr float kDynamicCullMargin = 1.0f;

// The world-space box around an object-space box moved by m.
void worldBounds(const glm::mat4& m, glm::vec3 lo, glm::vec3 hi, glm::vec3& outMin,
                 glm::vec3& outMax) {
    outMin = glm::vec3(1e30f);
    outMax = glm::vec3(-1e30f);
    for (int c = 0; c < 8; ++c) {
        const glm::vec3 corner((c & 1) ? hi.x : lo.x, (c & 2) ? hi.y : lo.y, (c & 4) ? hi.z : lo.z);
        const glm::vec3 w = glm::vec3(m * glm::vec4(corner, 1.0f));
        outMin = glm::min(outMin, w);
        outMax = glm::max(outMax, w);
    }
}

// The draw of a static surface, with its primary's shadow unless it is unoccluded and
// `dynamicShadow` (a dynamic caster's shadow may reach it) is false, and of a dynamic mesh lit
// by `primary` (its material and key set by the caller).
Draw drawOf(const DrawSurface& surface, bool dynamicShadow) {
    Draw d;
    d.firstIndex = surface.firstIndex;
    d.indexCount = surface.indexCount;
    d.primaryLight = surface.primaryLight;
    d.primaryKind = surface.primaryKind;
    d.atlas = surface.atlas;
    d.primaryShadow = !surface.unoccluded || dynamicShadow;
    d.directEdges = surface.directEdges;
    return d;
}
Draw drawOf(const DrawDynamicMesh& mesh, uint32_t primary) {
    Draw d;
    d.firstIndex = mesh.firstIndex;
    d.indexCount = mesh.indexCount;
    d.vertexOffset = mesh.vertexOffset;
    d.primaryLight = primary;
    d.entity = mesh.entity;
    return d;
}

struct Box {
    glm::vec3 lo{0.0f}, hi{0.0f};
};

bool overlap(const Box& a, const Box& b) {
    return glm::all(glm::lessThanEqual(a.lo, b.hi)) && glm::all(glm::lessThanEqual(b.lo, a.hi));
}

// A box around everywhere caster box `c` may cast its shadow under `light`, out to `reach`
// metres: a sun's shadow is the box swept along the sun's travel; a point or spot light's lies
// in the box's image under the scaling about the light by reach / (the light's distance to the
// box), with the box itself the convex hull of the rays from the light through it, cut at reach.
// The whole world when the light is in the box.
Box shadowReach(const world::Light& light, const Box& c, float reach) {
    Box r = c;
    glm::vec3 shift(0.0f);
    float scale = 1.0f;
    if (light.type == world::LightType::kDirectional) {
        shift = glm::normalize(light.direction) * reach;
    } else {
        const float distance = glm::length(glm::clamp(light.position, c.lo, c.hi) - light.position);
        if (distance < 1e-4f) return {glm::vec3(-1e30f), glm::vec3(1e30f)};
        scale = std::max(reach / distance, 1.0f);
    }
    for (int k = 0; k < 8; ++k) {
        const glm::vec3 corner((k & 1) ? c.hi.x : c.lo.x, (k & 2) ? c.hi.y : c.lo.y,
                               (k & 4) ? c.hi.z : c.lo.z);
        const glm::vec3 far = light.type == world::LightType::kDirectional
                                  ? corner + shift
                                  : light.position + (corner - light.position) * scale;
        r.lo = glm::min(r.lo, far);
        r.hi = glm::max(r.hi, far);
    }
    return r;
}

// The pipeline key of draw d (static when it has no entity) of its material.
uint32_t drawKeyOf(const SceneMaterials& materials, const RendererOptions& options, const Draw& d,
                   bool effectLights) {
    const bool dynamic = d.entity != kNoIndex;
    const int secondary = dynamic               ? glsl::SECONDARY_OBJECT
                          : d.atlas != kNoIndex ? glsl::SECONDARY_LIGHTMAP
                                                : glsl::SECONDARY_CONSTANT;
    return drawPipelineKey(materials, options, d.material, d.primaryKind, uint32_t(secondary),
                           effectLights, d.primaryShadow, d.fadeLight != kNoIndex, d.directEdges);
}

}  // namespace

GpuLight gpuLightOf(const world::Light& l, ShadowViewRange shadowViews) {
    GpuLight g{};
    g.positionRange = glm::vec4(l.position, l.range);
    g.direction = glm::vec4(glm::normalize(l.direction), 0.0f);
    g.color = glm::vec4(l.color * l.intensity, 0.0f);
    g.cones = glm::vec4(std::cos(l.innerCone), std::cos(l.outerCone), 0.0f, 0.0f);
    g.info = glm::uvec4(uint32_t(l.type), shadowViews.first, shadowViews.count, 0u);
    return g;
}

GpuLight gpuLightOf(const EffectOmni& omni) {
    GpuLight g{};
    g.positionRange = glm::vec4(omni.position, omni.range);
    g.direction = glm::vec4(0.0f, 0.0f, -1.0f, 0.0f);
    g.color = glm::vec4(omni.color * omni.intensity, 0.0f);
    g.cones = glm::vec4(1.0f, 0.0f, 0.0f, 0.0f);
    g.info = glm::uvec4(uint32_t(world::LightType::kPoint), kNoIndex, 0u, 0u);
    return g;
}

GpuLight gpuLightOf(const EffectSpot& spot) {
    GpuLight g{};
    g.positionRange = glm::vec4(spot.position, spot.range);
    g.direction = glm::vec4(glm::normalize(spot.direction), 0.0f);
    g.color = glm::vec4(spot.color * spot.intensity, 0.0f);
    g.cones = glm::vec4(std::cos(spot.innerCone), std::cos(spot.outerCone), 0.0f, 0.0f);
    g.info = glm::uvec4(uint32_t(world::LightType::kSpot), kNoIndex, 0u, 0u);
    return g;
}

FrameView frameViewOf(const LevelData& level, float aspect, const FrameInputs& inputs) {
    FrameView v;
    v.camera = inputs.camera;
    const float diagonal = std::max(glm::length(level.boundsMax - level.boundsMin), 1.0f);
    const float zfar =
        v.camera.zfar > 0.0f
            ? v.camera.zfar
            : glm::length(v.camera.position - 0.5f * (level.boundsMin + level.boundsMax)) +
                  diagonal;
    v.projection = projectionMatrix(v.camera, aspect, zfar);
    v.effectLights = inputs.effects.omniCount > 0 || inputs.effects.spotOn;
    v.viewProj = v.projection * viewMatrix(v.camera);
    v.ev100 = v.camera.hasExposure         ? v.camera.ev100
              : level.settings.hasExposure ? level.settings.exposureEv100
                                           : level.autoEv100;
    v.exposure = glsl::exposure_fromEV100(v.ev100);

    const std::vector<world::Entity>& entities = level.entities;
    v.entityTransforms.resize(entities.size());
    v.entityPrimary.assign(entities.size(), kNoIndex);
    v.entityHidden.assign(entities.size(), 0);
    v.entityFadeFrom.assign(entities.size(), kNoIndex);
    v.entityPrimaryWeight.assign(entities.size(), 1.0f);
    for (size_t e = 0; e < entities.size(); ++e)
        v.entityTransforms[e] = world::worldFromObject(entities[e], entities[e].position);
    for (const DynamicTransform& t : inputs.dynamicTransforms) {
        if (t.entity >= v.entityTransforms.size()) continue;
        v.entityTransforms[t.entity] = t.worldFromObject;
        if (t.primary < level.lights.size()) v.entityPrimary[t.entity] = t.primary;
        v.entityHidden[t.entity] = t.hidden ? 1 : 0;
        if (v.entityPrimary[t.entity] != kNoIndex && t.fadingFrom < level.lights.size() &&
            t.fadingFrom != t.primary && t.fadeWeight < 1.0f) {
            v.entityFadeFrom[t.entity] = t.fadingFrom;
            v.entityPrimaryWeight[t.entity] = std::clamp(t.fadeWeight, 0.0f, 1.0f);
        }
    }
    return v;
}

DrawList buildDrawList(const Scene& scene, const RendererOptions& options, const FrameView& view,
                       FrameStats& stats) {
    const SceneGeometry& geometry = scene.geometry;
    const SceneMaterials& materials = scene.materials;
    const world::Visibility& visibility = scene.baked.visibility;
    const size_t entityCount = scene.level.entities.size();
    DrawList list;
    // Every dynamic caster, seen or not: its shadow may fall in view.
    std::vector<Box> casters;
    for (const DrawDynamicMesh& mesh : geometry.dynamicMeshes) {
        if (!mesh.castsShadow || view.entityHidden[mesh.entity]) continue;
        Box b;
        worldBounds(view.entityTransforms[mesh.entity], mesh.boundsMin, mesh.boundsMax, b.lo, b.hi);
        casters.push_back(b);
    }
    const float levelReach = glm::length(scene.level.boundsMax - scene.level.boundsMin) + 1.0f;
    // Per primary light, where each caster's shadow may reach: made once a frame, when the first
    // unoccluded surface of that light asks.
    std::vector<std::vector<Box>> reachOf(casters.empty() ? 0 : scene.level.lights.size());
    // Whether a dynamic caster's shadow may reach static surface s under its primary.
    auto dynamicShadowOn = [&](const DrawSurface& s) {
        if (!s.unoccluded || casters.empty()) return false;
        std::vector<Box>& reaches = reachOf.at(s.primaryLight);
        if (reaches.empty()) {
            const world::Light& light = scene.level.lights[s.primaryLight];
            const float reach = light.range > 0.0f ? light.range : levelReach;
            for (const Box& c : casters) reaches.push_back(shadowReach(light, c, reach));
        }
        for (const Box& r : reaches)
            if (overlap(r, {s.boundsMin, s.boundsMax})) return true;
        return false;
    };
    const Frustum frustum = frustumOf(view.viewProj);
    const glm::vec3 eye = view.camera.position;
    const uint32_t materialCount = uint32_t(materials.classes.size());
    // A draw of `material`, its bounds [lo, hi] for the front-to-back order, and its primary
    // counted as visible.
    auto add = [&](Draw d, uint32_t material, glm::vec3 lo, glm::vec3 hi) {
        d.material = std::min(material, materialCount - 1);
        d.key = drawKeyOf(materials, options, d, view.effectLights);
        const glm::vec3 toCentre = 0.5f * (lo + hi) - eye;
        d.distance2 = glm::dot(toCentre, toCentre);
        list.draws.push_back(d);
        if (d.primaryLight != kNoIndex && d.primaryShadow)
            list.visibleLights.push_back(d.primaryLight);
    };
    const uint32_t visibleRow =
        options.visibilityCulling ? world::visibilityRowAt(visibility, eye) : kNoIndex;
    for (size_t i = 0; i < geometry.surfaces.size(); ++i) {  // in the level's order
        const DrawSurface& surface = geometry.surfaces[i];
        if (!intersects(frustum, surface.boundsMin, surface.boundsMax)) {
            ++stats.surfacesCulled;
            continue;
        }
        if (visibleRow != kNoIndex &&
            !world::clusterInRow(visibility, visibleRow, visibility.surfaceCluster[i])) {
            ++stats.surfacesCulled;
            ++stats.surfacesHidden;
            continue;
        }
        add(drawOf(surface, dynamicShadowOn(surface)), surface.material, surface.boundsMin,
            surface.boundsMax);
        ++stats.surfacesDrawn;
    }
    // A dynamic object is out of sight when the static surfaces around it (the clusters whose
    // bounds meet its box grown by kDynamicCullMargin) are all out of the eye's potentially
    // visible set; one near no surface (in the open) is never culled so.
    const std::vector<glm::vec3>& clusterMin = scene.baked.clusterMin;
    const std::vector<glm::vec3>& clusterMax = scene.baked.clusterMax;
    auto hiddenByVisibility = [&](glm::vec3 lo, glm::vec3 hi) {
        if (visibleRow == kNoIndex || clusterMin.empty()) return false;
        lo -= glm::vec3(kDynamicCullMargin);
        hi += glm::vec3(kDynamicCullMargin);
        bool near = false;
        for (uint32_t c = 0; c < clusterMin.size(); ++c) {
            if (glm::any(glm::greaterThan(lo, clusterMax[c])) ||
                glm::any(glm::lessThan(hi, clusterMin[c])))
                continue;
            if (world::clusterInRow(visibility, visibleRow, c)) return false;
            near = true;
        }
        return near;
    };
    list.entityVisible.assign(entityCount, 0);
    for (const DrawDynamicMesh& mesh : geometry.dynamicMeshes) {
        if (view.entityHidden[mesh.entity]) continue;
        glm::vec3 lo, hi;
        worldBounds(view.entityTransforms[mesh.entity], mesh.boundsMin, mesh.boundsMax, lo, hi);
        if (!intersects(frustum, lo, hi)) continue;
        if (hiddenByVisibility(lo, hi)) {
            ++stats.dynamicMeshesHidden;
            continue;
        }
        list.entityVisible[mesh.entity] = 1;
        Draw d = drawOf(mesh, view.entityPrimary[mesh.entity]);
        d.primaryKind = primaryKindOf(scene.level.lights, d.primaryLight);
        d.fadeLight = view.entityFadeFrom[mesh.entity];
        d.primaryWeight = view.entityPrimaryWeight[mesh.entity];
        if (d.fadeLight != kNoIndex) list.visibleLights.push_back(d.fadeLight);
        add(d, mesh.material, lo, hi);
        ++stats.dynamicMeshesDrawn;
    }
    std::sort(list.visibleLights.begin(), list.visibleLights.end());
    list.visibleLights.erase(std::unique(list.visibleLights.begin(), list.visibleLights.end()),
                             list.visibleLights.end());
    batchDraws(list.draws, options.rasterFloor);
    stats.draws = uint32_t(list.draws.size());
    if (options.flatShading) list.visibleLights.clear();
    return list;
}

DrawList warmUpDrawList(const SceneGeometry& geometry, const SceneMaterials& materials,
                        const RendererOptions& options, size_t entityCount,
                        uint32_t shadowedLight) {
    DrawList list;
    list.entityVisible.assign(entityCount, 0);
    const uint32_t materialCount = uint32_t(materials.classes.size());
    std::set<std::pair<uint32_t, uint32_t>> drawn;  // (pipeline key, material)
    auto add = [&](Draw d, uint32_t material) {
        d.material = std::min(material, materialCount - 1);
        d.indexCount = std::min(d.indexCount, 3u);
        bool added = false;
        for (const bool effects : {false, true}) {
            d.key = drawKeyOf(materials, options, d, effects);
            if (!drawn.insert({d.key, d.material}).second) continue;
            list.draws.push_back(d);
            added = true;
        }
        return added;
    };
    for (const DrawSurface& surface : geometry.surfaces) {
        add(drawOf(surface, false), surface.material);
        // An unoccluded surface is drawn with its shadow while a dynamic caster's may reach it.
        if (surface.unoccluded && geometry.dynamicCasters)
            add(drawOf(surface, true), surface.material);
    }
    for (const DrawDynamicMesh& mesh : geometry.dynamicMeshes)
        for (const uint32_t kind : geometry.dynamicPrimaryKinds) {
            // Without a light (the pipeline's type is all the key needs): nothing lit.
            Draw d = drawOf(mesh, kNoIndex);
            d.primaryKind = kind;
            if (add(d, mesh.material)) list.entityVisible[mesh.entity] = 1;
            // The pipeline of a primary switch's fade, into a light of this type (a pick never
            // leaves a light for none: the view fades only between two lights).
            if (kind == uint32_t(glsl::PRIMARY_NONE)) continue;
            d.fadeLight = 0;
            if (add(d, mesh.material)) list.entityVisible[mesh.entity] = 1;
        }
    if (shadowedLight != kNoIndex && !options.flatShading) list.visibleLights = {shadowedLight};
    batchDraws(list.draws, options.rasterFloor);
    return list;
}

void batchDraws(std::vector<Draw>& draws, bool geometryOnly) {
    // Opaque draws first: static before dynamic (the level's walls fill the depth buffer
    // first, so that a dynamic object behind them is rejected before it is shaded: a map's
    // items and movers are mostly out of sight), then by pipeline, then by what a draw binds and
    // pushes, then by index range, so that the surfaces a draw could share lie side by side;
    // dynamic meshes front to back. With geometryOnly (the raster floor) only the index range
    // counts. Static and dynamic draws never share a state, so the two orders never meet (a
    // strict weak order). Blended draws (keyAlphaBlend) last, back to front by their bounds'
    // centres, each over what is behind it.
    const auto state = [geometryOnly](const Draw& d) {
        const uint32_t dynamic = d.entity == kNoIndex ? 0u : 1u;
        return geometryOnly ? std::make_tuple(dynamic, 0u, 0u, 0u, 0u)
                            : std::make_tuple(dynamic, d.key, d.material, d.primaryLight, d.atlas);
    };
    std::stable_sort(draws.begin(), draws.end(), [&](const Draw& a, const Draw& b) {
        const bool blendA = !geometryOnly && keyAlphaBlend(a.key);
        const bool blendB = !geometryOnly && keyAlphaBlend(b.key);
        if (blendA != blendB) return blendB;
        if (blendA) return a.distance2 > b.distance2;
        if (state(a) != state(b)) return state(a) < state(b);
        if (a.entity != kNoIndex || b.entity != kNoIndex) return a.distance2 < b.distance2;
        return std::tie(a.vertexOffset, a.firstIndex) < std::tie(b.vertexOffset, b.firstIndex);
    });
    size_t kept = 0;
    for (size_t i = 0; i < draws.size(); ++i) {
        Draw& last = draws[kept == 0 ? 0 : kept - 1];
        const Draw& d = draws[i];
        if (kept > 0 && last.entity == kNoIndex && d.entity == kNoIndex &&
            state(last) == state(d) && last.vertexOffset == d.vertexOffset &&
            last.firstIndex + last.indexCount == d.firstIndex) {
            last.indexCount += d.indexCount;
            continue;
        }
        draws[kept++] = d;
    }
    draws.resize(kept);
}

namespace {

// How many lattice samples an object takes along an edge of its bounds `extent` metres long,
// for a grid of `cell` metres, where the edge's rank among the three is `rank` (0 the longest):
// a cell or less apart from end to end, up to 8, 3 and 2 along the longest, middle and shortest
// edge; two (its two faces) along an edge of at least a quarter cell; else one.
uint32_t latticeSamples(float extent, float cell, int rank) {
    const uint32_t cap = rank == 0 ? 8u : rank == 1 ? 3u : 2u;
    if (extent > cell) return std::min(uint32_t(std::ceil(extent / cell)) + 1u, cap);
    return extent >= 0.25f * cell ? 2u : 1u;
}

}  // namespace

void writeObjectLighting(const LevelData& level, const BakedLightingMaps& baked,
                         const SceneGeometry& geometry, const FrameView& view, const DrawList& list,
                         GpuObjectLighting* out) {
    const bool useGrid = baked.present && !baked.grid.cells.empty();
    const std::vector<glm::vec3>& lo = geometry.entityBoundsMin;
    const std::vector<glm::vec3>& hi = geometry.entityBoundsMax;
    const float cell =
        std::min({baked.grid.cellSize.x, baked.grid.cellSize.y, baked.grid.cellSize.z});
    for (uint32_t e = 0; e < level.entities.size(); ++e) {
        if (!list.entityVisible[e]) continue;
        // Written in place, the header and the samples the shader reads only (a record holds
        // room for MAX_OBJECT_SAMPLES; most objects take one).
        GpuObjectLighting& o = out[e];
        const glm::mat4& m = view.entityTransforms[e];
        o.from = glm::vec4(glm::vec3(m[3]), 1.0f);
        for (glm::vec4& axis : o.axes) axis = glm::vec4(0.0f, 0.0f, 0.0f, 1.0f);
        if (!useGrid) {  // the placeholder textures' neutral values: the ambient, visible
            for (size_t f = 0; f < 6; ++f)
                o.ambientCube[f] = glm::vec4(glm::vec3(level.ambientLux), 0.0f);
            o.ambientCube[0].w = 1.0f;
            continue;
        }
        const uint32_t primary = view.entityPrimary[e];
        auto sampleAt = [&](glm::vec3 point, uint32_t s) {
            const world::LightGridSample sample = world::sampleLightGrid(baked.grid, point);
            for (size_t f = 0; f < 6; ++f)
                o.ambientCube[6 * s + f] = glm::vec4(sample.ambientCube[f], 0.0f);
            o.ambientCube[6 * s].w =
                primary != kNoIndex ? world::bakedVisibility(baked.grid, sample, primary) : 1.0f;
        };
        // Its bounds' edges in the world (rotation and uniform scale keep them square).
        glm::vec3 corner(m[3]), edge[3] = {glm::vec3(0.0f), glm::vec3(0.0f), glm::vec3(0.0f)};
        float length[3] = {0.0f, 0.0f, 0.0f};
        if (lo[e].x <= hi[e].x) {
            corner = glm::vec3(m * glm::vec4(lo[e], 1.0f));
            for (int a = 0; a < 3; ++a) {
                glm::vec3 side(0.0f);
                side[a] = hi[e][a] - lo[e][a];
                edge[a] = glm::vec3(m * glm::vec4(side, 0.0f));
                length[a] = glm::length(edge[a]);
            }
        }
        const float longest = std::max({length[0], length[1], length[2]});
        if (!(longest > cell)) {  // within a cell: the one sample at its origin
            sampleAt(glm::vec3(m[3]), 0);
            continue;
        }
        uint32_t n[3];
        for (int a = 0; a < 3; ++a) {
            int rank = 0;  // edges longer than this one, ties broken by axis order
            for (int b = 0; b < 3; ++b)
                rank += length[b] > length[a] || (length[b] == length[a] && b < a) ? 1 : 0;
            n[a] = latticeSamples(length[a], cell, rank);
            o.axes[a] = n[a] > 1u ? glm::vec4(edge[a] / (length[a] * length[a]), float(n[a]))
                                  : glm::vec4(0.0f, 0.0f, 0.0f, 1.0f);
        }
        // One sample edge's single sample sits mid-way across it; more span it end to end.
        auto along = [&](int a, uint32_t i) {
            return n[a] > 1u ? float(i) / float(n[a] - 1u) : 0.5f;
        };
        o.from = glm::vec4(
            corner + along(0, 0) * edge[0] + along(1, 0) * edge[1] + along(2, 0) * edge[2], 1.0f);
        for (uint32_t k = 0; k < n[2]; ++k)
            for (uint32_t j = 0; j < n[1]; ++j)
                for (uint32_t i = 0; i < n[0]; ++i)
                    sampleAt(corner + along(0, i) * edge[0] + along(1, j) * edge[1] +
                                 along(2, k) * edge[2],
                             i + n[0] * (j + n[1] * k));
    }
}

FrameUniforms frameUniformsOf(const Scene& scene, const RendererOptions& options,
                              const FrameView& view, const EffectLights& effects) {
    FrameUniforms u{};
    u.viewProj = view.viewProj;
    u.cameraPosition = glm::vec4(view.camera.position, view.exposure);
    u.shadowParams = glm::vec4(options.shadowRadius, options.shadowBand,
                               1.0f / float(options.shadowMapSize), 0.0f);
    u.baked = glm::vec4(scene.level.ambientLux, scene.baked.lightmapDecode, 0.0f, 0.0f);
    u.probeParams =
        glm::vec4(float(scene.probes.mips), options.probesPerNormal ? 1.0f : 0.0f, 0.0f, 0.0f);
    const uint32_t omnis = std::min(effects.omniCount, kMaxEffectOmnis);
    u.counts = glm::uvec4(omnis, effects.spotOn ? 1u : 0u, scene.probes.count, 0u);
    u.skyFromClip = glm::inverse(view.projection * glm::mat4(glm::mat3(viewMatrix(view.camera))));
    u.sky = glm::vec4(scene.level.settings.skyRadiance, scene.sky.present ? 1.0f : 0.0f);
    for (uint32_t i = 0; i < omnis; ++i) u.effectOmnis[i] = gpuLightOf(effects.omni[i]);
    u.effectSpot = gpuLightOf(effects.spot);
    return u;
}

}  // namespace onelight::render
