// The GPU scene: the level's geometry, materials, textures and lights, its baked lighting (or
// neutral placeholders) and the colour LUT, uploaded once.
#include "render/scene.hpp"

#include <algorithm>
#include <array>
#include <cfloat>
#include <cmath>
#include <cstring>
#include <span>
#include <stdexcept>
#include <tuple>

#include <glm/gtc/packing.hpp>

#include "env_brdf_table.hpp"
#include "render/frame_view.hpp"
#include "render/probe_records.hpp"
#include "shading.hpp"
#include "world/package/probe_section.hpp"
#include "world/surface_shadow.hpp"

namespace onelight::render {

namespace {

namespace glsl = onelight::glsl;

constexpr uint32_t kLutSize = 64;

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
    slots[glsl::TEXTURE_FACETS] = m.facets;
    return slots;
}

TextureSlots materialSlots(const assets::LoadedLevel& loaded, size_t material) {
    if (loaded.hasProcessedTextures)
        return processedSlotsOf(loaded.processedTextures.materials.at(material));
    return textureSlotsOf(loaded.level.materials.at(material));
}

// Every slot's placeholder: white, a flat normal for the normal map.
MaterialTextures placeholderTextures(const SceneMaterials& materials, VkSampler linearClamp) {
    MaterialTextures bound;
    for (uint32_t t = 0; t < bound.size(); ++t)
        bound[t] = {
            int(t) == glsl::TEXTURE_NORMAL ? materials.flatNormal.view : materials.white.view,
            linearClamp};
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
float referenceIlluminance(const LevelData& level, const world::HdrImage& sky) {
    const glm::vec3 centre = 0.5f * (level.boundsMin + level.boundsMax);
    float best = 0.0f;
    for (const world::Light& light : level.lights) {
        if (light.role != world::LightRole::kPrimary) continue;
        float e = light.intensity * glsl::luminance(light.color);
        if (light.type != world::LightType::kDirectional) {
            const glm::vec3 d = centre - light.position;
            e /= std::max(glm::dot(d, d), 1.0f);
        }
        best = std::max(best, e);
    }
    return std::max(best, skyIlluminance(level.settings, sky));
}

uint32_t textureFor(const vk::Context& ctx, SceneMaterials& materials,
                    const assets::LoadedLevel& loaded, uint32_t textureIndex, bool srgb) {
    const world::Texture& texture = loaded.level.textures.at(textureIndex);
    // Out of range, or the sky's image (decoded apart, as HDR): no material texture.
    if (texture.image >= loaded.images.size() || loaded.images[texture.image].width == 0)
        return kNoIndex;
    const uint64_t key = (uint64_t(texture.image) << 1) | (srgb ? 1u : 0u);
    auto found = materials.textureIndex.find(key);
    if (found != materials.textureIndex.end()) return found->second;
    const world::DecodedImage& decoded = loaded.images[texture.image];
    vk::ImageDesc desc;
    desc.format = srgb ? VK_FORMAT_R8G8B8A8_SRGB : VK_FORMAT_R8G8B8A8_UNORM;
    desc.width = decoded.width;
    desc.height = decoded.height;
    desc.mipLevels = mipCount(decoded.width, decoded.height);
    desc.usage = VK_IMAGE_USAGE_SAMPLED_BIT | VK_IMAGE_USAGE_TRANSFER_DST_BIT |
                 VK_IMAGE_USAGE_TRANSFER_SRC_BIT;
    materials.textures.emplace_back();
    vk::createImage(ctx, materials.textures.back(), desc);
    vk::uploadImage(ctx, materials.textures.back(), decoded.rgba);
    const uint32_t index = uint32_t(materials.textures.size() - 1);
    materials.textureIndex[key] = index;
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
        case world::TexelFormat::kR16Float:
            return VK_FORMAT_R16_SFLOAT;
    }
    return VK_FORMAT_R8G8B8A8_UNORM;
}

// The processed texture `index` uploaded with its own mips (the package checked their sizes),
// once.
uint32_t processedTextureFor(const vk::Context& ctx, SceneMaterials& materials,
                             const assets::LoadedLevel& loaded, uint32_t index) {
    const uint64_t key = (uint64_t(1) << 63) | index;
    auto found = materials.textureIndex.find(key);
    if (found != materials.textureIndex.end()) return found->second;
    const world::ProcessedTexture& texture = loaded.processedTextures.textures.at(index);
    vk::ImageDesc desc;
    desc.format = formatOf(texture.format);
    desc.width = texture.width;
    desc.height = texture.height;
    desc.mipLevels = texture.mipCount;
    desc.usage = VK_IMAGE_USAGE_SAMPLED_BIT | VK_IMAGE_USAGE_TRANSFER_DST_BIT;
    materials.textures.emplace_back();
    vk::createImage(ctx, materials.textures.back(), desc);
    vk::uploadImageMips(ctx, materials.textures.back(), texture.texels);
    const uint32_t uploaded = uint32_t(materials.textures.size() - 1);
    materials.textureIndex[key] = uploaded;
    return uploaded;
}

VkSampler samplerFor(const vk::Context& ctx, SceneMaterials& materials,
                     const world::Sampler& sampler, float anisotropy) {
    const uint64_t key = uint64_t(sampler.magFilter) | uint64_t(sampler.minFilter) << 16 |
                         uint64_t(sampler.wrapS) << 32 | uint64_t(sampler.wrapT) << 48;
    auto found = materials.samplers.find(key);
    if (found != materials.samplers.end()) return found->second;
    vk::SamplerDesc desc = samplerDesc(sampler);
    // Anisotropy only where there are mips to choose from (NEAREST and LINEAR have none).
    if (desc.maxLod != 0.0f)
        desc.maxAnisotropy = std::min(anisotropy, ctx.properties.limits.maxSamplerAnisotropy);
    VkSampler created = vk::createSampler(ctx, desc);
    materials.samplers[key] = created;
    return created;
}

void createGeometry(const vk::Context& ctx, SceneGeometry& geometry,
                    const world::CompiledLevel& level) {
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
    createRecordBuffer(ctx, geometry.vertices, vertices, VK_BUFFER_USAGE_VERTEX_BUFFER_BIT);
    createRecordBuffer(ctx, geometry.indices, indices, VK_BUFFER_USAGE_INDEX_BUFFER_BIT);

    for (uint32_t i = 0; i < level.surfaces.size(); ++i) {
        const world::Surface& surface = level.surfaces[i];
        DrawSurface d;
        d.firstIndex = firstIndex[i];
        d.indexCount = surface.indexCount;
        d.material = surface.material;
        d.primaryLight = surface.primaryLight;
        d.primaryKind = primaryKindOf(level.lights, surface.primaryLight);
        d.atlas = surface.atlas;
        d.boundsMin = surface.boundsMin;
        d.boundsMax = surface.boundsMax;
        geometry.surfaces.push_back(d);
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
            d.castsShadow = !(entity.flags & world::kEntityItem);
            geometry.dynamicCasters = geometry.dynamicCasters || d.castsShadow;
            d.boundsMin = glm::vec3(1e30f);
            d.boundsMax = glm::vec3(-1e30f);
            for (uint32_t v = 0; v < mesh.vertexCount; ++v) {
                const glm::vec3 p = level.dynamicVertices[mesh.firstVertex + v].position;
                d.boundsMin = glm::min(d.boundsMin, p);
                d.boundsMax = glm::max(d.boundsMax, p);
            }
            geometry.dynamicMeshes.push_back(d);
        }
    }
    // A dynamic mesh takes the primary of wherever it stands, of any type the level's primaries
    // have, or none.
    geometry.dynamicPrimaryKinds = {uint32_t(glsl::PRIMARY_NONE)};
    for (uint32_t i = 0; i < level.lights.size(); ++i)
        if (level.lights[i].role == world::LightRole::kPrimary)
            geometry.dynamicPrimaryKinds.push_back(primaryKindOf(level.lights, i));
    std::sort(geometry.dynamicPrimaryKinds.begin(), geometry.dynamicPrimaryKinds.end());
    geometry.dynamicPrimaryKinds.erase(
        std::unique(geometry.dynamicPrimaryKinds.begin(), geometry.dynamicPrimaryKinds.end()),
        geometry.dynamicPrimaryKinds.end());
    geometry.entityBoundsMin.assign(level.entities.size(), glm::vec3(1e30f));
    geometry.entityBoundsMax.assign(level.entities.size(), glm::vec3(-1e30f));
    for (const DrawDynamicMesh& d : geometry.dynamicMeshes) {
        geometry.entityBoundsMin[d.entity] =
            glm::min(geometry.entityBoundsMin[d.entity], d.boundsMin);
        geometry.entityBoundsMax[d.entity] =
            glm::max(geometry.entityBoundsMax[d.entity], d.boundsMax);
    }
}

// The materials' records and the classes, sidedness and alpha mode that pick their permutation.
void uploadMaterialRecords(const vk::Context& ctx, SceneMaterials& materials,
                           const assets::LoadedLevel& loaded, int forceMaterialClass) {
    const world::CompiledLevel& level = loaded.level;
    std::vector<GpuMaterial> gpu(std::max<size_t>(level.materials.size(), 1));
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
        uint32_t flags = 0;
        if (loaded.hasProcessedTextures &&
            loaded.processedTextures.materials.at(i).baseRoughnessInAlpha)
            flags |= uint32_t(glsl::MATERIAL_FLAG_BASE_ROUGHNESS);
        if (loaded.hasProcessedTextures &&
            loaded.processedTextures.materials.at(i).slopeKurtosisInNormalAlpha)
            flags |= uint32_t(glsl::MATERIAL_FLAG_SLOPE_KURTOSIS);
        g.textures = glm::uvec4(bits, flags, 0u, 0u);
        uint8_t cls = uint8_t(m.materialClass);
        if (forceMaterialClass >= 0) cls = uint8_t(forceMaterialClass);
        materials.classes.push_back(cls);
        materials.doubleSided.push_back(m.doubleSided ? 1 : 0);
        materials.alphaMode.push_back(uint8_t(m.alphaMode));
        materials.castsShadows.push_back(m.castsShadows ? 1 : 0);
        // A blended caster's shadow map holds the texels at least half opaque (the baked mask
        // transmits 1 - alpha; a depth map can only hold a texel or not).
        materials.maskAlpha.emplace_back(
            m.baseColor.a, m.alphaMode == world::AlphaMode::kBlend ? 0.5f : m.alphaCutoff);
        materials.textureSlots.push_back(uint8_t(bits));
    }
    if (level.materials.empty()) {
        gpu[0].baseColor = glm::vec4(0.8f, 0.8f, 0.8f, 1.0f);
        gpu[0].params = glm::vec4(0.0f, 1.0f, 1.0f, 1.0f);
    }
    // A page's offset suits any device (Vulkan's largest minUniformBufferOffsetAlignment is 256).
    static_assert(glsl::MAX_MATERIAL_RECORDS * sizeof(GpuMaterial) % 256 == 0);
    // Pages of MAX_MATERIAL_RECORDS, each bound at its own dynamic offset with the same range:
    // the last one padded to a whole page (of a level with more than one).
    const size_t perPage = std::min<size_t>(gpu.size(), glsl::MAX_MATERIAL_RECORDS);
    materials.pageBytes = perPage * sizeof(GpuMaterial);
    gpu.resize((gpu.size() + perPage - 1) / perPage * perPage);
    vk::createDeviceBuffer(ctx, materials.records, vk::bytesOf(std::span<const GpuMaterial>(gpu)),
                           VK_BUFFER_USAGE_UNIFORM_BUFFER_BIT);
}

void createPlaceholders(const vk::Context& ctx, SceneMaterials& materials) {
    vk::ImageDesc desc;
    desc.usage = VK_IMAGE_USAGE_SAMPLED_BIT | VK_IMAGE_USAGE_TRANSFER_DST_BIT;
    const uint8_t white[4] = {255, 255, 255, 255};
    const uint8_t flat[4] = {128, 128, 255, 255};
    vk::createImage(ctx, materials.white, desc);
    vk::uploadImage(ctx, materials.white, white);
    vk::createImage(ctx, materials.flatNormal, desc);
    vk::uploadImage(ctx, materials.flatNormal, flat);
}

// The largest power of two 2^-k (k >= 0) that keeps every stored lightmap coefficient within
// kLightmapStoredMax: RGBA16F tops out at 65504 and the sun's secondary can pass 100 klx.
constexpr float kLightmapStoredMax = 32768.0f;
float lightmapStorageScale(const world::BakedLighting& baked) {
    float largest = 0.0f;  // c0 = E / (2 w) bounds |c0| and |c.xyz| (|d| <= 0.5)
    for (const world::LightmapTexel& t : baked.texels)
        for (int c = 0; c < 3; ++c)
            largest = std::max({largest, world::linearIrradianceCoefficients(t, c).x,
                                t.directIrradiance[c], t.indirectIrradiance[c]});
    float scale = 1.0f;
    while (largest * scale > kLightmapStoredMax) scale *= 0.5f;
    return scale;
}

// Lightmaps and shadow masks of a baked level: every atlas a layer range of one 2D array as large
// as the largest atlas (a smaller atlas sits at the top-left; atlasUvScale maps its uv1). The
// lightmap holds LIGHTMAP_LAYERS per atlas in RGBA16F (shaders/gpu_interface.glsl): per colour
// channel the four linear coefficients of world::linearIrradianceCoefficients, then the baked
// direct light's irradiance (alpha: its visibility), its direction and the rest's average over
// normals, every irradiance times a power-of-two storage scale; the shadow mask RGBA8: the
// primary's mask byte, then the direct light's shadow edge (directEdgeMask) (linear filtering is
// guaranteed for both formats).
void uploadLightmaps(const vk::Context& ctx, BakedLightingMaps& baked,
                     const assets::LoadedLevel& loaded) {
    const auto unorm = [](float v) {
        return static_cast<uint8_t>(std::lround(std::clamp(v, 0.0f, 1.0f) * 255.0f));
    };
    const world::CompiledLevel& level = loaded.level;
    const world::BakedLighting& package = loaded.baked;
    uint32_t width = 1, height = 1;
    for (const world::Atlas& a : level.atlases) {
        width = std::max(width, a.width);
        height = std::max(height, a.height);
    }
    const uint32_t atlases = std::max<uint32_t>(uint32_t(level.atlases.size()), 1);
    const float scale = lightmapStorageScale(package);
    baked.lightmapDecode = 1.0f / scale;
    const size_t layerTexels = size_t(width) * height;
    const size_t layers = glsl::LIGHTMAP_LAYERS;
    std::vector<uint16_t> coefficients(layerTexels * 4 * layers * atlases, 0);
    std::vector<uint8_t> mask(layerTexels * 4 * atlases, 0);
    baked.atlasUvScale.clear();
    for (uint32_t a = 0; a < level.atlases.size(); ++a) {
        const world::Atlas& atlas = level.atlases[a];
        baked.atlasUvScale.push_back(
            glm::vec2(float(atlas.width) / float(width), float(atlas.height) / float(height)));
        const uint64_t first = world::atlasTexelOffset(level, a);
        for (uint32_t y = 0; y < atlas.height; ++y)
            for (uint32_t x = 0; x < atlas.width; ++x) {
                const uint64_t texel = first + uint64_t(y) * atlas.width + x;
                const size_t at = size_t(y) * width + x;
                const world::LightmapTexel& t = package.texels[texel];
                const auto put = [&](size_t layer, glm::vec4 k) {
                    uint16_t* out =
                        &coefficients[((size_t(a) * layers + layer) * layerTexels + at) * 4];
                    for (int i = 0; i < 4; ++i) out[i] = glm::packHalf1x16(k[i]);
                };
                for (int c = 0; c < 3; ++c)
                    put(size_t(c), world::linearIrradianceCoefficients(t, c) * scale);
                put(glsl::LIGHTMAP_LAYER_DIRECT,
                    glm::vec4(t.directIrradiance * scale, t.directVisibility));
                put(glsl::LIGHTMAP_LAYER_DIRECT_LIGHT, glm::vec4(t.directLight, 0.0f));
                put(glsl::LIGHTMAP_LAYER_INDIRECT, glm::vec4(t.indirectIrradiance * scale, 0.0f));
                uint8_t* m = &mask[(size_t(a) * layerTexels + at) * 4];
                m[0] = package.shadowMask[texel];
                const DirectEdgeMask e = directEdgeMask(t);
                m[1] = unorm(e.ramps);
                m[2] = unorm(e.low);
                m[3] = unorm(e.high);
            }
    }
    vk::ImageDesc desc;
    desc.width = width;
    desc.height = height;
    desc.layers = glsl::LIGHTMAP_LAYERS * atlases;
    desc.viewType = VK_IMAGE_VIEW_TYPE_2D_ARRAY;
    desc.format = VK_FORMAT_R16G16B16A16_SFLOAT;
    desc.usage = VK_IMAGE_USAGE_SAMPLED_BIT | VK_IMAGE_USAGE_TRANSFER_DST_BIT;
    vk::createImage(ctx, baked.lightmap, desc);
    vk::uploadImage(ctx, baked.lightmap,
                    {reinterpret_cast<const uint8_t*>(coefficients.data()),
                     coefficients.size() * sizeof(uint16_t)});
    desc.layers = atlases;
    desc.format = VK_FORMAT_R8G8B8A8_UNORM;
    vk::createImage(ctx, baked.shadowMask, desc);
    vk::uploadImage(ctx, baked.shadowMask, mask);
}

// The environment probes: every probe's RGB9E5 texels, as baked, in one cube array (cube i for
// record i of makeProbeRecords' order). The package's texel order (per probe: mips from the
// largest, each six faces of rows) becomes the upload's (per mip: every probe's six faces).
// Without probes (or with options.probes off) one neutral cube: a uniform environment of
// normalised radiance 1 / pi (its irradiance is its average: a uniform environment of L gives
// E = pi L) behind a record that influences everything.
void createProbes(const vk::Context& ctx, EnvironmentProbes& out,
                  const std::vector<world::EnvironmentProbe>& probes, bool useBaked,
                  glm::vec3 boundsMin, glm::vec3 boundsMax) {
    vk::ImageDesc desc;
    desc.cube = true;
    desc.viewType = VK_IMAGE_VIEW_TYPE_CUBE_ARRAY;
    desc.usage = VK_IMAGE_USAGE_SAMPLED_BIT | VK_IMAGE_USAGE_TRANSFER_DST_BIT;
    std::vector<GpuProbe> records;
    if (useBaked && !probes.empty()) {
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
        const uint32_t maxProbes = ctx.properties.limits.maxImageArrayLayers / 6;
        if (probes.size() > maxProbes)
            throw std::runtime_error(std::to_string(probes.size()) + " environment probes; this " +
                                     "device holds at most " + std::to_string(maxProbes) +
                                     " (maxImageArrayLayers " + std::to_string(maxProbes * 6) +
                                     " / 6 faces)");
        const ProbeRecords ordered = makeProbeRecords(probes, boundsMin, boundsMax);
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
        vk::createImage(ctx, out.cubes, desc);
        vk::uploadImageMips(ctx, out.cubes,
                            {reinterpret_cast<const uint8_t*>(texels.data()), texels.size() * 4});
        out.baked = uint32_t(probes.size());
        out.bytes = texels.size() * 4;
    } else {
        records = {placeholderProbeRecord()};
        desc.layers = 6;
        std::vector<float> faces;
        for (int f = 0; f < 6; ++f)
            for (int c = 0; c < 4; ++c) faces.push_back(c < 3 ? float(glsl::INV_PI) : 1.0f);
        createHalfImage(ctx, out.cubes, desc, faces);
        out.baked = 0;
        out.bytes = 0;
    }
    out.count = uint32_t(records.size());
    out.mips = out.cubes.desc.mipLevels;
    createRecordBuffer(ctx, out.records, records, VK_BUFFER_USAGE_STORAGE_BUFFER_BIT);
    const ProbeCells cells = makeProbeCells(records, boundsMin, boundsMax);
    std::vector<uint32_t> cellWords(sizeof(GpuProbeGrid) / 4);
    std::memcpy(cellWords.data(), &cells.grid, sizeof(GpuProbeGrid));
    cellWords.insert(cellWords.end(), cells.words.begin(), cells.words.end());
    createRecordBuffer(ctx, out.cells, cellWords, VK_BUFFER_USAGE_STORAGE_BUFFER_BIT);
}

void destroyProbes(const vk::Context& ctx, EnvironmentProbes& probes) {
    vk::destroyBuffer(ctx, probes.cells);
    vk::destroyBuffer(ctx, probes.records);
    vk::destroyImage(ctx, probes.cubes);
}

// The baked-lighting interface: the package's lightmaps, shadow masks and light grid, or
// neutral content for a level without them (a constant ambient of ambientLux, no baked shadow)
// that the placeholder-fetching test permutation reads.
void createBakedLighting(const vk::Context& ctx, BakedLightingMaps& baked,
                         const assets::LoadedLevel& loaded, float ambientLux) {
    baked.present = loaded.hasBakedLighting;
    if (baked.present) {
        uploadLightmaps(ctx, baked, loaded);
        baked.grid = loaded.baked.grid;
        baked.visibility = loaded.baked.visibility;
    } else {
        const float a = ambientLux;
        vk::ImageDesc lm;
        lm.layers = glsl::LIGHTMAP_LAYERS;
        lm.viewType = VK_IMAGE_VIEW_TYPE_2D_ARRAY;
        // The ambient as every channel's c0, no direct light, and all of it indirect.
        std::vector<float> layers(size_t(glsl::LIGHTMAP_LAYERS) * 4, 0.0f);
        for (int c = 0; c < 3; ++c) layers[size_t(c) * 4] = a;
        for (int c = 0; c < 3; ++c) layers[size_t(glsl::LIGHTMAP_LAYER_INDIRECT) * 4 + c] = a;
        layers[size_t(glsl::LIGHTMAP_LAYER_DIRECT) * 4 + 3] = 1.0f;  // visibility
        createHalfImage(ctx, baked.lightmap, lm, layers);
        vk::ImageDesc mask;
        mask.viewType = VK_IMAGE_VIEW_TYPE_2D_ARRAY;
        // Lit, and no shadow edge (its two levels one).
        createHalfImage(ctx, baked.shadowMask, mask, {1.0f, 1.0f, 1.0f, 1.0f});
        baked.lightmapDecode = 1.0f;
        baked.atlasUvScale.assign(loaded.level.atlases.size(), glm::vec2(1.0f));
        baked.grid = world::LightGrid{};
        baked.visibility = world::Visibility{};
    }
}

void destroyBakedLighting(const vk::Context& ctx, BakedLightingMaps& baked) {
    vk::destroyImage(ctx, baked.shadowMask);
    vk::destroyImage(ctx, baked.lightmap);
}

// The colour LUT: filmic curve and sRGB encoding at the shaper's texel centres.
void createLut(const vk::Context& ctx, vk::Image& lut) {
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
    createHalfImage(ctx, lut, desc, texels);
}

// The split-sum table of the runtime model (shaders/lighting.glsl, env_brdf_table.hpp): the
// lobe's albedo integrated at the grid points, read at envBrdfTableCoord; one fetch.
void createEnvBrdfTable(const vk::Context& ctx, vk::Image& envBrdf) {
    std::vector<float> texels;
    for (uint32_t t = 0; t < glsl::kEnvBrdfTableSize * glsl::kEnvBrdfTableSize; ++t)
        texels.insert(texels.end(),
                      {glsl::kEnvBrdfTable[2 * t], glsl::kEnvBrdfTable[2 * t + 1], 0.0f, 1.0f});
    vk::ImageDesc desc;
    desc.width = desc.height = glsl::kEnvBrdfTableSize;
    createHalfImage(ctx, envBrdf, desc, texels);
}

void createLookupTables(const vk::Context& ctx, LookupTables& tables) {
    vk::SamplerDesc clamp;
    clamp.addressU = clamp.addressV = clamp.addressW = VK_SAMPLER_ADDRESS_MODE_CLAMP_TO_EDGE;
    tables.linearClamp = vk::createSampler(ctx, clamp);
    clamp.magFilter = clamp.minFilter = VK_FILTER_NEAREST;
    clamp.mipmapMode = VK_SAMPLER_MIPMAP_MODE_NEAREST;
    tables.nearestClamp = vk::createSampler(ctx, clamp);
    createLut(ctx, tables.lut);
    createEnvBrdfTable(ctx, tables.envBrdf);
}

void destroyLookupTables(const vk::Context& ctx, LookupTables& tables) {
    vk::destroyImage(ctx, tables.envBrdf);
    vk::destroyImage(ctx, tables.lut);
    if (tables.nearestClamp) vkDestroySampler(ctx.device, tables.nearestClamp, nullptr);
    if (tables.linearClamp) vkDestroySampler(ctx.device, tables.linearClamp, nullptr);
    tables.nearestClamp = tables.linearClamp = VK_NULL_HANDLE;
}

// The sky image at full resolution (its light is already in the baked lighting; here it is
// only seen), linear RGB in half floats, clamped to their range; one black texel without one.
void createSky(const vk::Context& ctx, SkyImage& out, const world::HdrImage& sky) {
    out.present = sky.width > 0 && sky.height > 0;
    vk::ImageDesc desc;
    desc.width = out.present ? sky.width : 1;
    desc.height = out.present ? sky.height : 1;
    std::vector<float> texels(size_t(desc.width) * desc.height * 4, 0.0f);
    if (out.present)
        for (size_t t = 0; t < size_t(sky.width) * sky.height; ++t)
            for (size_t c = 0; c < 3; ++c)
                texels[4 * t + c] = std::min(sky.rgb[3 * t + c], glsl::HDR_MAX);
    createHalfImage(ctx, out.image, desc, texels);
    vk::SamplerDesc wrapU;
    wrapU.addressU = VK_SAMPLER_ADDRESS_MODE_REPEAT;
    wrapU.addressV = wrapU.addressW = VK_SAMPLER_ADDRESS_MODE_CLAMP_TO_EDGE;
    out.sampler = vk::createSampler(ctx, wrapU);
}

void destroySky(const vk::Context& ctx, SkyImage& sky) {
    if (sky.sampler) vkDestroySampler(ctx.device, sky.sampler, nullptr);
    sky.sampler = VK_NULL_HANDLE;
    vk::destroyImage(ctx, sky.image);
}

LevelData levelDataOf(const assets::LoadedLevel& loaded, const RendererOptions& options) {
    const world::CompiledLevel& level = loaded.level;
    LevelData d;
    d.settings = level.settings;
    d.lights = level.lights;
    d.entities = level.entities;
    d.boundsMin = level.settings.boundsMin;
    d.boundsMax = level.settings.boundsMax;
    for (const world::Entity& e : level.entities) {  // dynamic objects widen the bounds
        d.boundsMin = glm::min(d.boundsMin, e.position);
        d.boundsMax = glm::max(d.boundsMax, e.position);
    }
    const float reference = referenceIlluminance(d, loaded.sky);
    d.ambientLux = options.placeholderAmbientLux >= 0.0f
                       ? options.placeholderAmbientLux
                       : (reference > 0.0f ? 0.1f * reference : 1.0f);
    d.autoEv100 = glsl::ev100_fromIlluminance(reference > 0.0f ? reference : d.ambientLux);
    return d;
}

// The materials: records, placeholders, and per slot the (image, sampler) bound, placeholders
// where absent; one default material when the level has none.
void createMaterials(const vk::Context& ctx, SceneMaterials& materials,
                     const assets::LoadedLevel& loaded, const RendererOptions& options,
                     VkSampler linearClamp) {
    const world::CompiledLevel& level = loaded.level;
    uploadMaterialRecords(ctx, materials, loaded, options.forceMaterialClass);
    createPlaceholders(ctx, materials);
    materials.bound.clear();
    for (size_t i = 0; i < level.materials.size(); ++i) {
        const TextureSlots slots = materialSlots(loaded, i);
        MaterialTextures bound = placeholderTextures(materials, linearClamp);
        for (uint32_t t = 0; t < slots.size(); ++t) {
            if (slots[t] == world::kNoIndex) continue;
            if (loaded.hasProcessedTextures) {
                const uint32_t image = processedTextureFor(ctx, materials, loaded, slots[t]);
                bound[t] = {
                    materials.textures[image].view,
                    samplerFor(ctx, materials, loaded.processedTextures.textures[slots[t]].sampler,
                               options.anisotropy)};
                continue;
            }
            const bool srgb =
                int(t) == glsl::TEXTURE_BASE_COLOR || int(t) == glsl::TEXTURE_EMISSIVE;
            const uint32_t image = textureFor(ctx, materials, loaded, slots[t], srgb);
            if (image == kNoIndex) continue;
            bound[t] = {materials.textures[image].view,
                        samplerFor(ctx, materials, level.textures.at(slots[t]).sampler,
                                   options.anisotropy)};
        }
        materials.bound.push_back(bound);
    }
    if (materials.bound.empty()) {
        materials.bound.push_back(placeholderTextures(materials, linearClamp));
        materials.classes.push_back(
            uint8_t(options.forceMaterialClass >= 0 ? options.forceMaterialClass : 3));
        materials.doubleSided.push_back(0);
        materials.alphaMode.push_back(uint8_t(world::AlphaMode::kOpaque));
        materials.castsShadows.push_back(1);
        materials.maskAlpha.emplace_back(1.0f, 0.0f);
        materials.textureSlots.push_back(0);
    }
}

void destroyMaterials(const vk::Context& ctx, SceneMaterials& materials) {
    materials.bound.clear();
    vk::destroyImage(ctx, materials.flatNormal);
    vk::destroyImage(ctx, materials.white);
    for (auto& [key, sampler] : materials.samplers) vkDestroySampler(ctx.device, sampler, nullptr);
    materials.samplers.clear();
    for (auto it = materials.textures.rbegin(); it != materials.textures.rend(); ++it)
        vk::destroyImage(ctx, *it);
    materials.textures.clear();
    materials.textureIndex.clear();
    vk::destroyBuffer(ctx, materials.records);
}

void destroyGeometry(const vk::Context& ctx, SceneGeometry& geometry) {
    vk::destroyBuffer(ctx, geometry.indices);
    vk::destroyBuffer(ctx, geometry.vertices);
}

// The surfaces whose baked shadow mask is one value over all of them (world/surface_shadow.hpp):
// wholly lit ones unoccluded, wholly shadowed ones without their primary.
void applySurfaceShadows(SceneGeometry& geometry, const assets::LoadedLevel& loaded) {
    const std::vector<world::SurfaceShadow> shadows =
        world::surfaceShadows(loaded.level, loaded.baked);
    for (size_t i = 0; i < geometry.surfaces.size() && i < shadows.size(); ++i) {
        DrawSurface& s = geometry.surfaces[i];
        if (shadows[i] == world::SurfaceShadow::kLit) s.unoccluded = true;
        if (shadows[i] == world::SurfaceShadow::kShadowed) {
            s.primaryLight = kNoIndex;
            s.primaryKind = uint32_t(glsl::PRIMARY_NONE);
        }
    }
}

// The surfaces whose lightmap draws a baked direct light's shadow edge.
void applyDirectEdges(SceneGeometry& geometry, const assets::LoadedLevel& loaded) {
    const std::vector<uint8_t> edges = world::surfaceDirectEdges(loaded.level, loaded.baked);
    for (size_t i = 0; i < geometry.surfaces.size() && i < edges.size(); ++i)
        geometry.surfaces[i].directEdges = edges[i] != 0;
}

}  // namespace

DirectEdgeMask directEdgeMask(const world::LightmapTexel& t) {
    const float width = std::max(t.directEdgeWidth, glsl::DIRECT_EDGE_MIN_WIDTH);
    const float ramps =
        std::clamp(t.directEdgeDistance / width, -glsl::DIRECT_EDGE_RAMPS, glsl::DIRECT_EDGE_RAMPS);
    const float k = std::clamp(t.directEdgeSharpness, 0.0f, 1.0f);
    DirectEdgeMask m;
    m.ramps = 0.5f + 0.5f * ramps / glsl::DIRECT_EDGE_RAMPS;
    m.low = t.directVisibility + k * (t.directEdgeLow - t.directVisibility);
    m.high = t.directVisibility + k * (t.directEdgeHigh - t.directVisibility);
    return m;
}

uint32_t primaryKindOf(const std::vector<world::Light>& lights, uint32_t primaryLight) {
    if (primaryLight >= lights.size()) return uint32_t(glsl::PRIMARY_NONE);
    return uint32_t(glsl::PRIMARY_DIRECTIONAL) + uint32_t(lights[primaryLight].type);
}

void createPrimaryRecords(const vk::Context& ctx, PrimaryRecords& records,
                          const std::vector<world::Light>& lights,
                          const std::vector<ShadowViewRange>& shadowViews) {
    std::vector<GpuLight> gpu(glsl::MAX_PRIMARY_RECORDS);
    records.recordOf.assign(lights.size(), kNoIndex);
    uint32_t count = 0;
    for (uint32_t i = 0; i < lights.size(); ++i) {
        if (lights[i].role != world::LightRole::kPrimary) continue;
        if (count == glsl::MAX_PRIMARY_RECORDS)
            throw std::runtime_error("the level has more than " +
                                     std::to_string(glsl::MAX_PRIMARY_RECORDS) +
                                     " primary lights; the renderer holds at most that many");
        records.recordOf[i] = count;
        gpu[count++] = gpuLightOf(lights[i], shadowViews.at(i));
    }
    const VkDeviceSize bytes = gpu.size() * sizeof(GpuLight);
    if (ctx.properties.limits.maxUniformBufferRange < bytes)
        throw std::runtime_error("the device's uniform buffers hold " +
                                 std::to_string(ctx.properties.limits.maxUniformBufferRange) +
                                 " bytes; the primary lights' records need " +
                                 std::to_string(bytes));
    vk::createDeviceBuffer(ctx, records.buffer, vk::bytesOf(std::span<const GpuLight>(gpu)),
                           VK_BUFFER_USAGE_UNIFORM_BUFFER_BIT);
}

void createScene(const vk::Context& ctx, Scene& scene, const assets::LoadedLevel& loaded,
                 const RendererOptions& options) {
    scene.level = levelDataOf(loaded, options);
    createLookupTables(ctx, scene.tables);
    createGeometry(ctx, scene.geometry, loaded.level);
    createMaterials(ctx, scene.materials, loaded, options, scene.tables.linearClamp);
    createBakedLighting(ctx, scene.baked, loaded, scene.level.ambientLux);
    if (scene.baked.present && options.skipUniformShadows && !options.flatShading)
        applySurfaceShadows(scene.geometry, loaded);
    if (scene.baked.present) applyDirectEdges(scene.geometry, loaded);
    const world::Visibility& visibility = scene.baked.visibility;
    if (!visibility.empty() && visibility.surfaceCluster.size() == scene.geometry.surfaces.size()) {
        scene.baked.clusterMin.assign(visibility.clusterCount, glm::vec3(FLT_MAX));
        scene.baked.clusterMax.assign(visibility.clusterCount, glm::vec3(-FLT_MAX));
        for (size_t i = 0; i < scene.geometry.surfaces.size(); ++i) {
            const uint32_t c = visibility.surfaceCluster[i];
            scene.baked.clusterMin[c] =
                glm::min(scene.baked.clusterMin[c], scene.geometry.surfaces[i].boundsMin);
            scene.baked.clusterMax[c] =
                glm::max(scene.baked.clusterMax[c], scene.geometry.surfaces[i].boundsMax);
        }
    }
    createProbes(ctx, scene.probes, loaded.baked.probes, scene.baked.present && options.probes,
                 scene.level.boundsMin, scene.level.boundsMax);
    createSky(ctx, scene.sky, loaded.sky);
}

void destroyScene(const vk::Context& ctx, Scene& scene) {
    destroySky(ctx, scene.sky);
    destroyProbes(ctx, scene.probes);
    destroyBakedLighting(ctx, scene.baked);
    destroyMaterials(ctx, scene.materials);
    destroyGeometry(ctx, scene.geometry);
    destroyLookupTables(ctx, scene.tables);
}

}  // namespace onelight::render
