// A Quake 3 map's collision, as the game module sees it: the world model's brushes that block
// the player (contents solid or player clip; never triggers, water, lava, slime, fog or
// surfaceparm nonsolid) and the trigger entities the game runs (trigger_push, trigger_teleport,
// trigger_hurt), converted to metres and Y up (map_axes.hpp).
#pragma once

#include <string>
#include <vector>

#include "world/collision.hpp"
#include "world/import/q3/bsp_file.hpp"
#include "world/import/q3/entity_lump.hpp"
#include "world/import/q3/mover_import.hpp"

namespace onelight::world::q3 {

/*
   Triggers: a trigger's "model" *N names brush model N, whose bounds are the trigger's box.
   trigger_push aims at the entity its "target" names (a target_position): the game launches the
   player so that its apex reaches that point (Quake 3's AimAtTarget, g_trigger.c).
   trigger_teleport sends the player to its target (a misc_teleporter_dest): the feet go to the
   destination's origin + 1 - 24 units (TeleportPlayer puts the player's origin 1 unit above it;
   the feet are 24 below the origin), facing its "angle" (or the yaw of "angles").
   trigger_hurt respawns the player (the damage is not modelled); one that starts off
   (spawnflags 1) is left out. A push or teleport without a target is left out and noted, as the
   game frees it.
*/

/// `nonsolidShaders[s]`: shader s's script says surfaceparm nonsolid. Besides the world's
/// brushes: a func_static's, where its origin puts them; each of `movers`' brush models', owned
/// by its mover (in its object space); and `movers`' triggers after the map's. Appends a note per
/// trigger left out to `notes`. Throws world::Error naming `where` and the entity's line for a
/// trigger whose model is not a brush model of the map.
[[nodiscard]] LevelCollision importCollision(const BspFile& bsp,
                                             const std::vector<MapEntity>& entities,
                                             const std::vector<bool>& nonsolidShaders,
                                             const ImportedMovers& movers, const std::string& where,
                                             std::vector<std::string>& notes);

}  // namespace onelight::world::q3
