// A Quake 3 map's pickups (weapons, ammo, armour, health, holdables, powerups) as dynamic
// entities: each item's world models (MD3, frame 0, from the game's pk3s) become its dynamic
// meshes, placed at its origin the way the game draws it, and the entity carries what the game
// needs to run it (world::kEntityItem, kEntitySuspended, itemRespawn). The game spins, bobs,
// drops, takes and brings them back (game/sim/items.hpp).
#pragma once

#include <array>
#include <functional>
#include <string>
#include <string_view>
#include <vector>

#include "world/import/q3/entity_lump.hpp"
#include "world/import/q3/pk3_archive.hpp"
#include "world/source_level.hpp"

namespace onelight::world::q3 {

/// An item class of Quake 3 and OpenArena (the game's item list) or Nexuiz: its world models
/// and how long it stays taken, per game. A map takes the Quake 3 models when its archives hold
/// them, else the Nexuiz one.
struct ItemClass {
    std::string_view classname;
    std::array<std::string_view, 2> models;  // Quake 3's (one or two: health's cross and
                                             // sphere, a powerup's body and ring), or none
    float respawnSeconds = 0.0f;             // Quake 3's defaults (g_items.c, FFA)
    bool weapon = false;  // Quake 3 draws it 1.5x, turning about its midpoint (CG_Item)
    std::string_view nexuizModel = {};  // Nexuiz's world model, or none
    float nexuizRespawnSeconds = 0.0f;  // Nexuiz's balance.cfg g_pickup_respawntime_*
};

/// The class named `classname` (case as the entity lump writes it), or nullptr.
[[nodiscard]] const ItemClass* itemClassOf(std::string_view classname);

/// Adds every item of `entities` that a free-for-all game spawns (not "notfree") to `level`:
/// an entity named CLASSNAME_N (N from 1 in the lump's order, per class) with its models'
/// meshes, whose surfaces take `materialOf(shader or image name)` (kNoIndex: the surface is
/// left out, e.g. an effect shell the engine does not model). A model no archive holds,
/// or a class the game does not know, is left out with a note in level.importNotes (one per
/// kind); a model that does not parse throws world::Error naming it.
void addItems(SourceLevel& level, const std::vector<MapEntity>& entities, const GameFiles& files,
              const std::function<uint32_t(const std::string&)>& materialOf,
              const std::string& where);

}  // namespace onelight::world::q3
