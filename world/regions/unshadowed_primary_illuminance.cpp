#include "world/light_model.hpp"
#include "world/regions/primary_illuminance.hpp"

namespace onelight::world {

uint32_t dominantPrimary(std::span<const double> illuminance) {
    uint32_t best = kNoIndex;
    double bestValue = 0.0;
    for (size_t i = 0; i < illuminance.size(); ++i) {
        if (illuminance[i] > bestValue) {
            bestValue = illuminance[i];
            best = static_cast<uint32_t>(i);
        }
    }
    return best;
}

PrimaryIlluminanceFn makeUnshadowedPrimaryIlluminance(std::vector<Light> primaries) {
    // The shared light model (shaders/lighting.glsl through world/light_model), which the
    // baker's shadowed illuminance and the runtime evaluate too.
    return [primaries = std::move(primaries)](const glm::dvec3& position, const glm::vec3& normal,
                                              std::span<double> illuminance) {
        for (size_t i = 0; i < primaries.size() && i < illuminance.size(); ++i)
            illuminance[i] =
                double(unshadowedIlluminance(primaries[i], glm::vec3(position), normal));
    };
}

}  // namespace onelight::world
