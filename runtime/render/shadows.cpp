// Runtime shadow maps of the primary lights: the sun's orthographic map fitted around the camera,
// a spot's perspective map, an omni's six faces. Static casters are rendered once into
// staticShadows and cached (the sun's again when the camera leaves its cell); with dynamic
// objects in the level, each frame copies the static layers and draws only the dynamic casters.
#include "render/shadows.hpp"

#include <algorithm>
#include <cmath>

#include <glm/gtc/matrix_transform.hpp>

#include "render/targets.hpp"
#include "vk/commands.hpp"
#include "vk/rendering.hpp"
#include "vk/vk_check.hpp"

namespace onelight::render {

namespace {

constexpr float kSunExtentScale = 1.25f;     // a sun map's half size over its far distance
constexpr float kSunCellsPerExtent = 4.0f;   // the camera may move extent / 4 before a refit
constexpr float kSunBiasClampTexels = 2.0f;  // the sun map's largest depth bias, in its texels

float levelDiagonal(const LevelData& level) {
    return std::max(glm::length(level.boundsMax - level.boundsMin), 1.0f);
}

glm::vec3 anyPerpendicular(glm::vec3 d) {
    return std::fabs(d.y) < 0.99f ? glm::vec3(0.0f, 1.0f, 0.0f) : glm::vec3(1.0f, 0.0f, 0.0f);
}

// The sun's cascade `view`, fitted around the camera: an orthographic map of half size
// sunCascadeExtent(split) centred on the camera's cell (a whole number of texels, so that the
// texels stay put while the camera moves within it), as deep as the level. Each cascade refits
// (and redraws its static casters) only when the camera leaves its cell.
void fitSunCascade(ShadowMaps& shadows, ShadowView& v, const LevelData& level,
                   const world::Light& light, const Camera& camera) {
    const glm::vec3 dir = glm::normalize(light.direction);
    const glm::vec3 right = glm::normalize(glm::cross(dir, anyPerpendicular(dir)));
    const glm::vec3 up = glm::cross(right, dir);
    const float extent = sunCascadeExtent(v.split, levelDiagonal(level));
    const float step = extent / kSunCellsPerExtent;
    const glm::vec2 cell(std::floor(glm::dot(camera.position, right) / step + 0.5f),
                         std::floor(glm::dot(camera.position, up) / step + 0.5f));
    if (v.staticValid && cell == v.sunCell) return;
    v.sunCell = cell;
    v.staticValid = false;

    const glm::vec3 boundsCentre = 0.5f * (level.boundsMin + level.boundsMax);
    const float depth = 0.5f * levelDiagonal(level) + 1.0f;
    const glm::vec3 centre =
        right * (cell.x * step) + up * (cell.y * step) + dir * glm::dot(boundsCentre, dir);
    const glm::mat4 view = glm::lookAtRH(centre - dir * depth, centre, up);
    const glm::mat4 proj = glm::orthoRH_ZO(-extent, extent, -extent, extent, 0.0f, 2.0f * depth);
    v.viewProj = proj * view;
    v.params = glm::vec4(2.0f * extent / float(shadows.mapSize), 0.0f, v.split, 0.0f);
    // The slope bias grows without bound on a caster the sun grazes: a wall 14 degrees off the
    // sun's rays got ~8 texels (0.8 m) of depth bias, and the room it stands in was sunlit for
    // 0.8 m behind it (bright bands along every wall of a room lit through a roof opening).
    // Two texels of depth are enough beside the receivers' normal offset (forward_shading.glsl).
    v.depthBiasClamp = kSunBiasClampTexels * v.params.x / (2.0f * depth);
}

void fitSpotOrOmni(ShadowMaps& shadows, const ShadowSlot& slot, const LevelData& level) {
    const world::Light& light = level.lights[slot.light];
    const float zfar = light.range > 0.0f ? light.range : levelDiagonal(level) * 2.0f;
    const float znear = std::clamp(zfar * 1e-4f, 0.01f, 0.1f);
    const float size = float(shadows.mapSize);
    if (light.type == world::LightType::kSpot) {
        const glm::vec3 dir = glm::normalize(light.direction);
        const float fov = std::min(2.0f * light.outerCone + 0.1f, glm::radians(170.0f));
        const glm::mat4 view =
            glm::lookAtRH(light.position, light.position + dir, anyPerpendicular(dir));
        ShadowView& v = shadows.views[slot.firstView];
        v.viewProj = glm::perspectiveRH_ZO(fov, 1.0f, znear, zfar) * view;
        v.params = glm::vec4(2.0f * std::tan(0.5f * fov) / size, 1.0f, 0.0f, 0.0f);
        v.staticValid = false;
        return;
    }
    // Omni: faces +X, -X, +Y, -Y, +Z, -Z (forward_shading.glsl picks them by the major axis), each
    // a little wider than 90 degrees so that the filter taps at a face's border stay inside it.
    const float tanHalf = 1.0f + 3.0f / size;
    const float fov = 2.0f * std::atan(tanHalf);
    const glm::vec3 dirs[6] = {{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}};
    for (uint32_t f = 0; f < 6; ++f) {
        const glm::vec3 up = std::fabs(dirs[f].y) > 0.5f ? glm::vec3(0, 0, 1) : glm::vec3(0, 1, 0);
        const glm::mat4 view = glm::lookAtRH(light.position, light.position + dirs[f], up);
        ShadowView& v = shadows.views[slot.firstView + f];
        v.viewProj = glm::perspectiveRH_ZO(fov, 1.0f, znear, zfar) * view;
        v.params = glm::vec4(2.0f * tanHalf / size, 1.0f, 0.0f, 0.0f);
        v.staticValid = false;
    }
}

// Slope-scaled depth bias of the shadow pass (constant, clamp, slope), in depth-buffer units.
constexpr float kShadowBiasConstant = 1.25f;
constexpr float kShadowBiasSlope = 2.0f;

void beginDepthRendering(VkCommandBuffer cmd, VkImageView view, uint32_t size, bool clear,
                         float biasClamp) {
    const VkRenderingAttachmentInfo depth =
        vk::depthAttachment(view, clear ? VK_ATTACHMENT_LOAD_OP_CLEAR : VK_ATTACHMENT_LOAD_OP_LOAD,
                            VK_ATTACHMENT_STORE_OP_STORE);
    vk::beginRendering(cmd, {size, size}, nullptr, &depth);
    vkCmdSetDepthBias(cmd, kShadowBiasConstant, biasClamp, kShadowBiasSlope);
}

// Whether `material` is alpha-masked or blended: drawn with the masked pipeline, its holes open.
bool masked(const ShadowDraw& draw, uint32_t material) {
    return draw.materials->alphaMode[material] != uint8_t(world::AlphaMode::kOpaque);
}

void pushMasked(VkCommandBuffer cmd, const ShadowDraw& draw, uint32_t material,
                const glm::mat4& clip) {
    MaskedShadowPush push{};
    push.clipFromObject = clip;
    push.alpha = glm::vec4(draw.materials->maskAlpha[material], 0.0f, 0.0f);
    vkCmdBindDescriptorSets(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, draw.maskedLayout, 0, 1,
                            &(*draw.materialSets)[material], 0, nullptr);
    vkCmdPushConstants(cmd, draw.maskedLayout,
                       VK_SHADER_STAGE_VERTEX_BIT | VK_SHADER_STAGE_FRAGMENT_BIT, 0, sizeof(push),
                       &push);
}

// Whether `material` casts a shadow at all (world::Material::castsShadows): the bake lets light
// through the others, so the shadow maps leave them out too.
bool casts(const ShadowDraw& draw, uint32_t material) {
    return draw.materials->castsShadows[material] != 0;
}

// The static casters in the view's frustum: the opaque ones, then the alpha-masked ones.
void drawStaticCasters(VkCommandBuffer cmd, const ShadowDraw& draw, const SceneGeometry& geometry,
                       const ShadowView& view) {
    const Frustum frustum = frustumOf(view.viewProj);
    vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, draw.opaque);
    vkCmdPushConstants(cmd, draw.opaqueLayout, VK_SHADER_STAGE_VERTEX_BIT, 0, sizeof(glm::mat4),
                       &view.viewProj);
    bool anyMasked = false;
    for (const DrawSurface& surface : geometry.surfaces)
        if (casts(draw, surface.material) &&
            intersects(frustum, surface.boundsMin, surface.boundsMax)) {
            if (masked(draw, surface.material))
                anyMasked = true;
            else
                vkCmdDrawIndexed(cmd, surface.indexCount, 1, surface.firstIndex, 0, 0);
        }
    if (!anyMasked) return;
    vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, draw.masked);
    for (const DrawSurface& surface : geometry.surfaces)
        if (masked(draw, surface.material) && casts(draw, surface.material) &&
            intersects(frustum, surface.boundsMin, surface.boundsMax)) {
            pushMasked(cmd, draw, surface.material, view.viewProj);
            vkCmdDrawIndexed(cmd, surface.indexCount, 1, surface.firstIndex, 0, 0);
        }
}

void drawDynamicCasters(VkCommandBuffer cmd, const ShadowDraw& draw, const SceneGeometry& geometry,
                        const ShadowView& view, const std::vector<glm::mat4>& entityTransforms,
                        const std::vector<uint8_t>& entityHidden) {
    for (const DrawDynamicMesh& mesh : geometry.dynamicMeshes) {
        if (!mesh.castsShadow || !casts(draw, mesh.material) || entityHidden[mesh.entity]) continue;
        const glm::mat4 clip = view.viewProj * entityTransforms[mesh.entity];
        if (masked(draw, mesh.material)) {
            vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, draw.masked);
            pushMasked(cmd, draw, mesh.material, clip);
        } else {
            vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, draw.opaque);
            vkCmdPushConstants(cmd, draw.opaqueLayout, VK_SHADER_STAGE_VERTEX_BIT, 0,
                               sizeof(glm::mat4), &clip);
        }
        vkCmdDrawIndexed(cmd, mesh.indexCount, 1, mesh.firstIndex, mesh.vertexOffset, 0);
    }
}

constexpr VkPipelineStageFlags kDepthStages =
    VK_PIPELINE_STAGE_EARLY_FRAGMENT_TESTS_BIT | VK_PIPELINE_STAGE_LATE_FRAGMENT_TESTS_BIT;

}  // namespace

std::vector<float> sunCascadeSplits(float shadowRadius, uint32_t cascades, float levelDiagonal) {
    const uint32_t n = std::max(cascades, 1u);
    std::vector<float> splits;
    for (uint32_t k = 0; k < n; ++k) {
        splits.push_back(shadowRadius / std::pow(kSunCascadeRatio, float(n - 1 - k)));
        // A cascade as wide as the level covers every farther view distance too.
        if (sunCascadeExtent(splits.back(), levelDiagonal) >= levelDiagonal) break;
    }
    splits.back() = std::max(splits.back(), shadowRadius);
    return splits;
}

float sunCascadeExtent(float split, float levelDiagonal) {
    // Never wider than the level: a 4 m room's sun map at the 40 m radius's size had 10 cm
    // texels, and the sun leaked along every junction of its walls for a texel's width.
    return std::min(split * kSunExtentScale, levelDiagonal);
}

void createShadows(const vk::Context& ctx, ShadowMaps& shadows, const LevelData& level,
                   const RendererOptions& options, bool dynamicCasters) {
    const std::vector<world::Light>& lights = level.lights;
    shadows.mapSize = options.shadowMapSize;
    const std::vector<float> splits =
        sunCascadeSplits(options.shadowRadius, options.sunCascades, levelDiagonal(level));
    // Slots for every primary light a surface uses (and every primary, for dynamic objects),
    // while layers last (and the forward pass's uniform array of views holds them).
    const uint32_t maxLayers = std::min(options.maxShadowLayers, glsl::MAX_SHADOW_VIEWS);
    shadows.lightSlot.assign(lights.size(), kNoIndex);
    uint32_t layers = 0;
    for (uint32_t i = 0; i < lights.size(); ++i) {
        if (lights[i].role != world::LightRole::kPrimary || options.flatShading) continue;
        const uint32_t need = lights[i].type == world::LightType::kPoint ? 6u
                              : lights[i].type == world::LightType::kDirectional
                                  ? uint32_t(splits.size())
                                  : 1u;
        if (layers + need > maxLayers) continue;
        ShadowSlot slot;
        slot.light = i;
        slot.firstView = layers;
        slot.viewCount = need;
        shadows.lightSlot[i] = uint32_t(shadows.slots.size());
        shadows.slots.push_back(slot);
        layers += need;
    }
    shadows.views.resize(std::max(layers, 1u));
    shadows.layers = layers;
    for (const ShadowSlot& slot : shadows.slots)
        if (lights[slot.light].type == world::LightType::kDirectional)
            for (uint32_t k = 0; k < slot.viewCount; ++k)
                shadows.views[slot.firstView + k].split = splits[k];

    vk::ImageDesc desc;
    desc.format = kDepthFormat;
    desc.width = desc.height = shadows.mapSize;
    desc.layers = uint32_t(shadows.views.size());
    desc.viewType = VK_IMAGE_VIEW_TYPE_2D_ARRAY;
    desc.usage = VK_IMAGE_USAGE_DEPTH_STENCIL_ATTACHMENT_BIT | VK_IMAGE_USAGE_SAMPLED_BIT |
                 VK_IMAGE_USAGE_TRANSFER_SRC_BIT | VK_IMAGE_USAGE_TRANSFER_DST_BIT;
    vk::createImage(ctx, shadows.staticShadows, desc);
    if (dynamicCasters) vk::createImage(ctx, shadows.frameShadows, desc);
    for (uint32_t i = 0; i < shadows.views.size(); ++i) {
        shadows.views[i].staticLayer = vk::createLayerView(ctx, shadows.staticShadows, i, 1);
        if (dynamicCasters)
            shadows.views[i].frameLayer = vk::createLayerView(ctx, shadows.frameShadows, i, 1);
    }

    // Every layer starts cleared to "unoccluded" and shader-readable.
    vk::submitOnce(ctx, [&](VkCommandBuffer cmd) {
        for (vk::Image* image : {&shadows.staticShadows, &shadows.frameShadows}) {
            if (!image->image) continue;
            vk::imageBarrier(
                cmd, *image,
                vk::layersBarrier(0, VK_REMAINING_ARRAY_LAYERS, VK_IMAGE_LAYOUT_UNDEFINED,
                                  VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL,
                                  VK_PIPELINE_STAGE_TOP_OF_PIPE_BIT, 0,
                                  VK_PIPELINE_STAGE_TRANSFER_BIT, VK_ACCESS_TRANSFER_WRITE_BIT));
            const VkClearDepthStencilValue one{1.0f, 0};
            const VkImageSubresourceRange range{VK_IMAGE_ASPECT_DEPTH_BIT, 0, 1, 0,
                                                VK_REMAINING_ARRAY_LAYERS};
            vkCmdClearDepthStencilImage(cmd, image->image, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL,
                                        &one, 1, &range);
            vk::imageBarrier(cmd, *image,
                             vk::layersBarrier(
                                 0, VK_REMAINING_ARRAY_LAYERS, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL,
                                 VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL,
                                 VK_PIPELINE_STAGE_TRANSFER_BIT, VK_ACCESS_TRANSFER_WRITE_BIT,
                                 VK_PIPELINE_STAGE_FRAGMENT_SHADER_BIT, VK_ACCESS_SHADER_READ_BIT));
        }
    });

    vk::SamplerDesc compare;
    compare.compare = true;
    compare.mipmapMode = VK_SAMPLER_MIPMAP_MODE_NEAREST;
    compare.addressU = compare.addressV = compare.addressW = VK_SAMPLER_ADDRESS_MODE_CLAMP_TO_EDGE;
    compare.maxLod = 0.0f;
    shadows.sampler = vk::createSampler(ctx, compare);
}

void destroyShadows(const vk::Context& ctx, ShadowMaps& shadows) {
    if (shadows.sampler) vkDestroySampler(ctx.device, shadows.sampler, nullptr);
    shadows.sampler = VK_NULL_HANDLE;
    for (auto it = shadows.views.rbegin(); it != shadows.views.rend(); ++it) {
        if (it->frameLayer) vkDestroyImageView(ctx.device, it->frameLayer, nullptr);
        if (it->staticLayer) vkDestroyImageView(ctx.device, it->staticLayer, nullptr);
        it->frameLayer = it->staticLayer = VK_NULL_HANDLE;
    }
    vk::destroyImage(ctx, shadows.frameShadows);
    vk::destroyImage(ctx, shadows.staticShadows);
}

std::vector<ShadowViewRange> lightShadowViews(const ShadowMaps& shadows) {
    std::vector<ShadowViewRange> ranges(shadows.lightSlot.size());
    for (size_t i = 0; i < ranges.size(); ++i)
        if (shadows.lightSlot[i] != kNoIndex) {
            const ShadowSlot& slot = shadows.slots[shadows.lightSlot[i]];
            ranges[i] = {slot.firstView, slot.viewCount};
        }
    return ranges;
}

const vk::Image& sampledShadowMaps(const ShadowMaps& shadows) {
    return shadows.frameShadows.image ? shadows.frameShadows : shadows.staticShadows;
}

void updateShadowViews(ShadowMaps& shadows, const LevelData& level, const Camera& camera,
                       const std::vector<uint32_t>& visibleLights) {
    for (uint32_t light : visibleLights) {
        if (shadows.lightSlot[light] == kNoIndex) continue;
        const ShadowSlot& slot = shadows.slots[shadows.lightSlot[light]];
        if (level.lights[light].type == world::LightType::kDirectional) {
            for (uint32_t v = slot.firstView; v < slot.firstView + slot.viewCount; ++v)
                fitSunCascade(shadows, shadows.views[v], level, level.lights[light], camera);
        } else if (!shadows.views[slot.firstView].staticValid) {
            fitSpotOrOmni(shadows, slot, level);
        }
    }
}

void writeShadowViews(const ShadowMaps& shadows, GpuShadowView* out) {
    for (size_t i = 0; i < shadows.views.size(); ++i) {
        out[i].viewProj = shadows.views[i].viewProj;
        out[i].params = shadows.views[i].params;
    }
}

uint32_t recordShadowPasses(ShadowMaps& shadows, VkCommandBuffer cmd, const ShadowDraw& draw,
                            const SceneGeometry& geometry,
                            const std::vector<uint32_t>& visibleLights,
                            const std::vector<glm::mat4>& entityTransforms,
                            const std::vector<uint8_t>& entityHidden) {
    const uint32_t size = shadows.mapSize;
    const VkDeviceSize offset = 0;
    vkCmdBindVertexBuffers(cmd, 0, 1, &geometry.vertices.buffer, &offset);
    vkCmdBindIndexBuffer(cmd, geometry.indices.buffer, 0, VK_INDEX_TYPE_UINT32);

    // Static casters of the views that need them, once.
    uint32_t rendered = 0;
    for (uint32_t light : visibleLights) {
        if (shadows.lightSlot[light] == kNoIndex) continue;
        const ShadowSlot& slot = shadows.slots[shadows.lightSlot[light]];
        for (uint32_t v = slot.firstView; v < slot.firstView + slot.viewCount; ++v) {
            ShadowView& view = shadows.views[v];
            if (view.staticValid) continue;
            vk::imageBarrier(cmd, shadows.staticShadows,
                             vk::layersBarrier(v, 1, VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL,
                                               VK_IMAGE_LAYOUT_DEPTH_ATTACHMENT_OPTIMAL,
                                               VK_PIPELINE_STAGE_FRAGMENT_SHADER_BIT,
                                               VK_ACCESS_SHADER_READ_BIT, kDepthStages,
                                               VK_ACCESS_DEPTH_STENCIL_ATTACHMENT_WRITE_BIT |
                                                   VK_ACCESS_DEPTH_STENCIL_ATTACHMENT_READ_BIT));
            beginDepthRendering(cmd, view.staticLayer, size, true, view.depthBiasClamp);
            drawStaticCasters(cmd, draw, geometry, view);
            vkCmdEndRendering(cmd);
            vk::imageBarrier(
                cmd, shadows.staticShadows,
                vk::layersBarrier(
                    v, 1, VK_IMAGE_LAYOUT_DEPTH_ATTACHMENT_OPTIMAL,
                    VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL, kDepthStages,
                    VK_ACCESS_DEPTH_STENCIL_ATTACHMENT_WRITE_BIT,
                    VK_PIPELINE_STAGE_FRAGMENT_SHADER_BIT | VK_PIPELINE_STAGE_TRANSFER_BIT,
                    VK_ACCESS_SHADER_READ_BIT | VK_ACCESS_TRANSFER_READ_BIT));
            view.staticValid = true;
            ++rendered;
        }
    }
    if (!geometry.dynamicCasters) return rendered;

    // Dynamic casters: the cached static layers, copied, plus the moving objects.
    for (uint32_t light : visibleLights) {
        if (shadows.lightSlot[light] == kNoIndex) continue;
        const ShadowSlot& slot = shadows.slots[shadows.lightSlot[light]];
        vk::imageBarrier(
            cmd, shadows.staticShadows,
            vk::layersBarrier(
                slot.firstView, slot.viewCount, VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL,
                VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, VK_PIPELINE_STAGE_FRAGMENT_SHADER_BIT, 0,
                VK_PIPELINE_STAGE_TRANSFER_BIT, VK_ACCESS_TRANSFER_READ_BIT));
        vk::imageBarrier(
            cmd, shadows.frameShadows,
            vk::layersBarrier(
                slot.firstView, slot.viewCount, VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL,
                VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, VK_PIPELINE_STAGE_FRAGMENT_SHADER_BIT, 0,
                VK_PIPELINE_STAGE_TRANSFER_BIT, VK_ACCESS_TRANSFER_WRITE_BIT));
        vk::copyImage(cmd, shadows.staticShadows.image, shadows.frameShadows.image,
                      VK_IMAGE_ASPECT_DEPTH_BIT, size, size, slot.firstView, slot.viewCount);
        vk::imageBarrier(
            cmd, shadows.staticShadows,
            vk::layersBarrier(slot.firstView, slot.viewCount, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL,
                              VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL,
                              VK_PIPELINE_STAGE_TRANSFER_BIT, 0,
                              VK_PIPELINE_STAGE_FRAGMENT_SHADER_BIT, VK_ACCESS_SHADER_READ_BIT));
        vk::imageBarrier(
            cmd, shadows.frameShadows,
            vk::layersBarrier(slot.firstView, slot.viewCount, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL,
                              VK_IMAGE_LAYOUT_DEPTH_ATTACHMENT_OPTIMAL,
                              VK_PIPELINE_STAGE_TRANSFER_BIT, VK_ACCESS_TRANSFER_WRITE_BIT,
                              kDepthStages,
                              VK_ACCESS_DEPTH_STENCIL_ATTACHMENT_WRITE_BIT |
                                  VK_ACCESS_DEPTH_STENCIL_ATTACHMENT_READ_BIT));
        for (uint32_t v = slot.firstView; v < slot.firstView + slot.viewCount; ++v) {
            beginDepthRendering(cmd, shadows.views[v].frameLayer, size, false,
                                shadows.views[v].depthBiasClamp);
            drawDynamicCasters(cmd, draw, geometry, shadows.views[v], entityTransforms,
                               entityHidden);
            vkCmdEndRendering(cmd);
        }
        vk::imageBarrier(
            cmd, shadows.frameShadows,
            vk::layersBarrier(slot.firstView, slot.viewCount,
                              VK_IMAGE_LAYOUT_DEPTH_ATTACHMENT_OPTIMAL,
                              VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL, kDepthStages,
                              VK_ACCESS_DEPTH_STENCIL_ATTACHMENT_WRITE_BIT,
                              VK_PIPELINE_STAGE_FRAGMENT_SHADER_BIT, VK_ACCESS_SHADER_READ_BIT));
    }
    return rendered;
}

}  // namespace onelight::render
