#include "world/import/q3/item_import.hpp"

#include <algorithm>
#include <map>
#include <set>

#include <glm/gtc/matrix_transform.hpp>

#include "world/error.hpp"
#include "world/import/q3/map_axes.hpp"
#include "world/import/q3/md3_file.hpp"

namespace onelight::world::q3 {
namespace {

// Quake 3's respawn defaults (g_items.c) in a free-for-all game.
constexpr float kArmour = 25.0f, kHealth = 35.0f, kAmmo = 40.0f, kHoldable = 60.0f,
                kPowerup = 120.0f, kWeapon = 5.0f;
// Nexuiz's (balance.cfg g_pickup_respawntime_*): short, medium and long items, powerups,
// weapons, ammo; a class's size as its name reads (1: short, 25/medium: medium, 50/100: long).
constexpr float kNexShort = 15.0f, kNexMedium = 20.0f, kNexLong = 30.0f, kNexPowerup = 120.0f,
                kNexWeapon = 15.0f, kNexAmmo = 15.0f;

// The game's item list (Quake 3's and the mission pack's, which OpenArena ships, and Nexuiz's),
// by class.
constexpr ItemClass kItems[] = {
    {"item_armor_shard",
     {"models/powerups/armor/shard.md3", ""},
     kArmour,
     false,
     "models/items/g_a1.md3",
     kNexShort},
    {"item_armor_combat",
     {"models/powerups/armor/armor_yel.md3", ""},
     kArmour,
     false,
     "models/items/g_armormedium.md3",
     kNexMedium},
    {"item_armor_body",
     {"models/powerups/armor/armor_red.md3", ""},
     kArmour,
     false,
     "models/items/g_a25.md3",
     kNexMedium},
    {"item_health_small",
     {"models/powerups/health/small_cross.md3", "models/powerups/health/small_sphere.md3"},
     kHealth,
     false,
     "models/items/g_h1.md3",
     kNexShort},
    {"item_health",
     {"models/powerups/health/medium_cross.md3", "models/powerups/health/medium_sphere.md3"},
     kHealth,
     false,
     "models/items/g_h25.md3",
     kNexMedium},
    {"item_health_large",
     {"models/powerups/health/large_cross.md3", "models/powerups/health/large_sphere.md3"},
     kHealth,
     false,
     "models/items/g_h50.md3",
     kNexLong},
    {"item_health_mega",
     {"models/powerups/health/mega_cross.md3", "models/powerups/health/mega_sphere.md3"},
     kHealth,
     false,
     "models/items/g_h100.md3",
     kNexLong},
    {"weapon_gauntlet", {"models/weapons2/gauntlet/gauntlet.md3", ""}, kWeapon, true},
    {"weapon_shotgun",
     {"models/weapons2/shotgun/shotgun.md3", ""},
     kWeapon,
     true,
     "models/weapons/g_shotgun.md3",
     kNexWeapon},
    {"weapon_machinegun",
     {"models/weapons2/machinegun/machinegun.md3", ""},
     kWeapon,
     true,
     "models/weapons/g_uzi.md3",
     kNexWeapon},
    {"weapon_grenadelauncher",
     {"models/weapons2/grenadel/grenadel.md3", ""},
     kWeapon,
     true,
     "models/weapons/g_gl.md3",
     kNexWeapon},
    {"weapon_rocketlauncher",
     {"models/weapons2/rocketl/rocketl.md3", ""},
     kWeapon,
     true,
     "models/weapons/g_rl.md3",
     kNexWeapon},
    {"weapon_lightning",
     {"models/weapons2/lightning/lightning.md3", ""},
     kWeapon,
     true,
     "models/weapons/g_electro.md3",
     kNexWeapon},
    {"weapon_railgun",
     {"models/weapons2/railgun/railgun.md3", ""},
     kWeapon,
     true,
     "models/weapons/g_nex.md3",
     kNexWeapon},
    {"weapon_plasmagun",
     {"models/weapons2/plasma/plasma.md3", ""},
     kWeapon,
     true,
     "models/weapons/g_hagar.md3",
     kNexWeapon},
    {"weapon_bfg", {"models/weapons2/bfg/bfg.md3", ""}, kWeapon, true},
    {"weapon_grapplinghook", {"models/weapons2/grapple/grapple.md3", ""}, kWeapon, true},
    {"weapon_nailgun", {"models/weapons/nailgun/nailgun.md3", ""}, kWeapon, true},
    {"weapon_prox_launcher", {"models/weapons/proxmine/proxmine.md3", ""}, kWeapon, true},
    {"weapon_chaingun", {"models/weapons/vulcan/vulcan.md3", ""}, kWeapon, true},
    {"ammo_shells",
     {"models/powerups/ammo/shotgunam.md3", ""},
     kAmmo,
     false,
     "models/items/a_shells.md3",
     kNexAmmo},
    {"ammo_bullets",
     {"models/powerups/ammo/machinegunam.md3", ""},
     kAmmo,
     false,
     "models/items/a_bullets.md3",
     kNexAmmo},
    {"ammo_grenades",
     {"models/powerups/ammo/grenadeam.md3", ""},
     kAmmo,
     false,
     "models/items/a_rockets.md3",
     kNexAmmo},
    {"ammo_cells",
     {"models/powerups/ammo/plasmaam.md3", ""},
     kAmmo,
     false,
     "models/items/a_cells.md3",
     kNexAmmo},
    {"ammo_lightning",
     {"models/powerups/ammo/lightningam.md3", ""},
     kAmmo,
     false,
     "models/items/a_cells.md3",
     kNexAmmo},
    {"ammo_rockets",
     {"models/powerups/ammo/rocketam.md3", ""},
     kAmmo,
     false,
     "models/items/a_rockets.md3",
     kNexAmmo},
    {"ammo_slugs",
     {"models/powerups/ammo/railgunam.md3", ""},
     kAmmo,
     false,
     "models/items/a_cells.md3",
     kNexAmmo},
    {"ammo_bfg", {"models/powerups/ammo/bfgam.md3", ""}, kAmmo},
    {"ammo_nails", {"models/powerups/ammo/nailgunam.md3", ""}, kAmmo},
    {"ammo_mines", {"models/powerups/ammo/proxmineam.md3", ""}, kAmmo},
    {"ammo_belt", {"models/powerups/ammo/chaingunam.md3", ""}, kAmmo},
    {"holdable_teleporter", {"models/powerups/holdable/teleporter.md3", ""}, kHoldable},
    {"holdable_medkit", {"models/powerups/holdable/medkit.md3", ""}, kHoldable},
    {"holdable_kamikaze", {"models/powerups/kamikazi.md3", ""}, kHoldable},
    {"holdable_invulnerability", {"models/powerups/holdable/invulnerability.md3", ""}, kHoldable},
    {"item_quad",
     {"models/powerups/instant/quad.md3", "models/powerups/instant/quad_ring.md3"},
     kPowerup,
     false,
     "models/items/g_strength.md3",
     kNexPowerup},
    {"item_enviro",
     {"models/powerups/instant/enviro.md3", "models/powerups/instant/enviro_ring.md3"},
     kPowerup},
    {"item_haste",
     {"models/powerups/instant/haste.md3", "models/powerups/instant/haste_ring.md3"},
     kPowerup},
    {"item_invis",
     {"models/powerups/instant/invis.md3", "models/powerups/instant/invis_ring.md3"},
     kPowerup},
    {"item_regen",
     {"models/powerups/instant/regen.md3", "models/powerups/instant/regen_ring.md3"},
     kPowerup},
    {"item_flight",
     {"models/powerups/instant/flight.md3", "models/powerups/instant/flight_ring.md3"},
     kPowerup},
    {"item_scout", {"models/powerups/scout.md3", ""}, kPowerup},
    {"item_guard", {"models/powerups/guard.md3", ""}, kPowerup},
    {"item_doubler", {"models/powerups/doubler.md3", ""}, kPowerup},
    {"item_ammoregen", {"models/powerups/ammo.md3", ""}, kPowerup},
    // Nexuiz's own classes (its models under models/items and models/weapons/g_*). The Quake 3
    // classes above that a Nexuiz map places take the Nexuiz model named with them.
    // Its armour and health by size (small, medium, big or large, mega), and the older names it
    // keeps for them (armor1, armor25, health1, health25, health100).
    {"item_armor_small", {}, 0.0f, false, "models/items/g_a1.md3", kNexShort},
    {"item_armor_medium", {}, 0.0f, false, "models/items/g_armormedium.md3", kNexMedium},
    {"item_armor_big", {}, 0.0f, false, "models/items/g_a50.md3", kNexLong},
    {"item_armor_large", {}, 0.0f, false, "models/items/g_a25.md3", kNexLong},
    {"item_health_medium", {}, 0.0f, false, "models/items/g_h25.md3", kNexMedium},
    {"item_armor1", {}, 0.0f, false, "models/items/g_a1.md3", kNexShort},
    {"item_armor25", {}, 0.0f, false, "models/items/g_a25.md3", kNexLong},
    {"item_health1", {}, 0.0f, false, "models/items/g_h1.md3", kNexShort},
    {"item_health25", {}, 0.0f, false, "models/items/g_h25.md3", kNexMedium},
    {"item_health100", {}, 0.0f, false, "models/items/g_h100.md3", kNexLong},
    {"item_bullets", {}, 0.0f, false, "models/items/a_bullets.md3", kNexAmmo},
    {"item_cells", {}, 0.0f, false, "models/items/a_cells.md3", kNexAmmo},
    {"item_rockets", {}, 0.0f, false, "models/items/a_rockets.md3", kNexAmmo},
    {"item_shells", {}, 0.0f, false, "models/items/a_shells.md3", kNexAmmo},
    {"item_fuel", {}, 0.0f, false, "models/items/g_fuel.md3", kNexAmmo},
    {"item_fuel_regen", {}, 0.0f, false, "models/items/g_fuelregen.md3", kNexPowerup},
    {"item_jetpack", {}, 0.0f, false, "models/items/g_jetpack.md3", kNexPowerup},
    {"item_strength", {}, 0.0f, false, "models/items/g_strength.md3", kNexPowerup},
    {"item_invincible", {}, 0.0f, false, "models/items/g_invincible.md3", kNexPowerup},
    {"weapon_laser", {}, 0.0f, false, "models/weapons/g_laser.md3", kNexWeapon},
    {"weapon_uzi", {}, 0.0f, false, "models/weapons/g_uzi.md3", kNexWeapon},
    {"weapon_electro", {}, 0.0f, false, "models/weapons/g_electro.md3", kNexWeapon},
    {"weapon_crylink", {}, 0.0f, false, "models/weapons/g_crylink.md3", kNexWeapon},
    {"weapon_nex", {}, 0.0f, false, "models/weapons/g_nex.md3", kNexWeapon},
    {"weapon_minstanex", {}, 0.0f, false, "models/weapons/g_minstanex.md3", kNexWeapon},
    {"weapon_hagar", {}, 0.0f, false, "models/weapons/g_hagar.md3", kNexWeapon},
    {"weapon_porto", {}, 0.0f, false, "models/weapons/g_porto.md3", kNexWeapon},
    {"weapon_hook", {}, 0.0f, false, "models/weapons/g_hookgun.md3", kNexWeapon},
    {"weapon_hlac", {}, 0.0f, false, "models/weapons/g_hlac.md3", kNexWeapon},
    {"weapon_campingrifle", {}, 0.0f, false, "models/weapons/g_campingrifle.md3", kNexWeapon},
    {"weapon_fireball", {}, 0.0f, false, "models/weapons/g_fireball.md3", kNexWeapon},
    {"weapon_tuba", {}, 0.0f, false, "models/weapons/g_tuba.md3", kNexWeapon},
};

// Whether an entity class is a pickup the list may hold (the game's prefixes).
bool looksLikeItem(const std::string& classname) {
    for (const char* prefix : {"item_", "weapon_", "ammo_", "holdable_"})
        if (classname.rfind(prefix, 0) == 0) return true;
    return false;
}

// A model's frame 0 surfaces as meshes in the level's space (metres, Y up), about the item's
// origin: a Quake 3 weapon 1.5x about its bounds' midpoint (cgame's CG_Item).
std::vector<MeshInstance> itemMeshes(
    const Md3Model& model, bool quake3Weapon,
    const std::function<uint32_t(const std::string&)>& materialOf) {
    const Md3FrameInfo& frame = model.frames.front();
    const glm::vec3 pivot =
        quake3Weapon ? 0.5f * (frame.boundsMin + frame.boundsMax) : glm::vec3(0);
    const float scale = quake3Weapon ? 1.5f : 1.0f;
    std::vector<MeshInstance> meshes;
    for (const Md3Surface& surface : model.surfaces) {
        if (surface.vertexCount == 0 || surface.indices.empty()) continue;
        MeshInstance mesh;
        mesh.nodeName = mesh.meshName = model.name + ":" + surface.name;
        mesh.material = materialOf(surface.shaders.empty() ? surface.name : surface.shaders[0]);
        if (mesh.material == kNoIndex) continue;  // a surface the engine does not draw
        mesh.dynamic = true;
        for (uint32_t v = 0; v < surface.vertexCount; ++v) {
            Vertex out;
            out.position = levelPoint((surface.positions[v] - pivot) * scale);
            const glm::vec3 n = surface.normals[v];
            const float nn[3] = {n.x, n.y, n.z};
            out.normal = levelDirection(nn);
            out.uv0 = surface.texCoords[v];
            mesh.vertices.push_back(out);
        }
        // Wound counter-clockwise about the vertex normals, as the level's surfaces are: the
        // majority of the triangles decides, so the surface keeps one sense.
        int agree = 0;
        for (size_t t = 0; t + 2 < surface.indices.size(); t += 3) {
            const Vertex& a = mesh.vertices[surface.indices[t]];
            const Vertex& b = mesh.vertices[surface.indices[t + 1]];
            const Vertex& c = mesh.vertices[surface.indices[t + 2]];
            const glm::vec3 face = glm::cross(b.position - a.position, c.position - a.position);
            agree += glm::dot(face, a.normal + b.normal + c.normal) >= 0.0f ? 1 : -1;
        }
        mesh.indices = surface.indices;
        if (agree < 0)
            for (size_t t = 0; t + 2 < mesh.indices.size(); t += 3)
                std::swap(mesh.indices[t + 1], mesh.indices[t + 2]);
        meshes.push_back(std::move(mesh));
    }
    return meshes;
}

}  // namespace

const ItemClass* itemClassOf(std::string_view classname) {
    for (const ItemClass& item : kItems)
        if (item.classname == classname) return &item;
    return nullptr;
}

void addItems(SourceLevel& level, const std::vector<MapEntity>& entities, const GameFiles& files,
              const std::function<uint32_t(const std::string&)>& materialOf,
              const std::string& where) {
    std::map<std::string, std::vector<MeshInstance>> models;  // by model path, in model space
    std::map<std::string, uint32_t> perClass;
    std::set<std::string> unknown, missing;
    uint32_t notFree = 0;
    for (const MapEntity& e : entities) {
        const std::string classname = e.get("classname");
        if (!looksLikeItem(classname)) continue;
        const ItemClass* item = itemClassOf(classname);
        if (!item) {
            unknown.insert(classname);
            continue;
        }
        if (numberKey(e, "notfree", 0.0f, where) != 0.0f) {
            ++notFree;
            continue;
        }
        // Quake 3's models where the archives hold them, else Nexuiz's.
        const bool quake3 = !item->models[0].empty() && files.has(std::string(item->models[0]));
        std::vector<std::string_view> paths;
        if (quake3 || item->nexuizModel.empty()) {
            for (std::string_view path : item->models)
                if (!path.empty()) paths.push_back(path);
        } else {
            paths.push_back(item->nexuizModel);
        }
        std::vector<MeshInstance> meshes;
        for (std::string_view path : paths) {
            const std::string name(path);
            auto found = models.find(name);
            if (found == models.end()) {
                std::vector<MeshInstance> loaded;
                const std::optional<std::vector<uint8_t>> bytes =
                    files.read(name, kMaxModelBytes, "a model");
                if (bytes) {
                    const Md3Model model = parseMd3(*bytes, files.where(name));
                    loaded = itemMeshes(model, quake3 && item->weapon, materialOf);
                } else {
                    missing.insert(name);
                }
                found = models.emplace(name, std::move(loaded)).first;
            }
            meshes.insert(meshes.end(), found->second.begin(), found->second.end());
        }
        if (meshes.empty()) continue;
        Entity entity;
        entity.name = classname + "_" + std::to_string(++perClass[classname]);
        entity.flags = kEntityDynamic | kEntityItem;
        if (int(numberKey(e, "spawnflags", 0.0f, where)) & 1) entity.flags |= kEntitySuspended;
        entity.position = levelPoint(vectorKey(e, "origin", glm::vec3(0.0f), where));
        // "wait": seconds before it comes back (-1: never), else the class's default.
        entity.itemRespawn = numberKey(e, "wait", 0.0f, where);
        if (entity.itemRespawn == 0.0f)
            entity.itemRespawn = quake3 ? item->respawnSeconds : item->nexuizRespawnSeconds;
        if (entity.itemRespawn < 0.0f) entity.itemRespawn = -1.0f;
        level.entities.push_back(entity);
        for (MeshInstance& mesh : meshes) {
            mesh.entity = uint32_t(level.entities.size() - 1);
            mesh.nodeName = entity.name;
            mesh.worldFromLocal = glm::translate(glm::dmat4(1.0), glm::dvec3(entity.position));
            level.instances.push_back(std::move(mesh));
        }
    }
    if (!unknown.empty()) {
        std::string list;
        for (const std::string& c : unknown) list += (list.empty() ? "" : ", ") + c;
        level.importNotes.push_back(where +
                                    ": items of classes the game does not list left out: " + list);
    }
    if (!missing.empty()) {
        std::string list;
        for (const std::string& m : missing) list += (list.empty() ? "" : ", ") + m;
        level.importNotes.push_back(
            where + ": item models no archive holds, their items left out: " + list);
    }
    if (notFree > 0)
        level.importNotes.push_back(where + ": " + std::to_string(notFree) +
                                    " items marked notfree (not in a free-for-all game) left out");
}

}  // namespace onelight::world::q3
