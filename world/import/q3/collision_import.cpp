#include "world/import/q3/collision_import.hpp"

#include <charconv>
#include <cmath>
#include <map>
#include <set>

#include "world/error.hpp"
#include "world/import/q3/map_axes.hpp"

namespace onelight::world::q3 {
namespace {

// The contents that never block the player, whatever else a brush carries.
constexpr int32_t kPassable =
    kContentsTrigger | kContentsWater | kContentsLava | kContentsSlime | kContentsFog;

// The blocking brushes of brush model `model` (the world is model 0; a map without a model lump
// has only world brushes), moved by `offset` (metres) and owned by `mover`. `planeOf` maps the
// map's planes to the level's, for one space (the world's, or one mover's).
void addBrushes(LevelCollision& out, const BspFile& bsp, size_t model, uint32_t mover,
                glm::vec3 offset, std::map<int32_t, uint32_t>& planeOf,
                const std::vector<bool>& nonsolid, const std::string& where) {
    int32_t first = 0, count = int32_t(bsp.brushes.size());
    if (model < bsp.models.size())
        first = bsp.models[model].firstBrush, count = bsp.models[model].brushCount;
    for (int32_t b = first; b < first + count; ++b) {
        const BspBrush& brush = bsp.brushes[size_t(b)];
        const int32_t contents = bsp.shaders[size_t(brush.shader)].contentFlags;
        const uint32_t blocking = uint32_t(contents) & kPlayerSolidContents;
        if (blocking == 0 || (contents & kPassable) || nonsolid[size_t(brush.shader)]) continue;
        CollisionBrush kept{uint32_t(out.sidePlanes.size()), uint32_t(brush.sideCount), blocking,
                            mover};
        if (kept.sideCount == 0) continue;
        for (int32_t s = 0; s < brush.sideCount; ++s) {
            const int32_t p = bsp.brushSides[size_t(brush.firstSide + s)].plane;
            auto [found, added] = planeOf.try_emplace(p, uint32_t(out.planes.size()));
            if (added) {
                const BspBrushPlane& plane = bsp.planes[size_t(p)];
                const glm::vec3 n = levelDirection(plane.normal);
                const float length = glm::length(n);
                if (!(length > 0.5f && length < 2.0f))
                    throw Error(where + ": plane " + std::to_string(p) +
                                " has a normal of length " + std::to_string(length) +
                                "; expected a unit normal");
                const glm::vec3 unit = n / length;
                out.planes.push_back(
                    {unit, float(double(plane.dist) * kQuake3MetresPerUnit / double(length) +
                                 double(glm::dot(unit, offset)))});
            }
            out.sidePlanes.push_back(found->second);
        }
        out.brushes.push_back(kept);
    }
}

// Brush model N of a "*N" model key; throws when it is not one of the map's.
const BspModel& triggerModel(const BspFile& bsp, const MapEntity& e, const std::string& where) {
    const std::string model = e.get("model");
    int32_t n = -1;
    const char* end = model.data() + model.size();
    if (model.size() < 2 || model[0] != '*' ||
        std::from_chars(model.data() + 1, end, n).ptr != end || n < 1 ||
        size_t(n) >= bsp.models.size())
        throw Error(where + ": entities line " + std::to_string(e.line) + ": " +
                    e.get("classname") + " has model '" + model + "'; expected *1 .. *" +
                    std::to_string(bsp.models.size() > 0 ? bsp.models.size() - 1 : 0) +
                    " (a brush model of the map)");
    return bsp.models[size_t(n)];
}

void addTriggers(LevelCollision& out, const BspFile& bsp, const std::vector<MapEntity>& entities,
                 const std::string& where, std::vector<std::string>& notes) {
    std::map<std::string, const MapEntity*> named;  // the first of each targetname, as G_Find
    for (const MapEntity& e : entities)
        if (e.keys.count("targetname")) named.emplace(e.get("targetname"), &e);
    for (const MapEntity& e : entities) {
        const std::string type = e.get("classname");
        Trigger t;
        if (type == "trigger_push") {
            t.kind = TriggerKind::kPush;
        } else if (type == "trigger_teleport") {
            t.kind = TriggerKind::kTeleport;
        } else if (type == "trigger_hurt") {
            t.kind = TriggerKind::kHurt;
            if (int(numberKey(e, "spawnflags", 0.0f, where)) & 1) continue;  // starts off
        } else {
            continue;
        }
        const BspModel& model = triggerModel(bsp, e, where);
        const glm::vec3 a = levelPoint(model.mins), b = levelPoint(model.maxs);
        t.boundsMin = glm::min(a, b);
        t.boundsMax = glm::max(a, b);
        if (t.kind != TriggerKind::kHurt) {
            const auto target = named.find(e.get("target"));
            if (!e.keys.count("target") || target == named.end()) {
                notes.push_back(where + ": entities line " + std::to_string(e.line) + ": " + type +
                                " has no target (left out, as the game frees it)");
                continue;
            }
            const glm::vec3 origin = vectorKey(*target->second, "origin", glm::vec3(0.0f), where);
            if (t.kind == TriggerKind::kPush) {
                t.target = levelPoint(origin);
            } else {
                t.target = levelPoint(origin + glm::vec3(0.0f, 0.0f, 1.0f - 24.0f));
                const glm::vec3 angles =
                    vectorKey(*target->second, "angles", glm::vec3(0.0f), where);
                const float yaw = numberKey(*target->second, "angle", angles.y, where);
                t.targetYaw = glm::radians(yaw - 90.0f);  // Quake's heading, as addSpawns
            }
        }
        out.triggers.push_back(t);
    }
}

}  // namespace

LevelCollision importCollision(const BspFile& bsp, const std::vector<MapEntity>& entities,
                               const std::vector<bool>& nonsolidShaders,
                               const ImportedMovers& movers, const std::string& where,
                               std::vector<std::string>& notes) {
    LevelCollision out;
    std::map<int32_t, uint32_t> worldPlanes;
    addBrushes(out, bsp, 0, kNoIndex, glm::vec3(0.0f), worldPlanes, nonsolidShaders, where);
    // func_static: still, where its origin puts it.
    std::set<size_t> still;
    for (const MapEntity& e : entities)
        if (e.get("classname") == "func_static") {
            const std::string model = e.get("model");
            size_t n = 0;
            const char* end = model.data() + model.size();
            if (model.size() >= 2 && model[0] == '*' &&
                std::from_chars(model.data() + 1, end, n).ptr == end && n >= 1 &&
                n < bsp.models.size() && movers.moverOfModel[n] == kNoIndex &&
                still.insert(n).second)
                addBrushes(out, bsp, n, kNoIndex, movers.originOfModel[n], worldPlanes,
                           nonsolidShaders, where);
        }
    // A mover's brushes, in its object space (the model's own).
    for (size_t n = 1; n < movers.moverOfModel.size(); ++n)
        if (movers.moverOfModel[n] != kNoIndex) {
            std::map<int32_t, uint32_t> planes;
            addBrushes(out, bsp, n, movers.moverOfModel[n], glm::vec3(0.0f), planes,
                       nonsolidShaders, where);
        }
    addTriggers(out, bsp, entities, where, notes);
    out.triggers.insert(out.triggers.end(), movers.triggers.begin(), movers.triggers.end());
    return out;
}

}  // namespace onelight::world::q3
