// Test environments for the probe tests: cubes filled from a function of direction.
#pragma once

#include <cmath>

#include "probes/cubemap.hpp"

namespace onelight::bake::test {

inline Cubemap filled(int size, glm::vec3 (*radiance)(glm::vec3)) {
    Cubemap c = makeCubemap(size);
    for (int f = 0; f < 6; ++f)
        for (int y = 0; y < size; ++y)
            for (int x = 0; x < size; ++x)
                c.mips[0].at(f, x, y) = radiance(texelDirection(f, x, y, size));
    return c;
}

// A black sky with a small bright source (about 3 degrees across) around +z, tilted a little
// so that it straddles texels.
inline glm::vec3 brightSource(glm::vec3 d) {
    glm::vec3 centre = glm::normalize(glm::vec3(0.05f, 0.02f, 1.0f));
    return glm::dot(d, centre) > std::cos(0.026f) ? glm::vec3(1000.0f) : glm::vec3(0.0f);
}

// A smooth sky with a bright band, so that seams would show.
inline glm::vec3 smoothSky(glm::vec3 d) {
    float band = std::exp(-20.0f * (d.y - 0.3f) * (d.y - 0.3f));
    return glm::vec3(1.0f + d.x, 2.0f + d.y + 5.0f * band, 1.5f + 0.5f * d.z);
}

inline float maxComponent(glm::vec3 v) {
    return std::max(v.x, std::max(v.y, v.z));
}

}  // namespace onelight::bake::test
