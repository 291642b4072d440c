// Components and worlds shared by the ECS tests and onelight-bench-ecs.
#pragma once

#include "ecs/registry.hpp"

namespace onelight::ecs::fixtures {

struct Position {
    float x, y, z;
};
struct Velocity {
    float x, y, z;
};

// count entities, entity i with Position{i, 0, 0} and Velocity{1, 2, 3}.
inline Registry makeWorld(int count) {
    Registry r;
    for (int i = 0; i < count; ++i) {
        Entity e = r.create();
        r.emplace<Position>(e, float(i), 0.f, 0.f);
        r.emplace<Velocity>(e, 1.f, 2.f, 3.f);
    }
    return r;
}

// One 60 Hz step of p along v: the update every benchmark times.
inline void integrate(Position& p, const Velocity& v) {
    p.x += v.x / 60.f, p.y += v.y / 60.f, p.z += v.z / 60.f;
}

}  // namespace onelight::ecs::fixtures
