// A Quake 3 map's movers (func_door, func_plat, func_button, func_bobbing, func_rotating,
// func_pendulum, func_train with its path_corners) as the level's movers (world/movers.hpp):
// each one an entity (kEntityDynamic | kEntityMover, named CLASSNAME_N, N from 1 in the lump's
// order) whose brush model's surfaces become its dynamic meshes and whose brushes move with it,
// with the numbers of the game's spawn functions (g_mover.c) and the triggers they spawn.
#pragma once

#include <string>
#include <vector>

#include "world/collision.hpp"
#include "world/compiled_level.hpp"
#include "world/import/q3/bsp_file.hpp"
#include "world/import/q3/entity_lump.hpp"
#include "world/movers.hpp"

namespace onelight::world::q3 {

/*
   From the game's spawn functions (g_mover.c), in map units and seconds before conversion. A
   brush model's bounds are the BSP's padded by 1 unit a side (the game's collision loader), and
   its geometry is relative to the entity's origin (q3map2 moves an origin brush's model there).
   Directions: "angle" -1 is up, -2 down, else (with "angles") the forward vector (G_SetMovedir).
   Door: speed 400, wait 2 s, lip 8; pos2 = pos1 + movedir (|movedir| . size - lip); START_OPEN
   (1) swaps the ends, CRUSHER (4) never turns round. Without a targetname or health it spawns a
   trigger: its team's box grown 120 units both ways along its thinnest axis.
   Plat: speed 200, lip 8, wait always 1 s; height = "height" or the model's height - lip; it
   rests lowered by height (pos1) and rises to where it was built; without a targetname, a
   trigger over its top (inset 33 units, up to 8 above).
   Button: speed 40, wait 1 s, lip 4, moved like a door; touched (no health), it uses its target.
   A door or button with "health" (not 0) takes damage instead of a trigger: kMoverShootable, a
   shot used at rest (G_Damage; game/sim/movers.hpp shootMovers).
   Binary travel: the distance over the speed in whole milliseconds (at least 1), as the game.
   Bobbing: period "speed" 4 s, "height" 32 along z (X_AXIS 1: x, Y_AXIS 2: y), "phase" 0.
   Rotating: "speed" 100 degrees a second about z (X_AXIS 4: x, Y_AXIS 8: y).
   Pendulum: "speed" 30 degrees each way about the forward axis of its "angles", period
   1 / (sqrt(800 / (3 L)) / 2 pi) in whole milliseconds, L = the model's depth below its origin
   (at least 8).
   Train: its origin goes from path_corner to path_corner (from its "target", each corner's
   "target" the next), the path closing on its first corner; a leg at the corner's "speed", else
   the train's (100, at least 1), in whole milliseconds; a corner's "wait" held first.
   Teams ("team"): the first mover of a team in the lump is its master; the others move with it.
   Names: "targetname" and "target" become ids shared by the level's movers.
   Left out, with a note: a mover whose model is not a brush model of the map, a train whose path
   breaks or does not close on its first corner (its surfaces stand still where built); damage.
*/

struct ImportedMovers {
    std::vector<Entity> entities;          // to append to the level's, in this order
    LevelMovers movers;                    // Mover::entity into `entities`
    std::vector<Trigger> triggers;         // the doors', plats' and buttons'; mover into `movers`
    std::vector<uint32_t> moverOfModel;    // per BSP model: the mover it is, or kNoIndex
    std::vector<glm::vec3> originOfModel;  // per BSP model: its entity's origin, metres (world:
                                           // 0); a model's geometry is relative to it
    std::vector<std::string> notes;
};

/// Throws world::Error naming `where` and the entity's line for a key that is not a number.
[[nodiscard]] ImportedMovers importMovers(const BspFile& bsp,
                                          const std::vector<MapEntity>& entities,
                                          const std::string& where);

}  // namespace onelight::world::q3
