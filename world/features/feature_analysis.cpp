#include "world/features/feature_analysis.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

#include "world/entity_transform.hpp"

namespace onelight::world {

Features analyseFeatures(const CompiledLevel& level, bool hasAuthoredGrid,
                         const glm::vec3& authoredGridMin, const glm::vec3& authoredGridMax,
                         float gridMargin) {
    Features f;
    std::vector<uint8_t> materialUsed(level.materials.size(), 0);
    for (const Surface& s : level.surfaces)
        if (s.material < materialUsed.size()) materialUsed[s.material] = 1;
    for (const DynamicMesh& m : level.dynamicMeshes)
        if (m.material < materialUsed.size()) materialUsed[m.material] = 1;
    for (size_t i = 0; i < level.materials.size(); ++i) {
        if (!materialUsed[i]) continue;
        const Material& m = level.materials[i];
        f.materialClasses |= 1u << static_cast<uint32_t>(m.materialClass);
        if (m.normalTexture != kNoIndex) f.flags |= kFeatureNormalMaps;
        if (m.alphaMode == AlphaMode::kMask) f.flags |= kFeatureAlphaMask;
        if (m.alphaMode == AlphaMode::kBlend) f.flags |= kFeatureAlphaBlend;
        if (m.emissive != glm::vec3(0.0f) || m.emissiveTexture != kNoIndex)
            f.flags |= kFeatureEmissive;
        if (m.doubleSided) f.flags |= kFeatureDoubleSided;
        if (m.materialClass != MaterialClass::kLambert) f.flags |= kFeatureProbes;
    }
    std::vector<uint8_t> primaryUsed(level.lights.size(), 0);
    for (const Surface& s : level.surfaces)
        if (s.primaryLight < primaryUsed.size()) primaryUsed[s.primaryLight] = 1;
    for (size_t i = 0; i < level.lights.size(); ++i) {
        const Light& light = level.lights[i];
        const uint32_t typeBit = 1u << static_cast<uint32_t>(light.type);
        switch (light.role) {
            case LightRole::kPrimary:
                // An unused primary still lights dynamic objects, which pick theirs at runtime.
                if (primaryUsed[i] || !level.dynamicMeshes.empty()) {
                    f.primaryLightTypes |= typeBit;
                    ++f.primaryCount;
                }
                break;
            case LightRole::kBaked:
                f.bakedLightTypes |= typeBit;
                ++f.bakedLightCount;
                break;
            case LightRole::kEffect:
                if (light.type == LightType::kSpot)
                    ++f.effectSpotCount;
                else
                    ++f.effectOmniCount;
                break;
        }
    }
    if (f.effectOmniCount > 0) f.flags |= kFeatureEffectOmni;
    if (f.effectSpotCount > 0) f.flags |= kFeatureEffectSpot;
    if (!level.surfaces.empty()) f.flags |= kFeatureLightmaps;
    if (!level.dynamicMeshes.empty()) f.flags |= kFeatureLightGrid;
    for (const Entity& e : level.entities)
        if (e.flags & kEntityProbe) ++f.probeCount;
    if ((f.flags & kFeatureProbes) && f.probeCount == 0) f.flags |= kFeatureAutoProbes;
    if (hasAuthoredGrid) {
        f.flags |= kFeatureAuthoredGrid;
        f.gridMin = authoredGridMin;
        f.gridMax = authoredGridMax;
    } else if (!level.surfaces.empty()) {
        f.gridMin = level.settings.boundsMin - glm::vec3(gridMargin);
        f.gridMax = level.settings.boundsMax + glm::vec3(gridMargin);
    }
    return f;
}

bool dynamicObjectReach(const CompiledLevel& level, glm::vec3& boxMin, glm::vec3& boxMax) {
    boxMin = glm::vec3(std::numeric_limits<float>::max());
    boxMax = glm::vec3(std::numeric_limits<float>::lowest());
    bool any = false;
    std::vector<std::vector<MoverPose>> poses(level.entities.size());  // a mover's reach
    for (const Mover& mover : level.movers.movers)
        if (mover.entity < poses.size()) poses[mover.entity] = moverReach(level.movers, mover);
    for (size_t i = 0; i < level.entities.size(); ++i) {
        const Entity& e = level.entities[i];
        if (!(e.flags & kEntityDynamic)) continue;
        if (poses[i].empty()) poses[i].push_back({e.position});
        for (const MoverPose& pose : poses[i]) {
            const glm::mat4 world = worldFromObject(e, pose.origin, pose.turn);
            for (uint32_t m = e.firstDynamicMesh;
                 m < e.firstDynamicMesh + e.dynamicMeshCount && m < level.dynamicMeshes.size();
                 ++m) {
                const DynamicMesh& mesh = level.dynamicMeshes[m];
                for (uint32_t v = mesh.firstVertex;
                     v < mesh.firstVertex + mesh.vertexCount && v < level.dynamicVertices.size();
                     ++v) {
                    const glm::vec3 p =
                        glm::vec3(world * glm::vec4(level.dynamicVertices[v].position, 1.0f));
                    if (!(std::isfinite(p.x) && std::isfinite(p.y) && std::isfinite(p.z))) continue;
                    boxMin = glm::min(boxMin, p);
                    boxMax = glm::max(boxMax, p);
                    any = true;
                }
            }
        }
    }
    return any;
}

}  // namespace onelight::world
