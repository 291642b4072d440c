#include "world/dynamic_primary.hpp"

#include "world/light_model.hpp"

namespace onelight::world {

bool updateDynamicPrimary(DynamicPrimary& pick, glm::vec3 origin,
                          std::span<const uint32_t> candidates, const PrimaryScore& score) {
    if (candidates.empty()) return false;
    if (glm::length(origin - pick.lastOrigin) < kPrimaryEvaluationDistance) return false;
    pick.lastOrigin = origin;
    uint32_t best = kNoIndex;
    float bestScore = -1.0f, currentScore = 0.0f;
    for (uint32_t light : candidates) {
        const float s = score(light, origin);
        if (s > bestScore) best = light, bestScore = s;  // ties: the earlier light
        if (light == pick.primary) currentScore = s;
    }
    if (pick.primary == kNoIndex || best == pick.primary) {
        pick.primary = best;
        pick.challenger = kNoIndex;
        pick.challengerEvaluations = 0;
        return true;
    }
    pick.challengerEvaluations = best == pick.challenger ? pick.challengerEvaluations + 1 : 1;
    pick.challenger = best;
    if (bestScore > currentScore * kPrimarySwitchRatio ||
        pick.challengerEvaluations >= kPrimarySwitchEvaluations) {
        pick.primary = best;
        pick.challenger = kNoIndex;
        pick.challengerEvaluations = 0;
    }
    return true;
}

float gridPrimaryScore(const std::vector<Light>& lights, const LightGrid& grid,
                       const LightGridSample& sample, uint32_t light, glm::vec3 point) {
    const float e = unshadowedIlluminance(lights.at(light), point);
    if (!(e > 0.0f)) return 0.0f;
    return e * dominantVisibility(grid, sample, light);
}

}  // namespace onelight::world
