// The GPU scene: the level's geometry, materials, textures and lights, its baked lighting (or
// neutral placeholders) and the colour LUT, uploaded once.
#include <algorithm>
#include <array>
#include <cmath>
#include <cstring>
#include <span>
#include <stdexcept>
#include <tuple>

#include <glm/gtc/packing.hpp>

#include "env_brdf_table.hpp"
#include "render/probe_records.hpp"
#include "render/renderer_state.hpp"
#include "shading.hpp"
#include "world/package/probe_section.hpp"

namespace onelight::render {

namespace {

namespace glsl = onelight::glsl;

// A material's texture indices by slot (TEXTURE_* of gpu_interface.glsl): into the package's
// processed textures when it holds them (the texture stage's mips), else into level.textures.
using TextureSlots = std::array<uint32_t, size_t(glsl::TEXTURE_SLOT_COUNT)>;
TextureSlots textureSlotsOf(const world::Material& m) {
    TextureSlots slots;
    slots.fill(world::kNoIndex);
    slots[glsl::TEXTURE_BASE_COLOR] = m.baseColorTexture;
    slots[glsl::TEXTURE_METALLIC_ROUGHNESS] = m.metallicRoughnessTexture;
    slots[glsl::TEXTURE_NORMAL] = m.normalTexture;
    slots[glsl::TEXTURE_OCCLUSION] = m.occlusionTexture;
    slots[glsl::TEXTURE_EMISSIVE] = m.emissiveTexture;
    return slots;
}

TextureSlots processedSlotsOf(const world::MaterialTextureSlots& m) {
    TextureSlots slots;
    slots[glsl::TEXTURE_BASE_COLOR] = m.baseColor;
    slots[glsl::TEXTURE_METALLIC_ROUGHNESS] = m.metallicRoughness;
    slots[glsl::TEXTURE_NORMAL] = m.normal;
    slots[glsl::TEXTURE_OCCLUSION] = m.occlusion;
    slots[glsl::TEXTURE_EMISSIVE] = m.emissive;
    slots[glsl::TEXTURE_CAVITY] = m.cavity;
    return slots;
}

TextureSlots materialSlots(const assets::LoadedLevel& loaded, size_t material) {
    if (loaded.hasProcessedTextures)
        return processedSlotsOf(loaded.processedTextures.materials.at(material));
    return textureSlotsOf(loaded.level.materials.at(material));
}

// Every slot's placeholder: white, a flat normal for the normal map.
MaterialTextures placeholderTextures(const RendererState& s) {
    MaterialTextures bound;
    for (uint32_t t = 0; t < bound.size(); ++t)
        bound[t] = {int(t) == glsl::TEXTURE_NORMAL ? s.flatNormal.view : s.white.view,
                    s.linearClamp};
    return bound;
}

// A device-local buffer holding `records`.
template <class T>
void createRecordBuffer(const vk::Context& ctx, vk::Buffer& buffer, const std::vector<T>& records,
                        VkBufferUsageFlags usage) {
    vk::createDeviceBuffer(ctx, buffer, vk::bytesOf(std::span<const T>(records)), usage);
}

// A 2D (array) or 3D image of RGBA16F texels given as floats.
void createHalfImage(const vk::Context& ctx, vk::Image& image, vk::ImageDesc desc,
                     const std::vector<float>& rgba) {
    desc.format = VK_FORMAT_R16G16B16A16_SFLOAT;
    desc.usage = VK_IMAGE_USAGE_SAMPLED_BIT | VK_IMAGE_USAGE_TRANSFER_DST_BIT;
    std::vector<uint16_t> halves(rgba.size());
    for (size_t i = 0; i < rgba.size(); ++i) halves[i] = glm::packHalf1x16(rgba[i]);
    vk::createImage(ctx, image, desc);
    vk::uploadImage(ctx, image,
                    {reinterpret_cast<const uint8_t*>(halves.data()), halves.size() * 2});
}

uint32_t mipCount(uint32_t width, uint32_t height) {
    uint32_t levels = 1;
    while ((width | height) >> levels) ++levels;
    return levels;
}

VkSamplerAddressMode addressMode(uint16_t wrap) {
    if (wrap == 33071) return VK_SAMPLER_ADDRESS_MODE_CLAMP_TO_EDGE;
    if (wrap == 33648) return VK_SAMPLER_ADDRESS_MODE_MIRRORED_REPEAT;
    return VK_SAMPLER_ADDRESS_MODE_REPEAT;
}

// glTF/GL filter enums: 9728 NEAREST, 9729 LINEAR, 9984..9987 the mipmap variants.
vk::SamplerDesc samplerDesc(const world::Sampler& sampler) {
    vk::SamplerDesc d;
    d.magFilter = sampler.magFilter == 9728 ? VK_FILTER_NEAREST : VK_FILTER_LINEAR;
    switch (sampler.minFilter) {
        case 9728:  // NEAREST: no mips
            d.minFilter = VK_FILTER_NEAREST;
            d.maxLod = 0.0f;
            break;
        case 9729:  // LINEAR: no mips
            d.maxLod = 0.0f;
            break;
        case 9984:  // NEAREST_MIPMAP_NEAREST
            d.minFilter = VK_FILTER_NEAREST;
            d.mipmapMode = VK_SAMPLER_MIPMAP_MODE_NEAREST;
            break;
        case 9985:  // LINEAR_MIPMAP_NEAREST
            d.mipmapMode = VK_SAMPLER_MIPMAP_MODE_NEAREST;
            break;
        case 9986:  // NEAREST_MIPMAP_LINEAR
            d.minFilter = VK_FILTER_NEAREST;
            break;
        default:  // 9987 LINEAR_MIPMAP_LINEAR, or unspecified
            break;
    }
    d.addressU = addressMode(sampler.wrapS);
    d.addressV = addressMode(sampler.wrapT);
    return d;
}

// The illuminance the sky gives an open floor (lux): pi L for a uniform sky, the upper rows of
// a sky image x cos(theta) x their solid angle (shaders/sky.glsl's mapping) for an image.
float skyIlluminance(const world::LevelSettings& settings, const world::HdrImage& sky) {
    if (sky.width == 0 || sky.height == 0) return glsl::PI * glsl::luminance(settings.skyRadiance);
    double e = 0.0;
    for (uint32_t i = 0; i < sky.height / 2; ++i) {
        const double pi = double(glsl::PI);
        const double t0 = pi * double(i) / sky.height, t1 = pi * (i + 1.0) / sky.height;
        // int cos sin over the row's theta, times its phi width 2 pi / W:
        const double weight = 0.5 * (std::sin(t1) * std::sin(t1) - std::sin(t0) * std::sin(t0)) *
                              (2.0 * pi / sky.width);
        for (uint32_t j = 0; j < sky.width; ++j) {
            const size_t t = (size_t(i) * sky.width + j) * 3;
            e += weight *
                 double(glsl::luminance(glm::vec3(sky.rgb[t], sky.rgb[t + 1], sky.rgb[t + 2]) *
                                        settings.skyRadiance));
        }
    }
    return float(e);
}

// The brightest primary's illuminance at the level centre, or the sky's on an open floor when
// brighter (lux): what automatic exposure and the automatic placeholder ambient are based on.
float referenceIlluminance(const RendererState& s, const world::HdrImage& sky) {
    const glm::vec3 centre = 0.5f * (s.boundsMin + s.boundsMax);
    float best = 0.0f;
    for (const world::Light& light : s.lights) {
        if (light.role != world::LightRole::kPrimary) continue;
        float e = light.intensity * glsl::luminance(light.color);
        if (light.type != world::LightType::kDirectional) {
            const glm::vec3 d = centre - light.position;
            e /= std::max(glm::dot(d, d), 1.0f);
        }
        best = std::max(best, e);
    }
    return std::max(best, skyIlluminance(s.settings, sky));
}

uint32_t textureFor(RendererState& s, const assets::LoadedLevel& loaded, uint32_t textureIndex,
                    bool srgb) {
    const world::Texture& texture = loaded.level.textures.at(textureIndex);
    // Out of range, or the sky's image (decoded apart, as HDR): no material texture.
    if (texture.image >= loaded.images.size() || loaded.images[texture.image].width == 0)
        return kNoIndex;
    const uint64_t key = (uint64_t(texture.image) << 1) | (srgb ? 1u : 0u);
    auto found = s.textureIndex.find(key);
    if (found != s.textureIndex.end()) return found->second;
    const world::DecodedImage& decoded = loaded.images[texture.image];
    vk::ImageDesc desc;
    desc.format = srgb ? VK_FORMAT_R8G8B8A8_SRGB : VK_FORMAT_R8G8B8A8_UNORM;
    desc.width = decoded.width;
    desc.height = decoded.height;
    desc.mipLevels = mipCount(decoded.width, decoded.height);
    desc.usage = VK_IMAGE_USAGE_SAMPLED_BIT | VK_IMAGE_USAGE_TRANSFER_DST_BIT |
                 VK_IMAGE_USAGE_TRANSFER_SRC_BIT;
    s.textures.emplace_back();
    vk::createImage(*s.ctx, s.textures.back(), desc);
    vk::uploadImage(*s.ctx, s.textures.back(), decoded.rgba);
    const uint32_t index = uint32_t(s.textures.size() - 1);
    s.textureIndex[key] = index;
    return index;
}

VkFormat formatOf(world::TexelFormat format) {
    switch (format) {
        case world::TexelFormat::kRgba8Srgb:
            return VK_FORMAT_R8G8B8A8_SRGB;
        case world::TexelFormat::kRgba8Unorm:
            return VK_FORMAT_R8G8B8A8_UNORM;
        case world::TexelFormat::kR8Unorm:
            return VK_FORMAT_R8_UNORM;
    }
    return VK_FORMAT_R8G8B8A8_UNORM;
}

// The processed texture `index` uploaded with its own mips (the package checked their sizes),
// once.
uint32_t processedTextureFor(RendererState& s, const assets::LoadedLevel& loaded, uint32_t index) {
    const uint64_t key = (uint64_t(1) << 63) | index;
    auto found = s.textureIndex.find(key);
    if (found != s.textureIndex.end()) return found->second;
    const world::ProcessedTexture& texture = loaded.processedTextures.textures.at(index);
    vk::ImageDesc desc;
    desc.format = formatOf(texture.format);
    desc.width = texture.width;
    desc.height = texture.height;
    desc.mipLevels = texture.mipCount;
    desc.usage = VK_IMAGE_USAGE_SAMPLED_BIT | VK_IMAGE_USAGE_TRANSFER_DST_BIT;
    s.textures.emplace_back();
    vk::createImage(*s.ctx, s.textures.back(), desc);
    vk::uploadImageMips(*s.ctx, s.textures.back(), texture.texels);
    const uint32_t uploaded = uint32_t(s.textures.size() - 1);
    s.textureIndex[key] = uploaded;
    return uploaded;
}

VkSampler samplerFor(RendererState& s, const world::Sampler& sampler) {
    const uint64_t key = uint64_t(sampler.magFilter) | uint64_t(sampler.minFilter) << 16 |
                         uint64_t(sampler.wrapS) << 32 | uint64_t(sampler.wrapT) << 48;
    auto found = s.samplers.find(key);
    if (found != s.samplers.end()) return found->second;
    vk::SamplerDesc desc = samplerDesc(sampler);
    // Anisotropy only where there are mips to choose from (NEAREST and LINEAR have none).
    if (desc.maxLod != 0.0f)
        desc.maxAnisotropy =
            std::min(s.options.anisotropy, s.ctx->properties.limits.maxSamplerAnisotropy);
    VkSampler created = vk::createSampler(*s.ctx, desc);
    s.samplers[key] = created;
    return created;
}

void uploadGeometry(RendererState& s, const world::CompiledLevel& level) {
    // Static vertices, then dynamic ones; static indices, then dynamic ones. The static
    // surfaces' indices are laid out grouped by what their draws bind and push (material,
    // primary, lightmap atlas), in the level's order within a group, so that the surfaces a
    // view keeps of one group lie side by side and batchDraws merges them into few draws.
    std::vector<world::Vertex> vertices = level.vertices;
    vertices.insert(vertices.end(), level.dynamicVertices.begin(), level.dynamicVertices.end());
    std::vector<uint32_t> order(level.surfaces.size());
    for (uint32_t i = 0; i < order.size(); ++i) order[i] = i;
    std::stable_sort(order.begin(), order.end(), [&](uint32_t a, uint32_t b) {
        const world::Surface &x = level.surfaces[a], &y = level.surfaces[b];
        return std::tie(x.material, x.primaryLight, x.atlas) <
               std::tie(y.material, y.primaryLight, y.atlas);
    });
    std::vector<uint32_t> indices;
    indices.reserve(level.indices.size() + level.dynamicIndices.size());
    std::vector<uint32_t> firstIndex(level.surfaces.size(), 0);
    uint64_t covered = 0;
    for (const world::Surface& surface : level.surfaces) covered += surface.indexCount;
    if (covered == level.indices.size()) {
        for (uint32_t i : order) {
            const world::Surface& surface = level.surfaces[i];
            firstIndex[i] = uint32_t(indices.size());
            indices.insert(indices.end(), level.indices.begin() + surface.firstIndex,
                           level.indices.begin() + surface.firstIndex + surface.indexCount);
        }
    } else {  // surfaces that share or skip indices (not what the compiler writes): as stored
        indices = level.indices;
        for (uint32_t i = 0; i < level.surfaces.size(); ++i)
            firstIndex[i] = level.surfaces[i].firstIndex;
    }
    indices.insert(indices.end(), level.dynamicIndices.begin(), level.dynamicIndices.end());
    createRecordBuffer(*s.ctx, s.vertices, vertices, VK_BUFFER_USAGE_VERTEX_BUFFER_BIT);
    createRecordBuffer(*s.ctx, s.indices, indices, VK_BUFFER_USAGE_INDEX_BUFFER_BIT);

    for (uint32_t i = 0; i < level.surfaces.size(); ++i) {
        const world::Surface& surface = level.surfaces[i];
        DrawSurface d;
        d.firstIndex = firstIndex[i];
        d.indexCount = surface.indexCount;
        d.material = surface.material;
        d.primaryLight = surface.primaryLight;
        d.atlas = surface.atlas;
        d.boundsMin = surface.boundsMin;
        d.boundsMax = surface.boundsMax;
        s.surfaces.push_back(d);
    }
    const uint32_t staticVertices = uint32_t(level.vertices.size());
    const uint32_t staticIndices = uint32_t(level.indices.size());
    for (uint32_t e = 0; e < level.entities.size(); ++e) {
        const world::Entity& entity = level.entities[e];
        if (!(entity.flags & world::kEntityDynamic)) continue;
        for (uint32_t k = 0; k < entity.dynamicMeshCount; ++k) {
            const world::DynamicMesh& mesh = level.dynamicMeshes.at(entity.firstDynamicMesh + k);
            if (mesh.indexCount == 0) continue;
            DrawDynamicMesh d;
            d.entity = e;
            d.firstIndex = staticIndices + mesh.firstIndex;
            d.indexCount = mesh.indexCount;
            d.vertexOffset = int32_t(staticVertices + mesh.firstVertex);
            d.material = mesh.material;
            d.boundsMin = glm::vec3(1e30f);
            d.boundsMax = glm::vec3(-1e30f);
            for (uint32_t v = 0; v < mesh.vertexCount; ++v) {
                const glm::vec3 p = level.dynamicVertices[mesh.firstVertex + v].position;
                d.boundsMin = glm::min(d.boundsMin, p);
                d.boundsMax = glm::max(d.boundsMax, p);
            }
            s.dynamicMeshes.push_back(d);
        }
    }
}

void uploadMaterials(RendererState& s, const assets::LoadedLevel& loaded) {
    const world::CompiledLevel& level = loaded.level;
    std::vector<GpuMaterial> gpu(std::max<size_t>(level.materials.size(), 1));
    s.diffuseModel = int(level.settings.diffuseModel);
    for (size_t i = 0; i < level.materials.size(); ++i) {
        const world::Material& m = level.materials[i];
        GpuMaterial& g = gpu[i];
        g.baseColor = m.baseColor;
        g.f0Gloss = glm::vec4(m.specularColor, m.gloss);
        g.emissive = glm::vec4(m.emissive, m.alphaCutoff);
        g.params = glm::vec4(m.metallic, m.roughness, m.normalScale, m.occlusionStrength);
        // Factors the texture stage folded into the textures read as 1.
        if (loaded.hasProcessedTextures) {
            const world::TextureFactors f =
                world::textureFactors(m, loaded.processedTextures.materials.at(i));
            g.params = glm::vec4(f.metallic, f.roughness, f.normalScale, m.occlusionStrength);
        }
        uint32_t bits = 0;
        const TextureSlots slots = materialSlots(loaded, i);
        for (uint32_t t = 0; t < slots.size(); ++t)
            if (slots[t] != world::kNoIndex) bits |= 1u << t;
        g.textures = glm::uvec4(bits, 0u, 0u, 0u);
        uint8_t cls = uint8_t(m.materialClass);
        if (s.options.forceMaterialClass >= 0) cls = uint8_t(s.options.forceMaterialClass);
        s.materialClasses.push_back(cls);
        s.materialDoubleSided.push_back(m.doubleSided ? 1 : 0);
        s.materialAlphaMask.push_back(m.alphaMode == world::AlphaMode::kMask ? 1 : 0);
    }
    if (level.materials.empty()) {
        gpu[0].baseColor = glm::vec4(0.8f, 0.8f, 0.8f, 1.0f);
        gpu[0].params = glm::vec4(0.0f, 1.0f, 1.0f, 1.0f);
    }
    createRecordBuffer(*s.ctx, s.materialBuffer, gpu, VK_BUFFER_USAGE_STORAGE_BUFFER_BIT);
}

void createPlaceholders(RendererState& s) {
    vk::ImageDesc desc;
    desc.usage = VK_IMAGE_USAGE_SAMPLED_BIT | VK_IMAGE_USAGE_TRANSFER_DST_BIT;
    const uint8_t white[4] = {255, 255, 255, 255};
    const uint8_t flat[4] = {128, 128, 255, 255};
    vk::createImage(*s.ctx, s.white, desc);
    vk::uploadImage(*s.ctx, s.white, white);
    vk::createImage(*s.ctx, s.flatNormal, desc);
    vk::uploadImage(*s.ctx, s.flatNormal, flat);
}

// The largest power of two 2^-k (k >= 0) that keeps every stored lightmap coefficient within
// kLightmapStoredMax: RGBA16F tops out at 65504 and the sun's secondary can pass 100 klx.
constexpr float kLightmapStoredMax = 32768.0f;
float lightmapStorageScale(const world::BakedLighting& baked) {
    float largest = 0.0f;  // c0 = E / (2 w) bounds |c0| and |c.xyz| (|d| <= 0.5)
    for (const world::LightmapTexel& t : baked.texels)
        for (int c = 0; c < 3; ++c)
            largest = std::max(largest, world::linearIrradianceCoefficients(t, c).x);
    float scale = 1.0f;
    while (largest * scale > kLightmapStoredMax) scale *= 0.5f;
    return scale;
}

// Lightmaps and shadow masks of a baked level: every atlas a layer range of one 2D array as large
// as the largest atlas (a smaller atlas sits at the top-left; atlasUvScale maps its uv1). The
// lightmap holds, per atlas and colour channel, the four linear coefficients of
// world::linearIrradianceCoefficients in RGBA16F times a power-of-two storage scale; the shadow
// mask its byte per texel in the red channel of RGBA8 (linear filtering is guaranteed for both).
void uploadLightmaps(RendererState& s, const assets::LoadedLevel& loaded) {
    const world::CompiledLevel& level = loaded.level;
    const world::BakedLighting& baked = loaded.baked;
    uint32_t width = 1, height = 1;
    for (const world::Atlas& a : level.atlases) {
        width = std::max(width, a.width);
        height = std::max(height, a.height);
    }
    const uint32_t atlases = std::max<uint32_t>(uint32_t(level.atlases.size()), 1);
    const float scale = lightmapStorageScale(baked);
    s.lightmapDecode = 1.0f / scale;
    const size_t layerTexels = size_t(width) * height;
    std::vector<uint16_t> coefficients(layerTexels * 4 * 3 * atlases, 0);
    std::vector<uint8_t> mask(layerTexels * 4 * atlases, 0);
    s.atlasUvScale.clear();
    for (uint32_t a = 0; a < level.atlases.size(); ++a) {
        const world::Atlas& atlas = level.atlases[a];
        s.atlasUvScale.push_back(
            glm::vec2(float(atlas.width) / float(width), float(atlas.height) / float(height)));
        const uint64_t first = world::atlasTexelOffset(level, a);
        for (uint32_t y = 0; y < atlas.height; ++y)
            for (uint32_t x = 0; x < atlas.width; ++x) {
                const uint64_t texel = first + uint64_t(y) * atlas.width + x;
                const size_t at = size_t(y) * width + x;
                for (int c = 0; c < 3; ++c) {
                    const glm::vec4 k =
                        world::linearIrradianceCoefficients(baked.texels[texel], c) * scale;
                    uint16_t* out = &coefficients[((size_t(a) * 3 + c) * layerTexels + at) * 4];
                    for (int i = 0; i < 4; ++i) out[i] = glm::packHalf1x16(k[i]);
                }
                uint8_t* m = &mask[(size_t(a) * layerTexels + at) * 4];
                m[0] = m[1] = m[2] = baked.shadowMask[texel];
                m[3] = 255;
            }
    }
    vk::ImageDesc desc;
    desc.width = width;
    desc.height = height;
    desc.layers = 3 * atlases;
    desc.viewType = VK_IMAGE_VIEW_TYPE_2D_ARRAY;
    desc.format = VK_FORMAT_R16G16B16A16_SFLOAT;
    desc.usage = VK_IMAGE_USAGE_SAMPLED_BIT | VK_IMAGE_USAGE_TRANSFER_DST_BIT;
    vk::createImage(*s.ctx, s.lightmap, desc);
    vk::uploadImage(*s.ctx, s.lightmap,
                    {reinterpret_cast<const uint8_t*>(coefficients.data()),
                     coefficients.size() * sizeof(uint16_t)});
    desc.layers = atlases;
    desc.format = VK_FORMAT_R8G8B8A8_UNORM;
    vk::createImage(*s.ctx, s.shadowMask, desc);
    vk::uploadImage(*s.ctx, s.shadowMask, mask);
}

// The environment probes: every probe's RGB9E5 texels, as baked, in one cube array (cube i for
// record i of makeProbeRecords' order). The package's texel order (per probe: mips from the
// largest, each six faces of rows) becomes the upload's (per mip: every probe's six faces).
// Without probes (or with options.probes off) one neutral cube: a uniform environment of
// normalised radiance 1 / pi (its irradiance is its average: a uniform environment of L gives
// E = pi L) behind a record that influences everything.
void uploadProbes(RendererState& s, const assets::LoadedLevel& loaded) {
    const std::vector<world::EnvironmentProbe>& probes = loaded.baked.probes;
    vk::ImageDesc desc;
    desc.cube = true;
    desc.viewType = VK_IMAGE_VIEW_TYPE_CUBE_ARRAY;
    desc.usage = VK_IMAGE_USAGE_SAMPLED_BIT | VK_IMAGE_USAGE_TRANSFER_DST_BIT;
    std::vector<GpuProbe> records;
    if (s.bakedLighting && s.options.probes && !probes.empty()) {
        const uint32_t size = probes[0].faceSize;
        for (size_t i = 0; i < probes.size(); ++i) {
            if (probes[i].faceSize != size || probes[i].mipCount != probes[0].mipCount)
                throw std::runtime_error("probe " + std::to_string(i) + " has face size " +
                                         std::to_string(probes[i].faceSize) + "; expected " +
                                         std::to_string(size) + " like probe 0 (one cube array)");
            const uint32_t mips = probes[i].mipCount;
            const bool chain = size != 0 && mips >= 1 && mips <= 32 && (size >> (mips - 1)) == 1;
            if (!chain || probes[i].texels.size() != world::probeTexelCount(size))
                throw std::runtime_error("probe " + std::to_string(i) + " holds " +
                                         std::to_string(probes[i].texels.size()) +
                                         " texels; expected every mip of a " +
                                         std::to_string(size) + "^2 cube down to 1x1");
        }
        const uint32_t maxProbes = s.ctx->properties.limits.maxImageArrayLayers / 6;
        if (probes.size() > maxProbes)
            throw std::runtime_error(std::to_string(probes.size()) + " environment probes; this " +
                                     "device holds at most " + std::to_string(maxProbes) +
                                     " (maxImageArrayLayers " + std::to_string(maxProbes * 6) +
                                     " / 6 faces)");
        const ProbeRecords ordered = makeProbeRecords(probes, s.boundsMin, s.boundsMax);
        records = ordered.records;
        desc.format = VK_FORMAT_E5B9G9R9_UFLOAT_PACK32;
        desc.width = desc.height = size;
        desc.mipLevels = probes[0].mipCount;
        desc.layers = 6 * uint32_t(probes.size());
        std::vector<uint32_t> texels;
        texels.reserve(probes.size() * probes[0].texels.size());
        size_t mipStart = 0;
        for (uint32_t mip = 0; mip < desc.mipLevels; ++mip) {
            const size_t mipTexels = 6 * size_t(size >> mip) * (size >> mip);
            for (uint32_t p : ordered.order)
                texels.insert(texels.end(), probes[p].texels.begin() + long(mipStart),
                              probes[p].texels.begin() + long(mipStart + mipTexels));
            mipStart += mipTexels;
        }
        vk::createImage(*s.ctx, s.probe, desc);
        vk::uploadImageMips(*s.ctx, s.probe,
                            {reinterpret_cast<const uint8_t*>(texels.data()), texels.size() * 4});
        s.info.probes = uint32_t(probes.size());
        s.info.probeBytes = texels.size() * 4;
    } else {
        records = {placeholderProbeRecord()};
        desc.layers = 6;
        std::vector<float> faces;
        for (int f = 0; f < 6; ++f)
            for (int c = 0; c < 4; ++c) faces.push_back(c < 3 ? float(glsl::INV_PI) : 1.0f);
        createHalfImage(*s.ctx, s.probe, desc, faces);
        s.info.probes = 0;
        s.info.probeBytes = 0;
    }
    s.probeCount = uint32_t(records.size());
    s.probeMips = s.probe.desc.mipLevels;
    createRecordBuffer(*s.ctx, s.probeBuffer, records, VK_BUFFER_USAGE_STORAGE_BUFFER_BIT);
    const ProbeCells cells = makeProbeCells(records, s.boundsMin, s.boundsMax);
    std::vector<uint32_t> cellWords(sizeof(GpuProbeGrid) / 4);
    std::memcpy(cellWords.data(), &cells.grid, sizeof(GpuProbeGrid));
    cellWords.insert(cellWords.end(), cells.words.begin(), cells.words.end());
    createRecordBuffer(*s.ctx, s.probeCellBuffer, cellWords, VK_BUFFER_USAGE_STORAGE_BUFFER_BIT);
}

// The baked-lighting interface: the package's lightmaps, shadow masks and light grid, or
// neutral content for a level without them (a constant ambient of ambientLux, no baked shadow)
// that the placeholder-fetching test permutation reads.
void uploadBakedLighting(RendererState& s, const assets::LoadedLevel& loaded) {
    s.bakedLighting = loaded.hasBakedLighting;
    if (s.bakedLighting) {
        uploadLightmaps(s, loaded);
        s.grid = loaded.baked.grid;
        s.visibility = loaded.baked.visibility;
    } else {
        const float a = s.ambientLux;
        vk::ImageDesc lm;
        lm.layers = 3;
        lm.viewType = VK_IMAGE_VIEW_TYPE_2D_ARRAY;
        createHalfImage(*s.ctx, s.lightmap, lm,
                        {a, 0.0f, 0.0f, 0.0f, a, 0.0f, 0.0f, 0.0f, a, 0.0f, 0.0f, 0.0f});
        vk::ImageDesc mask;
        mask.viewType = VK_IMAGE_VIEW_TYPE_2D_ARRAY;
        createHalfImage(*s.ctx, s.shadowMask, mask, {1.0f, 1.0f, 1.0f, 1.0f});
        s.lightmapDecode = 1.0f;
        s.atlasUvScale.assign(loaded.level.atlases.size(), glm::vec2(1.0f));
        s.grid = world::LightGrid{};
        s.visibility = world::Visibility{};
    }
    s.info.bakedLighting = s.bakedLighting;
    s.info.lightmapDecode = s.lightmapDecode;
    uploadProbes(s, loaded);
}

// The colour LUT: filmic curve and sRGB encoding at the shaper's texel centres.
void createLut(RendererState& s) {
    std::vector<float> texels;
    texels.reserve(size_t(kLutSize) * kLutSize * kLutSize * 4);
    float curve[kLutSize];
    for (uint32_t i = 0; i < kLutSize; ++i)
        curve[i] =
            glsl::displayValue(glsl::linear_fromLutCoordinate(float(i) / float(kLutSize - 1)));
    for (uint32_t b = 0; b < kLutSize; ++b)
        for (uint32_t g = 0; g < kLutSize; ++g)
            for (uint32_t r = 0; r < kLutSize; ++r) {
                texels.push_back(curve[r]);
                texels.push_back(curve[g]);
                texels.push_back(curve[b]);
                texels.push_back(1.0f);
            }
    vk::ImageDesc desc;
    desc.width = desc.height = desc.depth = kLutSize;
    createHalfImage(*s.ctx, s.lut, desc, texels);
}

// The split-sum table of the runtime model (shaders/lighting.glsl, env_brdf_table.hpp): the
// lobe's albedo integrated at the grid points, read at envBrdfTableCoord; one fetch.
void createEnvBrdfTable(RendererState& s) {
    std::vector<float> texels;
    for (uint32_t t = 0; t < glsl::kEnvBrdfTableSize * glsl::kEnvBrdfTableSize; ++t)
        texels.insert(texels.end(),
                      {glsl::kEnvBrdfTable[2 * t], glsl::kEnvBrdfTable[2 * t + 1], 0.0f, 1.0f});
    vk::ImageDesc desc;
    desc.width = desc.height = glsl::kEnvBrdfTableSize;
    createHalfImage(*s.ctx, s.envBrdf, desc, texels);
}

// The sky image at full resolution (its light is already in the baked lighting; here it is
// only seen), linear RGB in half floats, clamped to their range; one black texel without one.
void uploadSky(RendererState& s, const assets::LoadedLevel& loaded) {
    const world::HdrImage& sky = loaded.sky;
    s.skyImage = sky.width > 0 && sky.height > 0;
    vk::ImageDesc desc;
    desc.width = s.skyImage ? sky.width : 1;
    desc.height = s.skyImage ? sky.height : 1;
    std::vector<float> texels(size_t(desc.width) * desc.height * 4, 0.0f);
    if (s.skyImage)
        for (size_t t = 0; t < size_t(sky.width) * sky.height; ++t)
            for (size_t c = 0; c < 3; ++c)
                texels[4 * t + c] = std::min(sky.rgb[3 * t + c], glsl::HDR_MAX);
    createHalfImage(*s.ctx, s.sky, desc, texels);
    vk::SamplerDesc wrapU;
    wrapU.addressU = VK_SAMPLER_ADDRESS_MODE_REPEAT;
    wrapU.addressV = wrapU.addressW = VK_SAMPLER_ADDRESS_MODE_CLAMP_TO_EDGE;
    s.skySampler = vk::createSampler(*s.ctx, wrapU);
    s.info.skyImage = s.skyImage;
}

}  // namespace

void uploadLights(RendererState& s) {
    std::vector<GpuLight> gpu;
    for (uint32_t i = 0; i < s.lights.size(); ++i) {
        const uint32_t slot = s.lightSlot.at(i);
        gpu.push_back(
            gpuLightOf(s.lights[i], slot == kNoIndex ? kNoIndex : s.slots[slot].firstView));
    }
    if (gpu.empty()) gpu.emplace_back();  // a binding needs a record
    createRecordBuffer(*s.ctx, s.lightBuffer, gpu, VK_BUFFER_USAGE_STORAGE_BUFFER_BIT);
}

void uploadScene(RendererState& s, const assets::LoadedLevel& loaded) {
    const world::CompiledLevel& level = loaded.level;
    s.settings = level.settings;
    s.lights = level.lights;
    s.entities = level.entities;
    s.boundsMin = level.settings.boundsMin;
    s.boundsMax = level.settings.boundsMax;
    for (const world::Entity& e : level.entities) {  // dynamic objects widen the bounds
        s.boundsMin = glm::min(s.boundsMin, e.position);
        s.boundsMax = glm::max(s.boundsMax, e.position);
    }
    s.drawnPrimary.assign(level.entities.size(), kNoIndex);

    const float reference = referenceIlluminance(s, loaded.sky);
    s.ambientLux = s.options.placeholderAmbientLux >= 0.0f
                       ? s.options.placeholderAmbientLux
                       : (reference > 0.0f ? 0.1f * reference : 1.0f);
    s.info.ambientLux = s.ambientLux;
    s.info.autoEv100 = glsl::ev100_fromIlluminance(reference > 0.0f ? reference : s.ambientLux);

    vk::SamplerDesc clamp;
    clamp.addressU = clamp.addressV = clamp.addressW = VK_SAMPLER_ADDRESS_MODE_CLAMP_TO_EDGE;
    s.linearClamp = vk::createSampler(*s.ctx, clamp);
    clamp.magFilter = clamp.minFilter = VK_FILTER_NEAREST;
    clamp.mipmapMode = VK_SAMPLER_MIPMAP_MODE_NEAREST;
    s.nearestClamp = vk::createSampler(*s.ctx, clamp);

    uploadGeometry(s, level);
    uploadMaterials(s, loaded);
    createPlaceholders(s);
    uploadBakedLighting(s, loaded);
    createLut(s);
    createEnvBrdfTable(s);
    uploadSky(s, loaded);

    // Material textures: (image, sampler) per slot, placeholders where absent.
    s.materialTextures.clear();
    for (size_t i = 0; i < level.materials.size(); ++i) {
        const TextureSlots slots = materialSlots(loaded, i);
        MaterialTextures bound = placeholderTextures(s);
        for (uint32_t t = 0; t < slots.size(); ++t) {
            if (slots[t] == world::kNoIndex) continue;
            if (loaded.hasProcessedTextures) {
                const uint32_t image = processedTextureFor(s, loaded, slots[t]);
                bound[t] = {s.textures[image].view,
                            samplerFor(s, loaded.processedTextures.textures[slots[t]].sampler)};
                continue;
            }
            const bool srgb =
                int(t) == glsl::TEXTURE_BASE_COLOR || int(t) == glsl::TEXTURE_EMISSIVE;
            const uint32_t image = textureFor(s, loaded, slots[t], srgb);
            if (image == kNoIndex) continue;
            bound[t] = {s.textures[image].view, samplerFor(s, level.textures.at(slots[t]).sampler)};
        }
        s.materialTextures.push_back(bound);
    }
    if (s.materialTextures.empty()) {
        s.materialTextures.push_back(placeholderTextures(s));
        s.materialClasses.push_back(
            uint8_t(s.options.forceMaterialClass >= 0 ? s.options.forceMaterialClass : 3));
        s.materialDoubleSided.push_back(0);
        s.materialAlphaMask.push_back(0);
    }
}

void destroyScene(RendererState& s) {
    const vk::Context& ctx = *s.ctx;
    if (s.nearestClamp) vkDestroySampler(ctx.device, s.nearestClamp, nullptr);
    if (s.linearClamp) vkDestroySampler(ctx.device, s.linearClamp, nullptr);
    s.nearestClamp = s.linearClamp = VK_NULL_HANDLE;
    vk::destroyImage(ctx, s.envBrdf);
    vk::destroyImage(ctx, s.sky);
    if (s.skySampler) vkDestroySampler(ctx.device, s.skySampler, nullptr);
    s.skySampler = VK_NULL_HANDLE;
    vk::destroyImage(ctx, s.lut);
    vk::destroyImage(ctx, s.shadowMask);
    vk::destroyImage(ctx, s.lightmap);
    vk::destroyImage(ctx, s.probe);
    vk::destroyBuffer(ctx, s.probeBuffer);
    vk::destroyBuffer(ctx, s.probeCellBuffer);
    vk::destroyImage(ctx, s.flatNormal);
    vk::destroyImage(ctx, s.white);
    for (auto& [key, sampler] : s.samplers) vkDestroySampler(ctx.device, sampler, nullptr);
    s.samplers.clear();
    for (auto it = s.textures.rbegin(); it != s.textures.rend(); ++it) vk::destroyImage(ctx, *it);
    s.textures.clear();
    s.textureIndex.clear();
    vk::destroyBuffer(ctx, s.materialBuffer);
    vk::destroyBuffer(ctx, s.lightBuffer);
    vk::destroyBuffer(ctx, s.indices);
    vk::destroyBuffer(ctx, s.vertices);
}

}  // namespace onelight::render
