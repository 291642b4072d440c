#include "assets/level_assets.hpp"

#include <filesystem>
#include <fstream>
#include <iterator>

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

bool decodeImage(const uint8_t* bytes, size_t size, DecodedImage& out, std::string& error) {
    if (size == 0 || size > size_t(1) << 30) {
        error = "empty or oversized image data";
        return false;
    }
    int width = 0, height = 0, channels = 0;
    stbi_uc* pixels = stbi_load_from_memory(bytes, int(size), &width, &height, &channels, 4);
    if (!pixels) {
        error = std::string("not a decodable PNG/JPEG image (") + stbi_failure_reason() + ")";
        return false;
    }
    out.width = uint32_t(width);
    out.height = uint32_t(height);
    out.rgba.assign(pixels, pixels + size_t(width) * size_t(height) * 4);
    stbi_image_free(pixels);
    return true;
}

bool loadLevel(const std::string& path, LoadedLevel& out, std::string& error) {
    package::PackageReadResult read = package::read_package_file(path);
    if (!read.ok()) {
        error = read.error;
        return false;
    }
    out.path = path;
    out.level = std::move(read.level);
    package::BakedReadResult baked =
        package::decode_baked_sections(read.baked_sections, out.level, path);
    if (!baked.ok()) {
        error = baked.error;
        return false;
    }
    if (baked.present && baked.baked.shard_count > 1) {
        error = path + ": holds part " + std::to_string(baked.baked.shard_index + 1) + " of " +
                std::to_string(baked.baked.shard_count) +
                " of a sharded bake; expected a complete package (join the parts with "
                "`onelight-bake merge`)";
        return false;
    }
    out.hasBakedLighting = baked.present;
    out.baked = baked.present ? std::move(baked.baked) : world::BakedLighting{};
    out.images.clear();
    out.images.resize(out.level.images.size());
    const std::filesystem::path folder = std::filesystem::path(path).parent_path();
    for (size_t i = 0; i < out.level.images.size(); ++i) {
        const world::Image& image = out.level.images[i];
        std::vector<uint8_t> fileBytes;
        const std::vector<uint8_t>* bytes = &image.encoded_bytes;
        std::string where = path + ": image " + std::to_string(i) + " '" + image.name + "'";
        if (image.encoded_bytes.empty()) {
            const std::filesystem::path file = folder / image.uri;
            std::ifstream in(file, std::ios::binary);
            if (!in) {
                error = file.string() + ": cannot open the image referenced by " + where +
                        "; expected a PNG or JPEG file";
                return false;
            }
            fileBytes.assign(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
            bytes = &fileBytes;
            where = file.string();
        }
        std::string why;
        if (!decodeImage(bytes->data(), bytes->size(), out.images[i], why)) {
            error = where + ": " + why;
            return false;
        }
    }
    return true;
}

}  // namespace onelight::assets
