// The source format's own bake (world::ImportedLightmap: a Quake 3 map's q3map2 lightmaps and
// vertex light) read at every lightmap texel of the compiled level, in the engine's texel
// layout, so that the runtime can show it in place of the engine's bake (`--view q3map2`).
#pragma once

#include <vector>

#include <embree3/rtcore.h>

#include "bake/lightmap/texel_placement.hpp"
#include "world/baked_lighting.hpp"
#include "world/compiled_level.hpp"
#include "world/source_level.hpp"

namespace onelight::bake {

/*
   For each texel sample, a ray from 1 cm above its surface point straight down its normal (and,
   when that finds nothing, from 1 cm below straight up) finds the source triangle under it, in
   an Embree scene of the imported triangles alone (the compile splits and merges triangles, so
   the compiled ones do not know their source). The hit's barycentrics interpolate the corners'
   page coordinates, and the page is read bilinearly (texel centres at (i + 1/2) / size, clamped
   at the page's edge); a triangle without a page interpolates its corners' vertex light. The
   value times luxPerValue is the texel's irradiance, non-directional (direction 0, normal weight
   0.5: E(n') = irradiance for every n'). Values are decoded (decodeImportedValue) before they
   are interpolated. Texels no ray reaches stay unsampled (flags 0), to be
   dilated like the engine's own.
*/
/// The value a source stored as `stored` (bytes as floats, 0 .. 255), before `encoding`: its
/// inverse, step by step (world::ImportedLightEncoding). A channel stored at 255 under an
/// exposure is read as 254.5 (the exposure's inverse is infinite there). Never negative, NaN or
/// infinite.
[[nodiscard]] glm::vec3 decodeImportedValue(glm::vec3 stored,
                                            const world::ImportedLightEncoding& encoding);

/// Texels of every atlas in order (the layout of BakedLighting::texels); empty when `imported`
/// has no triangles. Deterministic at any thread count.
[[nodiscard]] std::vector<world::LightmapTexel> resampleImportedLightmap(
    RTCDevice device, const world::CompiledLevel& level, const std::vector<TexelSample>& samples,
    const world::ImportedLightmap& imported);

}  // namespace onelight::bake
