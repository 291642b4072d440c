// A level as imported (SourceLevel: a glTF or a Quake 3 map) written back as glTF 2.0, so that
// an outside renderer (Blender's Cycles, scripts/cycles-render.py) can draw what the engine
// traces: its static triangles in world space, its materials and their textures (each decoded
// and written as a PNG), its lights (KHR_lights_punctual, the range included), its cameras and
// its sky, in the units the importer reads them in (docs/lighting.md, "The reference against an
// outside path tracer"). Re-importing the file gives the same static scene.
//
// Not written: dynamic objects (items, movers: the static reference leaves them out too), the
// map's collision, triggers and visible set, the source's own lightmaps, probes' placements.
#pragma once

#include <cstddef>
#include <filesystem>
#include <string>

#include "world/source_level.hpp"

namespace onelight::world {

struct LevelExportStats {
    size_t instances = 0, triangles = 0, materials = 0, images = 0, lights = 0, cameras = 0;
    size_t dynamicLeftOut = 0;  // dynamic instances not written
    size_t imagesMissing = 0;   // images that could not be read or decoded (textures dropped)
};

/// Writes `level` as `folder`/NAME.gltf, NAME.bin and NAME_images/*.png (.hdr for the sky),
/// every file atomically. `level`'s relative image uris are read from `sourceFolder`. Throws
/// world::Error naming the file on a write failure.
LevelExportStats exportLevelGltf(const SourceLevel& level,
                                 const std::filesystem::path& sourceFolder,
                                 const std::filesystem::path& folder, const std::string& name);

}  // namespace onelight::world
