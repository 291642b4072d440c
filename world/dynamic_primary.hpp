// The primary light of a dynamic object: picked by the game whenever the object moves, with
// hysteresis so that an object resting on a boundary between two lights does not flicker, and
// handed to the renderer, which draws with it (docs/lighting.md, "Dynamic objects"). One algorithm
// and one set of constants for every consumer.
#pragma once

#include <cstdint>
#include <functional>
#include <span>
#include <vector>

#include <glm/glm.hpp>

#include "world/baked_lighting.hpp"
#include "world/compiled_level.hpp"
#include "world/light_grid_sample.hpp"

namespace onelight::world {

/// A challenger takes over when it scores this many times the current primary...
inline constexpr float kPrimarySwitchRatio = 1.25f;
/// ...or when it has led for this many evaluations in a row.
inline constexpr int kPrimarySwitchEvaluations = 6;
/// An object is evaluated again once its lighting origin has moved this far (metres).
inline constexpr float kPrimaryEvaluationDistance = 0.01f;
/// A switch cross-fades the old primary's light into the new one's over this long (seconds), so
/// that the object's lighting does not pop (the game's DynamicLighting keeps the fade).
inline constexpr float kPrimaryFadeSeconds = 0.25f;

/// A dynamic object's pick and its hysteresis state.
struct DynamicPrimary {
    uint32_t primary = kNoIndex;     // into the level's lights; kNoIndex before the first pick
    uint32_t challenger = kNoIndex;  // a light that currently beats the primary
    int challengerEvaluations = 0;   // consecutive evaluations the challenger has led
    glm::vec3 lastOrigin{1e30f};     // where it was last evaluated
};

/// How bright light `light` is at `point`, shadowing included (larger wins).
using PrimaryScore = std::function<float(uint32_t light, glm::vec3 point)>;

/// Re-picks `pick` for an object whose lighting origin is `origin`, when it moved more than
/// kPrimaryEvaluationDistance since its last evaluation: the candidate with the largest score
/// (the earlier on ties) becomes the primary at once when there is none yet or when it beats the
/// current one by kPrimarySwitchRatio, or after leading for kPrimarySwitchEvaluations
/// evaluations in a row. Returns whether it evaluated.
bool updateDynamicPrimary(DynamicPrimary& pick, glm::vec3 origin,
                          std::span<const uint32_t> candidates, const PrimaryScore& score);

/// The light grid's score of primary `light` at `point`: its unshadowed illuminance (lux) times
/// its baked visibility where it is the dominant primary of the surrounding cells
/// (dominantVisibility), so an object in a primary's shadow does not pick it. `sample` is the
/// grid sampled at `point`.
[[nodiscard]] float gridPrimaryScore(const std::vector<Light>& lights, const LightGrid& grid,
                                     const LightGridSample& sample, uint32_t light,
                                     glm::vec3 point);

}  // namespace onelight::world
