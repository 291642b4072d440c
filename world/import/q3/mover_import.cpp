#include "world/import/q3/mover_import.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <map>

#include <glm/gtc/quaternion.hpp>

#include "world/import/q3/map_axes.hpp"

namespace onelight::world::q3 {
namespace {

constexpr double kPi = 3.14159265358979323846;

// A map-space offset (units) in metres and a map-space direction as a unit vector, Y up: the
// linear part of map_axes.hpp's conversion.
glm::vec3 levelVector(glm::dvec3 v) {
    return levelPoint(glm::vec3(v));
}
glm::vec3 levelAxis(glm::dvec3 v) {
    const float n[3] = {float(v.x), float(v.y), float(v.z)};
    return glm::normalize(levelDirection(n));
}

// The game's duration of a move: whole milliseconds, at least 1 (InitMover, Reached_Train).
float travelSeconds(double units, double unitsPerSecond) {
    const double ms = std::floor(units * 1000.0 / unitsPerSecond);
    return float(std::max(ms, 1.0) / 1000.0);
}

// A key's number, or `fallback` when it is absent or 0 (the game's "if 0, the default").
double keyOr(const MapEntity& e, const char* key, double fallback, const std::string& where) {
    const double v = double(numberKey(e, key, 0.0f, where));
    return v != 0.0 ? v : fallback;
}

// The forward vector of Quake's angles (pitch, yaw, roll), degrees (AngleVectors).
glm::dvec3 forwardOf(glm::dvec3 angles) {
    const double p = angles.x * kPi / 180.0, y = angles.y * kPi / 180.0;
    return {std::cos(p) * std::cos(y), std::cos(p) * std::sin(y), -std::sin(p)};
}

// The entity's angles: "angle" A is (0, A, 0), else "angles".
glm::dvec3 anglesOf(const MapEntity& e, const std::string& where) {
    if (e.keys.count("angle")) return {0.0, double(numberKey(e, "angle", 0.0f, where)), 0.0};
    return glm::dvec3(vectorKey(e, "angles", glm::vec3(0.0f), where));
}

// G_SetMovedir.
glm::dvec3 moveDirection(const MapEntity& e, const std::string& where) {
    const glm::dvec3 a = anglesOf(e, where);
    if (a == glm::dvec3(0.0, -1.0, 0.0)) return {0.0, 0.0, 1.0};
    if (a == glm::dvec3(0.0, -2.0, 0.0)) return {0.0, 0.0, -1.0};
    return forwardOf(a);
}

// Quake's angles as a rotation in the level: yaw about the map's z, pitch about its y, roll
// about its x (AnglesToAxis), each a rotation about the same axis in the level's space.
glm::quat levelRotation(glm::dvec3 angles) {
    const auto about = [](double degrees, glm::dvec3 axis) {
        return glm::angleAxis(float(degrees * kPi / 180.0), levelAxis(axis));
    };
    return about(angles.y, {0, 0, 1}) * about(angles.x, {0, 1, 0}) * about(angles.z, {1, 0, 0});
}

int32_t modelNumber(const MapEntity& e) {
    const std::string model = e.get("model");
    int32_t n = -1;
    const char* end = model.data() + model.size();
    if (model.size() < 2 || model[0] != '*' || std::from_chars(model.data() + 1, end, n).ptr != end)
        return -1;
    return n;
}

bool isMoverClass(const std::string& c) {
    return c == "func_door" || c == "func_plat" || c == "func_button" || c == "func_bobbing" ||
           c == "func_rotating" || c == "func_pendulum" || c == "func_train";
}

struct Ids {
    std::map<std::string, uint32_t> of;
    uint32_t operator()(const std::string& name) {
        if (name.empty()) return kNoIndex;
        return of.emplace(name, uint32_t(of.size())).first->second;
    }
};

// The world box (metres) of map-space corners lo..hi (units).
void levelBox(glm::dvec3 lo, glm::dvec3 hi, glm::vec3& boxMin, glm::vec3& boxMax) {
    const float a[3] = {float(lo.x), float(lo.y), float(lo.z)};
    const float b[3] = {float(hi.x), float(hi.y), float(hi.z)};
    boxMin = glm::min(levelPoint(a), levelPoint(b));
    boxMax = glm::max(levelPoint(a), levelPoint(b));
}

struct Spawned {
    const MapEntity* source = nullptr;
    int32_t model = -1;
    glm::dvec3 origin{0.0}, mins{0.0}, maxs{0.0};  // map units; bounds padded by 1
    glm::dvec3 pos1{0.0}, pos2{0.0};               // binary movers, map units
};

}  // namespace

ImportedMovers importMovers(const BspFile& bsp, const std::vector<MapEntity>& entities,
                            const std::string& where) {
    ImportedMovers out;
    out.moverOfModel.assign(bsp.models.size(), kNoIndex);
    out.originOfModel.assign(bsp.models.size(), glm::vec3(0.0f));
    std::map<std::string, const MapEntity*> named;  // the first of each targetname (G_Find)
    for (const MapEntity& e : entities)
        if (e.keys.count("targetname")) named.emplace(e.get("targetname"), &e);
    Ids ids;
    std::map<std::string, uint32_t> perClass, teamMaster;
    std::vector<Spawned> spawned;
    for (size_t k = 1; k < entities.size(); ++k) {
        const MapEntity& e = entities[k];
        const std::string type = e.get("classname");
        const int32_t model = modelNumber(e);
        if (model >= 1 && size_t(model) < bsp.models.size())
            out.originOfModel[size_t(model)] =
                levelPoint(vectorKey(e, "origin", glm::vec3(0.0f), where));
        if (!isMoverClass(type)) continue;
        const std::string line = where + ": entities line " + std::to_string(e.line) + ": ";
        if (model < 1 || size_t(model) >= bsp.models.size()) {
            out.notes.push_back(line + type + " has model '" + e.get("model") +
                                "', not a brush model of the map (left out)");
            continue;
        }
        if (out.moverOfModel[size_t(model)] != kNoIndex) {
            out.notes.push_back(line + type + " moves brush model *" + std::to_string(model) +
                                ", which another mover moves already (left out)");
            continue;
        }
        Spawned s;
        s.source = &e;
        s.model = model;
        s.origin = glm::dvec3(vectorKey(e, "origin", glm::vec3(0.0f), where));
        const BspModel& m = bsp.models[size_t(model)];
        s.mins = glm::dvec3(m.mins[0], m.mins[1], m.mins[2]) - 1.0;
        s.maxs = glm::dvec3(m.maxs[0], m.maxs[1], m.maxs[2]) + 1.0;
        const glm::dvec3 size = s.maxs - s.mins;

        Mover mover;
        mover.pos1 = mover.pos2 = levelPoint(glm::vec3(s.origin));
        const double speedKey = double(numberKey(e, "speed", 0.0f, where));
        const int flags = int(numberKey(e, "spawnflags", 0.0f, where));
        glm::quat rotation(1.0f, 0.0f, 0.0f, 0.0f);
        if (type == "func_door" || type == "func_button") {
            const bool door = type == "func_door";
            mover.kind = door ? MoverKind::kDoor : MoverKind::kButton;
            const double speed = speedKey != 0.0 ? speedKey : (door ? 400.0 : 40.0);
            mover.wait = float(keyOr(e, "wait", door ? 2.0 : 1.0, where));
            const double lip = double(numberKey(e, "lip", door ? 8.0f : 4.0f, where));
            const glm::dvec3 dir = moveDirection(e, where);
            const double distance = std::fabs(dir.x) * size.x + std::fabs(dir.y) * size.y +
                                    std::fabs(dir.z) * size.z - lip;
            s.pos1 = s.origin;
            s.pos2 = s.origin + dir * distance;
            if (door && (flags & 1)) std::swap(s.pos1, s.pos2);  // START_OPEN
            if (door && (flags & 4)) mover.flags |= kMoverCrusher;
            mover.travelSeconds = travelSeconds(glm::length(s.pos2 - s.pos1), speed);
        } else if (type == "func_plat") {
            mover.kind = MoverKind::kPlat;
            const double speed = speedKey != 0.0 ? speedKey : 200.0;
            const double lip = double(numberKey(e, "lip", 8.0f, where));
            const double height =
                e.keys.count("height") ? double(numberKey(e, "height", 0.0f, where)) : size.z - lip;
            s.pos2 = s.origin;
            s.pos1 = s.origin - glm::dvec3(0.0, 0.0, height);
            mover.wait = 1.0f;  // the game ignores the key
            mover.travelSeconds = travelSeconds(std::fabs(height), speed);
        } else if (type == "func_bobbing") {
            mover.kind = MoverKind::kBobbing;
            mover.period =
                float(std::max(std::floor(keyOr(e, "speed", 4.0, where) * 1000.0), 1.0) / 1000.0);
            const double height = keyOr(e, "height", 32.0, where);
            const glm::dvec3 axis = (flags & 1)   ? glm::dvec3(1, 0, 0)
                                    : (flags & 2) ? glm::dvec3(0, 1, 0)
                                                  : glm::dvec3(0, 0, 1);
            mover.amplitude = levelVector(axis * height);
            mover.phase = numberKey(e, "phase", 0.0f, where);
        } else if (type == "func_rotating") {
            mover.kind = MoverKind::kRotating;
            mover.speed = float(keyOr(e, "speed", 100.0, where) * kPi / 180.0);
            mover.axis = levelAxis((flags & 4)   ? glm::dvec3(1, 0, 0)
                                   : (flags & 8) ? glm::dvec3(0, 1, 0)
                                                 : glm::dvec3(0, 0, 1));
        } else if (type == "func_pendulum") {
            mover.kind = MoverKind::kPendulum;
            mover.speed = float(keyOr(e, "speed", 30.0, where) * kPi / 180.0);
            const double length = std::max(std::fabs(s.mins.z), 8.0);
            const double frequency = std::sqrt(800.0 / (3.0 * length)) / (2.0 * kPi);
            mover.period = float(std::max(std::floor(1000.0 / frequency), 1.0) / 1000.0);
            mover.phase = numberKey(e, "phase", 0.0f, where);
            const glm::dvec3 angles = glm::dvec3(vectorKey(e, "angles", glm::vec3(0.0f), where));
            mover.axis = levelAxis(forwardOf(angles));
            rotation = levelRotation(angles);
        } else {  // func_train: its path, closing on its first corner
            mover.kind = MoverKind::kTrain;
            const double trainSpeed = speedKey != 0.0 ? speedKey : 100.0;
            // Think_SetupTrainTargets: the first entity of its target's name, then from each
            // corner the first path_corner of the corner's target's name.
            std::vector<const MapEntity*> corners;
            std::string broken;
            const auto first = named.find(e.get("target"));
            if (!e.keys.count("target") || first == named.end()) broken = "has no target";
            for (const MapEntity* corner = broken.empty() ? first->second : nullptr; corner;) {
                corners.push_back(corner);
                const MapEntity* next = nullptr;
                if (corner->keys.count("target"))
                    for (const MapEntity& c : entities)
                        if (c.get("classname") == "path_corner" &&
                            c.get("targetname") == corner->get("target")) {
                            next = &c;
                            break;
                        }
                if (!next) {
                    broken = "has a corner whose target is no path_corner";
                } else if (next != first->second &&
                           std::find(corners.begin(), corners.end(), next) != corners.end()) {
                    broken = "has a path that loops back to a corner after its first";
                    next = nullptr;
                } else if (next == first->second) {
                    next = nullptr;  // closed
                }
                corner = next;
            }
            if (broken.empty() && corners.size() < 2) broken = "has a path of one corner";
            if (!broken.empty()) {
                out.notes.push_back(line + "func_train " + broken +
                                    "; the game never starts it (left standing where built)");
                continue;
            }
            mover.firstPoint = uint32_t(out.movers.path.size());
            mover.pointCount = uint32_t(corners.size());
            for (size_t c = 0; c < corners.size(); ++c) {
                const MapEntity& from = *corners[c];
                const MapEntity& to = *corners[(c + 1) % corners.size()];
                const glm::dvec3 a(vectorKey(from, "origin", glm::vec3(0.0f), where));
                const glm::dvec3 b(vectorKey(to, "origin", glm::vec3(0.0f), where));
                const double speed = std::max(keyOr(from, "speed", trainSpeed, where), 1.0);
                MoverPoint p;
                p.position = levelPoint(glm::vec3(a));
                p.wait = std::max(0.0f, numberKey(from, "wait", 0.0f, where));
                p.legSeconds = travelSeconds(glm::length(b - a), speed);
                out.movers.path.push_back(p);
            }
        }
        if (isBinaryMover(mover.kind)) {
            mover.pos1 = levelPoint(glm::vec3(s.pos1));
            mover.pos2 = levelPoint(glm::vec3(s.pos2));
        }
        mover.name = ids(e.get("targetname"));
        mover.target = isBinaryMover(mover.kind) ? ids(e.get("target")) : kNoIndex;
        const std::string team = e.get("team");
        if (!team.empty()) {
            const auto [found, first] =
                teamMaster.emplace(team, uint32_t(out.movers.movers.size()));
            if (!first) mover.teamMaster = found->second;
        }

        Entity entity;
        entity.name = type + "_" + std::to_string(++perClass[type]);
        entity.flags = kEntityDynamic | kEntityMover;
        entity.position = levelPoint(glm::vec3(s.origin));
        entity.rotation = rotation;
        mover.entity = uint32_t(out.entities.size());
        out.entities.push_back(entity);
        out.moverOfModel[size_t(model)] = uint32_t(out.movers.movers.size());
        out.movers.movers.push_back(mover);
        spawned.push_back(s);
    }
    // A team's members move with a master of the same kind of motion only (a door's team of
    // doors); another's is its own master.
    for (Mover& m : out.movers.movers)
        if (m.teamMaster != kNoIndex &&
            !(isBinaryMover(m.kind) && isBinaryMover(out.movers.movers[m.teamMaster].kind)))
            m.teamMaster = kNoIndex;

    // The triggers the spawn functions make.
    for (uint32_t i = 0; i < out.movers.movers.size(); ++i) {
        Mover& m = out.movers.movers[i];
        const Spawned& s = spawned[i];
        const MapEntity& e = *s.source;
        const bool hasName = e.keys.count("targetname") > 0;
        // A door or button with health takes damage: shot at rest, it is used (G_Damage), and
        // it makes no touch trigger.
        const bool shootable = (m.kind == MoverKind::kDoor || m.kind == MoverKind::kButton) &&
                               numberKey(e, "health", 0.0f, where) != 0.0f;
        if (shootable) m.flags |= kMoverShootable;
        Trigger t;
        t.mover = i;
        if (m.kind == MoverKind::kDoor && m.teamMaster == kNoIndex && !hasName && !shootable) {
            // Think_SpawnNewDoorTrigger: the team's boxes at rest (linked: padded once more),
            // grown 120 units both ways along the thinnest axis.
            glm::dvec3 lo(1e30), hi(-1e30);
            for (uint32_t j = 0; j < out.movers.movers.size(); ++j)
                if (j == i || out.movers.movers[j].teamMaster == i) {
                    lo = glm::min(lo, spawned[j].pos1 + spawned[j].mins - 1.0);
                    hi = glm::max(hi, spawned[j].pos1 + spawned[j].maxs + 1.0);
                }
            const glm::dvec3 extent = hi - lo;
            int best = 0;
            for (int a = 1; a < 3; ++a)
                if (extent[a] < extent[best]) best = a;
            lo[best] -= 120.0;
            hi[best] += 120.0;
            t.kind = TriggerKind::kUseMover;
            levelBox(lo, hi, t.boundsMin, t.boundsMax);
            out.triggers.push_back(t);
        } else if (m.kind == MoverKind::kPlat && !hasName) {
            // SpawnPlatTrigger: over its top at rest (lowered), inset 33 units, 8 above.
            glm::dvec3 lo = s.pos1 + s.mins + glm::dvec3(33.0, 33.0, 0.0);
            glm::dvec3 hi = s.pos1 + s.maxs + glm::dvec3(-33.0, -33.0, 8.0);
            for (int a = 0; a < 2; ++a)
                if (hi[a] <= lo[a]) {
                    lo[a] = s.pos1[a] + (s.mins[a] + s.maxs[a]) * 0.5;
                    hi[a] = lo[a] + 1.0;
                }
            t.kind = TriggerKind::kRaisePlat;
            levelBox(lo, hi, t.boundsMin, t.boundsMax);
            out.triggers.push_back(t);
        } else if (m.kind == MoverKind::kButton && !shootable) {
            // Touch_Button: walking into it, i.e. touching its linked box at rest.
            t.kind = TriggerKind::kUseMover;
            levelBox(s.pos1 + s.mins - 1.0, s.pos1 + s.maxs + 1.0, t.boundsMin, t.boundsMax);
            out.triggers.push_back(t);
        }
    }
    return out;
}

}  // namespace onelight::world::q3
