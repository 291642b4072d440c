#include "assets/level_assets.hpp"

#include <filesystem>
#include <fstream>
#include <iterator>

#include "world/error.hpp"
#include "world/package/baked_sections.hpp"
#include "world/package/package_reader.hpp"

#define STB_IMAGE_IMPLEMENTATION
#define STBI_ONLY_PNG
#define STBI_ONLY_JPEG
#define STBI_FAILURE_USERMSG
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wshadow"
#pragma GCC diagnostic ignored "-Wdouble-promotion"
#pragma GCC diagnostic ignored "-Wmissing-field-initializers"
#include <stb_image.h>
#pragma GCC diagnostic pop

namespace onelight::assets {

DecodedImage decodeImage(const uint8_t* bytes, size_t size, const std::string& where) {
    if (size == 0 || size > size_t(1) << 30)
        throw world::Error(where + ": empty or oversized image data");
    int width = 0, height = 0, channels = 0;
    stbi_uc* pixels = stbi_load_from_memory(bytes, int(size), &width, &height, &channels, 4);
    if (!pixels)
        throw world::Error(where + ": not a decodable PNG/JPEG image (" + stbi_failure_reason() +
                           ")");
    DecodedImage out;
    out.width = uint32_t(width);
    out.height = uint32_t(height);
    out.rgba.assign(pixels, pixels + size_t(width) * size_t(height) * 4);
    stbi_image_free(pixels);
    return out;
}

LoadedLevel loadLevel(const std::string& path) {
    package::PackageContents read = package::readPackageFile(path);
    LoadedLevel out;
    out.path = path;
    out.level = std::move(read.level);
    package::BakedContents baked =
        package::decodeBakedSections(read.bakedSections, out.level, path);
    if (baked.present && baked.baked.shardCount > 1)
        throw world::Error(path + ": holds part " + std::to_string(baked.baked.shardIndex + 1) +
                           " of " + std::to_string(baked.baked.shardCount) +
                           " of a sharded bake; expected a complete package (join the parts "
                           "with `onelight-bake merge`)");
    out.hasBakedLighting = baked.present;
    if (baked.present) out.baked = std::move(baked.baked);
    out.images.reserve(out.level.images.size());
    const std::filesystem::path folder = std::filesystem::path(path).parent_path();
    for (size_t i = 0; i < out.level.images.size(); ++i) {
        const world::Image& image = out.level.images[i];
        const std::string where = path + ": image " + std::to_string(i) + " '" + image.name + "'";
        if (!image.encodedBytes.empty()) {
            out.images.push_back(
                decodeImage(image.encodedBytes.data(), image.encodedBytes.size(), where));
            continue;
        }
        const std::filesystem::path file = folder / image.uri;
        std::ifstream in(file, std::ios::binary);
        if (!in)
            throw world::Error(file.string() + ": cannot open the image referenced by " + where +
                               "; expected a PNG or JPEG file");
        const std::vector<uint8_t> bytes((std::istreambuf_iterator<char>(in)),
                                         std::istreambuf_iterator<char>());
        out.images.push_back(decodeImage(bytes.data(), bytes.size(), file.string()));
    }
    return out;
}

}  // namespace onelight::assets
