#include "assets/level_assets.hpp"

#include <filesystem>
#include <fstream>
#include <iterator>

#include "world/error.hpp"
#include "world/file_read.hpp"
#include "world/package/package_decode.hpp"

namespace onelight::assets {

LoadedLevel loadLevel(const std::string& path) {
    package::DecodedPackage decoded =
        package::decodePackage(world::readRegularFile(path, "a .olpak package"), path);
    LoadedLevel out;
    out.path = path;
    out.level = std::move(decoded.contents.level);
    package::BakedContents& baked = decoded.baked;
    if (baked.present && baked.baked.shardCount > 1)
        throw world::Error(path + ": holds part " + std::to_string(baked.baked.shardIndex + 1) +
                           " of " + std::to_string(baked.baked.shardCount) +
                           " of a sharded bake; expected a complete package (join the parts "
                           "with `onelight-bake merge`)");
    out.hasBakedLighting = baked.present;
    if (baked.present) out.baked = std::move(baked.baked);
    package::TextureContents& processed = decoded.textures;
    out.hasProcessedTextures = processed.present;
    if (processed.present) out.processedTextures = std::move(processed.textures);
    out.images.reserve(out.level.images.size());
    const std::filesystem::path folder = std::filesystem::path(path).parent_path();
    // RGBA8 texels and float RGB sky texels, charged before each image is decoded.
    world::ImageMemoryBudget rgba8{4.0}, skyRgb{12.0};
    for (size_t i = 0; i < out.level.images.size(); ++i) {
        const world::Image& image = out.level.images[i];
        const std::string where = path + ": image " + std::to_string(i) + " '" + image.name + "'";
        const bool sky = i == out.level.settings.skyImage;
        if (!sky && out.hasProcessedTextures) {  // the stage's mips replace the image
            out.images.emplace_back();
            continue;
        }
        if (!image.encodedBytes.empty()) {
            if (sky) {
                out.sky = world::decodeHdrImage(image.encodedBytes.data(),
                                                image.encodedBytes.size(), where, &skyRgb);
                out.images.emplace_back();
            } else {
                out.images.push_back(world::decodeImage(image.encodedBytes.data(),
                                                        image.encodedBytes.size(), where, &rgba8));
            }
            continue;
        }
        // The reader allows only relative uris below the package's folder; readImageFile and
        // readHdrFile open only regular files, and name this one.
        const std::filesystem::path file = folder / image.uri;
        if (sky) {
            out.sky = world::readHdrFile(file.string(), &skyRgb);
            out.images.emplace_back();
            continue;
        }
        out.images.push_back(world::readImageFile(file.string(), &rgba8));
    }
    return out;
}

}  // namespace onelight::assets
