// The demo game's systems: free functions over the registry, run once per fixed tick in the
// order stepSession calls them (movers, player, triggers, items, effect lights, primary
// selection; the movers' own system is movers.hpp's).
#pragma once

#include <cstdint>
#include <functional>
#include <limits>
#include <span>
#include <vector>

#include "brush_trace.hpp"
#include "components.hpp"
#include "ecs/registry.hpp"
#include "ecs/schedule.hpp"
#include "input.hpp"
#include "movers.hpp"
#include "tuning.hpp"
#include "world/bsp/bsp_query.hpp"

namespace onelight::game {

// Unit view direction for yaw/pitch in radians (yaw 0 looks down -z, positive turns left).
[[nodiscard]] glm::vec3 viewDirection(float yaw, float pitch);

// The player's eye: `tuning.eyeHeight` above the feet at `transform.position`.
[[nodiscard]] glm::vec3 eyeOf(const Transform& transform, const Tuning& tuning);

// Moves a sphere of `radius` from `center` by `delta`, sliding along what it touches (at most
// four contacts a move). Returns the new centre; `floor` tells whether it stood on a surface
// whose normal.y exceeds `floorCos`. Without a BSP (an empty level) it moves freely.
[[nodiscard]] glm::vec3 moveAndSlide(const world::BspView* bsp, glm::vec3 center, glm::vec3 delta,
                                     float radius, float skin, float floorCos, bool& floor);

// WASD relative to the view, mouse look, gravity, jumping, collision against the BSP.
void playerSystem(ecs::Registry& registry, const ecs::Tick& tick, const InputState& input,
                  const Tuning& tuning, const world::BspView* bsp);

// Where the player may respawn: the feet and the view's yaw.
struct SpawnPoint {
    glm::vec3 feet{0.0f};
    float yaw = 0.0f;  // radians about +y, 0 looks down -z
};

// What the player moves through: a Quake 3 map's brushes and triggers when the level has them,
// else the drawn surfaces' BSP (glTF levels); where a fall ends and where respawns go.
struct PlayerWorld {
    const world::BspView* surfaces = nullptr;  // borrowed; null: an empty level
    const BrushWorld* brushes = nullptr;       // borrowed; null: collide with `surfaces`
    float fallLimitY = -std::numeric_limits<float>::infinity();  // feet below: respawn
    std::vector<SpawnPoint> spawns;  // respawns take them in turn; none: the player stays
};

// The player's move through `world`: Quake 3's movement (quake_move.hpp) on brushes, else the
// sphere of the overload above on the surfaces.
void playerSystem(ecs::Registry& registry, const ecs::Tick& tick, const InputState& input,
                  const Tuning& tuning, const PlayerWorld& world);

// After the move: the triggers the player's box overlaps act (a jump pad launches it to reach
// its target at the apex, Quake 3's AimAtTarget; a teleporter sends it to its destination
// facing its yaw at tuning.teleportSpeed; a hurt trigger respawns it; a door's, button's or
// plat's trigger asks `movers` for a use, when there are movers), and a player whose feet fell
// below world.fallLimitY respawns. Counts each in TriggerEvents when the player has one.
void triggerSystem(ecs::Registry& registry, const Tuning& tuning, const PlayerWorld& world,
                   MoverWorld* movers = nullptr);

// Puts `player` at the next of world.spawns (in turn), still, facing the spawn's yaw, and counts
// the respawn in its TriggerEvents; nothing when the world has no spawn.
void respawnPlayer(ecs::Registry& registry, ecs::Entity player, const Tuning& tuning,
                   const PlayerWorld& world);

// The launch velocity of a jump pad whose box is centred at `centre` aiming at `target`, under
// `gravity` (Quake 3's AimAtTarget, g_trigger.c): time = sqrt(height / (gravity / 2)),
// horizontal speed = distance / time, vertical = time * gravity. Zero when the target is not
// above the centre.
[[nodiscard]] glm::vec3 jumpPadVelocity(glm::vec3 centre, glm::vec3 target, float gravity);

// The flashlight toggle and the gun flashes: a shot spawns one in front of the eye; flashes die
// after tuning.gunFlashSeconds; beyond tuning.maxGunFlashes the oldest gives way.
void effectLightSystem(ecs::Registry& registry, const ecs::Tick& tick, const InputState& input,
                       const Tuning& tuning, uint64_t& shotSerial);

// Re-picks the primary of every dynamic object whose lighting origin moved, by
// world::updateDynamicPrimary (its hysteresis and constants) over `candidates` scored by `score`:
// the shadowed contribution of a light at a point (the light grid's answer, or a direct evaluation
// with visibility). A switch starts a cross-fade from the old primary (DynamicLighting); one
// during a fade continues from the weights it had, so the light never jumps.
void primarySelectionSystem(ecs::Registry& registry, const ecs::Tick& tick,
                            std::span<const uint32_t> candidates, const world::PrimaryScore& score);

}  // namespace onelight::game
