#include "bake/textures/texture_stage.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <filesystem>
#include <map>
#include <optional>
#include <tuple>
#include <utility>

#include "bake/parallel_for.hpp"
#include "bake/textures/facet_table.hpp"
#include "bake/textures/gloss_tables.hpp"
#include "bake/textures/normal_gloss_mips.hpp"
#include "shading.hpp"
#include "world/error.hpp"
#include "world/images/image_decode.hpp"

namespace onelight::bake {

namespace {

// glTF sampler wrap modes (GL enums).
constexpr uint16_t kGlClampToEdge = 33071;
constexpr uint16_t kGlMirroredRepeat = 33648;

float finiteOr(float value, float fallback) {
    return std::isfinite(value) ? value : fallback;
}

// round(255 v) with v clamped to [0, 1]; NaN gives 0.
uint8_t unorm8(double v) {
    if (!(v > 0.0)) return 0;
    if (v >= 1.0) return 255;
    return uint8_t(std::lround(v * 255.0));
}

// A value in byte units rounded to nearest and clamped to [0, 255]; NaN gives 0.
uint8_t nearestByte(double v) {
    if (!(v > 0.0)) return 0;
    if (v >= 255.0) return 255;
    return uint8_t(std::lround(v));
}

// Byte offset of every mip of a packed chain, then the chain's size.
std::vector<size_t> mipOffsets(world::TexelFormat format, uint32_t width, uint32_t height) {
    const int levels = mipLevelCount(int(width), int(height));
    std::vector<size_t> offsets(size_t(levels) + 1, 0);
    for (int k = 0; k < levels; ++k)
        offsets[size_t(k) + 1] = offsets[size_t(k)] + size_t(mipSize(int(width), k)) *
                                                          size_t(mipSize(int(height), k)) *
                                                          world::bytesPerTexel(format);
    return offsets;
}

world::ProcessedTexture emptyTexture(std::string name, world::TexelFormat format, uint32_t width,
                                     uint32_t height, const world::Sampler& sampler) {
    world::ProcessedTexture t;
    t.name = std::move(name);
    t.format = format;
    t.width = width;
    t.height = height;
    t.mipCount = world::fullMipCount(width, height);
    t.sampler = sampler;
    t.texels.resize(world::mipChainBytes(format, width, height, t.mipCount));
    return t;
}

// For every texel of mips 1 and on of a width x height level 0, the mean over its level-0
// footprint (mipFootprint) of `Channels` values: load(i, values) writes level-0 texel i's, and
// emit(level, i, means) receives texel i of `level`. Each level's sums are its children's
// (mipChildren, row-major order), in double, so every mean is of level 0 itself; rows run in
// parallel, each texel in a fixed order.
template <int Channels, typename Load, typename Emit>
void footprintMeans(int width, int height, const Load& load, const Emit& emit) {
    using Sums = std::array<double, Channels>;
    std::vector<Sums> sumsAbove;
    std::vector<int> columnsAbove, rowsAbove;  // level-0 texels under each column, each row
    const int levels = mipLevelCount(width, height);
    for (int level = 1; level < levels; ++level) {
        const int pw = mipSize(width, level - 1), ph = mipSize(height, level - 1);
        const int w = mipSize(width, level), h = mipSize(height, level);
        auto footprints = [&](int parentSize, int size, const std::vector<int>& above) {
            std::vector<int> counts(size_t(size), 0);
            for (int i = 0; i < size; ++i) {
                const TexelRange r = mipChildren(parentSize, i);
                for (int p = r.begin; p < r.end; ++p)
                    counts[size_t(i)] += level == 1 ? 1 : above[size_t(p)];
            }
            return counts;
        };
        std::vector<int> columns = footprints(pw, w, columnsAbove);
        std::vector<int> rows = footprints(ph, h, rowsAbove);
        std::vector<Sums> sums(size_t(w) * size_t(h));
        parallelFor(0, h, [&](int y) {
            const TexelRange ry = mipChildren(ph, y);
            for (int x = 0; x < w; ++x) {
                const TexelRange rx = mipChildren(pw, x);
                Sums s{};
                for (int py = ry.begin; py < ry.end; ++py)
                    for (int px = rx.begin; px < rx.end; ++px) {
                        const size_t j = size_t(py) * size_t(pw) + size_t(px);
                        Sums child{};
                        if (level == 1)
                            load(j, child.data());
                        else
                            child = sumsAbove[j];
                        for (int c = 0; c < Channels; ++c) s[size_t(c)] += child[size_t(c)];
                    }
                const size_t i = size_t(y) * size_t(w) + size_t(x);
                sums[i] = s;
                const double count = double(columns[size_t(x)]) * double(rows[size_t(y)]);
                Sums mean;
                for (int c = 0; c < Channels; ++c) mean[size_t(c)] = s[size_t(c)] / count;
                emit(level, i, mean.data());
            }
        });
        sumsAbove = std::move(sums);
        columnsAbove = std::move(columns);
        rowsAbove = std::move(rows);
    }
}

// The colour of every wholly clear texel (alpha byte 0) of a cut-out's RGBA8 mips, from mip 0 up:
// its parent's at the next level, the coarsest first, so that it is the colour of what covers the
// nearest footprint that anything covers (a push of the coverage-weighted means; a texture that
// nothing covers keeps its own). A filter reaching from a covered texel into a clear one then
// blends the covered colour with itself, not with whatever the holes held (black, often): no dark
// fringe along a cut-out's edges. Alpha is untouched, so is every texel anything covers (a
// texture that nothing covers takes its coarsest mean, and stays invisible).
void fillClearTexels(uint8_t* texels, const std::vector<size_t>& offsets, uint32_t width,
                     uint32_t height) {
    const int levels = int(offsets.size()) - 1;  // offsets: one per level, then the end
    for (int level = levels - 2; level >= 0; --level) {
        const int w = mipSize(int(width), level), h = mipSize(int(height), level);
        const int pw = mipSize(int(width), level + 1), ph = mipSize(int(height), level + 1);
        uint8_t* here = texels + offsets[size_t(level)];
        const uint8_t* parent = texels + offsets[size_t(level) + 1];
        for (int y = 0; y < h; ++y)
            for (int x = 0; x < w; ++x) {
                uint8_t* t = here + 4 * (size_t(y) * size_t(w) + size_t(x));
                if (t[3] != 0) continue;
                const uint8_t* p = parent + 4 * (size_t(std::min(y / 2, ph - 1)) * size_t(pw) +
                                                 size_t(std::min(x / 2, pw - 1)));
                std::copy(p, p + 3, t);
            }
    }
}

// A plain texture: mip 0 the image, further mips footprint means, in linear light for an sRGB
// texture's colour, in byte values for a linear texture's and for alpha. A base colour whose
// alpha is its coverage (`overCoverage`: a MASK or BLEND material's; an OPAQUE material ignores
// its alpha, which a Quake 3 texture may use for something else) is averaged over what covers the
// footprint, sum(c a) / sum(a), as premultiplied alpha filters, and plainly only where nothing or
// everything covers it. A plain mean would darken a cut-out grate's bars with its holes' (black)
// colour wherever a mip reaches over both, and tint whatever an alpha-blended edge fades out; and
// its clear texels take the colour of what covers nearby (fillClearTexels).
world::ProcessedTexture plainTexture(const world::DecodedImage& image, bool srgb, bool overCoverage,
                                     const world::Sampler& sampler, std::string name) {
    const world::TexelFormat format =
        srgb ? world::TexelFormat::kRgba8Srgb : world::TexelFormat::kRgba8Unorm;
    world::ProcessedTexture out =
        emptyTexture(std::move(name), format, image.width, image.height, sampler);
    const std::vector<size_t> offsets = mipOffsets(format, image.width, image.height);
    std::copy(image.rgba.begin(), image.rgba.end(), out.texels.begin());
    std::array<double, 256> colour{};  // what a colour byte averages as
    for (int b = 0; b < 256; ++b)
        colour[size_t(b)] = srgb ? double(glsl::srgbDecode(float(b) / 255.0f)) : double(b);
    const uint8_t* rgba = image.rgba.data();
    const auto store = [&](int level, size_t i, const double* rgb, double alpha) {
        uint8_t* t = out.texels.data() + offsets[size_t(level)] + 4 * i;
        for (int c = 0; c < 3; ++c)
            t[c] = srgb ? unorm8(double(glsl::srgbEncode(float(rgb[c])))) : nearestByte(rgb[c]);
        t[3] = nearestByte(alpha);
    };
    if (!overCoverage) {
        footprintMeans<4>(
            int(image.width), int(image.height),
            [&](size_t i, double* v) {
                for (int c = 0; c < 3; ++c) v[c] = colour[rgba[4 * i + size_t(c)]];
                v[3] = double(rgba[4 * i + 3]);
            },
            [&](int level, size_t i, const double* mean) { store(level, i, mean, mean[3]); });
        return out;
    }
    // Per texel: the colour times the alpha byte, the alpha byte, the colour.
    footprintMeans<7>(
        int(image.width), int(image.height),
        [&](size_t i, double* v) {
            const double a = double(rgba[4 * i + 3]);
            for (int c = 0; c < 3; ++c) {
                v[4 + c] = colour[rgba[4 * i + size_t(c)]];
                v[c] = v[4 + c] * a;
            }
            v[3] = a;
        },
        [&](int level, size_t i, const double* mean) {
            // Wholly opaque (every alpha 255) or wholly clear: the plain mean, exactly as before.
            const double a = mean[3];
            if (a >= 255.0 || a <= 0.0) {
                store(level, i, mean + 4, a);
                return;
            }
            const double rgb[3] = {mean[0] / a, mean[1] / a, mean[2] / a};
            store(level, i, rgb, a);
        });
    fillClearTexels(out.texels.data(), offsets, image.width, image.height);
    return out;
}

// The texel of an axis of `size` texels that index `i` reads under a glTF wrap mode.
int wrapTexel(int i, int size, uint16_t wrap) {
    if (wrap == kGlClampToEdge) return std::clamp(i, 0, size - 1);
    if (wrap == kGlMirroredRepeat) {
        const int period = 2 * size, m = ((i % period) + period) % period;
        return m < size ? m : period - 1 - m;
    }
    return ((i % size) + size) % size;  // REPEAT, glTF's default
}

// Where the centre of texel `index` of an axis of `targetSize` texels falls on an axis of
// `sourceSize` texels, in source texels (texel j's centre at j): (index + 0.5) sourceSize /
// targetSize - 0.5, exact integers over one division (so equal sizes give `index` exactly).
double sourceCoordinate(int index, int targetSize, int sourceSize) {
    return (double(2 * index + 1) * double(sourceSize) - double(targetSize)) /
           (2.0 * double(targetSize));
}

// RGB of `image` in [0, 1], bilinear at source texel coordinates (sx, sy) through `sampler`'s
// wrap modes.
glm::dvec3 bilinearRgb(const world::DecodedImage& image, const world::Sampler& sampler, double sx,
                       double sy) {
    const int w = int(image.width), h = int(image.height);
    const double fx0 = std::floor(sx), fy0 = std::floor(sy);
    const double fx = sx - fx0, fy = sy - fy0;
    const int x0 = int(fx0), y0 = int(fy0);
    const int xs[2] = {wrapTexel(x0, w, sampler.wrapS), wrapTexel(x0 + 1, w, sampler.wrapS)};
    const int ys[2] = {wrapTexel(y0, h, sampler.wrapT), wrapTexel(y0 + 1, h, sampler.wrapT)};
    auto texel = [&](int x, int y) {
        const uint8_t* t = image.rgba.data() + (size_t(y) * size_t(w) + size_t(x)) * 4;
        return glm::dvec3(t[0], t[1], t[2]) / 255.0;
    };
    const glm::dvec3 top = texel(xs[0], ys[0]) * (1.0 - fx) + texel(xs[1], ys[0]) * fx;
    const glm::dvec3 bottom = texel(xs[0], ys[1]) * (1.0 - fx) + texel(xs[1], ys[1]) * fx;
    return top * (1.0 - fy) + bottom * fy;
}

CavityWrap cavityWrap(uint16_t wrap) {
    return wrap == kGlClampToEdge || wrap == kGlMirroredRepeat ? CavityWrap::kClamp
                                                               : CavityWrap::kRepeat;
}

std::string imageLabel(const world::SourceLevel& level, uint32_t index) {
    const world::Image& image = level.images[index];
    if (!image.name.empty()) return image.name;
    if (!image.uri.empty()) return std::filesystem::path(image.uri).filename().string();
    return "image " + std::to_string(index);
}

std::string materialLabel(const world::SourceLevel& level, uint32_t index) {
    const std::string& name = level.materials[index].name;
    return name.empty() ? "material " + std::to_string(index) : name;
}

// The level's images decoded against one budget.
world::DecodedImage decodeLevelImage(const world::SourceLevel& level, uint32_t index,
                                     double bytesPerTexel, world::ImageMemoryBudget& budget) {
    const world::Image& source = level.images[index];
    const std::string where =
        level.sourcePath + ": image " + std::to_string(index) + " '" + source.name + "'";
    budget.bytesPerTexel = bytesPerTexel;
    if (!source.encodedBytes.empty())
        return world::decodeImage(source.encodedBytes.data(), source.encodedBytes.size(), where,
                                  &budget);
    if (source.uri.empty()) throw world::Error(where + ": neither a uri nor embedded bytes");
    try {
        return world::readImageFile(source.uri, &budget);
    } catch (const world::Error& e) {
        throw world::Error(where + ": " + e.what());
    }
}

// The stage's state: the level, what has been made and the memory charged.
struct Stage {
    const world::SourceLevel& level;
    const TextureStageOptions& options;
    world::GlossMipMethod method;
    world::ImageMemoryBudget budget;
    world::ProcessedTextures out;
    // (texture, sRGB, averaged over its coverage) -> out texture
    std::map<std::tuple<uint32_t, bool, bool>, uint32_t> plainMade;
    // (normal texture, scale, metallic-roughness texture, roughness, metallic, packed occlusion,
    // Lambert) -> the pair's first texture (normal; metallic-roughness follows)
    std::map<std::tuple<uint32_t, float, uint32_t, float, float, bool, bool>, uint32_t> pairMade;
    std::map<std::pair<uint32_t, float>, uint32_t> cavityMade;  // (normal texture, scale)
};

uint32_t add(Stage& stage, world::ProcessedTexture texture) {
    stage.out.textures.push_back(std::move(texture));
    return uint32_t(stage.out.textures.size() - 1);
}

// Once a texture is made, only what it keeps stays charged.
void keepOnly(world::ImageMemoryBudget& budget, uint64_t usedBefore, uint64_t keptBytes) {
    budget.usedBytes = usedBefore + keptBytes;
}

// The glTF texture a material slot reads, or nullptr: no index, a texture without an image, or
// the sky's image.
const world::Texture* slotTexture(const world::SourceLevel& level, uint32_t material,
                                  uint32_t index, const char* slot) {
    if (index == world::kNoIndex) return nullptr;
    const std::string where = level.sourcePath + ": material " + std::to_string(material) + " '" +
                              level.materials[material].name + "' " + slot;
    if (index >= level.textures.size())
        throw world::Error(where + " reads texture " + std::to_string(index) + " of " +
                           std::to_string(level.textures.size()));
    const world::Texture& texture = level.textures[index];
    if (texture.image == world::kNoIndex || texture.image == level.skyImage) return nullptr;
    if (texture.image >= level.images.size())
        throw world::Error(where + ": texture " + std::to_string(index) + " reads image " +
                           std::to_string(texture.image) + " of " +
                           std::to_string(level.images.size()));
    return &texture;
}

// `overCoverage`: the slot is a base colour whose alpha is coverage (plainTexture).
uint32_t plainSlot(Stage& stage, uint32_t material, uint32_t index, bool srgb, bool overCoverage,
                   const char* slot, const char* use) {
    const world::Texture* texture = slotTexture(stage.level, material, index, slot);
    if (!texture) return world::kNoIndex;
    const auto key = std::make_tuple(index, srgb, overCoverage);
    const auto found = stage.plainMade.find(key);
    if (found != stage.plainMade.end()) return found->second;
    const uint64_t usedBefore = stage.budget.usedBytes;
    world::ProcessedTexture made = plainTexture(
        decodeLevelImage(stage.level, texture->image, kPlainTextureBytesPerTexel, stage.budget),
        srgb, overCoverage, texture->sampler, imageLabel(stage.level, texture->image) + " " + use);
    keepOnly(stage.budget, usedBefore, made.texels.size());
    return stage.plainMade[key] = add(stage, std::move(made));
}

// Level 0 of a normal and metallic-roughness pair on the normal map's grid: the normals and
// gloss, and the roughness, metallic and occlusion planes.
struct PairLevel0 {
    NormalGlossLevel normalGloss;
    std::vector<float> roughness, metallic, occlusion;
};

struct PairInputs {
    const world::Texture* normal = nullptr;
    const world::Texture* metallicRoughness = nullptr;  // nullptr: the factors alone
    float normalScale = 1.0f, roughness = 1.0f, metallic = 1.0f;
    bool packedOcclusion = false;  // R of the metallic-roughness texture is the occlusion
};

PairLevel0 pairLevel0(Stage& stage, const PairInputs& in) {
    const world::DecodedImage normalImage =
        decodeLevelImage(stage.level, in.normal->image, kNormalMapBytesPerTexel, stage.budget);
    world::DecodedImage mrImage;
    if (in.metallicRoughness)
        mrImage = decodeLevelImage(stage.level, in.metallicRoughness->image, 4.0, stage.budget);
    const int w = int(normalImage.width), h = int(normalImage.height);
    const size_t n = size_t(w) * size_t(h);
    PairLevel0 out{NormalGlossLevel{w, h, std::vector<glm::vec3>(n), std::vector<float>(n), {}, {}},
                   std::vector<float>(n), std::vector<float>(n), std::vector<float>(n)};
    parallelFor(0, h, [&](int y) {
        const double sy = in.metallicRoughness ? sourceCoordinate(y, h, int(mrImage.height)) : 0.0;
        for (int x = 0; x < w; ++x) {
            const size_t i = size_t(y) * size_t(w) + size_t(x);
            const uint8_t* t = normalImage.rgba.data() + 4 * i;
            const glsl::vec3 texel = glsl::vec3(t[0], t[1], t[2]) / 255.0f;
            out.normalGloss.normals[i] =
                glsl::normal_fromTangentSpace(texel, in.normalScale, glsl::vec3(0.0f, 0.0f, 1.0f),
                                              glsl::vec3(1.0f, 0.0f, 0.0f), 1.0f);
            glm::dvec3 mr(1.0);
            if (in.metallicRoughness)
                mr = bilinearRgb(mrImage, in.metallicRoughness->sampler,
                                 sourceCoordinate(x, w, int(mrImage.width)), sy);
            out.roughness[i] = float(double(in.roughness) * mr.y);
            out.metallic[i] = float(double(in.metallic) * mr.z);
            out.occlusion[i] = in.packedOcclusion ? float(mr.x) : 1.0f;
            out.normalGloss.gloss[i] = glsl::gloss_fromRoughness(out.roughness[i]);
        }
    });
    return out;
}

world::ProcessedTexture cavityTexture(const NormalGlossLevel& level0, const world::Sampler& sampler,
                                      const TextureStageOptions& options, std::string name) {
    const CavitySettings settings{{cavityWrap(sampler.wrapS), cavityWrap(sampler.wrapT)},
                                  options.cavityDepthScale,
                                  options.cavityScan};
    const CavityMap cavity = cavityFromNormals(
        TangentNormalMap{uint32_t(level0.width), uint32_t(level0.height), level0.normals},
        settings);
    world::ProcessedTexture out = emptyTexture(std::move(name), world::TexelFormat::kR8Unorm,
                                               cavity.width, cavity.height, sampler);
    size_t offset = 0;
    for (const CavityMap& mip : cavityMipChain(cavity)) {
        const std::vector<uint8_t> bytes = cavityToUnorm8(mip);
        std::copy(bytes.begin(), bytes.end(), out.texels.begin() + std::ptrdiff_t(offset));
        offset += bytes.size();
    }
    return out;
}

world::ProcessedTexture normalTexture(const NormalGlossChain& chain, const world::Sampler& sampler,
                                      std::string name) {
    const int w = chain[0].width, h = chain[0].height;
    world::ProcessedTexture out = emptyTexture(std::move(name), world::TexelFormat::kRgba8Unorm,
                                               uint32_t(w), uint32_t(h), sampler);
    const std::vector<size_t> offsets =
        mipOffsets(world::TexelFormat::kRgba8Unorm, uint32_t(w), uint32_t(h));
    for (size_t k = 0; k < chain.size(); ++k) {
        const NormalGlossLevel& level = chain[k];
        parallelFor(0, level.height, [&](int y) {
            for (int x = 0; x < level.width; ++x) {
                const size_t i = size_t(y) * size_t(level.width) + size_t(x);
                uint8_t* t = out.texels.data() + offsets[k] + 4 * i;
                for (int c = 0; c < 3; ++c) t[c] = unorm8(0.5 + 0.5 * double(level.normals[i][c]));
                // The slopes' kurtosis (MaterialTextureSlots::slopeKurtosisInNormalAlpha).
                t[3] = unorm8(0.5 * (double(level.slopeKurtosis[i]) - 1.0));
            }
        });
    }
    return out;
}

// From level 0's roughness, metallic and occlusion planes and the chain's gloss.
world::ProcessedTexture metallicRoughnessTexture(const PairLevel0& level0,
                                                 const NormalGlossChain& chain,
                                                 const world::Sampler& sampler, std::string name) {
    const int w = chain[0].width, h = chain[0].height;
    world::ProcessedTexture out = emptyTexture(std::move(name), world::TexelFormat::kRgba8Unorm,
                                               uint32_t(w), uint32_t(h), sampler);
    const std::vector<size_t> offsets =
        mipOffsets(world::TexelFormat::kRgba8Unorm, uint32_t(w), uint32_t(h));
    parallelFor(0, h, [&](int y) {
        for (int x = 0; x < w; ++x) {
            const size_t i = size_t(y) * size_t(w) + size_t(x);
            uint8_t* t = out.texels.data() + 4 * i;
            t[0] = unorm8(double(level0.occlusion[i]));
            t[1] = unorm8(double(level0.roughness[i]));
            t[2] = unorm8(double(level0.metallic[i]));
            t[3] = t[1];  // a texel's own lobe is its whole lobe
        }
    });
    footprintMeans<2>(
        w, h,
        [&](size_t i, double* v) {
            v[0] = double(level0.occlusion[i]);
            v[1] = double(level0.metallic[i]);
        },
        [&](int level, size_t i, const double* mean) {
            uint8_t* t = out.texels.data() + offsets[size_t(level)] + 4 * i;
            t[0] = unorm8(mean[0]);
            t[1] = unorm8(roughness_fromGloss(double(chain[size_t(level)].gloss[i])));
            t[2] = unorm8(mean[1]);
            // The texels' own lobes (MaterialTextureSlots::baseRoughnessInAlpha), never rougher
            // than G after rounding.
            t[3] = std::min(t[1],
                            unorm8(roughness_fromGloss(double(chain[size_t(level)].baseGloss[i]))));
        });
    return out;
}

struct PairSlots {
    uint32_t normal = world::kNoIndex, metallicRoughness = world::kNoIndex,
             cavity = world::kNoIndex, facets = world::kNoIndex;
};

PairSlots pairSlots(Stage& stage, uint32_t material, uint32_t normalIndex, const PairInputs& in,
                    bool lambert) {
    const world::Material& m = stage.level.materials[material];
    const uint32_t mrIndex = in.metallicRoughness ? m.metallicRoughnessTexture : world::kNoIndex;
    const auto pairKey = std::make_tuple(normalIndex, in.normalScale, mrIndex, in.roughness,
                                         in.metallic, in.packedOcclusion, lambert);
    const auto cavityKey = std::make_pair(normalIndex, in.normalScale);
    const auto madeCavity = stage.cavityMade.find(cavityKey);
    const auto madePair = stage.pairMade.find(pairKey);
    if (madePair != stage.pairMade.end())  // then its cavity was made with it, and its facets
        return {madePair->second, madePair->second + 1, madeCavity->second,
                lambert || !stage.options.facetTables ? world::kNoIndex : madePair->second + 2};

    const std::string label = materialLabel(stage.level, material);
    const uint64_t usedBefore = stage.budget.usedBytes;
    uint64_t kept = 0;
    PairLevel0 level0 = pairLevel0(stage, in);
    PairSlots slots;
    if (madeCavity != stage.cavityMade.end()) {
        slots.cavity = madeCavity->second;
    } else {
        world::ProcessedTexture cavity =
            cavityTexture(level0.normalGloss, in.normal->sampler, stage.options, label + " cavity");
        kept += cavity.texels.size();
        slots.cavity = stage.cavityMade[cavityKey] = add(stage, std::move(cavity));
    }
    const NormalGlossChain chain = buildNormalGlossMips(
        level0.normalGloss, lambert ? world::GlossMipMethod::kBlit : stage.method);
    level0.normalGloss = {};  // the chain holds level 0; the planes are still needed
    // A specular lobe's facets over the whole tile (Lambert has no lobe to shape).
    std::optional<world::ProcessedTexture> facets;
    if (!lambert && stage.options.facetTables)
        facets = facetTableTexture(facetTable(chain[0], in.normal->sampler.wrapS == 10497,
                                              in.normal->sampler.wrapT == 10497),
                                   label + " facets");
    world::ProcessedTexture normal = normalTexture(chain, in.normal->sampler, label + " normal");
    world::ProcessedTexture mr =
        metallicRoughnessTexture(level0, chain, in.normal->sampler, label + " metallic-roughness");
    kept += normal.texels.size() + mr.texels.size();
    slots.normal = stage.pairMade[pairKey] = add(stage, std::move(normal));
    slots.metallicRoughness = add(stage, std::move(mr));
    if (facets) {
        kept += facets->texels.size();
        slots.facets = add(stage, std::move(*facets));
    }
    keepOnly(stage.budget, usedBefore, kept);
    return slots;
}

}  // namespace

world::ProcessedTextures processLevelTextures(const world::SourceLevel& level,
                                              world::GlossMipMethod method,
                                              const TextureStageOptions& options) {
    Stage stage{level, options, method, {}, {}, {}, {}, {}};
    stage.budget.limitBytes = options.memoryLimitBytes;
    stage.out.method = method;
    stage.out.materials.resize(level.materials.size());
    for (uint32_t m = 0; m < uint32_t(level.materials.size()); ++m) {
        const world::Material& material = level.materials[m];
        world::MaterialTextureSlots& slots = stage.out.materials[m];
        slots.baseColor = plainSlot(stage, m, material.baseColorTexture, true,
                                    material.alphaMode != world::AlphaMode::kOpaque,
                                    "baseColorTexture", "base colour");
        const world::Texture* normal =
            slotTexture(level, m, material.normalTexture, "normalTexture");
        if (normal) {
            PairInputs in;
            in.normal = normal;
            in.metallicRoughness = slotTexture(level, m, material.metallicRoughnessTexture,
                                               "metallicRoughnessTexture");
            in.normalScale = finiteOr(material.normalScale, 1.0f);
            in.roughness = std::clamp(finiteOr(material.roughness, 1.0f), 0.0f, 1.0f);
            in.metallic = std::clamp(finiteOr(material.metallic, 1.0f), 0.0f, 1.0f);
            const world::Texture* occlusion =
                slotTexture(level, m, material.occlusionTexture, "occlusionTexture");
            in.packedOcclusion = in.metallicRoughness && occlusion &&
                                 (material.occlusionTexture == material.metallicRoughnessTexture ||
                                  occlusion->image == in.metallicRoughness->image);
            const PairSlots pair =
                pairSlots(stage, m, material.normalTexture, in,
                          material.materialClass == world::MaterialClass::kLambert);
            slots.normal = pair.normal;
            slots.metallicRoughness = pair.metallicRoughness;
            slots.cavity = pair.cavity;
            slots.facets = pair.facets;
            slots.factorsFolded = true;
            slots.baseRoughnessInAlpha = true;
            slots.slopeKurtosisInNormalAlpha = true;
            if (in.packedOcclusion) slots.occlusion = pair.metallicRoughness;
        } else {
            slots.metallicRoughness =
                plainSlot(stage, m, material.metallicRoughnessTexture, false, false,
                          "metallicRoughnessTexture", "metallic-roughness");
        }
        if (slots.occlusion == world::kNoIndex)
            slots.occlusion = plainSlot(stage, m, material.occlusionTexture, false, false,
                                        "occlusionTexture", "occlusion");
        slots.emissive = plainSlot(stage, m, material.emissiveTexture, true, false,
                                   "emissiveTexture", "emissive");
    }
    return std::move(stage.out);
}

TextureStageReport textureStageReport(const world::ProcessedTextures& textures) {
    TextureStageReport report;
    for (const world::ProcessedTexture& t : textures.textures) {
        report.textures.push_back(
            {t.name, t.format, t.width, t.height, t.mipCount, uint64_t(t.texels.size())});
        report.totalBytes += t.texels.size();
    }
    return report;
}

const char* texelFormatName(world::TexelFormat format) {
    switch (format) {
        case world::TexelFormat::kRgba8Srgb:
            return "RGBA8 sRGB";
        case world::TexelFormat::kRgba8Unorm:
            return "RGBA8";
        case world::TexelFormat::kR8Unorm:
            return "R8";
        case world::TexelFormat::kR16Float:
            return "R16F";
    }
    return "unknown";
}

}  // namespace onelight::bake
