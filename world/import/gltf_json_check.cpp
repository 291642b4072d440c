#include "world/import/gltf_json_check.hpp"

#include <cmath>
#include <cstring>
#include <numbers>
#include <vector>

#include <nlohmann/json.hpp>

#include "world/error.hpp"
#include "world/file_read.hpp"

namespace onelight::world {

namespace {

using Json = nlohmann::json;

constexpr uint32_t kGlbMagic = 0x46546C67;      // "glTF"
constexpr uint32_t kGlbJsonChunk = 0x4E4F534A;  // "JSON"

uint32_t readU32(const std::vector<uint8_t>& bytes, size_t at) {
    uint32_t v = 0;
    std::memcpy(&v, bytes.data() + at, 4);
    return v;
}

// The deepest nesting of `[` and `{` outside strings, stopping at the first byte past `limit`.
void checkDepth(const char* text, size_t size, const std::string& path) {
    uint32_t depth = 0;
    bool inString = false;
    for (size_t i = 0; i < size; ++i) {
        const char c = text[i];
        if (inString) {
            if (c == '\\') {
                ++i;
            } else if (c == '"') {
                inString = false;
            }
        } else if (c == '"') {
            inString = true;
        } else if (c == '[' || c == '{') {
            if (++depth > kMaxGltfJsonDepth)
                throw Error(path + ": byte " + std::to_string(i) + ": JSON nested deeper than " +
                            std::to_string(kMaxGltfJsonDepth) + " levels; expected a glTF");
        } else if ((c == ']' || c == '}') && depth > 0) {
            --depth;
        }
    }
}

// Checks one glTF document; each check names its place as a JSON path.
class Checker {
public:
    explicit Checker(const std::string& path) : path_(path) {}

    void document(const Json& root) {
        if (!root.is_object()) fail("the document", "is not an object; expected a glTF object");
        asset(root);
        extras(root, "the document");
        stringArray(root, "extensionsUsed", "extensionsUsed");
        if (root.contains("extensionsRequired")) {
            stringArray(root, "extensionsRequired", "extensionsRequired");
            const Json& required = root["extensionsRequired"];
            for (size_t i = 0; i < required.size(); ++i) {
                const std::string name = required[i].get<std::string>();
                bool known = false;
                for (const char* supported : kSupportedGltfExtensions) known |= name == supported;
                if (!known)
                    fail("extensionsRequired[" + std::to_string(i) + "]",
                         "'" + clipForMessage(name) +
                             "' is not supported; expected only KHR_lights_punctual and "
                             "KHR_materials_emissive_strength");
            }
        }
        integer(root, "scene", "scene", 0);
        each(root, "scenes", [&](const Json& s, const std::string& at) {
            integerArray(s, "nodes", at + ".nodes");
            extras(s, at);
        });
        each(root, "nodes", [&](const Json& n, const std::string& at) { node(n, at); });
        nodeTrees(root);
        each(root, "meshes", [&](const Json& m, const std::string& at) {
            extras(m, at);
            each(m, "primitives", at + ".primitives", [&](const Json& p, const std::string& pat) {
                if (!p.contains("attributes") || !p["attributes"].is_object())
                    fail(pat + ".attributes", "is missing or not an object");
                for (const auto& [name, index] : p["attributes"].items())
                    if (!index.is_number_integer() || index.get<int64_t>() < 0)
                        fail(pat + ".attributes." + clipForMessage(name),
                             "expected an accessor index >= 0");
                integer(p, "indices", pat + ".indices", 0);
                integer(p, "material", pat + ".material", 0);
                integer(p, "mode", pat + ".mode", 0, 6);
            });
        });
        each(root, "materials", [&](const Json& m, const std::string& at) { material(m, at); });
        each(root, "textures", [&](const Json& t, const std::string& at) {
            integer(t, "source", at + ".source", 0);
            integer(t, "sampler", at + ".sampler", 0);
        });
        each(root, "samplers", [&](const Json& s, const std::string& at) {
            for (const char* key : {"magFilter", "minFilter", "wrapS", "wrapT"})
                integer(s, key, at + "." + key, 0, 65535);
        });
        each(root, "images", [&](const Json& i, const std::string& at) {
            string(i, "uri", at + ".uri");
            string(i, "mimeType", at + ".mimeType");
            integer(i, "bufferView", at + ".bufferView", 0);
        });
        each(root, "accessors", [&](const Json& a, const std::string& at) {
            integer(a, "bufferView", at + ".bufferView", 0);
            integer(a, "byteOffset", at + ".byteOffset", 0);
            required(a, "count", at);
            integer(a, "count", at + ".count", 1);
            required(a, "componentType", at);
            integer(a, "componentType", at + ".componentType", 5120, 5126);
            required(a, "type", at);
            string(a, "type", at + ".type");
            boolean(a, "normalized", at + ".normalized");
        });
        each(root, "bufferViews", [&](const Json& v, const std::string& at) {
            required(v, "buffer", at);
            integer(v, "buffer", at + ".buffer", 0);
            integer(v, "byteOffset", at + ".byteOffset", 0);
            required(v, "byteLength", at);
            integer(v, "byteLength", at + ".byteLength", 1);
            integer(v, "byteStride", at + ".byteStride", 4, 252);
        });
        each(root, "buffers", [&](const Json& b, const std::string& at) {
            required(b, "byteLength", at);
            integer(b, "byteLength", at + ".byteLength", 1);
            string(b, "uri", at + ".uri");
        });
        each(root, "cameras", [&](const Json& c, const std::string& at) { camera(c, at); });
        if (root.contains("extensions")) {
            object(root, "extensions", "extensions");
            const Json& e = root["extensions"];
            if (e.contains("KHR_lights_punctual")) {
                object(e, "KHR_lights_punctual", "extensions.KHR_lights_punctual");
                each(e["KHR_lights_punctual"], "lights", "extensions.KHR_lights_punctual.lights",
                     [&](const Json& l, const std::string& at) { light(l, at); });
            }
        }
    }

private:
    const std::string& path_;

    // asset.version: "2.x" (glTF 2.0; a minor version this importer does not know reads as 2.0,
    // as the spec allows); asset.minVersion, when given, no newer than 2.0.
    void asset(const Json& root) const {
        required(root, "asset", "the document");
        object(root, "asset", "asset");
        const Json& a = root["asset"];
        required(a, "version", "asset");
        string(a, "version", "asset.version");
        string(a, "minVersion", "asset.minVersion");
        const auto major = [](const std::string& v) {
            const size_t dot = v.find('.');
            if (dot == std::string::npos || dot == 0 || dot + 1 == v.size()) return -1;
            for (size_t i = 0; i < v.size(); ++i)
                if (i != dot && !(v[i] >= '0' && v[i] <= '9')) return -1;
            return dot > 3 ? -1 : std::stoi(v.substr(0, dot));
        };
        const std::string version = a["version"].get<std::string>();
        if (major(version) != 2)
            fail("asset.version",
                 "'" + clipForMessage(version, 40) +
                     "'; expected 2.x (glTF 2.0, the version this importer reads)");
        if (a.contains("minVersion")) {
            const std::string minimum = a["minVersion"].get<std::string>();
            if (major(minimum) != 2 || minimum != "2.0")
                fail("asset.minVersion", "'" + clipForMessage(minimum, 40) +
                                             "'; expected 2.0 (this importer reads glTF 2.0)");
        }
    }

    // The node hierarchy is a set of disjoint strict trees (glTF 2.0, 3.5.3): every child index
    // in range, no node the child of two parents, and no cycle (a cycle has no root, so its nodes
    // would be dropped unseen).
    void nodeTrees(const Json& root) const {
        if (!root.contains("nodes")) return;
        const Json& nodes = root["nodes"];
        const size_t count = nodes.size();
        std::vector<int64_t> parent(count, -1);
        for (size_t i = 0; i < count; ++i) {
            if (!nodes[i].contains("children")) continue;
            const Json& children = nodes[i]["children"];
            for (size_t k = 0; k < children.size(); ++k) {
                const std::string at =
                    "nodes[" + std::to_string(i) + "].children[" + std::to_string(k) + "]";
                const uint64_t c = children[k].get<uint64_t>();
                if (c >= count)
                    fail(at, "is " + std::to_string(c) + "; expected a node index below " +
                                 std::to_string(count));
                if (parent[c] >= 0)
                    fail(at, "node " + std::to_string(c) + " is already a child of node " +
                                 std::to_string(parent[c]) +
                                 "; expected a tree (a node has one parent)");
                parent[c] = int64_t(i);
            }
        }
        // With one parent each, a node is in a cycle when walking up from it never ends.
        for (size_t i = 0; i < count; ++i) {
            int64_t up = parent[i];
            for (size_t steps = 0; up >= 0; ++steps) {
                if (size_t(up) == i || steps > count)
                    fail("nodes[" + std::to_string(i) + "].children",
                         "node " + std::to_string(i) +
                             " is its own ancestor (a cycle of children); expected a tree");
                up = parent[size_t(up)];
            }
        }
    }

    [[noreturn]] void fail(const std::string& place, const std::string& what) const {
        throw Error(path_ + ": " + place + ": " + what);
    }

    static std::string typeName(const Json& v) { return v.type_name(); }

    void required(const Json& parent, const char* key, const std::string& at) const {
        if (!parent.contains(key)) fail(at, std::string("has no '") + key + "'; it is required");
    }

    void object(const Json& parent, const char* key, const std::string& at) const {
        if (parent.contains(key) && !parent[key].is_object())
            fail(at, "is " + typeName(parent[key]) + "; expected an object");
    }

    // glTF's extras are objects; a null or another type would be dropped silently.
    void extras(const Json& parent, const std::string& at) const {
        if (!parent.contains("extras")) return;
        const Json& e = parent["extras"];
        if (!e.is_object()) fail(at + ".extras", "is " + typeName(e) + "; expected an object");
        if (e.contains("onelight") && (!e["onelight"].is_object() || e["onelight"].empty()))
            fail(at + ".extras.onelight",
                 "is " +
                     (e["onelight"].is_object() ? std::string("empty") : typeName(e["onelight"])) +
                     "; expected an object with at least one setting (docs/level-authoring.md)");
        if (e.contains("onelight")) {
            static const char* const kKeys[] = {
                "role",     "dynamic",          "spawn",         "probe", "mover",   "grid",
                "exposure", "texels_per_metre", "probe_spacing", "sky",   "diffuse", "gloss_mips",
                "prop",     "casts_shadows"};
            for (const auto& [key, value] : e["onelight"].items()) {
                bool known = false;
                for (const char* k : kKeys) known |= key == k;
                if (!known)
                    fail(at + ".extras.onelight." + clipForMessage(key),
                         "is not a setting; expected role, dynamic, spawn, probe, mover, grid, "
                         "exposure, texels_per_metre, probe_spacing, sky, diffuse, gloss_mips, "
                         "prop or casts_shadows");
                if (value.is_null())
                    fail(at + ".extras.onelight." + key,
                         "is null; expected a value (leave the setting out for its default)");
                if (key == "casts_shadows" && !value.is_boolean())
                    fail(at + ".extras.onelight.casts_shadows",
                         "is " + typeName(value) + "; expected true or false");
            }
        }
    }

    void string(const Json& parent, const char* key, const std::string& at) const {
        if (parent.contains(key) && !parent[key].is_string())
            fail(at, "is " + typeName(parent[key]) + "; expected a string");
    }

    void boolean(const Json& parent, const char* key, const std::string& at) const {
        if (parent.contains(key) && !parent[key].is_boolean())
            fail(at, "is " + typeName(parent[key]) + "; expected true or false");
    }

    void integer(const Json& parent, const char* key, const std::string& at, int64_t low,
                 int64_t high = int64_t(1) << 31) const {
        if (!parent.contains(key)) return;
        const Json& v = parent[key];
        const bool whole = v.is_number_integer() ||
                           (v.is_number_float() && std::floor(v.get<double>()) == v.get<double>() &&
                            std::fabs(v.get<double>()) < 9e15);
        if (!whole) fail(at, "is " + describe(v) + "; expected an integer");
        const int64_t x = v.is_number_unsigned() && v.get<uint64_t>() > uint64_t(INT64_MAX)
                              ? INT64_MAX
                              : int64_t(v.get<double>());
        if (x < low || x > high)
            fail(at, "is " + std::to_string(x) + "; expected " + std::to_string(low) + ".." +
                         std::to_string(high));
    }

    void number(const Json& parent, const char* key, const std::string& at, double low,
                double high) const {
        if (parent.contains(key)) numberValue(parent[key], at, low, high);
    }

    void numberValue(const Json& v, const std::string& at, double low, double high) const {
        if (!v.is_number()) fail(at, "is " + describe(v) + "; expected a number");
        const double x = v.get<double>();
        if (!(x >= low && x <= high))
            fail(at, "is " + std::to_string(x) + "; expected a number in [" + std::to_string(low) +
                         ", " + std::to_string(high) + "]");
    }

    void numberArray(const Json& parent, const char* key, const std::string& at, size_t count,
                     double low, double high) const {
        if (!parent.contains(key)) return;
        const Json& v = parent[key];
        if (!v.is_array() || v.size() != count)
            fail(at, (v.is_array() ? std::to_string(v.size()) + " elements" : "is " + typeName(v)) +
                         "; expected " + std::to_string(count) + " numbers");
        for (size_t i = 0; i < count; ++i)
            numberValue(v[i], at + "[" + std::to_string(i) + "]", low, high);
    }

    void integerArray(const Json& parent, const char* key, const std::string& at) const {
        if (!parent.contains(key)) return;
        const Json& v = parent[key];
        if (!v.is_array()) fail(at, "is " + typeName(v) + "; expected an array of indices");
        for (size_t i = 0; i < v.size(); ++i)
            if (!v[i].is_number_integer() || v[i].get<int64_t>() < 0)
                fail(at + "[" + std::to_string(i) + "]",
                     "is " + describe(v[i]) + "; expected an index >= 0");
    }

    void stringArray(const Json& parent, const char* key, const std::string& at) const {
        if (!parent.contains(key)) return;
        const Json& v = parent[key];
        if (!v.is_array()) fail(at, "is " + typeName(v) + "; expected an array of strings");
        for (size_t i = 0; i < v.size(); ++i)
            if (!v[i].is_string())
                fail(at + "[" + std::to_string(i) + "]",
                     "is " + typeName(v[i]) + "; expected a string");
    }

    static std::string describe(const Json& v) {
        if (v.is_number() || v.is_boolean()) return clipForMessage(v.dump(), 40);
        return typeName(v);
    }

    template <typename F>
    void each(const Json& parent, const char* key, const F& visit) const {
        each(parent, key, key, visit);
    }
    template <typename F>
    void each(const Json& parent, const char* key, const std::string& at, const F& visit) const {
        if (!parent.contains(key)) return;
        const Json& v = parent[key];
        if (!v.is_array()) fail(at, "is " + typeName(v) + "; expected an array");
        for (size_t i = 0; i < v.size(); ++i) {
            const std::string place = at + "[" + std::to_string(i) + "]";
            if (!v[i].is_object()) fail(place, "is " + typeName(v[i]) + "; expected an object");
            visit(v[i], place);
        }
    }

    void textureInfo(const Json& parent, const char* key, const std::string& at) const {
        if (!parent.contains(key)) return;
        object(parent, key, at);
        const Json& t = parent[key];
        required(t, "index", at);
        integer(t, "index", at + ".index", 0);
        integer(t, "texCoord", at + ".texCoord", 0, 1);
    }

    void node(const Json& n, const std::string& at) const {
        extras(n, at);
        string(n, "name", at + ".name");
        numberArray(n, "matrix", at + ".matrix", 16, -HUGE_VAL, HUGE_VAL);
        numberArray(n, "translation", at + ".translation", 3, -HUGE_VAL, HUGE_VAL);
        numberArray(n, "rotation", at + ".rotation", 4, -1.0, 1.0);
        numberArray(n, "scale", at + ".scale", 3, -HUGE_VAL, HUGE_VAL);
        integerArray(n, "children", at + ".children");
        integer(n, "mesh", at + ".mesh", 0);
        integer(n, "camera", at + ".camera", 0);
        if (n.contains("extensions")) {
            object(n, "extensions", at + ".extensions");
            const Json& e = n["extensions"];
            if (e.contains("KHR_lights_punctual")) {
                object(e, "KHR_lights_punctual", at + ".extensions.KHR_lights_punctual");
                required(e["KHR_lights_punctual"], "light", at + ".extensions.KHR_lights_punctual");
                integer(e["KHR_lights_punctual"], "light",
                        at + ".extensions.KHR_lights_punctual.light", 0);
            }
        }
    }

    void material(const Json& m, const std::string& at) const {
        extras(m, at);
        if (m.contains("pbrMetallicRoughness")) {
            object(m, "pbrMetallicRoughness", at + ".pbrMetallicRoughness");
            const Json& p = m["pbrMetallicRoughness"];
            const std::string pat = at + ".pbrMetallicRoughness";
            numberArray(p, "baseColorFactor", pat + ".baseColorFactor", 4, 0.0, 1.0);
            number(p, "metallicFactor", pat + ".metallicFactor", 0.0, 1.0);
            number(p, "roughnessFactor", pat + ".roughnessFactor", 0.0, 1.0);
            textureInfo(p, "baseColorTexture", pat + ".baseColorTexture");
            textureInfo(p, "metallicRoughnessTexture", pat + ".metallicRoughnessTexture");
        }
        numberArray(m, "emissiveFactor", at + ".emissiveFactor", 3, 0.0, 1.0);
        number(m, "alphaCutoff", at + ".alphaCutoff", 0.0, 1.0);
        boolean(m, "doubleSided", at + ".doubleSided");
        if (m.contains("alphaMode")) {
            string(m, "alphaMode", at + ".alphaMode");
            const std::string mode = m["alphaMode"].get<std::string>();
            if (mode != "OPAQUE" && mode != "MASK" && mode != "BLEND")
                fail(at + ".alphaMode",
                     "'" + clipForMessage(mode) + "'; expected OPAQUE, MASK or BLEND");
        }
        textureInfo(m, "normalTexture", at + ".normalTexture");
        textureInfo(m, "occlusionTexture", at + ".occlusionTexture");
        textureInfo(m, "emissiveTexture", at + ".emissiveTexture");
        if (m.contains("normalTexture"))
            number(m["normalTexture"], "scale", at + ".normalTexture.scale", -1e6, 1e6);
        if (m.contains("occlusionTexture"))
            number(m["occlusionTexture"], "strength", at + ".occlusionTexture.strength", 0.0, 1.0);
        if (m.contains("extensions") && m["extensions"].is_object() &&
            m["extensions"].contains("KHR_materials_emissive_strength")) {
            const std::string eat = at + ".extensions.KHR_materials_emissive_strength";
            object(m["extensions"], "KHR_materials_emissive_strength", eat);
            number(m["extensions"]["KHR_materials_emissive_strength"], "emissiveStrength",
                   eat + ".emissiveStrength", 0.0, 1e12);
        }
    }

    void camera(const Json& c, const std::string& at) const {
        extras(c, at);
        required(c, "type", at);
        string(c, "type", at + ".type");
        const std::string type = c["type"].get<std::string>();
        if (type != "perspective" && type != "orthographic")
            fail(at + ".type",
                 "'" + clipForMessage(type) + "'; expected perspective or orthographic");
        required(c, type.c_str(), at);
        object(c, type.c_str(), at + "." + type);
        const Json& p = c[type];
        const std::string pat = at + "." + type;
        if (type == "perspective") {
            required(p, "yfov", pat);
            number(p, "yfov", pat + ".yfov", 1e-6, std::numbers::pi - 1e-6);
            number(p, "aspectRatio", pat + ".aspectRatio", 1e-6, 1e6);
            required(p, "znear", pat);
            number(p, "znear", pat + ".znear", 1e-9, 1e9);
            number(p, "zfar", pat + ".zfar", 0.0, HUGE_VAL);
        } else {
            for (const char* key : {"xmag", "ymag", "znear", "zfar"}) required(p, key, pat);
            number(p, "xmag", pat + ".xmag", -1e9, 1e9);
            number(p, "ymag", pat + ".ymag", -1e9, 1e9);
            number(p, "znear", pat + ".znear", 0.0, 1e9);
            number(p, "zfar", pat + ".zfar", 0.0, 1e9);
            if (p["xmag"].get<double>() == 0.0 || p["ymag"].get<double>() == 0.0)
                fail(pat, "xmag or ymag is 0; expected a non-zero magnification");
        }
        if (p.contains("zfar") && !(p["zfar"].get<double>() > p["znear"].get<double>()))
            fail(pat + ".zfar", "is " + describe(p["zfar"]) + ", not beyond znear " +
                                    describe(p["znear"]) + "; expected zfar > znear");
    }

    void light(const Json& l, const std::string& at) const {
        extras(l, at);
        required(l, "type", at);
        string(l, "type", at + ".type");
        const std::string type = l["type"].get<std::string>();
        if (type != "directional" && type != "point" && type != "spot")
            fail(at + ".type",
                 "'" + clipForMessage(type) + "'; expected directional, point or spot");
        string(l, "name", at + ".name");
        numberArray(l, "color", at + ".color", 3, 0.0, 1e6);
        number(l, "intensity", at + ".intensity", 0.0, 1e15);
        number(l, "range", at + ".range", 1e-9, HUGE_VAL);
        if (type == "spot") {
            required(l, "spot", at);
            object(l, "spot", at + ".spot");
            const Json& s = l["spot"];
            const double half = std::numbers::pi / 2.0;
            number(s, "innerConeAngle", at + ".spot.innerConeAngle", 0.0, half);
            number(s, "outerConeAngle", at + ".spot.outerConeAngle", 1e-6, half);
            const double inner = s.value("innerConeAngle", 0.0);
            const double outer = s.value("outerConeAngle", std::numbers::pi / 4.0);
            if (!(inner < outer))
                fail(at + ".spot", "innerConeAngle " + std::to_string(inner) +
                                       " is not below outerConeAngle " + std::to_string(outer) +
                                       "; expected inner < outer");
        }
    }
};

}  // namespace

void checkGltfJson(const char* text, size_t size, const std::string& path) {
    checkDepth(text, size, path);
    Json root;
    try {
        root = Json::parse(text, text + size);
    } catch (const Json::exception& e) {  // parse_error, and out_of_range for 1e400
        throw Error(path + ": not a valid glTF 2.0 file: not JSON (" +
                    clipForMessage(e.what(), 160) + ")");
    }
    Checker(path).document(root);
}

GltfFile readCheckedGltf(const std::string& path) {
    return checkGltfBytes(readRegularFile(path, "a .gltf or .glb file"), path);
}

GltfFile checkGltfBytes(std::vector<uint8_t> bytes, const std::string& path) {
    GltfFile file;
    file.bytes = std::move(bytes);
    const std::vector<uint8_t>& b = file.bytes;
    file.binary = b.size() >= 4 && readU32(b, 0) == kGlbMagic;
    if (!file.binary) {
        checkGltfJson(reinterpret_cast<const char*>(b.data()), b.size(), path);
        return file;
    }
    if (b.size() < 20)
        throw Error(path + ": glb of " + std::to_string(b.size()) +
                    " bytes; expected a 12-byte header and a JSON chunk");
    const uint32_t version = readU32(b, 4), length = readU32(b, 8);
    if (version != 2)
        throw Error(path + ": glb version " + std::to_string(version) + "; expected version 2");
    if (length > b.size() || length < 20)
        throw Error(path + ": glb header length " + std::to_string(length) + " with " +
                    std::to_string(b.size()) + " bytes in the file; expected 20..file size");
    const uint32_t jsonLength = readU32(b, 12), jsonType = readU32(b, 16);
    if (jsonType != kGlbJsonChunk || jsonLength > length - 20)
        throw Error(path + ": glb's first chunk (type " + std::to_string(jsonType) + ", " +
                    std::to_string(jsonLength) + " bytes); expected a JSON chunk within " +
                    std::to_string(length - 20) + " bytes");
    checkGltfJson(reinterpret_cast<const char*>(b.data()) + 20, jsonLength, path);
    return file;
}

}  // namespace onelight::world
