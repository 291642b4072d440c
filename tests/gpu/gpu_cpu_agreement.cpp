// GPU/CPU agreement of the BRDF pieces: every piece of shaders/brdf_pieces.glsl, compiled once
// to SPIR-V (run on the Vulkan device, lavapipe here) and once as C++ (shading.hpp), over a grid
// of hard cases, denormals and a seeded random sweep. Both sides must be finite and non-negative
// and agree to |gpu - cpu| <= 1e-5 |cpu| or <= 1e-6, with no validation-layer error.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <exception>
#include <random>
#include <string>
#include <utility>
#include <vector>

#include "shading.hpp"
#include "vk/buffer.hpp"
#include "vk/commands.hpp"
#include "vk/context.hpp"
#include "vk/descriptors.hpp"
#include "vk/pipeline.hpp"

#include "brdf_pieces.comp.spv.h"

namespace {

namespace vk = onelight::vk;
using onelight::glsl::vec4;

constexpr int kPieces = BRDF_PIECE_COUNT;
constexpr uint32_t kWorkgroupSize = 64;  // local_size_x of brdf_pieces.comp
constexpr double kRelTolerance = 1e-5;
constexpr double kAbsTolerance = 1e-6;

// Mirrors the switch of brdf_pieces.glsl, for the messages only.
const char* pieceName(int piece) {
    static const char* const names[] = {"specPower_fromGloss",
                                        "gloss_fromSpecPower",
                                        "beckmannM_fromSpecPower",
                                        "ggxAlpha_fromGloss",
                                        "schlickSmithA_fromSpecPower",
                                        "D_BlinnPhong",
                                        "D_Beckmann",
                                        "D_GGX",
                                        "V_None",
                                        "V_Kelemen",
                                        "V_SchlickSmith",
                                        "V_SmithBeckmannCorrelated",
                                        "V_SmithGGXCorrelated",
                                        "F_Schlick",
                                        "Fd_Lambert",
                                        "EnvBRDF_BlackOps.scale",
                                        "EnvBRDF_BlackOps.bias",
                                        "EnvBRDF_Fit.scale",
                                        "EnvBRDF_Fit.bias",
                                        "lobe BlinnPhong/None/Schlick",
                                        "lobe BlinnPhong/Kelemen/Schlick",
                                        "lobe BlinnPhong/SchlickSmith/Schlick",
                                        "lobe Beckmann/SmithCorrelated/Schlick",
                                        "lobe GGX/SmithCorrelated/Schlick",
                                        "Fd_Chan",
                                        "ggxExcessArea",
                                        "gloss_fromAverageNormalDistance",
                                        "gloss_withFilteredNormal",
                                        "specularFacets_Beckmann",
                                        "bumpShare",
                                        "bumpSlopeRadius",
                                        "footprintReflectance",
                                        "specularFacets_Nakagami",
                                        "exp(logGamma)"};
    return piece < int(std::size(names)) ? names[piece] : "?";
}

// One input of the shader, std430 layout of PieceInput in brdf_pieces.comp.
struct PieceInput {
    vec4 dots;    // NoV, NoL, LoH, NxH2
    vec4 params;  // gloss, f0, 0, 0
};
static_assert(sizeof(PieceInput) == 32);

// A float with enough digits to round-trip, and its exact hex form.
std::string number(float v) {
    char text[64];
    std::snprintf(text, sizeof(text), "%.9g (%a)", double(v), double(v));
    return text;
}

std::string ratioText(double ratio) {
    char text[32];
    std::snprintf(text, sizeof(text), "%.3g", ratio);
    return text;
}

std::string describe(const PieceInput& in) {
    char text[200];
    std::snprintf(text, sizeof(text), "NoV=%.9g NoL=%.9g LoH=%.9g NxH2=%.9g gloss=%.9g f0=%.9g",
                  double(in.dots.x), double(in.dots.y), double(in.dots.z), double(in.dots.w),
                  double(in.params.x), double(in.params.y));
    return text;
}

// The grid of hard cases, denormals in every slot, and a seeded random sweep.
std::vector<PieceInput> makeInputs() {
    const float dotValues[] = {0.0f, 1e-7f, 1e-4f, 0.01f, 0.1f, 0.5f, 0.9f, 0.9999f, 1.0f};
    const float nxh2Values[] = {0.0f, 1e-7f, 1e-6f, 1e-5f, 1e-4f, 1e-3f, 0.01f, 0.1f, 0.5f, 1.0f};
    const float glossValues[] = {0.0f, 0.1f, 0.25f, 0.5f, 0.75f, 0.9f, 1.0f};
    const float f0Values[] = {0.04f, 1.0f};

    std::vector<PieceInput> inputs;
    for (float NoV : dotValues)
        for (float NoL : dotValues)
            for (float LoH : dotValues)
                for (float NxH2 : nxh2Values)
                    for (float gloss : glossValues)
                        for (float f0 : f0Values)
                            inputs.push_back({vec4(NoV, NoL, LoH, NxH2), vec4(gloss, f0, 0, 0)});

    // A denormal in each slot in turn, then in all of them, around a few ordinary points.
    const float denormal = 1e-40f;
    const PieceInput bases[] = {{vec4(0.5f, 0.5f, 0.5f, 0.1f), vec4(0.5f, 0.04f, 0, 0)},
                                {vec4(1.0f, 1.0f, 1.0f, 0.0f), vec4(1.0f, 1.0f, 0, 0)},
                                {vec4(1e-4f, 0.0f, 0.0f, 1.0f), vec4(0.0f, 0.04f, 0, 0)}};
    for (const PieceInput& base : bases) {
        for (int slot = 0; slot < 6; ++slot) {
            PieceInput in = base;
            (slot < 4 ? in.dots[slot] : in.params[slot - 4]) = denormal;
            inputs.push_back(in);
        }
        inputs.push_back({vec4(denormal), vec4(denormal, denormal, 0, 0)});
    }

    // Uniform dot products and gloss; NxH2 uniform or log-uniform down to 1e-8 (the highlight
    // core of glossy lobes).
    std::mt19937 rng(20110801u);
    std::uniform_real_distribution<float> unit(0.0f, 1.0f);
    std::uniform_real_distribution<float> log10NxH2(-8.0f, 0.0f);
    for (int i = 0; i < 4096; ++i) {
        PieceInput in;
        in.dots = vec4(unit(rng), unit(rng), unit(rng), unit(rng));
        if (i % 2) in.dots.w = std::pow(10.0f, log10NxH2(rng));
        in.params = vec4(unit(rng), unit(rng), 0, 0);
        inputs.push_back(in);
    }
    return inputs;
}

// Everything the tests look at, computed once per process.
struct AgreementRun {
    std::string error;        // a Vulkan failure; empty if the GPU ran
    std::string deviceName;   // the Vulkan device that ran the shader
    bool validation = false;  // the validation layer was on
    uint32_t validationErrors = 0;
    uint32_t validationWarnings = 0;
    std::vector<PieceInput> inputs;
    std::vector<float> gpu;  // [input * kPieces + piece]
    std::vector<float> cpu;  // same layout
};

void runOnGpu(AgreementRun& run) {
    const VkDeviceSize inputBytes = run.inputs.size() * sizeof(PieceInput);
    const VkDeviceSize outputBytes = run.inputs.size() * kPieces * sizeof(float);
    const uint32_t inputCount = uint32_t(run.inputs.size());

    vk::Context ctx;
    vk::ContextOptions options;
    options.appName = "onelight_gpu_cpu_agreement";
    options.validation = true;  // NoValidationErrors asserts on the counts, whatever the env says
    vk::createContext(ctx, options);
    run.deviceName = ctx.properties.deviceName;
    run.validation = ctx.validation;

    vk::Buffer input, output;
    vk::createHostBuffer(ctx, input, inputBytes, VK_BUFFER_USAGE_STORAGE_BUFFER_BIT);
    vk::createHostBuffer(ctx, output, outputBytes, VK_BUFFER_USAGE_STORAGE_BUFFER_BIT);
    std::memcpy(input.mapped, run.inputs.data(), inputBytes);

    const VkDescriptorSetLayoutBinding bindings[] = {
        vk::storageBufferBinding(0, VK_SHADER_STAGE_COMPUTE_BIT),
        vk::storageBufferBinding(1, VK_SHADER_STAGE_COMPUTE_BIT)};
    vk::ComputePipeline pipeline;
    vk::createComputePipeline(ctx, pipeline, kBrdfPiecesCompSpirv, bindings, sizeof(uint32_t));

    const vk::Buffer* const setBuffers[] = {&input, &output};
    vk::DescriptorSet set;
    vk::createStorageBufferSet(ctx, set, pipeline.setLayout, setBuffers);

    vk::submitOnce(ctx, [&](VkCommandBuffer cmd) {
        vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, pipeline.pipeline);
        vkCmdBindDescriptorSets(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, pipeline.layout, 0, 1,
                                &set.set, 0, nullptr);
        vkCmdPushConstants(cmd, pipeline.layout, VK_SHADER_STAGE_COMPUTE_BIT, 0, sizeof(inputCount),
                           &inputCount);
        vkCmdDispatch(cmd, (inputCount + kWorkgroupSize - 1) / kWorkgroupSize, 1, 1);
        vk::bufferBarrier(cmd, output, VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT,
                          VK_ACCESS_SHADER_WRITE_BIT, VK_PIPELINE_STAGE_HOST_BIT,
                          VK_ACCESS_HOST_READ_BIT);
    });

    run.gpu.resize(run.inputs.size() * kPieces);
    std::memcpy(run.gpu.data(), output.mapped, outputBytes);

    vk::destroyDescriptorSet(ctx, set);
    vk::destroyComputePipeline(ctx, pipeline);
    vk::destroyBuffer(ctx, output);
    vk::destroyBuffer(ctx, input);
    vk::destroyContext(ctx);
    // The counts outlive the handles, so messages from the destroy calls are included.
    run.validationErrors = ctx.validationCounts.errors.load();
    run.validationWarnings = ctx.validationCounts.warnings.load();
}

const AgreementRun& agreementRun() {
    static const AgreementRun run = [] {
        AgreementRun r;
        r.inputs = makeInputs();
        r.cpu.resize(r.inputs.size() * kPieces);
        for (size_t i = 0; i < r.inputs.size(); ++i)
            for (int p = 0; p < kPieces; ++p)
                r.cpu[i * kPieces + p] =
                    onelight::glsl::brdfPiece(p, r.inputs[i].dots, r.inputs[i].params);
        try {
            runOnGpu(r);
        } catch (const std::exception& e) {
            r.error = e.what();
        }
        return r;
    }();
    return run;
}

TEST(GpuCpuAgreement, EveryPieceWithinTolerance) {
    const AgreementRun& run = agreementRun();
    ASSERT_TRUE(run.error.empty()) << run.error;
    std::printf(
        "device: %s; %zu inputs x %d pieces; tolerance |gpu - cpu| <= %.0e |cpu| or <= %.0e\n",
        run.deviceName.c_str(), run.inputs.size(), kPieces, kRelTolerance, kAbsTolerance);
    std::printf("%-5s %-38s %-12s %-12s %-12s %s\n", "piece", "name", "max rel", "max abs",
                "err/tol", "beyond");
    for (int p = 0; p < kPieces; ++p) {
        double maxRel = 0.0, maxAbs = 0.0, worst = 0.0;
        size_t worstInput = 0, beyond = 0;
        for (size_t i = 0; i < run.inputs.size(); ++i) {
            const double g = run.gpu[i * kPieces + p];
            const double c = run.cpu[i * kPieces + p];
            if (!std::isfinite(g) || !std::isfinite(c)) continue;  // see FiniteAndNonNegative
            const double diff = std::fabs(g - c);
            maxAbs = std::max(maxAbs, diff);
            if (std::fabs(c) >= kAbsTolerance) maxRel = std::max(maxRel, diff / std::fabs(c));
            const double ratio = diff / std::max(kRelTolerance * std::fabs(c), kAbsTolerance);
            if (ratio > 1.0) ++beyond;
            if (ratio > worst) worst = ratio, worstInput = i;
        }
        std::printf("%-5d %-38s %-12.3e %-12.3e %-12.3g %zu\n", p, pieceName(p), maxRel, maxAbs,
                    worst, beyond);
        if (beyond > 0) {
            const float g = run.gpu[worstInput * kPieces + p];
            const float c = run.cpu[worstInput * kPieces + p];
            ADD_FAILURE() << "piece " << p << " (" << pieceName(p) << "): " << beyond
                          << " outputs beyond tolerance; worst at "
                          << describe(run.inputs[worstInput]) << ": gpu " << number(g) << " cpu "
                          << number(c) << ", |diff| " << number(std::fabs(g - c)) << " = "
                          << ratioText(worst) << " x tolerance";
        }
    }
    std::fflush(stdout);
}

TEST(GpuCpuAgreement, FiniteAndNonNegative) {
    const AgreementRun& run = agreementRun();
    ASSERT_TRUE(run.error.empty()) << run.error;
    for (int p = 0; p < kPieces; ++p) {
        for (const auto& [side, values] :
             {std::pair{"gpu", &run.gpu}, std::pair{"cpu", &run.cpu}}) {
            size_t bad = 0, first = 0;
            for (size_t i = 0; i < run.inputs.size(); ++i) {
                const float v = (*values)[i * kPieces + p];
                if (std::isfinite(v) && v >= 0.0f) continue;
                if (bad++ == 0) first = i;
            }
            if (bad > 0)
                ADD_FAILURE() << side << " piece " << p << " (" << pieceName(p) << "): " << bad
                              << " outputs not finite and >= 0; first at "
                              << describe(run.inputs[first]) << ": gpu "
                              << number(run.gpu[first * kPieces + p]) << " cpu "
                              << number(run.cpu[first * kPieces + p]);
        }
    }
}

TEST(GpuCpuAgreement, NoValidationErrors) {
    const AgreementRun& run = agreementRun();
    ASSERT_TRUE(run.error.empty()) << run.error;
    ASSERT_TRUE(run.validation);
    std::printf("validation layer: %u errors, %u warnings\n", run.validationErrors,
                run.validationWarnings);
    EXPECT_EQ(run.validationErrors, 0u);
}

}  // namespace
