// Quake 3 shader scripts (scripts/*.shader): each shader's name, surfaceparms, stages and the
// q3map keys the importer uses. Keywords it does not use are skipped (the scripts hold
// hundreds, for the game's renderer), and numbers read as q3map2 reads them (a word that is no
// number is 0); structure is checked: braces balance, a shader has a name and its keys their
// values, and every fault names "file:line".
#pragma once

#include <map>
#include <optional>
#include <set>
#include <string>
#include <vector>

#include <glm/glm.hpp>

namespace onelight::world::q3 {

struct ShaderStage {
    std::string map;        // "map" / "clampmap" / the first of "animmap"; "$lightmap" etc. kept
    std::string tcGen;      // "environment", "lightmap", ... (lower case), empty = base
    std::string blendFunc;  // lower case, the words as written ("add", "gl_one gl_one"), empty
    std::string alphaFunc;  // "gt0", "lt128", "ge128", empty
};

struct ShaderSun {
    glm::vec3 color{1.0f};
    float intensity = 0.0f;  // q3map2's units
    float degrees = 0.0f;    // heading about +Z from +X
    float elevation = 0.0f;  // degrees above the horizon
};

struct ShaderScript {
    std::string name;  // as written
    std::string file;  // where it was defined ("pak0.pk3:scripts/x.shader")
    int line = 0;
    std::set<std::string> surfaceParms;  // lower case
    std::vector<ShaderStage> stages;
    std::string editorImage;       // qer_editorimage
    std::string lightImage;        // q3map_lightimage
    float surfaceLight = 0.0f;     // q3map_surfacelight
    std::optional<ShaderSun> sun;  // q3map_sun / q3map_sunExt
    float skyLight = 0.0f;         // q3map_skylight's value
    int skyLightIterations = 0;    // and its iterations (q3map2 makes no sky light below 2)
    bool cullNone = false;         // cull none / disable / twosided

    /// The stage whose texture is the surface's colour: the first with a texture that is not
    /// the lightmap, a white image or an environment map; nullptr when none.
    [[nodiscard]] const ShaderStage* colorStage() const;
};

/// Parses one script's text. Throws world::Error "file:line: ..." on a malformed script.
[[nodiscard]] std::vector<ShaderScript> parseShaderScript(const std::string& text,
                                                          const std::string& file);

}  // namespace onelight::world::q3
