#include "world/import/extras_import.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>

#include <tiny_gltf.h>

#include "world/error.hpp"
#include "world/file_read.hpp"

namespace onelight::world {
namespace {

bool readBool(const tinygltf::Value& v, const std::string& place) {
    if (!v.IsBool()) throw Error(place + " must be true or false");
    return v.Get<bool>();
}

float readNumber(const tinygltf::Value& v, const std::string& place) {
    if (!v.IsNumber() || !std::isfinite(v.GetNumberAsDouble()))
        throw Error(place + " must be a finite number");
    return static_cast<float>(v.GetNumberAsDouble());
}

std::string readString(const tinygltf::Value& v, const std::string& place) {
    if (!v.IsString()) throw Error(place + " must be a string");
    return v.Get<std::string>();
}

glm::vec3 readVec3(const tinygltf::Value& v, const std::string& place) {
    if (!v.IsArray() || v.ArrayLen() != 3) throw Error(place + " must be an array of 3 numbers");
    glm::vec3 out;
    for (int i = 0; i < 3; ++i)
        out[i] = readNumber(v.Get(i), place + "[" + std::to_string(i) + "]");
    return out;
}

void readBox(const tinygltf::Value& v, const char* minKey, const char* maxKey,
             const std::string& place, glm::vec3& lo, glm::vec3& hi) {
    if (!v.IsObject() || !v.Has(minKey) || !v.Has(maxKey))
        throw Error(place + std::string(" must be an object with \"") + minKey + "\" and \"" +
                    maxKey + "\"");
    lo = readVec3(v.Get(minKey), place + "." + minKey);
    hi = readVec3(v.Get(maxKey), place + "." + maxKey);
    if (!(lo.x < hi.x && lo.y < hi.y && lo.z < hi.z))
        throw Error(place + ": expected " + minKey + " < " + maxKey + " on every axis");
}

// True when `name` ends in ".hdr", in any case.
bool endsWithHdr(const std::string& name) {
    if (name.size() < 4) return false;
    std::string end = name.substr(name.size() - 4);
    for (char& c : end) c = char(std::tolower(static_cast<unsigned char>(c)));
    return end == ".hdr";
}

}  // namespace

NodeExtras parseNodeExtras(const tinygltf::Value& extras, const std::string& where) {
    NodeExtras out;
    if (!extras.IsObject() || !extras.Has("onelight")) return out;
    const tinygltf::Value& o = extras.Get("onelight");
    const std::string base = where + " extras.onelight";
    if (!o.IsObject()) throw Error(base + " must be an object");
    if (o.Has("role")) {
        const tinygltf::Value& role = o.Get("role");
        const std::string value = role.IsString() ? role.Get<std::string>() : std::string();
        out.hasRole = true;
        if (value == "primary")
            out.role = LightRole::kPrimary;
        else if (value == "baked")
            out.role = LightRole::kBaked;
        else if (value == "effect")
            out.role = LightRole::kEffect;
        else
            throw Error(base + ".role is \"" + value +
                        "\"; expected \"primary\", \"baked\" or \"effect\"");
    }
    if (o.Has("dynamic")) out.dynamic = readBool(o.Get("dynamic"), base + ".dynamic");
    if (o.Has("spawn")) out.spawn = readBool(o.Get("spawn"), base + ".spawn");
    if (o.Has("prop")) {
        const tinygltf::Value& prop = o.Get("prop");
        if (prop.IsBool()) {
            out.prop = prop.Get<bool>();
        } else if (prop.IsObject() && prop.Has("lighting_origin")) {
            out.prop = out.hasLightingOrigin = true;
            out.lightingOrigin =
                readVec3(prop.Get("lighting_origin"), base + ".prop.lighting_origin");
        } else {
            throw Error(base + ".prop: expected true, false or {\"lighting_origin\": [x, y, z]}");
        }
    }
    if (o.Has("probe")) {
        const tinygltf::Value& probe = o.Get("probe");
        if (probe.IsBool()) {
            out.probe = probe.Get<bool>();
        } else {
            out.probe = true;
            out.hasProbeBox = true;
            readBox(probe, "box_min", "box_max", base + ".probe", out.probeBoxMin, out.probeBoxMax);
        }
    }
    if (o.Has("mover")) {
        const tinygltf::Value& mover = o.Get("mover");
        const std::string place = base + ".mover";
        if (!mover.IsObject() || !mover.Has("offset") || !mover.Has("period"))
            throw Error(place + " must be an object with \"offset\" and \"period\"");
        out.mover = true;
        out.dynamic = true;
        out.moverOffset = readVec3(mover.Get("offset"), place + ".offset");
        out.moverPeriod = readNumber(mover.Get("period"), place + ".period");
        if (!(out.moverPeriod > 0.0f))
            throw Error(place + ".period is " + std::to_string(out.moverPeriod) +
                        "; expected seconds > 0");
    }
    if (o.Has("grid")) {
        out.hasGrid = true;
        readBox(o.Get("grid"), "min", "max", base + ".grid", out.gridMin, out.gridMax);
    }
    if (o.Has("texels_per_metre")) {
        out.texelsPerMetre = readNumber(o.Get("texels_per_metre"), base + ".texels_per_metre");
        if (!(out.texelsPerMetre > 0.0f && out.texelsPerMetre <= 1024.0f))
            throw Error(base + ".texels_per_metre is " + std::to_string(out.texelsPerMetre) +
                        "; expected a density in (0, 1024] texels per metre");
    }
    if (o.Has("probe_spacing")) {
        out.probeSpacing = readNumber(o.Get("probe_spacing"), base + ".probe_spacing");
        if (!(out.probeSpacing > 0.0f))
            throw Error(base + ".probe_spacing is " + std::to_string(out.probeSpacing) +
                        "; expected metres > 0 between automatic probes");
    }
    if (o.Has("diffuse")) {
        const std::string name = readString(o.Get("diffuse"), base + ".diffuse");
        if (name == "lambert")
            out.diffuseModel = DiffuseModel::kLambert;
        else if (name == "multiscatter")
            out.diffuseModel = DiffuseModel::kMultiscatter;
        else
            throw Error(base + ".diffuse is '" + clipForMessage(name) +
                        "'; expected \"lambert\" or \"multiscatter\"");
    }
    if (o.Has("gloss_mips")) {
        const std::string name = readString(o.Get("gloss_mips"), base + ".gloss_mips");
        if (name == "blit")
            out.glossMips = GlossMipMethod::kBlit;
        else if (name == "black_ops")
            out.glossMips = GlossMipMethod::kBlackOps;
        else if (name == "wwii")
            out.glossMips = GlossMipMethod::kWwii;
        else if (name == "clean")
            out.glossMips = GlossMipMethod::kClean;
        else
            throw Error(base + ".gloss_mips is '" + clipForMessage(name) +
                        "'; expected \"blit\", \"black_ops\", \"wwii\" or \"clean\"");
    }
    if (o.Has("sky")) {
        const tinygltf::Value& sky = o.Get("sky");
        out.hasSky = true;
        // An image: "file.hdr", or {"image": "file.hdr", "scale": s or [r, g, b]}.
        const tinygltf::Value* scale = nullptr;
        if (sky.IsString()) {
            out.skyImage = sky.Get<std::string>();
        } else if (sky.IsObject()) {
            if (!sky.Has("image") || !sky.Get("image").IsString())
                throw Error(base +
                            ".sky is an object without \"image\"; expected {\"image\": "
                            "\"sky.hdr\", \"scale\": cd/m^2 per unit}");
            out.skyImage = sky.Get("image").Get<std::string>();
            if (sky.Has("scale")) scale = &sky.Get("scale");
        }
        if (!out.skyImage.empty() && !endsWithHdr(out.skyImage))
            throw Error(base + ".sky names '" + out.skyImage +
                        "'; expected a Radiance .hdr file, or a radiance in cd/m^2");
        const tinygltf::Value* radiance = out.skyImage.empty() ? &sky : scale;
        const std::string what = out.skyImage.empty() ? ".sky" : ".sky.scale";
        out.skyRadiance = radiance == nullptr   ? glm::vec3(1.0f)
                          : radiance->IsArray() ? readVec3(*radiance, base + what)
                                                : glm::vec3(readNumber(*radiance, base + what));
        if (!(std::min({out.skyRadiance.x, out.skyRadiance.y, out.skyRadiance.z}) >= 0.0f))
            throw Error(base + what +
                        " is negative; expected a radiance in cd/m^2 >= 0 "
                        "(one number, or [r, g, b])");
    }
    if (o.Has("exposure")) {
        out.hasExposure = true;
        out.exposureEv100 = readNumber(o.Get("exposure"), base + ".exposure");
    }
    if (out.prop && out.dynamic)
        throw Error(base +
                    ": a prop is static (one primary, baked); it cannot also be dynamic "
                    "or a mover");
    return out;
}

}  // namespace onelight::world
