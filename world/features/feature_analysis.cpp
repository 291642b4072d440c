#include "world/features/feature_analysis.hpp"

#include <vector>

namespace onelight::world {

Features analyse_features(const CompiledLevel& level, bool has_authored_grid,
                          const glm::vec3& authored_grid_min, const glm::vec3& authored_grid_max,
                          float grid_margin) {
    Features f;
    std::vector<uint8_t> material_used(level.materials.size(), 0);
    for (const Surface& s : level.surfaces)
        if (s.material < material_used.size()) material_used[s.material] = 1;
    for (const DynamicMesh& m : level.dynamic_meshes)
        if (m.material < material_used.size()) material_used[m.material] = 1;
    for (size_t i = 0; i < level.materials.size(); ++i) {
        if (!material_used[i]) continue;
        const Material& m = level.materials[i];
        f.material_classes |= 1u << static_cast<uint32_t>(m.material_class);
        if (m.normal_texture != kNoIndex) f.flags |= feature_normal_maps;
        if (m.alpha_mode == AlphaMode::mask) f.flags |= feature_alpha_mask;
        if (m.alpha_mode == AlphaMode::blend) f.flags |= feature_alpha_blend;
        if (m.emissive != glm::vec3(0.0f) || m.emissive_texture != kNoIndex)
            f.flags |= feature_emissive;
        if (m.double_sided) f.flags |= feature_double_sided;
        if (m.material_class != MaterialClass::lambert) f.flags |= feature_probes;
    }
    std::vector<uint8_t> primary_used(level.lights.size(), 0);
    for (const Surface& s : level.surfaces)
        if (s.primary_light < primary_used.size()) primary_used[s.primary_light] = 1;
    for (size_t i = 0; i < level.lights.size(); ++i) {
        const Light& light = level.lights[i];
        const uint32_t type_bit = 1u << static_cast<uint32_t>(light.type);
        switch (light.role) {
            case LightRole::primary:
                // An unused primary still lights dynamic objects, which pick theirs at runtime.
                if (primary_used[i] || !level.dynamic_meshes.empty()) {
                    f.primary_light_types |= type_bit;
                    ++f.primary_count;
                }
                break;
            case LightRole::baked:
                f.baked_light_types |= type_bit;
                ++f.baked_light_count;
                break;
            case LightRole::effect:
                if (light.type == LightType::spot)
                    ++f.effect_spot_count;
                else
                    ++f.effect_omni_count;
                break;
        }
    }
    if (f.effect_omni_count > 0) f.flags |= feature_effect_omni;
    if (f.effect_spot_count > 0) f.flags |= feature_effect_spot;
    if (!level.surfaces.empty()) f.flags |= feature_lightmaps;
    if (!level.dynamic_meshes.empty()) f.flags |= feature_light_grid;
    for (const Entity& e : level.entities)
        if (e.flags & entity_probe) ++f.probe_count;
    if ((f.flags & feature_probes) && f.probe_count == 0) f.flags |= feature_auto_probes;
    if (has_authored_grid) {
        f.flags |= feature_authored_grid;
        f.grid_min = authored_grid_min;
        f.grid_max = authored_grid_max;
    } else if (!level.surfaces.empty()) {
        f.grid_min = level.settings.bounds_min - glm::vec3(grid_margin);
        f.grid_max = level.settings.bounds_max + glm::vec3(grid_margin);
    }
    return f;
}

}  // namespace onelight::world
