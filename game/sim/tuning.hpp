// The game's constants, in SI units, in one place. The defaults are the demo's (glTF levels: a
// sphere on the drawn surfaces); quake3Tuning() gives Quake 3's on a map's brushes.
#pragma once

#include <glm/glm.hpp>

namespace onelight::game {

inline constexpr float kMetresPerQuakeUnit = 1.0f / 32.0f;  // as world/import/q3 imports maps

struct Tuning {
    float walkSpeed = 4.0f;               // m/s
    float gravity = 9.81f;                // m/s^2
    float jumpSpeed = 4.5f;               // m/s
    float eyeHeight = 1.7f;               // m above the feet
    float bodyRadius = 0.35f;             // m, the collision sphere sits on the feet
    float skin = 0.002f;                  // m kept between the body and walls
    float maxSlopeCos = 0.7f;             // floors are surfaces whose normal.y exceeds this
    float gunFlashSeconds = 0.06f;        // life of a gun flash
    float gunFlashIntensity = 4000.0f;    // cd, omni, diffuse only
    float gunFlashRange = 0.6f;           // m in front of the eye
    float flashlightIntensity = 2500.0f;  // cd on the axis
    float flashlightInnerDeg = 12.0f;     // half-angle where the cone starts to fall off
    float flashlightOuterDeg = 25.0f;     // half-angle where it reaches zero
    int maxGunFlashes = 4;                // the Black Ops budget of omni effect lights
    float shotRange = 4096.0f;            // m a shot reaches (Quake 3's bullets: 131072 units)

    // Quake 3's movement on brushes (game/sim/quake_move.hpp), Quake's constants at 1/32 m per
    // unit: bg_local.h, bg_pmove.c, cm_local.h, g_misc.c.
    glm::vec3 boxMin{-15.0f / 32.0f, 0.0f, -15.0f / 32.0f};         // m about the feet: Quake's
    glm::vec3 boxMax{15.0f / 32.0f, 56.0f / 32.0f, 15.0f / 32.0f};  // (-15 -15 -24)..(15 15 32)
    float stepHeight = 18.0f / 32.0f;                               // STEPSIZE 18
    float clipEpsilon = 0.125f / 32.0f;    // SURFACE_CLIP_EPSILON: kept from brushes
    float groundProbe = 0.25f / 32.0f;     // PM_GroundTrace looks this far down
    float overclip = 1.001f;               // OVERCLIP
    float groundAcceleration = 10.0f;      // pm_accelerate, 1/s
    float airAcceleration = 1.0f;          // pm_airaccelerate, 1/s
    float friction = 6.0f;                 // pm_friction, 1/s
    float stopSpeed = 100.0f / 32.0f;      // pm_stopspeed, m/s
    float kickoffSpeed = 10.0f / 32.0f;    // rising this fast off the ground leaves it, m/s
    float teleportSpeed = 400.0f / 32.0f;  // TeleportPlayer's exit speed, m/s
    float knockbackSeconds = 0.16f;        // and its hold time without friction
    float spawnLift = 9.0f / 32.0f;        // a respawn is this far above the spawn point
    float fallMargin = 2.0f;               // m below the level's bounds: a fall respawns
};

// Quake 3's tuning: g_speed 320, g_gravity 800, JUMP_VELOCITY 270 units/s, MIN_WALK_NORMAL 0.7,
// the eyes DEFAULT_VIEWHEIGHT 26 units above the origin (50 above the feet).
[[nodiscard]] inline Tuning quake3Tuning() {
    Tuning t;
    t.walkSpeed = 320.0f * kMetresPerQuakeUnit;
    t.gravity = 800.0f * kMetresPerQuakeUnit;
    t.jumpSpeed = 270.0f * kMetresPerQuakeUnit;
    t.eyeHeight = 50.0f * kMetresPerQuakeUnit;
    t.maxSlopeCos = 0.7f;
    return t;
}

}  // namespace onelight::game
