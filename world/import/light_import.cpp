#include "world/import/light_import.hpp"

#include <cmath>
#include <numbers>

#include <tiny_gltf.h>

#include "world/error.hpp"

namespace onelight::world {

Light importLight(const tinygltf::Light& source, const glm::dmat4& worldFromLocal,
                  const std::string& name, LightRole role, const std::string& where) {
    Light light;
    light.name = name;
    light.role = role;
    if (source.type == "directional")
        light.type = LightType::kDirectional;
    else if (source.type == "point")
        light.type = LightType::kPoint;
    else if (source.type == "spot")
        light.type = LightType::kSpot;
    else
        throw Error(where + ": light type \"" + source.type +
                    "\"; expected \"directional\", \"point\" or \"spot\"");
    if (!std::isfinite(source.intensity) || source.intensity < 0.0)
        throw Error(where + ": light intensity " + std::to_string(source.intensity) +
                    "; expected a finite value >= 0");
    light.intensity = static_cast<float>(source.intensity);
    for (size_t i = 0; i < 3 && i < source.color.size(); ++i) {
        if (!std::isfinite(source.color[i]) || source.color[i] < 0.0)
            throw Error(where + ": light color[" + std::to_string(i) +
                        "]; expected a finite value >= 0");
        light.color[static_cast<int>(i)] = static_cast<float>(source.color[i]);
    }
    if (!std::isfinite(source.range) || source.range < 0.0)
        throw Error(where + ": light range; expected a finite value >= 0");
    light.range = static_cast<float>(source.range);
    if (light.type == LightType::kSpot) {
        const double inner = source.spot.innerConeAngle, outer = source.spot.outerConeAngle;
        if (!(inner >= 0.0 && inner < outer && outer <= 0.5 * std::numbers::pi + 1e-6))
            throw Error(where + ": spot cone angles inner " + std::to_string(inner) + ", outer " +
                        std::to_string(outer) + "; expected 0 <= inner < outer <= pi/2");
        light.innerCone = static_cast<float>(inner);
        light.outerCone = static_cast<float>(outer);
    }
    const glm::dvec3 position(worldFromLocal[3]);
    const glm::dvec3 direction = glm::dvec3(worldFromLocal * glm::dvec4(0.0, 0.0, -1.0, 0.0));
    const double length = glm::length(direction);
    if (!std::isfinite(length) || !(length > 0.0))
        throw Error(where + ": the light's node transform is degenerate");
    light.position = glm::vec3(position);
    light.direction = glm::vec3(direction / length);
    return light;
}

}  // namespace onelight::world
