#include "world/import/extras_import.hpp"

#include <algorithm>
#include <cmath>

#include <tiny_gltf.h>

#include "world/error.hpp"

namespace onelight::world {
namespace {

bool read_bool(const tinygltf::Value& v, const std::string& place) {
    if (!v.IsBool()) throw Error(place + " must be true or false");
    return v.Get<bool>();
}

float read_number(const tinygltf::Value& v, const std::string& place) {
    if (!v.IsNumber() || !std::isfinite(v.GetNumberAsDouble()))
        throw Error(place + " must be a finite number");
    return static_cast<float>(v.GetNumberAsDouble());
}

glm::vec3 read_vec3(const tinygltf::Value& v, const std::string& place) {
    if (!v.IsArray() || v.ArrayLen() != 3) throw Error(place + " must be an array of 3 numbers");
    glm::vec3 out;
    for (int i = 0; i < 3; ++i)
        out[i] = read_number(v.Get(i), place + "[" + std::to_string(i) + "]");
    return out;
}

void read_box(const tinygltf::Value& v, const char* min_key, const char* max_key,
              const std::string& place, glm::vec3& lo, glm::vec3& hi) {
    if (!v.IsObject() || !v.Has(min_key) || !v.Has(max_key))
        throw Error(place + std::string(" must be an object with \"") + min_key + "\" and \"" +
                    max_key + "\"");
    lo = read_vec3(v.Get(min_key), place + "." + min_key);
    hi = read_vec3(v.Get(max_key), place + "." + max_key);
    if (!(lo.x < hi.x && lo.y < hi.y && lo.z < hi.z))
        throw Error(place + ": expected " + min_key + " < " + max_key + " on every axis");
}

}  // namespace

NodeExtras parse_node_extras(const tinygltf::Value& extras, const std::string& where) {
    NodeExtras out;
    if (!extras.IsObject() || !extras.Has("onelight")) return out;
    const tinygltf::Value& o = extras.Get("onelight");
    const std::string base = where + " extras.onelight";
    if (!o.IsObject()) throw Error(base + " must be an object");
    if (o.Has("role")) {
        const tinygltf::Value& role = o.Get("role");
        const std::string value = role.IsString() ? role.Get<std::string>() : std::string();
        out.has_role = true;
        if (value == "primary")
            out.role = LightRole::primary;
        else if (value == "baked")
            out.role = LightRole::baked;
        else if (value == "effect")
            out.role = LightRole::effect;
        else
            throw Error(base + ".role is \"" + value +
                        "\"; expected \"primary\", \"baked\" or \"effect\"");
    }
    if (o.Has("dynamic")) out.dynamic = read_bool(o.Get("dynamic"), base + ".dynamic");
    if (o.Has("spawn")) out.spawn = read_bool(o.Get("spawn"), base + ".spawn");
    if (o.Has("probe")) {
        const tinygltf::Value& probe = o.Get("probe");
        if (probe.IsBool()) {
            out.probe = probe.Get<bool>();
        } else {
            out.probe = true;
            out.has_probe_box = true;
            read_box(probe, "box_min", "box_max", base + ".probe", out.probe_box_min,
                     out.probe_box_max);
        }
    }
    if (o.Has("mover")) {
        const tinygltf::Value& mover = o.Get("mover");
        const std::string place = base + ".mover";
        if (!mover.IsObject() || !mover.Has("offset") || !mover.Has("period"))
            throw Error(place + " must be an object with \"offset\" and \"period\"");
        out.mover = true;
        out.dynamic = true;
        out.mover_offset = read_vec3(mover.Get("offset"), place + ".offset");
        out.mover_period = read_number(mover.Get("period"), place + ".period");
        if (!(out.mover_period > 0.0f))
            throw Error(place + ".period is " + std::to_string(out.mover_period) +
                        "; expected seconds > 0");
    }
    if (o.Has("grid")) {
        out.has_grid = true;
        read_box(o.Get("grid"), "min", "max", base + ".grid", out.grid_min, out.grid_max);
    }
    if (o.Has("texels_per_metre")) {
        out.texels_per_metre = read_number(o.Get("texels_per_metre"), base + ".texels_per_metre");
        if (!(out.texels_per_metre > 0.0f && out.texels_per_metre <= 1024.0f))
            throw Error(base + ".texels_per_metre is " + std::to_string(out.texels_per_metre) +
                        "; expected a density in (0, 1024] texels per metre");
    }
    if (o.Has("probe_spacing")) {
        out.probe_spacing = read_number(o.Get("probe_spacing"), base + ".probe_spacing");
        if (!(out.probe_spacing > 0.0f))
            throw Error(base + ".probe_spacing is " + std::to_string(out.probe_spacing) +
                        "; expected metres > 0 between automatic probes");
    }
    if (o.Has("sky")) {
        const tinygltf::Value& sky = o.Get("sky");
        out.has_sky = true;
        out.sky_radiance = sky.IsArray() ? read_vec3(sky, base + ".sky")
                                         : glm::vec3(read_number(sky, base + ".sky"));
        if (!(std::min({out.sky_radiance.x, out.sky_radiance.y, out.sky_radiance.z}) >= 0.0f))
            throw Error(base +
                        ".sky is negative; expected a radiance in cd/m^2 >= 0 "
                        "(one number, or [r, g, b])");
    }
    if (o.Has("exposure")) {
        out.has_exposure = true;
        out.exposure_ev100 = read_number(o.Get("exposure"), base + ".exposure");
    }
    return out;
}

}  // namespace onelight::world
