#include "items.hpp"

#include <cmath>
#include <numbers>

namespace onelight::game {

bool dropItem(const BrushWorld* brushes, glm::vec3 origin, bool suspended, glm::vec3& rest) {
    rest = origin;
    if (!brushes || !brushes->collision) return true;
    const glm::vec3 half(kItemRadius);
    const float epsilon = 0.125f / 32.0f;  // Quake 3's SURFACE_CLIP_EPSILON
    if (suspended) return !traceBox(*brushes, origin, origin, -half, half, epsilon).startSolid;
    // Quake 3 drops 4096 units.
    const BoxTrace trace =
        traceBox(*brushes, origin, origin - glm::vec3(0.0f, 128.0f, 0.0f), -half, half, epsilon);
    if (trace.startSolid) return false;
    rest = trace.end;
    return true;
}

float itemYaw(double seconds) {
    const int64_t ms = int64_t(std::floor(seconds * 1000.0));
    return float(double(ms & 2047) / 2048.0 * 2.0 * std::numbers::pi);
}

float itemBob(double seconds, uint32_t number) {
    const double scale = 0.005 + double(number) * 0.00001;
    const double units = 4.0 + std::cos((seconds * 1000.0 + 1000.0) * scale) * 4.0;
    return float(units / 32.0);
}

bool playerTouchesItem(glm::vec3 feet, glm::vec3 rest) {
    // The player's origin is 24 units above its feet; Quake 3's x is ours, its y our -z, its z
    // our y: x - x' in [-50, 44] units, the other two within 36.
    const glm::vec3 d = (feet + glm::vec3(0.0f, 24.0f / 32.0f, 0.0f) - rest) * 32.0f;
    return d.x >= -50.0f && d.x <= 44.0f && std::abs(d.y) <= 36.0f && std::abs(d.z) <= 36.0f;
}

void itemSystem(ecs::Registry& registry, const ecs::Tick& tick, ecs::Entity player) {
    const Transform* body = registry.tryGet<Transform>(player);
    const double t = tick.time();
    for (auto [e, transform, item] : registry.view<Transform, Item>().each()) {
        if (!item.present && item.respawnSeconds >= 0.0f && tick.index >= item.backAtTick)
            item.present = true;
        transform.yaw = itemYaw(t);
        transform.position = item.rest + glm::vec3(0.0f, itemBob(t, item.number), 0.0f);
        if (!item.present || !body || !playerTouchesItem(body->position, item.rest)) continue;
        item.present = false;
        ++item.timesTaken;
        item.backAtTick =
            tick.index + uint64_t(std::llround(double(item.respawnSeconds) / tick.seconds));
    }
}

}  // namespace onelight::game
