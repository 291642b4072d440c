// The level as imported from glTF, before compile: world-placed mesh instances plus the
// materials, lights, cameras and entities they use. Only what the active scene uses is kept.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "world/compiled_level.hpp"
#include "world/imported_visibility.hpp"

namespace onelight::world {

/// One glTF mesh primitive placed by one node. Vertices stay in the node's space.
struct MeshInstance {
    std::string nodeName;
    std::string meshName;
    uint32_t primitive = 0;        // index within the glTF mesh
    uint32_t material = kNoIndex;  // into SourceLevel::materials (a default is added if needed)
    glm::dmat4 worldFromLocal{1.0};
    std::vector<Vertex> vertices;    // local space
    std::vector<uint32_t> indices;   // triangles
    bool hasUv1 = false;             // TEXCOORD_1 was present
    bool dynamic = false;            // not part of the BSP, lit by the grid
    uint32_t entity = kNoIndex;      // into SourceLevel::entities when dynamic
    bool prop = false;               // static, one primary for all of it, chosen at:
    glm::dvec3 lightingOrigin{0.0};  // world metres (a prop's node: given, or its bounds' centre)
};

/// How the source stored its light values as bytes, inverted by bake::decodeImportedValue. For
/// q3map2, its ColorToBytes under the -light stage's options (q3map2_command_line.hpp): a value v
/// is scaled by brightness, raised to 1/gamma (on v/255), clamped by its brightest channel to 255
/// or, with an exposure E > 0, that channel mapped to 255 (1 - exp(-max / E)), divided by
/// compensate, stretched about 128 by contrast, and sRGB-encoded when srgb.
struct ImportedLightEncoding {
    float brightness = 1.0f;
    float gamma = 1.0f;
    float exposure = 0.0f;  // 0: clamped, not exposed
    float compensate = 1.0f;
    float contrast = 1.0f;
    bool srgb = false;
};

/// Light the source format baked itself (a Quake 3 map: q3map2's lightmaps and vertex light),
/// kept so that the engine's bake can be compared with it (`onelight LEVEL --view q3map2`). Each
/// triangle of the level's static geometry, with where its corners read the light.
struct ImportedLightmap {
    struct Triangle {
        glm::vec3 corners[3];      // metres, world, as in the level's instances
        glm::vec2 uv[3];           // in the page, [0, 1]^2
        glm::vec3 vertexLight[3];  // the light at the corners, used when page is kNoIndex
        uint32_t page = kNoIndex;  // into pages
    };
    std::string producer;                 // who baked it ("q3map2"); empty: none
    uint32_t pageSize = 0;                // texels per side of a page
    std::vector<uint8_t> pages;           // RGB8, pageSize^2 per page, row-major
    std::vector<uint8_t> directionPages;  // q3map2 -deluxe: each page's light direction, same
                                          // layout as pages; empty when the source has none
    ImportedLightEncoding encoding;       // how pages and vertex light store their values
    float luxPerValue = 1.0f;             // irradiance of one unit of a decoded value
    std::vector<Triangle> triangles;
};

struct SourceLevel {
    std::string sourcePath;               // the .gltf, for messages
    std::vector<std::string> inputFiles;  // every file the import read (the level, its buffers
                                          // and images, the map or pk3s): never an output
    std::vector<Material> materials;
    std::vector<Texture> textures;
    std::vector<Image> images;  // uri relative to the glTF's folder
    std::vector<Light> lights;
    std::vector<Camera> cameras;
    std::vector<MeshInstance> instances;
    std::vector<Entity> entities;  // dynamic-mesh ranges are filled at compile
    float exposureEv100 = 0.0f;
    bool hasExposure = false;
    float texelsPerMetre = 0.0f;  // the level's lightmap density (extras), 0 when not given
    float probeSpacing = 0.0f;    // metres between automatic probes (extras), 0 when not given
    DiffuseModel diffuseModel = DiffuseModel::kLambert;  // extras.onelight.diffuse
    GlossMipMethod glossMips = GlossMipMethod::kClean;   // extras.onelight.gloss_mips
    glm::vec3 skyRadiance{0.0f};   // cd/m^2, RGB: a uniform sky around the level (extras), or
                                   // the scale of skyImage's texels
    uint32_t skyImage = kNoIndex;  // into images: an equirectangular Radiance .hdr sky
    bool hasGridBounds = false;
    glm::vec3 gridMin{0.0f}, gridMax{0.0f};
    ImportedLightmap importedLightmap;      // the source's own bake, if it carries one
    LevelCollision collision;               // a Quake 3 map's brushes and triggers, as compiled
    LevelMovers movers;                     // the movers of kEntityMover entities, as compiled
    ImportedVisibility importedVisibility;  // the source's own visible set (q3map2 -vis), if any
    std::vector<std::string> importNotes;   // what the import approximated or ignored, one line
                                            // each; the bake reports them as warnings
    std::vector<std::string> lightSources;  // where each kind of light came from, one line each
                                            // (a Quake 3 map's: entities, surface lights, sky)
    std::string lightless;  // not empty: why nothing lights the level (a Quake 3 map without
                            // any light source); the bake refuses it with this message
    bool lightmapIsImported = false;  // the lightmaps are importedLightmap's, not baked: the
                                      // source's lights are lost (q3_import.hpp)
};

}  // namespace onelight::world
