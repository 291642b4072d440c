#include "systems.hpp"

#include <algorithm>
#include <cmath>
#include <vector>

#include "quake_move.hpp"

namespace onelight::game {

glm::vec3 viewDirection(float yaw, float pitch) {
    float c = std::cos(pitch);
    return {-std::sin(yaw) * c, std::sin(pitch), -std::cos(yaw) * c};
}

glm::vec3 eyeOf(const Transform& transform, const Tuning& tuning) {
    return transform.position + glm::vec3(0.0f, tuning.eyeHeight, 0.0f);
}

glm::vec3 moveAndSlide(const world::BspView* bsp, glm::vec3 center, glm::vec3 delta, float radius,
                       float skin, float floorCos, bool& floor) {
    floor = false;
    if (!bsp) return center + delta;
    for (int contact = 0; contact < 4; ++contact) {
        float length = glm::length(delta);
        if (length < 1e-6f) break;
        world::SweepHit hit =
            world::sweepSphere(*bsp, glm::dvec3(center), glm::dvec3(center + delta), radius);
        if (!hit.hit) return center + delta;
        glm::vec3 n = glm::vec3(hit.normal);
        if (n.y > floorCos) floor = true;
        if (glm::dot(delta, n) >= 0.0f) {
            // Touching a surface it moves along or away from: step off by the skin and retry.
            center += n * skin;
            continue;
        }
        // Stop `skin` short of the contact, then keep only the motion along the surface.
        float travel = std::max(0.0f, float(hit.fraction) * length - skin);
        center += delta * (travel / length);
        glm::vec3 rest = delta * (1.0f - travel / length);
        delta = rest - n * glm::dot(rest, n);
    }
    return center;
}

void playerSystem(ecs::Registry& registry, const ecs::Tick& tick, const InputState& input,
                  const Tuning& tuning, const world::BspView* bsp) {
    float dt = float(tick.seconds);
    for (auto [e, transform, player] : registry.view<Transform, Player>().each()) {
        player.yaw += glm::radians(input.lookYawDegrees);
        player.pitch = std::clamp(player.pitch + glm::radians(input.lookPitchDegrees),
                                  glm::radians(-89.0f), glm::radians(89.0f));
        glm::vec3 forward(-std::sin(player.yaw), 0.0f, -std::cos(player.yaw));
        glm::vec3 right(std::cos(player.yaw), 0.0f, -std::sin(player.yaw));
        glm::vec3 wish(0.0f);
        if (input.down("W")) wish += forward;
        if (input.down("S")) wish -= forward;
        if (input.down("D")) wish += right;
        if (input.down("A")) wish -= right;
        if (glm::length(wish) > 0.0f) wish = glm::normalize(wish) * tuning.walkSpeed;
        player.velocity.x = wish.x;
        player.velocity.z = wish.z;
        if (player.onGround && input.down("SPACE")) player.velocity.y = tuning.jumpSpeed;
        player.velocity.y -= tuning.gravity * dt;

        // The body is a sphere resting on the feet.
        glm::vec3 center = transform.position + glm::vec3(0.0f, tuning.bodyRadius, 0.0f);
        bool floor = false;
        center = moveAndSlide(bsp, center, player.velocity * dt, tuning.bodyRadius, tuning.skin,
                              tuning.maxSlopeCos, floor);
        player.onGround = floor;
        if (floor && player.velocity.y < 0.0f) player.velocity.y = 0.0f;
        transform.position = center - glm::vec3(0.0f, tuning.bodyRadius, 0.0f);
        transform.yaw = player.yaw;
    }
}

void playerSystem(ecs::Registry& registry, const ecs::Tick& tick, const InputState& input,
                  const Tuning& tuning, const PlayerWorld& world) {
    if (!world.brushes) {
        playerSystem(registry, tick, input, tuning, world.surfaces);
        return;
    }
    MoveIntent intent;
    intent.forward = float(input.down("W")) - float(input.down("S"));
    intent.right = float(input.down("D")) - float(input.down("A"));
    intent.jump = input.down("SPACE");
    for (auto [e, transform, player] : registry.view<Transform, Player>().each()) {
        player.yaw += glm::radians(input.lookYawDegrees);
        player.pitch = std::clamp(player.pitch + glm::radians(input.lookPitchDegrees),
                                  glm::radians(-89.0f), glm::radians(89.0f));
        quakeMove(*world.brushes, tuning, float(tick.seconds), intent, transform.position, player);
        transform.yaw = player.yaw;
    }
}

glm::vec3 jumpPadVelocity(glm::vec3 centre, glm::vec3 target, float gravity) {
    const float height = target.y - centre.y;
    if (!(height > 0.0f) || !(gravity > 0.0f)) return glm::vec3(0.0f);
    const float time = std::sqrt(height / (0.5f * gravity));
    glm::vec2 flat(target.x - centre.x, target.z - centre.z);
    const float distance = glm::length(flat);
    const glm::vec2 horizontal =
        distance > 0.0f ? flat / distance * (distance / time) : glm::vec2(0.0f);
    return glm::vec3(horizontal.x, time * gravity, horizontal.y);
}

namespace {

void respawn(glm::vec3& feet, Player& player, TriggerEvents* events, const Tuning& tuning,
             const PlayerWorld& world) {
    if (world.spawns.empty()) return;
    const uint32_t count = events ? events->respawns : 0;
    const SpawnPoint& spawn = world.spawns[count % world.spawns.size()];
    feet = spawn.feet + glm::vec3(0.0f, tuning.spawnLift, 0.0f);
    player.velocity = glm::vec3(0.0f);
    player.yaw = spawn.yaw;
    player.pitch = 0.0f;
    player.knockbackSeconds = 0.0f;
    player.onGround = false;
    player.groundMover = world::kNoIndex;
    if (events) ++events->respawns;
}

}  // namespace

void respawnPlayer(ecs::Registry& registry, ecs::Entity player, const Tuning& tuning,
                   const PlayerWorld& world) {
    Transform* body = registry.tryGet<Transform>(player);
    Player* state = registry.tryGet<Player>(player);
    if (!body || !state) return;
    respawn(body->position, *state, registry.tryGet<TriggerEvents>(player), tuning, world);
    body->yaw = state->yaw;
}

void triggerSystem(ecs::Registry& registry, const Tuning& tuning, const PlayerWorld& world,
                   MoverWorld* movers) {
    const std::vector<world::Trigger>* triggers =
        world.brushes && world.brushes->collision ? &world.brushes->collision->triggers : nullptr;
    for (auto [e, transform, player] : registry.view<Transform, Player>().each()) {
        TriggerEvents* events = registry.tryGet<TriggerEvents>(e);
        glm::vec3& feet = transform.position;
        uint32_t pad = UINT32_MAX;
        for (size_t i = 0; triggers && i < triggers->size(); ++i) {
            const world::Trigger& t = (*triggers)[i];
            const glm::vec3 lo = feet + tuning.boxMin, hi = feet + tuning.boxMax;
            if (glm::any(glm::greaterThan(lo, t.boundsMax)) ||
                glm::any(glm::lessThan(hi, t.boundsMin)))
                continue;
            if (t.kind == world::TriggerKind::kPush) {
                const glm::vec3 v =
                    jumpPadVelocity(0.5f * (t.boundsMin + t.boundsMax), t.target, tuning.gravity);
                if (v == glm::vec3(0.0f)) continue;
                player.velocity = v;  // BG_TouchJumpPad, every tick it is touched
                player.onGround = false;
                player.groundMover = world::kNoIndex;
                pad = uint32_t(i);
                if (events && events->touchingPad != pad) ++events->jumpPadLaunches;
            } else if (t.kind == world::TriggerKind::kUseMover ||
                       t.kind == world::TriggerKind::kRaisePlat) {
                if (movers) touchMoverTrigger(*movers, t);
            } else if (t.kind == world::TriggerKind::kTeleport) {
                feet = t.target;  // TeleportPlayer
                player.yaw = t.targetYaw;
                player.pitch = 0.0f;
                player.velocity = viewDirection(t.targetYaw, 0.0f) * tuning.teleportSpeed;
                player.knockbackSeconds = tuning.knockbackSeconds;
                player.onGround = false;
                player.groundMover = world::kNoIndex;
                if (events) ++events->teleports;
                break;
            } else {
                respawn(feet, player, events, tuning, world);
                break;
            }
        }
        if (events) events->touchingPad = pad;
        if (feet.y < world.fallLimitY) respawn(feet, player, events, tuning, world);
        transform.yaw = player.yaw;
    }
}

void effectLightSystem(ecs::Registry& registry, const ecs::Tick& tick, const InputState& input,
                       const Tuning& tuning, uint64_t& shotSerial) {
    // Expire old flashes (collect first: no structural change while iterating).
    std::vector<ecs::Entity> expired;
    for (auto [e, flash] : registry.view<GunFlash>().each())
        if (double(tick.index - flash.bornTick) * tick.seconds >= double(tuning.gunFlashSeconds))
            expired.push_back(e);
    for (ecs::Entity e : expired) registry.destroy(e);

    std::vector<glm::vec3> muzzles;  // flashes are created after the view is done
    for (auto [e, transform, player, flashlight] :
         registry.view<Transform, Player, Flashlight>().each()) {
        if (input.toggleFlashlight) flashlight.on = !flashlight.on;
        if (input.setFlashlight) flashlight.on = input.flashlightValue;
        if (!input.fire) continue;
        const glm::vec3 eye = eyeOf(transform, tuning);
        muzzles.push_back(eye + viewDirection(player.yaw, player.pitch) * tuning.gunFlashRange);
    }
    for (const glm::vec3& muzzle : muzzles) {
        ecs::Entity flash = registry.create();
        registry.emplace<Transform>(flash, Transform{muzzle});
        registry.emplace<GunFlash>(flash, GunFlash{tick.index, shotSerial++});
    }

    // The budget: the oldest flashes give way.
    while (registry.pool<GunFlash>().size() > size_t(tuning.maxGunFlashes)) {
        ecs::Entity oldest = ecs::kNullEntity;
        uint64_t oldestSerial = UINT64_MAX;
        for (auto [e, flash] : registry.view<GunFlash>().each())
            if (flash.serial < oldestSerial) oldest = e, oldestSerial = flash.serial;
        registry.destroy(oldest);
    }
}

void primarySelectionSystem(ecs::Registry& registry, const ecs::Tick& tick,
                            std::span<const uint32_t> candidates,
                            const world::PrimaryScore& score) {
    const double now = tick.time();
    for (auto [e, transform, lit] : registry.view<Transform, DynamicLighting>().each()) {
        const uint32_t before = lit.pick.primary;
        const float weight = primaryWeight(lit, now);  // of `before`, were it to switch now
        if (weight >= 1.0f) lit.fadingFrom = world::kNoIndex;
        world::updateDynamicPrimary(lit.pick, lit.fixedOrigin ? lit.origin : transform.position,
                                    candidates, score);
        if (lit.pick.primary == before || before == world::kNoIndex) continue;
        if (lit.pick.primary == lit.fadingFrom) {
            // Back to the light it was leaving: the fade turns round where it stood.
            lit.fadingFrom = before;
            lit.fadeStart = now - double(1.0f - weight) * double(world::kPrimaryFadeSeconds);
        } else {
            // A new light: it starts from nothing (a third light's share, if one was still
            // fading out, is dropped: the rarest case, a small step).
            lit.fadingFrom = before;
            lit.fadeStart = now;
        }
    }
}

}  // namespace onelight::game
