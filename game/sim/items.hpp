// The level's items (world::kEntityItem): Quake 3's pickups as the game runs them. Each turns
// and bobs as cgame draws items (CG_Item), stands where it dropped to the floor at the start
// (g_items.c FinishSpawningItem), is taken when the player comes within the game's reach of it
// (BG_PlayerTouchesItem, wider than its box), and comes back its respawn time later.
#pragma once

#include <cstdint>

#include <glm/glm.hpp>

#include "brush_trace.hpp"
#include "components.hpp"
#include "ecs/registry.hpp"
#include "ecs/schedule.hpp"

namespace onelight::game {

// Half the side of an item's box, metres (Quake 3's ITEM_RADIUS, 15 units): what it drops on.
inline constexpr float kItemRadius = 15.0f / 32.0f;

struct Item {
    glm::vec3 rest{0.0f};         // its origin at rest (on the floor), metres
    float respawnSeconds = 0.0f;  // taken this long; < 0: it never comes back
    uint32_t number = 0;          // its level entity: the rate of its bob (cgame's)
    bool present = true;
    uint64_t backAtTick = 0;  // while taken (and it comes back): the tick it returns
    uint32_t timesTaken = 0;
};

// Where an item placed at `origin` comes to rest: dropped along -y until its box meets a brush,
// or where it is when `suspended`. Returns false when its box starts inside a brush (the game
// then leaves the item out).
[[nodiscard]] bool dropItem(const BrushWorld* brushes, glm::vec3 origin, bool suspended,
                            glm::vec3& rest);

// The turn (radians about +y) and the height above its rest (metres) of item `number` at time
// `seconds`: one turn in 2.048 s, and 4 + 4 cos((t + 1 s) x (0.005 + number x 0.00001) per ms)
// units up (cgame's autoAngles and bob).
[[nodiscard]] float itemYaw(double seconds);
[[nodiscard]] float itemBob(double seconds, uint32_t number);

// Whether a player with its feet at `feet` reaches an item resting at `rest` (BG_PlayerTouchesItem:
// the player's origin, 24 units above its feet, within -50..44 units of the item's along the
// game's x and 36 along the other two axes; metres here, Y up).
[[nodiscard]] bool playerTouchesItem(glm::vec3 feet, glm::vec3 rest);

// Turns and bobs every present item, lets the player take those it reaches, and brings back
// those whose time has come (on the tick it comes, the player may take it again).
void itemSystem(ecs::Registry& registry, const ecs::Tick& tick, ecs::Entity player);

}  // namespace onelight::game
