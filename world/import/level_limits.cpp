#include "world/import/level_limits.hpp"

#include <cmath>
#include <cstdio>

#include "world/error.hpp"

namespace onelight::world {

namespace {

bool inRange(glm::dvec3 p) {
    for (int c = 0; c < 3; ++c)
        if (!(std::fabs(p[c]) <= kMaxCoordinateMetres)) return false;  // NaN fails too
    return true;
}

[[noreturn]] void outOfRange(const SourceLevel& level, const std::string& what, glm::dvec3 p) {
    char text[160];
    std::snprintf(text, sizeof text, " at (%g, %g, %g) m; expected |x|, |y|, |z| <= %g m", p.x, p.y,
                  p.z, kMaxCoordinateMetres);
    throw Error(level.sourcePath + ": " + what + text);
}

void checkPoint(const SourceLevel& level, glm::dvec3 p, const std::string& what) {
    if (!inRange(p)) outOfRange(level, what, p);
}

}  // namespace

void checkLevelLimits(const SourceLevel& level) {
    uint64_t triangles = 0;
    for (const MeshInstance& instance : level.instances) {
        triangles += instance.indices.size() / 3;
        for (size_t v = 0; v < instance.vertices.size(); ++v) {
            const glm::dvec3 p = glm::dvec3(instance.worldFromLocal *
                                            glm::dvec4(instance.vertices[v].position, 1.0));
            if (!inRange(p))
                outOfRange(level,
                           "node '" + instance.nodeName + "' mesh '" + instance.meshName +
                               "' primitive " + std::to_string(instance.primitive) + " vertex " +
                               std::to_string(v) + " lies in the world",
                           p);
        }
    }
    if (triangles > kMaxLevelTriangles)
        throw Error(level.sourcePath + ": " + std::to_string(triangles) +
                    " triangles; expected at most " + std::to_string(kMaxLevelTriangles));
    if (level.lights.size() > kMaxLevelLights)
        throw Error(level.sourcePath + ": " + std::to_string(level.lights.size()) +
                    " lights; expected at most " + std::to_string(kMaxLevelLights));
    for (const Light& light : level.lights)
        checkPoint(level, light.position, "light '" + light.name + "'");
    for (const Camera& camera : level.cameras)
        checkPoint(level, camera.position, "camera '" + camera.name + "'");
    for (const Entity& entity : level.entities) {
        checkPoint(level, entity.position, "entity '" + entity.name + "'");
        checkPoint(level, entity.probeBoxMin, "entity '" + entity.name + "' probe box min");
        checkPoint(level, entity.probeBoxMax, "entity '" + entity.name + "' probe box max");
    }
    for (const Mover& mover : level.movers.movers)
        for (const MoverPose& pose : moverReach(level.movers, mover))
            checkPoint(level, pose.origin,
                       "entity '" +
                           (mover.entity < level.entities.size() ? level.entities[mover.entity].name
                                                                 : std::to_string(mover.entity)) +
                           "' mover's reach");
    if (level.hasGridBounds) {
        checkPoint(level, level.gridMin, "the light grid's min");
        checkPoint(level, level.gridMax, "the light grid's max");
    }
}

}  // namespace onelight::world
