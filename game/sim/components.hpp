// The demo game's components: plain structs, one concern each.
#pragma once

#include <cstdint>
#include <string>

#include <glm/glm.hpp>
#include <glm/gtc/quaternion.hpp>

#include "world/dynamic_primary.hpp"

namespace onelight::game {

struct Name {
    std::string value;  // as in the level (node name), for replays and captures
};

struct Transform {
    glm::vec3 position{0.0f};  // metres, world
    glm::vec3 scale{1.0f};
    float yaw = 0.0f;                        // radians about +y, 0 looks down -z
    glm::quat turn{1.0f, 0.0f, 0.0f, 0.0f};  // a mover's turn (after the yaw), world
};

// The player: feet position in Transform, view angles here.
struct Player {
    float yaw = 0.0f;          // radians about +y; 0 looks down -z, positive turns left
    float pitch = 0.0f;        // radians, positive looks up, clamped to +-89 degrees
    glm::vec3 velocity{0.0f};  // metres per second
    bool onGround = false;
    bool jumpHeld = false;                   // Quake movement: jumped, the key not yet released
    float knockbackSeconds = 0.0f;           // Quake movement: no ground friction for this long
    uint32_t groundMover = world::kNoIndex;  // Quake movement: the mover it stands on (into the
                                             // level's movers), which carries it
};

// What a level's triggers did to the player (game/sim/systems.hpp triggerSystem), counted from
// the start, for replays to check.
struct TriggerEvents {
    uint32_t teleports = 0;
    uint32_t jumpPadLaunches = 0;       // a pad counts once until the player leaves it
    uint32_t respawns = 0;              // by a hurt trigger or by falling below the level
    uint32_t touchingPad = UINT32_MAX;  // the jump pad touched last tick (into the triggers)
};

// The one spot effect light, carried by the player (the flashlight).
struct Flashlight {
    bool on = false;
};

// A diffuse-only omni effect light that lives for a few ticks (a gun flash).
struct GunFlash {
    uint64_t bornTick = 0;
    uint64_t serial = 0;  // order of firing; the oldest gives way first
};

// A dynamic object lit by one primary light, picked at its origin (Transform.position, where the
// renderer also reads the light grid for it) whenever it moves (world/dynamic_primary.hpp), and
// handed to the renderer with its transform.
struct DynamicLighting {
    world::DynamicPrimary pick;  // pick.primary: into the level's lights, or world::kNoIndex
    // A switch's cross-fade (world::kPrimaryFadeSeconds): the primary it left, lit at
    // 1 - primaryWeight(), and when the new one started to take over (seconds).
    uint32_t fadingFrom = world::kNoIndex;
    double fadeStart = 0.0;
    // Where its primary is picked from when that is not where it is drawn: an item's rest (its
    // bob is for show; picked at the bobbing origin, an item on a boundary switched lights with
    // every bob), a mover's bounds' centre where it is (a door's origin is the map's).
    bool fixedOrigin = false;
    glm::vec3 origin{0.0f};
};

// The weight of a dynamic object's primary at `seconds` (its old primary's is 1 - this): from 0
// at the switch to 1 kPrimaryFadeSeconds later; 1 when not fading.
[[nodiscard]] inline float primaryWeight(const DynamicLighting& lit, double seconds) {
    if (lit.fadingFrom == world::kNoIndex) return 1.0f;
    const double w = (seconds - lit.fadeStart) / double(world::kPrimaryFadeSeconds);
    return float(w < 0.0 ? 0.0 : w > 1.0 ? 1.0 : w);
}

}  // namespace onelight::game
