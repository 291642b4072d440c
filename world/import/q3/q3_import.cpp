#include "world/import/q3/q3_import.hpp"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <map>
#include <numbers>
#include <set>
#include <string>

#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/quaternion.hpp>

#include "shading.hpp"
#include "world/error.hpp"
#include "world/file_read.hpp"
#include "world/images/image_decode.hpp"
#include "world/import/level_limits.hpp"
#include "world/import/q3/bsp_file.hpp"
#include "world/import/q3/collision_import.hpp"
#include "world/import/q3/computed_view.hpp"
#include "world/import/q3/entity_lump.hpp"
#include "world/import/q3/game_search_path.hpp"
#include "world/import/q3/item_import.hpp"
#include "world/import/q3/lightmap_pages.hpp"
#include "world/import/q3/map_axes.hpp"
#include "world/import/q3/map_source.hpp"
#include "world/import/q3/mover_import.hpp"
#include "world/import/q3/patch_tessellation.hpp"
#include "world/import/q3/pk3_archive.hpp"
#include "world/import/q3/q3map2_command_line.hpp"
#include "world/import/q3/shader_script.hpp"
#include "world/import/q3/visibility_import.hpp"
#include "world/light_model.hpp"

namespace onelight::world {
namespace {

using namespace q3;

bool endsWith(const std::string& s, const std::string& end) {
    return s.size() >= end.size() && fileKey(s.substr(s.size() - end.size())) == end;
}

// The map's name for messages.
struct MapSource {
    std::string where;
};

// The game's shader scripts by name (lower case); the first definition of a name wins, as in
// the game.
using ShaderScripts = std::map<std::string, ShaderScript>;
ShaderScripts loadShaderScripts(const GameFiles& files) {
    ShaderScripts out;
    for (const auto& [key, file] : files.files) {
        if (key.rfind("scripts/", 0) != 0 || !endsWith(key, ".shader")) continue;
        const std::vector<uint8_t> bytes =
            *files.read(key, kMaxShaderScriptBytes, "a shader script");
        for (ShaderScript& s :
             parseShaderScript(std::string(bytes.begin(), bytes.end()), files.where(key)))
            out.emplace(fileKey(s.name), std::move(s));
    }
    return out;
}

const ShaderScript* scriptNamed(const ShaderScripts& scripts, const std::string& name) {
    const auto found = scripts.find(fileKey(name));
    return found == scripts.end() ? nullptr : &found->second;
}

const ShaderScript* scriptOf(const ShaderScripts& scripts, const BspShader& shader) {
    return scriptNamed(scripts, shaderName(shader));
}

// Whether a shader's surfaces are drawn, or left out: sky, clip, triggers, nodraw, fog, hints.
bool drawn(const BspShader& shader, const ShaderScript* script) {
    if (shader.surfaceFlags & (kSurfNoDraw | kSurfSky | kSurfHint | kSurfSkip)) return false;
    if (shader.contentFlags & kContentsFog) return false;
    if (script)
        for (const char* parm : {"nodraw", "sky", "fog", "hint", "skip", "areaportal"})
            if (script->surfaceParms.count(parm)) return false;
    const std::string name = fileKey(shaderName(shader));
    for (const char* skip : {"common/clip", "common/trigger", "common/nodraw", "common/caulk",
                             "common/hint", "common/skip", "textures/skies/", "/sky", "noshader"})
        if (name.find(skip) != std::string::npos) return false;
    return true;
}

// Whether q3map2 lets a shader's surfaces shadow: light_trace.c traces no translucent surface
// unless it is alphashadow or lightfilter, translucent being the surfaceparms its game table
// marks C_TRANSLUCENT. From the script; castsShadowInBsp reads the flags q3map2 compiled.
bool castsShadowInQ3map2(const ShaderScript& script) {
    const std::set<std::string>& parms = script.surfaceParms;
    if (parms.count("alphashadow") || parms.count("lightfilter")) return true;
    for (const char* parm :
         {"trans", "water", "slime", "lava", "origin", "areaportal", "trigger", "playerclip",
          "monsterclip", "nodrop", "clusterportal", "donotenter", "botclip"})
        if (parms.count(parm)) return false;
    return true;
}
bool castsShadowInBsp(const BspShader& shader) {
    if (shader.surfaceFlags & (kSurfAlphaShadow | kSurfLightFilter)) return true;
    return !(shader.contentFlags &
             (kContentsTranslucent | kContentsWater | kContentsSlime | kContentsLava));
}

// The image path without a .tga, .png or .jpg extension.
std::string withoutImageExtension(std::string name) {
    for (const char* ext : {".tga", ".png", ".jpg"})
        if (endsWith(name, ext)) name = name.substr(0, name.size() - 4);
    return name;
}

// The mean colour of the image `name` (.tga or .jpg, as textureOf finds it): of its bytes as
// they are (q3map2's: it lights a surface light with that mean, display-referred, scaled to a
// brightest channel of 1) and of its sRGB-decoded texels (what the engine's emissive texture
// gives). White for both when there is no such image.
struct ImageMeans {
    glm::vec3 bytes{1.0f};   // mean byte / 255
    glm::vec3 linear{1.0f};  // mean sRGB-decoded value
};
ImageMeans meanColours(const GameFiles& files, const std::string& name) {
    const std::string base = withoutImageExtension(name);
    for (const char* ext : {".tga", ".png", ".jpg"}) {
        const std::optional<std::vector<uint8_t>> bytes =
            files.read(base + ext, kMaxEncodedImageBytes, "an image");
        if (!bytes) continue;
        const DecodedImage pixels =
            decodeImage(bytes->data(), bytes->size(), files.where(base + ext));
        if (pixels.rgba.empty()) return {};
        glm::dvec3 sumBytes(0.0), sumLinear(0.0);
        for (size_t i = 0; i + 3 < pixels.rgba.size(); i += 4)
            for (int c = 0; c < 3; ++c) {
                const float v = float(pixels.rgba[i + size_t(c)]) / 255.0f;
                sumBytes[c] += double(v);
                sumLinear[c] += double(glsl::srgbDecode(v));
            }
        const double n = double(pixels.rgba.size() / 4);
        return {glm::vec3(sumBytes / n), glm::vec3(sumLinear / n)};
    }
    return {};
}

// `colour` scaled to a brightest channel of 1; white when it is black.
glm::vec3 normalisedColour(glm::vec3 colour) {
    const float peak = std::max({colour.x, colour.y, colour.z});
    return peak > 1e-6f ? colour / peak : glm::vec3(1.0f);
}

// The image a surface light's colour comes from: its q3map_lightimage, else its colour stage's,
// else its editor image, else its name.
std::string lightImageOf(const ShaderScript& script) {
    if (!script.lightImage.empty()) return script.lightImage;
    if (const ShaderStage* stage = script.colorStage()) return stage->map;
    return script.editorImage.empty() ? script.name : script.editorImage;
}

// The level's material for each drawn shader (q3_import.hpp, "Shaders").
struct MaterialTable {
    SourceLevel& level;
    const GameFiles& files;
    std::map<int32_t, uint32_t> byShader;
    std::map<std::string, uint32_t> byName;          // a model's shader or image names (file keys)
    std::map<std::string, uint32_t> textureByImage;  // (name + sRGB) -> textures
    uint32_t missingImages = 0;
    float areaScale = 1.0f;  // q3map2's -area / -scale (q3map2_command_line.hpp)

    // A texture of the image `name` (.tga or .jpg, the extension as written or not), or
    // kNoIndex when no archive holds it.
    uint32_t textureOf(const std::string& name) {
        const std::string base = withoutImageExtension(name);
        const auto known = textureByImage.find(fileKey(base));
        if (known != textureByImage.end()) return known->second;
        uint32_t index = kNoIndex;
        for (const auto& [ext, mime] :
             {std::pair{".tga", "image/x-tga"}, std::pair{".png", "image/png"},
              std::pair{".jpg", "image/jpeg"}}) {
            std::optional<std::vector<uint8_t>> bytes =
                files.read(base + ext, kMaxEncodedImageBytes, "an image");
            if (!bytes) continue;
            Image image;
            image.name = files.where(base + ext);
            image.mimeType = mime;
            image.encodedBytes = std::move(*bytes);
            level.images.push_back(std::move(image));
            Texture texture;
            texture.image = uint32_t(level.images.size() - 1);
            texture.sampler.magFilter = 9729;  // LINEAR
            texture.sampler.minFilter = 9987;  // LINEAR_MIPMAP_LINEAR
            level.textures.push_back(texture);
            index = uint32_t(level.textures.size() - 1);
            break;
        }
        return textureByImage[fileKey(base)] = index;
    }

    uint32_t materialOf(const BspShader& shader, int32_t index, const ShaderScript* script) {
        const auto found = byShader.find(index);
        if (found != byShader.end()) return found->second;
        const uint32_t m = makeMaterial(shaderName(shader), script);
        if (!script) level.materials[m].castsShadows = castsShadowInBsp(shader);
        return byShader[index] = m;
    }

    // A model surface's material: its shader's script where one is named so, else the image.
    uint32_t materialNamed(const std::string& name, const ShaderScript* script) {
        const std::string key = fileKey(withoutImageExtension(name));
        const auto found = byName.find(key);
        if (found != byName.end()) return found->second;
        return byName[key] = makeMaterial(name, script);
    }

    uint32_t makeMaterial(const std::string& name, const ShaderScript* script) {
        Material m;
        m.name = name;
        m.materialClass = MaterialClass::kLambert;
        m.metallic = 0.0f;
        m.roughness = 1.0f;
        m.specularColor = glm::vec3(0.0f);
        const ShaderStage* stage = script ? script->colorStage() : nullptr;
        if (stage) m.baseColorTexture = textureOf(stage->map);
        if (m.baseColorTexture == kNoIndex && script && !script->editorImage.empty())
            m.baseColorTexture = textureOf(script->editorImage);
        if (m.baseColorTexture == kNoIndex) m.baseColorTexture = textureOf(m.name);
        if (m.baseColorTexture == kNoIndex) {
            ++missingImages;
            m.baseColor = glm::vec4(0.5f, 0.5f, 0.5f, 1.0f);
        }
        if (stage && !stage->alphaFunc.empty()) {
            m.alphaMode = AlphaMode::kMask;  // gt0: any alpha; ge128 and lt128: half
            m.alphaCutoff = stage->alphaFunc == "gt0" ? 0.5f / 255.0f : 0.5f;
        } else if (stage && !stage->blendFunc.empty() && stage->blendFunc != "gl_one gl_zero") {
            m.alphaMode = AlphaMode::kBlend;
        }
        if (script) {
            m.doubleSided = script->cullNone;
            m.castsShadows = castsShadowInQ3map2(*script);
            if (script->surfaceLight > 0.0f) {
                // q3map2 gives an area light value x area x 0.25 photons (a point light
                // value x 7500): at 1 lux per lightmap unit and 1/32 m per unit that is a
                // radiance of 0.25 value cd/m^2, in its light image's (or its texture's) mean
                // colour scaled to a brightest channel of 1; the image keeps its pattern.
                m.emissiveTexture =
                    script->lightImage.empty() ? kNoIndex : textureOf(script->lightImage);
                if (m.emissiveTexture == kNoIndex) m.emissiveTexture = m.baseColorTexture;
                // The factor makes the texture's mean emission q3map2's colour: its light
                // image's mean bytes, normalised (q3_import.hpp, "Shaders").
                const ImageMeans mean = meanColours(files, lightImageOf(*script));
                const glm::vec3 colour = normalisedColour(mean.bytes);
                for (int c = 0; c < 3; ++c)
                    m.emissive[c] = mean.linear[c] > 1e-4f
                                        ? float(kQuake3NitsPerSurfaceLight *
                                                double(script->surfaceLight) * double(areaScale)) *
                                              colour[c] / mean.linear[c]
                                        : 0.0f;
            }
        }
        m.albedo = glm::vec3(m.baseColor);
        level.materials.push_back(m);
        return uint32_t(level.materials.size() - 1);
    }
};

Vertex levelVertex(const PatchPoint& p) {
    Vertex v;
    v.position = levelPoint(p.position);
    const float n[3] = {p.normal.x, p.normal.y, p.normal.z};
    const glm::vec3 d = levelDirection(n);
    const float length = glm::length(d);
    v.normal = length > 1e-12f ? d / length : glm::vec3(0.0f, 1.0f, 0.0f);
    v.uv0 = p.uv;
    return v;
}

PatchPoint patchPoint(const BspVertex& v) {
    return {glm::vec3(v.position[0], v.position[1], v.position[2]),
            glm::vec3(v.normal[0], v.normal[1], v.normal[2]),
            glm::vec2(v.texcoord[0], v.texcoord[1]), glm::vec2(v.lightmap[0], v.lightmap[1]),
            glm::vec3(v.color[0], v.color[1], v.color[2])};
}

// Keeps where q3map2's light lies on a surface's triangles (SourceLevel::importedLightmap).
void appendImportedLight(ImportedLightmap& imported, const std::vector<PatchPoint>& points,
                         const std::vector<uint32_t>& triangles, int32_t page) {
    for (size_t t = 0; t + 2 < triangles.size(); t += 3) {
        ImportedLightmap::Triangle triangle;
        for (int k = 0; k < 3; ++k) {
            const PatchPoint& p = points[triangles[t + size_t(k)]];
            triangle.corners[k] = levelPoint(p.position);
            triangle.uv[k] = p.lightmapUv;
            triangle.vertexLight[k] = p.vertexLight;
        }
        triangle.page = page >= 0 ? uint32_t(page) : kNoIndex;
        imported.triangles.push_back(triangle);
    }
}

// Appends a surface's triangles to `mesh`, wound counter-clockwise about the vertex normals
// (the majority of its triangles decides, so a surface keeps one sense).
void appendOriented(MeshInstance& mesh, const std::vector<Vertex>& vertices,
                    const std::vector<uint32_t>& triangles) {
    double agreement = 0.0;
    for (size_t t = 0; t + 2 < triangles.size(); t += 3) {
        const Vertex &a = vertices[triangles[t]], &b = vertices[triangles[t + 1]],
                     &c = vertices[triangles[t + 2]];
        const glm::vec3 n = glm::cross(b.position - a.position, c.position - a.position);
        agreement += double(glm::dot(n, a.normal + b.normal + c.normal));
    }
    const uint32_t base = uint32_t(mesh.vertices.size());
    mesh.vertices.insert(mesh.vertices.end(), vertices.begin(), vertices.end());
    for (size_t t = 0; t + 2 < triangles.size(); t += 3) {
        const uint32_t a = base + triangles[t], b = base + triangles[t + 1],
                       c = base + triangles[t + 2];
        if (agreement >= 0.0)
            mesh.indices.insert(mesh.indices.end(), {a, b, c});
        else
            mesh.indices.insert(mesh.indices.end(), {a, c, b});
    }
}

// A player spawn's class: info_player_deathmatch and info_player_start; a map without those
// (team games, races: Nexuiz's info_player_team1, info_player_race, OpenArena's
// team_CTF_redspawn) has the other player starts instead, the intermission camera excepted.
bool deathmatchSpawn(const std::string& type) {
    return type == "info_player_deathmatch" || type == "info_player_start";
}
bool otherSpawn(const std::string& type) {
    const std::string key = fileKey(type);
    return (key.rfind("info_player_", 0) == 0 && key != "info_player_intermission") ||
           key == "team_ctf_redspawn" || key == "team_ctf_bluespawn";
}

// Player spawns, with a camera at each one's eyes looking along its "angle".
void addSpawns(SourceLevel& level, const std::vector<MapEntity>& entities,
               const std::string& where) {
    bool deathmatch = false;
    for (const MapEntity& e : entities) deathmatch |= deathmatchSpawn(e.get("classname"));
    uint32_t n = 0;
    for (const MapEntity& e : entities) {
        const std::string type = e.get("classname");
        if (deathmatch ? !deathmatchSpawn(type) : !otherSpawn(type)) continue;
        const glm::vec3 origin = vectorKey(e, "origin", glm::vec3(0.0f), where);
        const float yaw = numberKey(e, "angle", 0.0f, where);  // degrees about Z from +X
        // Quake's heading (cos, sin, 0) is (cos, 0, -sin) here: a turn about +Y of yaw - 90
        // degrees takes a camera's -Z there.
        const glm::quat turn = glm::angleAxis(glm::radians(yaw - 90.0f), glm::vec3(0, 1, 0));
        Entity spawn;
        spawn.name = "spawn" + std::to_string(n);
        spawn.flags = kEntitySpawn;
        spawn.position = levelPoint(origin + glm::vec3(0.0f, 0.0f, -24.0f));  // the feet
        spawn.rotation = turn;
        level.entities.push_back(spawn);
        Camera camera;
        camera.name = spawn.name;
        camera.position = levelPoint(origin + glm::vec3(0.0f, 0.0f, 26.0f));  // the eyes
        camera.rotation = turn;
        camera.yfov = glm::radians(73.74f);  // Quake's 90 degree horizontal fov at 4:3
        level.cameras.push_back(camera);
        ++n;
    }
}

// Point lights, spots where they aim at a target (q3map2's cone), candela by
// kQuake3CandelaPerLight times q3map2's -point / -spot scales, all baked until chooseLightRoles.
// The lights q3map2 leaves out are left out too (its light.c, CreateEntityLights): a light with
// "noradiosity" 1, and, from a source .map (`fromSource`), one with a targetname, which q3map2
// takes only from the BSP (a switched light's).
void addLights(SourceLevel& level, const std::vector<MapEntity>& entities, const std::string& where,
               const Q3map2LightOptions& q3map2, bool fromSource) {
    // A map scaled by S after q3map2 lit it (Q3map2LightOptions::scaledAfterLight): its BSP's
    // origins are scaled, a source's are as lit; either way q3map2's distances were 1/S of the
    // stored ones, so a point or spot light is S^2 as intense and a linear one reaches S as far.
    const float scaled = q3map2.scaledAfterLight;
    const float placed = fromSource ? scaled : 1.0f;
    std::map<std::string, glm::vec3> targets;
    for (const MapEntity& e : entities)
        if (e.keys.count("targetname"))
            targets[e.get("targetname")] = placed * vectorKey(e, "origin", glm::vec3(0.0f), where);
    uint32_t linear = 0, halfLife = 0, switched = 0, noRadiosity = 0, suns = 0, junior = 0;
    // A light baked until chooseLightRoles, once its intensity and range are numbers.
    auto keep = [&](const MapEntity& e, Light& l) {
        if (!std::isfinite(l.intensity) || !std::isfinite(l.range))
            throw Error(where + ": entities line " + std::to_string(e.line) + ": light '" +
                        clipForMessage(e.get("_light", e.get("light", "300"))) +
                        "' makes an intensity past a float's range; expected a value the "
                        "engine can hold (at most about 4e37)");
        l.role = LightRole::kBaked;
        level.lights.push_back(l);
    };
    for (const MapEntity& e : entities) {
        // q3map2 takes every class whose name starts with "light", in any case (Nexuiz's
        // light_spot without a target is a point light there); "lightJunior" lights only its
        // light grid, never a surface, so the bake leaves it out with a note.
        const std::string type = fileKey(e.get("classname"));
        if (!type.starts_with("light")) continue;
        if (type.starts_with("lightjunior")) {
            ++junior;
            continue;
        }
        if (e.get("noradiosity").starts_with("1")) {
            ++noRadiosity;
            continue;
        }
        if (fromSource && !e.get("targetname").empty()) {
            ++switched;
            continue;
        }
        Light l;
        l.name = e.get("targetname", "light" + std::to_string(level.lights.size()));
        const glm::vec3 origin = placed * vectorKey(e, "origin", glm::vec3(0.0f), where);
        l.position = levelPoint(origin);
        // q3map2's order: "_light", else "light", and 300 where neither gives a non-zero value.
        bool more = false;
        float value = firstNumberKey(e, "_light", 0.0f, where, &more);
        if (value == 0.0f) value = firstNumberKey(e, "light", 0.0f, where, &more);
        if (value == 0.0f) value = 300.0f;
        halfLife += more;
        const float own = numberKey(e, "scale", 0.0f, where);  // q3map2: the light's "scale", 0 = 1
        if (own != 0.0f) value *= own;
        float scale = q3map2.pointScale;  // -point; -spot for a spot
        glm::vec3 color = vectorKey(e, "_color", glm::vec3(1.0f), where);
        const float peak = std::max({color.x, color.y, color.z});
        l.color = peak > 0.0f ? glm::max(color / peak, glm::vec3(0.0f)) : glm::vec3(1.0f);
        l.type = LightType::kPoint;
        const auto target = targets.find(e.get("target"));
        bool spot = false;
        if (e.keys.count("target") && target != targets.end()) {
            // q3map2 (light.c): the cone's radius at distance t along the axis is
            // (radius + 16) t / (distance to the target), radius 64 where 0, and the light
            // ramps down linearly over the last 32 units of it: an inner cone through radius -
            // 16 at the target.
            const glm::vec3 to = target->second - origin;
            const float distance = glm::length(to);
            if (distance > 0.0f) {
                float radius = numberKey(e, "radius", 0.0f, where);
                if (radius == 0.0f) radius = 64.0f;
                if (!(radius >= 0.0f))
                    throw Error(where + ": entities line " + std::to_string(e.line) +
                                ": spot light radius '" + clipForMessage(e.get("radius")) +
                                "'; expected >= 0 units (its cone's radius at its target)");
                spot = true;
                const float tangent[3] = {to.x / distance, to.y / distance, to.z / distance};
                l.direction = levelDirection(tangent);
                if (e.get("_sun").starts_with("1")) {
                    // q3map2 makes it a sun along the spot's axis, of the value itself (no
                    // point scale): lux, as a sky shader's q3map_sun.
                    l.type = LightType::kDirectional;
                    l.intensity = std::max(0.0f, value);
                    ++suns;
                    keep(e, l);
                    continue;
                }
                l.type = LightType::kSpot;
                scale = q3map2.spotScale;
                const float lit = distance / scaled;  // the distance to the target q3map2 saw
                l.outerCone = std::min(1.5f, std::atan((radius + 16.0f) / lit));
                l.innerCone =
                    std::min(l.outerCone, std::atan(std::max(0.0f, radius - 16.0f) / lit));
            }
        }
        value = std::max(0.0f, value) * scale;
        l.intensity =
            float(double(value) * kQuake3CandelaPerLight * double(scaled) * double(scaled));
        const int flags = int(numberKey(e, "spawnflags", 0.0f, where));
        if ((flags & 1) && !spot) {  // q3map2 clears a spot's linear flag
            // Linear falloff (q3_import.hpp, "Linear lights"), matched at half its reach.
            const double fade = std::max(1e-3, double(numberKey(e, "fade", 1.0f, where)));
            const double reach = kQuake3LinearScale * double(value) / fade * double(scaled);
            const double half = 0.5 * reach * kQuake3MetresPerUnit;
            const double window = (1.0 - 1.0 / 16.0) * (1.0 - 1.0 / 16.0);
            const double atHalf = 0.5 * kQuake3LinearScale * double(value);  // lux
            l.intensity = float(atHalf * half * half / window);
            l.range = float(reach * kQuake3MetresPerUnit);
            ++linear;
        }
        keep(e, l);
    }
    if (halfLife > 0)
        level.importNotes.push_back(
            where + ": " + std::to_string(halfLife) +
            " light(s) whose intensity key holds several numbers (\"R G B I\", the Half-Life "
            "form): the first is the intensity, as q3map2 reads it");
    if (switched > 0)
        level.importNotes.push_back(
            where + ": " + std::to_string(switched) +
            " light(s) with a targetname left out: q3map2 bakes a named (switched) light only "
            "from the BSP, never from the source .map");
    if (suns > 0)
        level.importNotes.push_back(where + ": " + std::to_string(suns) +
                                    " spot light(s) with \"_sun\" 1 made suns along their axes "
                                    "(directional, the value in lux), as q3map2 does");
    if (junior > 0)
        level.importNotes.push_back(where + ": " + std::to_string(junior) +
                                    " lightJunior light(s) left out: q3map2 lights only its "
                                    "light grid with them, never a surface");
    if (noRadiosity > 0)
        level.importNotes.push_back(where + ": " + std::to_string(noRadiosity) +
                                    " light(s) with \"noradiosity\" 1 left out, as q3map2 does");
    if (linear > 0)
        level.importNotes.push_back(
            where + ": " + std::to_string(linear) +
            " light(s) with q3map2's linear falloff approximated by inverse-square lights with a "
            "range, equal to q3map2 at half their reach");
}

// A map without a player spawn gets one where its geometry says (computed_view.hpp).
void addComputedSpawn(SourceLevel& level, const std::string& where) {
    if (!level.cameras.empty()) return;
    const std::optional<ComputedView> view = computeViewInside(level);
    if (!view) {
        level.importNotes.push_back(where +
                                    ": no player spawn, and no open space inside the level found "
                                    "for a view: the game frames the level from outside");
        return;
    }
    Entity spawn;
    spawn.name = "spawn0";
    spawn.flags = kEntitySpawn;
    spawn.position = view->feet;
    spawn.rotation = view->rotation;
    level.entities.push_back(spawn);
    Camera camera;
    camera.name = spawn.name;
    camera.position = view->eye;
    camera.rotation = view->rotation;
    camera.yfov = glm::radians(73.74f);
    level.cameras.push_back(camera);
    char text[160];
    std::snprintf(text, sizeof text,
                  ": no player spawn: a view computed from the level's bounds, eyes at (%.1f, "
                  "%.1f, %.1f) m looking along %s%s",
                  double(view->eye.x), double(view->eye.y), double(view->eye.z),
                  view->forward.x + view->forward.z > 0.0f ? "+" : "-",
                  view->forward.x != 0.0f ? "X" : "Z");
    level.importNotes.push_back(where + text);
}

// Worldspawn's constant light (q3_import.hpp): reported, not modelled.
void noteIgnoredAmbient(SourceLevel& level, const std::vector<MapEntity>& entities,
                        const std::string& where) {
    if (entities.empty()) return;
    for (const char* key : {"ambient", "_ambient", "_minlight"})
        if (entities[0].keys.count(key) && numberKey(entities[0], key, 0.0f, where) != 0.0f)
            level.importNotes.push_back(where + ": worldspawn '" + key + "' " +
                                        entities[0].get(key) +
                                        " ignored: a constant added to every luxel is light from "
                                        "nowhere; the bake's bounces light what it stood in for");
}

// The map's source (.map) where one ships with it: maps/NAME.map or sources/maps/NAME.map in
// the BSP's own pk3 first, then in any of the game's, or NAME.map beside a loose NAME.bsp.
struct SourceText {
    std::string text;
    std::string where;
};
std::optional<SourceText> findMapSource(const OpenedMap& map) {
    const std::vector<std::string> names = {"maps/" + map.name + ".map",
                                            "sources/maps/" + map.name + ".map"};
    const auto text = [](const std::vector<uint8_t>& bytes) {
        return std::string(bytes.begin(), bytes.end());
    };
    if (!map.pk3.empty()) {
        const Pk3Archive archive(map.pk3);
        for (const std::string& wanted : names)
            for (const std::string& n : archive.names())
                if (fileKey(n) == fileKey(wanted))
                    return SourceText{
                        text(archive.read(n, kMaxMapSourceBytes, "a Quake 3 .map source")),
                        archive.path() + ":" + n};
    } else if (!map.bspFile.empty()) {
        std::error_code ec;
        const std::filesystem::path beside =
            std::filesystem::path(map.bspFile).replace_extension(".map");
        if (std::filesystem::is_regular_file(beside, ec))
            return SourceText{
                text(readRegularFile(beside.string(), "a Quake 3 .map source", kMaxMapSourceBytes)),
                beside.string()};
    }
    for (const std::string& wanted : names)
        if (auto bytes = map.files.read(wanted, kMaxMapSourceBytes, "a Quake 3 .map source"))
            return SourceText{text(*bytes), map.files.where(wanted)};
    return std::nullopt;
}

// The level's geometry bounds, metres (empty: min > max).
std::pair<glm::vec3, glm::vec3> geometryBounds(const SourceLevel& level) {
    glm::vec3 lo(1e30f), hi(-1e30f);
    for (const MeshInstance& mesh : level.instances)
        for (const Vertex& v : mesh.vertices) {
            lo = glm::min(lo, v.position);
            hi = glm::max(hi, v.position);
        }
    return {lo, hi};
}

// The light entities of the map's source .map (q3_import.hpp, "Where the lights come from"),
// added as if the BSP had kept them; lights far outside the map's geometry (a source that does
// not match the BSP) are left out. A source that does not parse is ignored with a note. Returns
// how many lights it added; `where` is the source's name.
size_t addSourceLights(SourceLevel& level, const OpenedMap& map, const Q3map2LightOptions& q3map2,
                       std::string& where) {
    std::optional<SourceText> source;
    const size_t before = level.lights.size();
    try {
        source = findMapSource(map);
        if (!source) return 0;
        where = source->where;
        addLights(level, parseMapSource(source->text, source->where), source->where, q3map2, true);
    } catch (const Error& e) {
        level.lights.resize(before);
        level.importNotes.push_back(std::string(e.what()) +
                                    ": the map's source is ignored, its lights are not used");
        return 0;
    }
    const std::pair<glm::vec3, glm::vec3> bounds = geometryBounds(level);
    // Half the map's size, at least 16 m: a light above an open floor is still the map's.
    const glm::vec3 margin(std::max(16.0f, 0.5f * glm::length(bounds.second - bounds.first)));
    const glm::vec3 lo = bounds.first - margin, hi = bounds.second + margin;
    const auto outside = [&](const Light& l) {
        return glm::any(glm::lessThan(l.position, lo)) ||
               glm::any(glm::greaterThan(l.position, hi));
    };
    const auto kept =
        std::remove_if(level.lights.begin() + long(before), level.lights.end(), outside);
    const size_t dropped = size_t(level.lights.end() - kept);
    level.lights.erase(kept, level.lights.end());
    if (dropped > 0)
        level.importNotes.push_back(source->where + ": " + std::to_string(dropped) +
                                    " light(s) far outside the map's geometry left out (the source "
                                    "does not match the BSP there)");
    return level.lights.size() - before;
}

// Whether q3map2's lightmaps or vertex light hold any light.
bool importedLightmapLit(const ImportedLightmap& imported) {
    for (uint8_t b : imported.pages)
        if (b != 0) return true;
    for (const ImportedLightmap::Triangle& t : imported.triangles)
        if (t.page == kNoIndex)
            for (const glm::vec3& v : t.vertexLight)
                if (glm::any(glm::greaterThan(v, glm::vec3(0.0f)))) return true;
    return false;
}

// Which source each kind of the map's light came from (SourceLevel::lightSources), and the
// q3map2-lightmap path where the light entities are lost (q3_import.hpp, "Where the lights
// come from"). A map that nothing lights is marked lightless: the bake refuses it; a map
// with nothing to draw is not (it bakes empty).
void settleLightSources(SourceLevel& level, size_t entityLights, const std::string& entityWhere,
                        const std::string& mapWhere) {
    std::vector<std::string>& out = level.lightSources;
    size_t sun = 0;
    for (const Light& l : level.lights) sun += l.type == LightType::kDirectional ? 1 : 0;
    const size_t points = level.lights.size() - sun;
    if (entityLights > 0)
        out.push_back("light entities: " + std::to_string(points) + " from " + entityWhere);
    else
        out.push_back(
            "light entities: none (q3map2 removed them from the BSP and no source "
            ".map ships with it)");
    size_t shaders = 0, triangles = 0;
    for (const MeshInstance& mesh : level.instances)
        if (glm::any(glm::greaterThan(level.materials[mesh.material].emissive, glm::vec3(0.0f)))) {
            ++shaders;
            triangles += mesh.indices.size() / 3;
        }
    out.push_back("surface lights: " + (shaders ? std::to_string(shaders) + " shader(s), " +
                                                      std::to_string(triangles) + " triangles"
                                                : std::string("none")));
    const float sky = std::max({level.skyRadiance.x, level.skyRadiance.y, level.skyRadiance.z});
    out.push_back(std::string("sky: ") + (sun ? "a sun" : "no sun") + ", " +
                  (sky > 0.0f ? "sky light " + std::to_string(sky) + " cd/m^2" : "no sky light"));
    size_t passed = 0, passedTriangles = 0;
    std::vector<bool> counted(level.materials.size(), false);
    for (const MeshInstance& mesh : level.instances)
        if (mesh.material < level.materials.size() &&
            !level.materials[mesh.material].castsShadows) {
            passed += counted[mesh.material] ? 0 : 1;
            counted[mesh.material] = true;
            passedTriangles += mesh.indices.size() / 3;
        }
    if (passed > 0)
        out.push_back("translucent: " + std::to_string(passed) + " shader(s), " +
                      std::to_string(passedTriangles) +
                      " triangles, cast no shadow (q3map2 traces no translucent surface)");
    if (entityLights > 0) return;
    if (importedLightmapLit(level.importedLightmap)) {
        level.lightmapIsImported = true;
        for (Light& l : level.lights) l.role = LightRole::kBaked;
        out.push_back(
            "lightmaps: recovered from q3map2's own (the map's lightmap lump) in place "
            "of the engine's bake, since its light entities are lost; the sun, sky "
            "and surface lights light the grid and probes only");
        return;
    }
    size_t drawn = 0;
    for (const MeshInstance& mesh : level.instances) drawn += mesh.indices.size() / 3;
    if (drawn == 0) {
        // Nothing to light (a placeholder map, such as a dedicated server's one caulk brush):
        // an empty level bakes and draws, black, which is what it holds.
        out.push_back("nothing drawn: the map has no visible surface, so nothing to light");
        return;
    }
    if (level.lights.empty() && shaders == 0 && !(sky > 0.0f)) {
        level.lightless = mapWhere +
                          ": no light source: no light entities (in the BSP or a source .map), "
                          "no sun, sky or surface lights, and q3map2's lightmaps are black; a "
                          "bake would be black";
        out.push_back("no light at all: the bake refuses the map");
    }
}

// The primaries (q3_import.hpp, "Which lights are primaries"): each light's share of the
// surface area where it is the brightest, unshadowed, at the triangles' centroids.
void chooseLightRoles(SourceLevel& level, uint32_t maximum) {
    std::vector<double> area(level.lights.size(), 0.0);
    double total = 0.0;
    for (const MeshInstance& mesh : level.instances)
        for (size_t t = 0; t + 2 < mesh.indices.size(); t += 3) {
            const Vertex &a = mesh.vertices[mesh.indices[t]],
                         &b = mesh.vertices[mesh.indices[t + 1]],
                         &c = mesh.vertices[mesh.indices[t + 2]];
            const glm::vec3 cross = glm::cross(b.position - a.position, c.position - a.position);
            const double size = 0.5 * double(glm::length(cross));
            if (!(size > 0.0)) continue;
            const glm::vec3 normal = cross / float(2.0 * size);
            const glm::vec3 centroid = (a.position + b.position + c.position) / 3.0f;
            const glm::vec3 lifted = centroid + normal * 0.01f;
            float best = 0.0f;
            size_t brightest = level.lights.size();
            for (size_t l = 0; l < level.lights.size(); ++l) {
                const LightAtPoint at = evaluateLight(level.lights[l], lifted);
                const float e =
                    glsl::luminance(at.illuminance) * std::max(0.0f, glm::dot(normal, at.toLight));
                if (e > best) {
                    best = e;
                    brightest = l;
                }
            }
            total += size;
            if (brightest < level.lights.size()) area[brightest] += size;
        }
    std::vector<size_t> order;
    for (size_t l = 0; l < level.lights.size(); ++l) {
        level.lights[l].role = LightRole::kBaked;
        if (total > 0.0 && area[l] >= kQuake3PrimaryAreaShare * total) order.push_back(l);
    }
    std::stable_sort(order.begin(), order.end(),
                     [&](size_t x, size_t y) { return area[x] > area[y]; });
    for (size_t i = 0; i < std::min<size_t>(maximum, order.size()); ++i)
        level.lights[order[i]].role = LightRole::kPrimary;
}

// The share of q3map_skylight's value an open floor gets from q3map2's dome of suns (light.c,
// CreateSkyLights): with n iterations, n - 1 rings of 4 (n - 1) suns at elevations
// (k + 1/2) 90 / n degrees and one sun at the zenith, each of value / (4 (n - 1)^2 + 1) lux at
// normal incidence; no sky light at all below 2 iterations.
double skyLightFloorShare(int iterations) {
    if (iterations < 2) return 0.0;
    const int rings = iterations - 1, perRing = 4 * rings;
    double sum = 1.0;  // the zenith's sun
    for (int k = 0; k < rings; ++k)
        sum += perRing * std::sin((double(k) + 0.5) * 0.5 * std::numbers::pi / iterations);
    return sum / (double(perRing) * rings + 1.0);
}

// The sun (q3map_sun, a primary directional light in lux) and a uniform sky of the map's sky
// shaders, times q3map2's -sky scale: q3map_skylight V with n iterations is a radiance of
// skyLightFloorShare(n) V / pi, so an open floor gets what q3map2's suns give it, in the light
// image's normalised mean colour (q3map2's shader colour); an older sky's surface light S is
// 0.25 S cd/m^2 times its -area scale.
void addSunAndSky(SourceLevel& level, const BspFile& bsp, const ShaderScripts& scripts,
                  const GameFiles& files, const Q3map2LightOptions& q3map2) {
    for (const BspShader& shader : bsp.shaders) {
        const ShaderScript* script = scriptOf(scripts, shader);
        if (!script || !script->surfaceParms.count("sky")) continue;
        if (script->sun && script->sun->intensity > 0.0f) {
            const ShaderSun& sun = *script->sun;
            const float d = glm::radians(sun.degrees), e = glm::radians(sun.elevation);
            const float toSun[3] = {std::cos(e) * std::cos(d), std::cos(e) * std::sin(d),
                                    std::sin(e)};
            Light l;
            l.name = "sun";
            l.type = LightType::kDirectional;
            l.role = LightRole::kPrimary;
            l.direction = -levelDirection(toSun);
            l.intensity = sun.intensity * q3map2.skyScale;
            const float peak = std::max({sun.color.x, sun.color.y, sun.color.z});
            l.color = peak > 0.0f ? glm::max(sun.color / peak, glm::vec3(0.0f)) : glm::vec3(1.0f);
            level.lights.push_back(l);
        }
        if (script->skyLight > 0.0f) {
            const double share = skyLightFloorShare(script->skyLightIterations);
            if (share == 0.0)
                level.importNotes.push_back(
                    clipForMessage(script->name) + ": q3map_skylight with " +
                    std::to_string(script->skyLightIterations) +
                    " iteration(s): q3map2 makes no sky light below 2, nor does the import");
            level.skyRadiance = float(double(script->skyLight) * share * double(q3map2.skyScale) /
                                      std::numbers::pi) *
                                normalisedColour(meanColours(files, lightImageOf(*script)).bytes);
        } else if (script->surfaceLight > 0.0f) {
            // The older way: q3map2 makes the sky's faces area lights of value S, which is a
            // sky of 0.25 S cd/m^2 (q3_import.hpp) in the light image's normalised mean colour.
            level.skyRadiance = float(kQuake3NitsPerSurfaceLight * double(script->surfaceLight) *
                                      double(q3map2.areaScale)) *
                                normalisedColour(meanColours(files, lightImageOf(*script)).bytes);
        }
        return;  // one sky per map
    }
}

// The triangles and vertices the drawn surfaces will make, counted from their records before
// any is built: past kMaxLevelTriangles or kMaxLevelVertices the map is refused, naming the
// largest surface (docs/limits.md).
void checkSurfaceSizes(const BspFile& bsp, const ShaderScripts& scripts, uint32_t patchLevel,
                       const std::string& where) {
    uint64_t triangles = 0, vertices = 0, largest = 0;
    size_t largestSurface = 0;
    for (size_t s = 0; s < bsp.surfaces.size(); ++s) {
        const BspSurface& f = bsp.surfaces[s];
        if (f.type == kSurfaceFlare || f.vertexCount == 0) continue;
        if (!drawn(bsp.shaders[size_t(f.shader)], scriptOf(scripts, bsp.shaders[size_t(f.shader)])))
            continue;
        uint64_t t = uint64_t(f.indexCount) / 3, v = uint64_t(f.vertexCount);
        if (f.type == kSurfacePatch) {
            const uint64_t pieces =
                uint64_t((f.patchWidth - 1) / 2) * uint64_t((f.patchHeight - 1) / 2);
            t = pieces * 2 * uint64_t(patchLevel) * patchLevel;
            v = pieces * uint64_t(patchLevel + 1) * (patchLevel + 1);
        }
        triangles += t;
        vertices += v;
        if (t > largest) largest = t, largestSurface = s;
    }
    if (triangles <= kMaxLevelTriangles && vertices <= kMaxLevelVertices) return;
    const BspSurface& big = bsp.surfaces[largestSurface];
    const std::string what = big.type == kSurfacePatch
                                 ? "a " + std::to_string(big.patchWidth) + " x " +
                                       std::to_string(big.patchHeight) + " patch at patch level " +
                                       std::to_string(patchLevel)
                                 : "a surface";
    throw Error(where + ": the surfaces would make " + std::to_string(triangles) +
                " triangles and " + std::to_string(vertices) + " vertices (the largest, surface " +
                std::to_string(largestSurface) + ", " + what + ", " + std::to_string(largest) +
                "); expected at most " + std::to_string(kMaxLevelTriangles) + " of each");
}

}  // namespace

std::vector<std::string> defaultQuake3Folders() {
    std::vector<std::string> out;
    for (const char* f : {"/usr/share/games/openarena/baseoa"})
        if (std::filesystem::is_directory(f)) out.push_back(f);
    return out;
}

SourceLevel importQuake3(const std::string& spec, const Quake3Options& options) {
    if (options.patchLevel < 1 || options.patchLevel > 64)
        throw Error(spec + ": patch level " + std::to_string(options.patchLevel) +
                    "; expected 1 .. 64 segments");
    OpenedMap opened = openQuake3Map(spec, options.gameFolders);
    const GameFiles& files = opened.files;
    const BspFile& bsp = opened.bsp;
    const MapSource map{opened.where};

    SourceLevel level;
    level.sourcePath = map.where;
    if (!opened.bspFile.empty()) level.inputFiles.push_back(opened.bspFile);
    for (const auto& archive : files.archives) level.inputFiles.push_back(archive->path());
    level.inputFiles.insert(level.inputFiles.end(), files.looseFiles.begin(),
                            files.looseFiles.end());
    level.importNotes = bsp.notes;
    const std::vector<MapEntity> entities = parseEntities(bsp.entities, map.where);
    Q3map2LightOptions q3map2 = readQ3map2LightOptions(entities, map.where);
    level.importNotes.insert(level.importNotes.end(), q3map2.notes.begin(), q3map2.notes.end());
    const LightmapPages lightmaps =
        readLightmapPages(bsp, entities, files, opened.name, opened.bspFile, map.where);
    level.importNotes.insert(level.importNotes.end(), lightmaps.notes.begin(),
                             lightmaps.notes.end());
    if (!q3map2.recorded) {
        q3map2.encoding.compensate = compensateShownByPages(lightmaps.colour);
        q3map2.compensateInferred = q3map2.encoding.compensate != 1.0f;
    }
    const ShaderScripts scripts = loadShaderScripts(files);
    checkSurfaceSizes(bsp, scripts, options.patchLevel, map.where);
    MaterialTable materials{level, files, {}, {}, {}, 0, q3map2.areaScale};
    // The movers: their entities first, then their surfaces as their dynamic meshes.
    ImportedMovers movers = importMovers(bsp, entities, map.where);
    level.importNotes.insert(level.importNotes.end(), movers.notes.begin(), movers.notes.end());
    const uint32_t firstMoverEntity = uint32_t(level.entities.size());
    level.entities.insert(level.entities.end(), movers.entities.begin(), movers.entities.end());
    level.movers = movers.movers;
    for (Mover& m : level.movers.movers) m.entity += firstMoverEntity;
    std::vector<uint32_t> modelOfSurface(bsp.surfaces.size(), 0);
    for (size_t n = 1; n < bsp.models.size(); ++n)
        for (int32_t k = 0; k < bsp.models[n].surfaceCount; ++k) {
            const size_t surface = size_t(bsp.models[n].firstSurface + k);
            if (surface < modelOfSurface.size()) modelOfSurface[surface] = uint32_t(n);
        }
    std::map<uint32_t, MeshInstance> meshes;                       // static, by material
    std::map<std::pair<uint32_t, uint32_t>, MeshInstance> moving;  // by mover and material
    for (size_t s = 0; s < bsp.surfaces.size(); ++s) {
        const BspSurface& f = bsp.surfaces[s];
        if (f.type == kSurfaceFlare || f.vertexCount == 0) continue;
        const uint32_t model = modelOfSurface[s];
        const BspShader& shader = bsp.shaders[size_t(f.shader)];
        const ShaderScript* script = scriptOf(scripts, shader);
        if (!drawn(shader, script)) continue;
        const uint32_t material = materials.materialOf(shader, f.shader, script);
        const uint32_t mover =
            model < movers.moverOfModel.size() ? movers.moverOfModel[model] : kNoIndex;
        MeshInstance& mesh = mover == kNoIndex ? meshes[material] : moving[{mover, material}];
        std::vector<PatchPoint> points;
        std::vector<uint32_t> triangles;
        if (f.type == kSurfacePatch) {
            std::vector<PatchPoint> controls;
            for (int32_t v = 0; v < f.vertexCount; ++v)
                controls.push_back(patchPoint(bsp.vertices[size_t(f.firstVertex + v)]));
            PatchMesh patch = tessellatePatch(controls, uint32_t(f.patchWidth),
                                              uint32_t(f.patchHeight), options.patchLevel);
            points = std::move(patch.vertices);
            triangles = std::move(patch.triangles);
        } else {
            for (int32_t v = 0; v < f.vertexCount; ++v)
                points.push_back(patchPoint(bsp.vertices[size_t(f.firstVertex + v)]));
            for (int32_t i = 0; i < f.indexCount; ++i)
                triangles.push_back(uint32_t(bsp.indices[size_t(f.firstIndex + i)]));
        }
        std::vector<Vertex> vertices;
        for (const PatchPoint& p : points) vertices.push_back(levelVertex(p));
        if (mover != kNoIndex) {  // in the mover's object space: the model's own
            appendOriented(mesh, vertices, triangles);
            continue;
        }
        // Another brush model (a func_static's) is drawn where its entity's origin puts it.
        const glm::vec3 offset =
            model < movers.originOfModel.size() ? movers.originOfModel[model] : glm::vec3(0.0f);
        if (offset != glm::vec3(0.0f)) {
            for (Vertex& v : vertices) v.position += offset;
            for (PatchPoint& p : points)
                p.position +=
                    glm::vec3(offset.x, -offset.z, offset.y) / float(kQuake3MetresPerUnit);
        }
        appendOriented(mesh, vertices, triangles);
        const uint32_t page = lightmaps.colourPage(f.lightmap);
        appendImportedLight(level.importedLightmap, points, triangles,
                            page == UINT32_MAX ? -1 : int32_t(page));
    }
    for (auto& [material, mesh] : meshes) {
        mesh.material = material;
        mesh.nodeName = mesh.meshName = level.materials[material].name;
        level.instances.push_back(std::move(mesh));
    }
    for (auto& [key, mesh] : moving) {
        const Entity& entity = level.entities[level.movers.movers[key.first].entity];
        mesh.material = key.second;
        mesh.dynamic = true;
        mesh.entity = level.movers.movers[key.first].entity;
        mesh.nodeName = entity.name;
        mesh.meshName = level.materials[key.second].name;
        mesh.worldFromLocal = glm::translate(glm::dmat4(1.0), glm::dvec3(entity.position)) *
                              glm::dmat4(glm::mat4_cast(entity.rotation));
        level.instances.push_back(std::move(mesh));
    }
    level.importedLightmap.producer = "q3map2";
    level.importedLightmap.pageSize = lightmaps.pageSize;
    level.importedLightmap.pages = lightmaps.colour;
    level.importedLightmap.directionPages = lightmaps.direction;
    level.importedLightmap.encoding = q3map2.encoding;
    level.importedLightmap.luxPerValue = 1.0f;  // one lightmap unit is one lux (q3_import.hpp)
    addSunAndSky(level, bsp, scripts, files, q3map2);
    // q3map2's lightmap density: one luxel per 16 units, times worldspawn's _lightmapscale.
    const float luxelUnits =
        16.0f *
        (entities.empty() ? 1.0f : numberKey(entities[0], "_lightmapscale", 1.0f, map.where));
    if (!(luxelUnits > 0.0f)) throw Error(map.where + ": worldspawn's _lightmapscale is not > 0");
    level.texelsPerMetre = float(1.0 / (double(luxelUnits) * kQuake3MetresPerUnit));
    addSpawns(level, entities, map.where);
    addItems(
        level, entities, files,
        [&](const std::string& name) {
            const ShaderScript* script = scriptNamed(scripts, name);
            if (!script) script = scriptNamed(scripts, withoutImageExtension(name));
            const uint32_t m = materials.materialNamed(name, script);
            Material& made = level.materials[m];
            if (made.baseColorTexture != kNoIndex || !script || script->stages.empty() ||
                script->stages[0].tcGen != "environment")
                return m;
            // Drawn by environment mapping alone (a health cross, its sphere), which the
            // engine does not model: a blended shell is left out rather than drawn as a grey
            // shell over the item; an opaque body takes its image's mean colour.
            const ShaderStage& first = script->stages[0];
            if (!first.blendFunc.empty() && first.blendFunc != "gl_one gl_zero") return kNoIndex;
            made.baseColor = glm::vec4(meanColours(files, first.map).linear, 1.0f);
            made.albedo = glm::vec3(made.baseColor);
            return m;
        },
        map.where);
    std::vector<bool> nonsolid;  // surfaceparm nonsolid, which the brushes' contents may miss
    for (const BspShader& shader : bsp.shaders) {
        const ShaderScript* script = scriptOf(scripts, shader);
        nonsolid.push_back(script && script->surfaceParms.count("nonsolid"));
    }
    level.collision =
        importCollision(bsp, entities, nonsolid, movers, map.where, level.importNotes);
    level.importedVisibility = importVisibility(bsp, map.where);
    addComputedSpawn(level, map.where);
    const size_t skyLights = level.lights.size();
    addLights(level, entities, map.where, q3map2, false);
    size_t entityLights = level.lights.size() - skyLights;
    std::string entityWhere = "the BSP's entities", sourceWhere;
    if (entityLights == 0 &&
        (entityLights = addSourceLights(level, opened, q3map2, sourceWhere)) > 0)
        entityWhere = "the source .map " + sourceWhere;
    noteIgnoredAmbient(level, entities, map.where);
    chooseLightRoles(level, options.primaryLights);
    settleLightSources(level, entityLights, entityWhere, map.where);
    level.lightSources.push_back(q3map2.summary());
    checkLevelLimits(level);
    return level;
}

}  // namespace onelight::world
