// How q3map2 lit a map, as far as the map records it: q3map2 writes its command line into
// worldspawn's "_q3map2_cmdline" ("-meta ...; -vis ...; -light -gamma 1.5 -bounce 8 ..."), and
// the options of the -light stage change how bright its lights are and how its lightmap bytes
// store the light. The import lights the map with the same scales and decodes q3map2's lightmaps
// with the same encoding (so that `--view q3map2` shows the light q3map2 computed, not its
// display encoding), and reports what it cannot reproduce (dirt, q3map2's bounce scale).
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "world/import/q3/entity_lump.hpp"
#include "world/source_level.hpp"

namespace onelight::world::q3 {

struct Q3map2LightOptions {
    bool recorded = false;           // worldspawn has a _q3map2_cmdline with a -light stage
    std::string lightStage;          // that stage's text, trimmed
    ImportedLightEncoding encoding;  // -brightness, -gamma, -exposure, -compensate, -contrast,
                                     // -sRGBlight / -sRGB
    // The lights' scales over q3map2's defaults (-scale multiplies all four; -point / -pointscale
    // the point and spot lights, -spherical the point lights, -spot the spot lights, -area the
    // surface lights, -sky the sun and sky).
    float pointScale = 1.0f, spotScale = 1.0f, areaScale = 1.0f, skyScale = 1.0f;
    uint32_t bounces = 0;      // -bounce N: q3map2's radiosity passes
    float bounceScale = 1.0f;  // -bouncescale (and -scale) over its default 0.25
    bool dirt = false;         // -dirty / -dirt: ambient occlusion darkening its lightmaps
    // A "-scale S" stage after the -light stage (q3map2's ScaleBSP): the map was lit at 1/S of
    // the size it is stored at, its geometry and entity origins scaled by S afterwards and its
    // light values not, so a light's distances to what it lit were 1/S of the stored ones.
    float scaledAfterLight = 1.0f;
    std::vector<std::string> notes;   // options read but unusable (a value that is not a number)
    bool compensateInferred = false;  // encoding.compensate from the pages
                                      // (compensateShownByPages), not the command line

    /// One line for the import's report: what the stage changes, or that nothing was recorded
    /// (q3map2's defaults assumed: no bounces, no dirt, linear bytes).
    [[nodiscard]] std::string summary() const;
};

/// Reads worldspawn's "_q3map2_cmdline" (entities[0]); a map without one gives recorded = false
/// and q3map2's defaults. A value that does not parse as a positive number (or a whole bounce
/// count) is left at its default with a note naming `where` and the option.
[[nodiscard]] Q3map2LightOptions readQ3map2LightOptions(const std::vector<MapEntity>& entities,
                                                        const std::string& where);

/// q3map2's -compensate C as a map's lightmap pages (RGB8) show it, for a map whose command line
/// is not recorded: q3map2 clamps a value's brightest channel at 255 and then divides by C, so the
/// brightest channels of a map compiled with C > 1 pile up at M = floor(255 / C) and never pass
/// it. A pile-up (M < 255 the largest brightest channel, held by at least 16 texels and 8 times
/// as many as hold M - 1) gives C = 255 / (M + 1/2), snapped to a multiple of 1/4 within 1%;
/// anything else gives 1.
[[nodiscard]] float compensateShownByPages(const std::vector<uint8_t>& rgbPages);

}  // namespace onelight::world::q3
