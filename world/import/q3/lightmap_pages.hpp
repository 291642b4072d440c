// q3map2's lightmap pages of a map, wherever q3map2 left them: in the BSP's lightmap lump (pages
// of 128 x 128), or, compiled with -external (-lightmapsize N), as images beside the map,
// maps/NAME/lm_0000.tga, lm_0001.tga, ... (the game's search path, or a NAME/ folder beside a
// .bsp file). Deluxe-mapped maps (q3map2 -deluxe) interleave them: page 2k is the light's colour,
// 2k + 1 the light's direction, and surfaces index only even pages. A map is taken as deluxe
// mapped as DarkPlaces takes it: worldspawn's "deluxeMaps" key (1 or 2) when present, else
// q3map2's -deluxe in worldspawn's "_q3map2_cmdline", else when it has an even number of pages
// of which its surfaces use only even ones (nothing is lost if that guess is wrong: an unused
// odd page is dropped). The colour pages are kept apart from the direction pages.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "world/import/q3/bsp_file.hpp"
#include "world/import/q3/entity_lump.hpp"
#include "world/import/q3/pk3_archive.hpp"

namespace onelight::world::q3 {

/// The most external lightmap pages read (lm_0000 .. lm_1023).
inline constexpr uint32_t kMaxExternalLightmaps = 1024;

struct LightmapPages {
    uint32_t pageSize = 0;           // texels per side
    std::vector<uint8_t> colour;     // RGB8 pages, row-major, pageSize^2 texels each
    std::vector<uint8_t> direction;  // deluxe maps: the direction pages, same layout; else
                                     // empty
    bool deluxe = false;             // surfaces' page numbers count colour and direction
    bool external = false;           // read from lm_NNNN.tga images
    std::vector<std::string> notes;  // what was not read and why, one line each

    [[nodiscard]] uint32_t colourPageCount() const {
        return pageSize ? uint32_t(colour.size() / (size_t(pageSize) * pageSize * 3)) : 0;
    }
    /// The colour page of a surface's lightmap number, or UINT32_MAX when it has none (< 0, or
    /// past the pages read): then its vertex light stands in.
    [[nodiscard]] uint32_t colourPage(int32_t lightmap) const;
};

/// `where` names the map in messages; `mapName` is NAME; `bspFile` the .bsp on disk or empty.
/// Throws world::Error naming the image when an external lightmap is not a readable image.
[[nodiscard]] LightmapPages readLightmapPages(const BspFile& bsp,
                                              const std::vector<MapEntity>& entities,
                                              const GameFiles& files, const std::string& mapName,
                                              const std::string& bspFile, const std::string& where);

}  // namespace onelight::world::q3
