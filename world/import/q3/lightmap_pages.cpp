#include "world/import/q3/lightmap_pages.hpp"

#include <cstdio>
#include <filesystem>
#include <optional>

#include "world/error.hpp"
#include "world/file_read.hpp"
#include "world/images/image_decode.hpp"

namespace onelight::world::q3 {
namespace {

namespace fs = std::filesystem;

// A page's RGB8 texels from a decoded image's RGBA.
std::vector<uint8_t> rgbOf(const DecodedImage& image) {
    std::vector<uint8_t> rgb;
    rgb.reserve(image.rgba.size() / 4 * 3);
    for (size_t i = 0; i + 3 < image.rgba.size(); i += 4)
        rgb.insert(rgb.end(), {image.rgba[i], image.rgba[i + 1], image.rgba[i + 2]});
    return rgb;
}

// The bytes of external page `index`: maps/NAME/lm_NNNN.tga in the game's files, else in a NAME/
// folder beside the .bsp file. Sets `from` to where it was found.
std::optional<std::vector<uint8_t>> externalPage(const GameFiles& files, const std::string& name,
                                                 const std::string& bspFile, uint32_t index,
                                                 std::string& from) {
    char file[32];
    std::snprintf(file, sizeof file, "lm_%04u.tga", index);
    const std::string inGame = "maps/" + name + "/" + file;
    if (auto bytes = files.read(inGame, kMaxEncodedImageBytes, "an image")) {
        from = files.where(inGame);
        return bytes;
    }
    if (bspFile.empty()) return std::nullopt;
    const fs::path beside = fs::path(bspFile).parent_path() / name / file;
    std::error_code ec;
    if (!fs::is_regular_file(beside, ec)) return std::nullopt;
    from = beside.string();
    return readRegularFile(from, "an external lightmap (q3map2 -external)", kMaxEncodedImageBytes);
}

bool takesDeluxe(const BspFile& bsp, const std::vector<MapEntity>& entities, size_t pages) {
    bool onlyEven = true;
    for (const BspSurface& f : bsp.surfaces)
        if (f.type != kSurfaceFlare && f.lightmap >= 0 && (f.lightmap & 1)) onlyEven = false;
    if (!onlyEven || pages < 2) return false;  // a surface on an odd page: not deluxe
    if (!entities.empty()) {
        const MapEntity& world = entities[0];
        if (world.keys.count("deluxeMaps") || world.keys.count("deluxemaps")) {
            const std::string v =
                world.get(world.keys.count("deluxeMaps") ? "deluxeMaps" : "deluxemaps");
            return v == "1" || v == "2";
        }
        std::string command = " ";
        command += world.get("_q3map2_cmdline");
        command += " ";
        if (command.find(" -deluxe ") != std::string::npos &&
            command.find(" -nodeluxe ") == std::string::npos)
            return true;
    }
    return pages % 2 == 0;
}

}  // namespace

uint32_t LightmapPages::colourPage(int32_t lightmap) const {
    if (lightmap < 0) return UINT32_MAX;
    const uint32_t page = deluxe ? uint32_t(lightmap) / 2 : uint32_t(lightmap);
    return page < colourPageCount() ? page : UINT32_MAX;
}

LightmapPages readLightmapPages(const BspFile& bsp, const std::vector<MapEntity>& entities,
                                const GameFiles& files, const std::string& mapName,
                                const std::string& bspFile, const std::string& where) {
    LightmapPages out;
    std::vector<std::vector<uint8_t>> pages;  // all of them, colour and direction
    if (!bsp.lightmaps.empty()) {
        out.pageSize = kLightmapPageSize;
        for (size_t at = 0; at + kLightmapPageBytes <= bsp.lightmaps.size();
             at += kLightmapPageBytes)
            pages.emplace_back(bsp.lightmaps.begin() + ptrdiff_t(at),
                               bsp.lightmaps.begin() + ptrdiff_t(at + kLightmapPageBytes));
    } else {
        bool used = false;
        for (const BspSurface& f : bsp.surfaces) used |= f.type != kSurfaceFlare && f.lightmap >= 0;
        uint64_t bytes = 0;
        for (uint32_t i = 0; used && i < kMaxExternalLightmaps; ++i) {
            std::string from;
            const std::optional<std::vector<uint8_t>> encoded =
                externalPage(files, mapName, bspFile, i, from);
            if (!encoded) break;
            const DecodedImage image = decodeImage(encoded->data(), encoded->size(), from);
            if (image.width != image.height || (i > 0 && image.width != out.pageSize)) {
                std::string expected = "a square page";
                if (i > 0) {
                    const std::string side = std::to_string(out.pageSize);
                    expected = "the ";
                    expected += side;
                    expected += " x ";
                    expected += side;
                    expected += " of lm_0000";
                }
                std::string note = from;
                note += ": ";
                note += std::to_string(image.width);
                note += " x ";
                note += std::to_string(image.height);
                note += " texels; expected ";
                note += expected;
                note += ": the external lightmaps are left out (vertex light instead)";
                out.notes.push_back(std::move(note));
                pages.clear();
                break;
            }
            bytes += uint64_t(image.width) * image.height * 3;
            if (bytes > (uint64_t(1) << 30))
                throw Error(from + ": the external lightmaps pass 1 GiB; expected at most that");
            out.pageSize = image.width;
            pages.push_back(rgbOf(image));
            out.external = true;
        }
        if (used && pages.empty() && out.notes.empty())
            out.notes.push_back(where + ": no lightmap lump and no external lightmaps (maps/" +
                                mapName + "/lm_0000.tga): q3map2's vertex light stands in");
    }
    out.deluxe = takesDeluxe(bsp, entities, pages.size());
    for (size_t p = 0; p < pages.size(); ++p) {
        std::vector<uint8_t>& to = out.deluxe && p % 2 == 1 ? out.direction : out.colour;
        to.insert(to.end(), pages[p].begin(), pages[p].end());
    }
    if (pages.empty()) out.pageSize = 0;
    uint32_t past = 0;
    for (const BspSurface& f : bsp.surfaces)
        past += f.type != kSurfaceFlare && f.lightmap >= 0 && out.pageSize &&
                out.colourPage(f.lightmap) == UINT32_MAX;
    if (past > 0)
        out.notes.push_back(
            where + ": " + std::to_string(past) + " surface(s) name a lightmap page past the " +
            std::to_string(out.colourPageCount()) + " read: their vertex light stands in");
    return out;
}

}  // namespace onelight::world::q3
