// Quake 3 / OpenArena / Nexuiz maps as levels: a map named as a .bsp file, as
// PAK.pk3:maps/NAME.bsp, or as NAME alone (searched in the installed games) is read into the same
// SourceLevel as a glTF, with its textures, shader scripts and external lightmaps from its game's
// search path (game_search_path.hpp), q3map2's lightmaps wherever q3map2 left them
// (lightmap_pages.hpp), and a computed view when it has no player spawn (computed_view.hpp).
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "world/source_level.hpp"

namespace onelight::world {

/*
   Units: one map unit is 1/32 m. Evidence: the player's box is 56 units tall (-24 .. +32 about
   its origin, eyes at +26), 1.75 m at 1/32 m; stair steps are 16 units (0.5 m, game-sized) and
   doors 96 .. 128 units (3 .. 4 m).
   Axes: Quake's Z is up; a map point (x, y, z) is (x, z, -y) / 32 in the level (a rotation, so
   windings keep their sense).
   Lightmap density: q3map2's, one luxel per 16 units (2 texels per metre) times worldspawn's
   _lightmapscale.
   Lights: q3map2 lights a surface at distance d (units) and cosine c from a point light of
   "light" L with L 7500 c / d^2 lightmap units (of 255 at full white). One unit is taken as
   1 lux, so the light's intensity is L 7500 / 32^2 = 7.32 L cd (the default L = 300 gives
   2197 cd: 137 lux at 4 m).
   Linear lights (spawnflags bit 1): q3map2 gives L 7500 / 8000 - d fade lightmap units (no
   cosine: it clears a linear light's angle attenuation), reaching zero at R = 0.9375 L / fade
   units. Approximated (and reported) as an inverse-square light with range R (the
   KHR_lights_punctual window, and a cosine) matched to q3map2 at R / 2:
   I = 0.46875 L x (R / 64 m)^2 / (1 - 1/16)^2 cd (q3map2 gives 0.46875 L there, for any fade).
   Spots (a light with a target): the cone's radius at the target is "radius" (64 where 0) + 16
   units, the light ramping down over its last 32 units (an inner cone through radius - 16);
   the linear flag is cleared, and "_sun" 1 makes a sun along the axis of the value in lux.
   q3map2's recorded options (worldspawn _q3map2_cmdline, its -light stage;
   q3map2_command_line.hpp): its light scales multiply the lights above, its lightmap encoding
   (gamma, exposure, compensate, brightness, contrast, sRGB) is inverted where q3map2's lightmaps
   are read, and a light's own "scale" key multiplies it, all as q3map2 does.
   Worldspawn ambient, _ambient and _minlight (constants q3map2 adds to every luxel, light from
   nowhere) are ignored and reported: the bake's bounces light what they stood in for.
   Where the lights come from (q3map2 strips light entities from the BSP it compiles): the
   BSP's entities; else the map's source .map (maps/NAME.map or sources/maps/NAME.map in the
   BSP's pk3, then the game's; NAME.map beside a loose NAME.bsp; map_source.hpp), its light
   entities as the BSP's would be, those more than half the map's size (>= 16 m) outside its
   geometry left out, a source that fails to parse ignored with a note; else q3map2's own
   lightmaps are the level's (SourceLevel::lightmapIsImported: the bake copies them and the
   remaining lights, all baked, light the grid and probes only). A map with surfaces to draw
   and no light source at all is SourceLevel::lightless, which the bake refuses; one with no
   visible surface (a placeholder) bakes empty. SourceLevel::lightSources says which,
   one line per kind.
   Which lights are primaries (the lights the runtime draws with shadow maps): a light is a
   candidate when it is the brightest on at least kQuake3PrimaryAreaShare of the map's surface
   area (each triangle's centroid, cosine-weighted illuminance, no shadows: an estimate, the
   compile assigns the real primaries with shadows), the largest shares first, at most
   Quake3Options::primaryLights (the sun counts among them); the others are baked. A light that
   is the brightest almost nowhere needs no shadow map of its own.
   Shaders (the .shader files in scripts/; a name without a script is the image of that name, .tga
   or .jpg): the colour stage (shader_script.hpp colorStage, else qer_editorimage, else the name) is
   a Lambert base colour; alphaFunc makes it MASK (GT0: any alpha, GE128 and LT128: 1/2), another
   blend of that stage BLEND (stochastic coverage, bake/README.md); cull none makes it double-sided;
   q3map_surfacelight S is emission of 0.25 S cd/m^2 (q3map2 gives an area light S x area x 0.25
   photons where a point light has light x 7500), times its q3map_lightimage (or its colour
   texture), its factor per channel q3map2's colour over the image's mean sRGB-decoded value:
   q3map2 lights with the mean of the image's bytes as stored (display-referred, not decoded)
   normalised to a brightest channel of 1, so the emission averages to 0.25 S times that.
   A translucent shader (surfaceparm trans, water, slime, lava and the other parms q3map2 marks
   translucent, or, without a script, the BSP's translucent and liquid contents) casts no shadow
   unless it is alphashadow or lightfilter: q3map2 traces no such surface, so light passes it in
   the bake and the runtime's shadow maps too (world::Material::castsShadows), although it is drawn.
   Surfaceparm nodraw, sky, fog, hint and skip leave a surface out. A sky shader's q3map_sun is a
   primary directional light (intensity in lux), its q3map_skylight V n a uniform sky that gives an
   open floor what q3map2's dome of n - 1 rings of suns gives it (0.51 V at 2 iterations, 0.59 V at
   8; none below 2), in its light image's normalised mean colour; without one, its
   q3map_surfacelight S (q3map2 makes the sky's faces area lights) a uniform sky of 0.25 S cd/m^2 in
   its light image's mean bytes normalised to a brightest channel of 1.
*/
inline constexpr double kQuake3MetresPerUnit = 1.0 / 32.0;
inline constexpr double kQuake3CandelaPerLight = 7500.0 / (32.0 * 32.0);
inline constexpr double kQuake3NitsPerSurfaceLight = 0.25;
inline constexpr double kQuake3PrimaryAreaShare = 0.02;
inline constexpr double kQuake3LinearScale = 7500.0 / 8000.0;  // q3map2's pointScale x linearScale

struct Quake3Options {
    uint32_t patchLevel = 4;     // segments per patch piece and direction, 1 .. 64
    uint32_t primaryLights = 8;  // at most this many primary candidates (q3_import.hpp, Lights)
    std::vector<std::string> gameFolders;  // the game's folders (pk3s and loose files, later
                                           // wins); empty: the installed game the map is in
                                           // (game_search_path.hpp)
};

/// The installed OpenArena game data folders that exist (Debian's openarena-data and maps).
[[nodiscard]] std::vector<std::string> defaultQuake3Folders();

/// Throws Error with a one-line message naming the file and the place on bad input.
[[nodiscard]] SourceLevel importQuake3(const std::string& spec, const Quake3Options& options = {});

}  // namespace onelight::world
