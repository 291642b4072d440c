// The one conversion from a Quake 3 map's space (units, Z up) to the level's (metres, Y up):
// a map point (x, y, z) is (x, z, -y) / 32 in the level (q3_import.hpp, "Units" and "Axes").
#pragma once

#include <glm/glm.hpp>

#include "world/import/q3/q3_import.hpp"

namespace onelight::world::q3 {

inline glm::vec3 levelPoint(const float p[3]) {
    const double s = kQuake3MetresPerUnit;
    return glm::vec3(float(double(p[0]) * s), float(double(p[2]) * s), float(-double(p[1]) * s));
}
inline glm::vec3 levelPoint(glm::vec3 p) {
    const float q[3] = {p.x, p.y, p.z};
    return levelPoint(q);
}
inline glm::vec3 levelDirection(const float n[3]) {
    return glm::vec3(n[0], n[2], -n[1]);
}

}  // namespace onelight::world::q3
