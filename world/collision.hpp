// What the player collides with and the volumes that act on it, from a Quake 3 map's brushes and
// trigger entities (world/import/q3/collision_import.hpp), in metres and Y up like the rest of
// the level. A mover's brushes (world/movers.hpp) are in its object space and move with it. A glTF
// level has none (the game then collides with the drawn surfaces' BSP). The package stores it in
// sections 41 and 42 (package/format.hpp, package/collision_section).
#pragma once

#include <cstdint>
#include <vector>

#include <glm/glm.hpp>

#include "world/no_index.hpp"

namespace onelight::world {

/// Quake 3's content bits a brush may carry (surfaceflags.h); only these two block the player.
inline constexpr uint32_t kContentsSolid = 0x1;
inline constexpr uint32_t kContentsPlayerClip = 0x10000;
inline constexpr uint32_t kPlayerSolidContents = kContentsSolid | kContentsPlayerClip;

/// A plane: the points p with dot(normal, p) == distance; a brush is the intersection of the
/// half-spaces behind (dot(normal, p) <= distance) its sides' planes.
struct CollisionPlane {
    glm::vec3 normal{0.0f, 1.0f, 0.0f};  // unit, world
    float distance = 0.0f;               // metres
};

/// A convex solid: the sides sidePlanes[firstSide, firstSide + sideCount).
struct CollisionBrush {
    uint32_t firstSide = 0;     // into LevelCollision::sidePlanes
    uint32_t sideCount = 0;     // >= 1
    uint32_t contents = 0;      // kContentsSolid and/or kContentsPlayerClip, nothing else
    uint32_t mover = kNoIndex;  // into LevelMovers::movers: its planes are in the mover's
                                // object space; kNoIndex: the world's, fixed
};

enum class TriggerKind : uint32_t {
    kPush = 1,       // a jump pad: launches the player to reach `target` at its apex
    kTeleport = 2,   // moves the player to `target`, facing `targetYaw`
    kHurt = 3,       // respawns the player
    kUseMover = 4,   // uses `mover` (a door's trigger, a button's touch): Quake 3's
                     // Touch_DoorTrigger, Touch_Button
    kRaisePlat = 5,  // uses plat `mover` when it rests at the bottom (Touch_PlatCenterTrigger)
};
inline constexpr uint32_t kTriggerKindLast = uint32_t(TriggerKind::kRaisePlat);

/// An axis-aligned volume that acts on a player whose box overlaps it.
struct Trigger {
    TriggerKind kind = TriggerKind::kHurt;
    glm::vec3 boundsMin{0.0f}, boundsMax{0.0f};  // metres, world, min <= max
    glm::vec3 target{0.0f};     // metres, world: push, the apex point (Quake's target_position);
                                // teleport, where the player's feet go; hurt, unused (0)
    float targetYaw = 0.0f;     // teleport: radians about +y, 0 looks down -z; otherwise 0
    uint32_t mover = kNoIndex;  // kUseMover, kRaisePlat: into LevelMovers::movers; else none
};

struct LevelCollision {
    std::vector<CollisionPlane> planes;
    std::vector<uint32_t> sidePlanes;  // into planes, ranges owned by brushes
    std::vector<CollisionBrush> brushes;
    std::vector<Trigger> triggers;

    [[nodiscard]] bool empty() const { return brushes.empty() && triggers.empty(); }
};

}  // namespace onelight::world
