// The demo game's systems: free functions over the registry, run once per fixed tick in the
// order stepSession calls them (player, movers, effect lights, primary selection).
#pragma once

#include <cstdint>
#include <functional>
#include <span>

#include "components.hpp"
#include "ecs/registry.hpp"
#include "ecs/schedule.hpp"
#include "input.hpp"
#include "tuning.hpp"
#include "world/bsp/bsp_query.hpp"

namespace onelight::game {

// Unit view direction for yaw/pitch in radians (yaw 0 looks down -z, positive turns left).
[[nodiscard]] glm::vec3 viewDirection(float yaw, float pitch);

// Moves a sphere of `radius` from `center` by `delta`, sliding along what it touches (at most
// four contacts a move). Returns the new centre; `floor` tells whether it stood on a surface
// whose normal.y exceeds `floorCos`. Without a BSP (an empty level) it moves freely.
[[nodiscard]] glm::vec3 moveAndSlide(const world::BspView* bsp, glm::vec3 center, glm::vec3 delta,
                                     float radius, float skin, float floorCos, bool& floor);

// WASD relative to the view, mouse look, gravity, jumping, collision against the BSP.
void playerSystem(ecs::Registry& registry, const ecs::Tick& tick, const InputState& input,
                  const Tuning& tuning, const world::BspView* bsp);

// Places every mover on its back-and-forth path at this tick's time (a pure function of time).
void moverSystem(ecs::Registry& registry, const ecs::Tick& tick);

// The flashlight toggle and the gun flashes: a shot spawns one in front of the eye; flashes die
// after tuning.gunFlashSeconds; beyond tuning.maxGunFlashes the oldest gives way.
void effectLightSystem(ecs::Registry& registry, const ecs::Tick& tick, const InputState& input,
                       const Tuning& tuning, uint64_t& shotSerial);

// Re-picks the primary of every dynamic object whose lighting origin moved, by
// world::updateDynamicPrimary (its hysteresis and constants) over `candidates` scored by `score`:
// the shadowed contribution of a light at a point (the light grid's answer, or a direct evaluation
// with visibility).
void primarySelectionSystem(ecs::Registry& registry, std::span<const uint32_t> candidates,
                            const world::PrimaryScore& score);

}  // namespace onelight::game
