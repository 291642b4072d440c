// Recording a frame after its shadow passes (frame_passes.cpp): the forward pass, the tonemap
// pass, the copies out, and reading a finished frame back.
#pragma once

#include "render/frame_view.hpp"
#include "render/pipelines.hpp"
#include "render/renderer.hpp"
#include "render/scene.hpp"
#include "render/targets.hpp"
#include "vk/context.hpp"

namespace onelight::render {

/// The forward pass into the HDR target (resolved from MSAA) with frame slot `slot`'s descriptor
/// sets, each draw's primary light at its record (`primaryRecord` per level light); counts
/// triangles in `stats`.
void recordForwardPass(VkCommandBuffer cmd, const Scene& scene, const RenderTargets& targets,
                       const Pipelines& pipelines, const DescriptorSets& sets, uint32_t slot,
                       const std::vector<uint32_t>& primaryRecord, const FrameView& view,
                       const DrawList& list, FrameStats& stats);
/// The tonemap pass from the HDR target into the display target.
void recordTonemapPass(VkCommandBuffer cmd, const RenderTargets& targets,
                       const Pipelines& pipelines, const DescriptorSets& sets);
/// Copies to the host (readback) and into the swapchain image, as `output` asks; (re)creates the
/// swapchain readback buffer at its image's size.
void recordOutputs(const vk::Context& ctx, VkCommandBuffer cmd, const RenderTargets& targets,
                   FrameReadback& readback, const FrameOutput& output);
/// Fills readback.captured from the readback buffers of a finished frame.
void readBackFrame(const RenderTargets& targets, FrameReadback& readback, const FrameOutput& output,
                   float exposure);

}  // namespace onelight::render
