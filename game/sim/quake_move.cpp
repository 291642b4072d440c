#include "quake_move.hpp"

#include <cmath>

namespace onelight::game {
namespace {

constexpr int kMaxClipPlanes = 5;  // MAX_CLIP_PLANES
constexpr int kBumps = 4;          // PM_SlideMove's tries

// One tick's state (Quake's pml).
struct Move {
    const BrushWorld& brushes;
    const Tuning& tuning;
    float seconds;
    glm::vec3& feet;
    Player& player;
    bool groundPlane = false;  // something is under the feet (maybe too steep)
    bool walking = false;      // ... and it is a floor
    glm::vec3 groundNormal{0.0f};

    BoxTrace trace(glm::vec3 from, glm::vec3 to) const {
        return traceBox(brushes, from, to, tuning.boxMin, tuning.boxMax, tuning.clipEpsilon);
    }
};

// PM_ClipVelocity: the part of `v` along the plane, pushed out by the overclip.
glm::vec3 clipVelocity(glm::vec3 v, glm::vec3 n, float overclip) {
    float backoff = glm::dot(v, n);
    backoff = backoff < 0.0f ? backoff * overclip : backoff / overclip;
    return v - n * backoff;
}

glm::vec3 normalizedOrZero(glm::vec3 v) {
    const float length = glm::length(v);
    return length > 0.0f ? v / length : glm::vec3(0.0f);
}

void groundTrace(Move& m) {
    const BoxTrace t = m.trace(m.feet, m.feet - glm::vec3(0.0f, m.tuning.groundProbe, 0.0f));
    m.groundPlane = m.walking = false;
    m.player.onGround = false;
    m.player.groundMover = world::kNoIndex;
    if (t.allSolid || t.fraction == 1.0f) return;  // stuck, or in free fall
    const glm::vec3& v = m.player.velocity;
    // Thrown off the ground (a jump, a jump pad).
    if (v.y > 0.0f && glm::dot(v, t.normal) > m.tuning.kickoffSpeed) return;
    m.groundPlane = true;
    m.groundNormal = t.normal;
    if (t.normal.y < m.tuning.maxSlopeCos) return;  // too steep: slides
    m.walking = true;
    m.player.onGround = true;
    m.player.groundMover = t.mover;  // PM_GroundTrace's groundEntityNum
}

void friction(Move& m) {
    glm::vec3& v = m.player.velocity;
    glm::vec3 along = v;
    if (m.walking) along.y = 0.0f;  // ignore slope movement
    const float speed = glm::length(along);
    if (speed < kMetresPerQuakeUnit) {
        v.x = v.z = 0.0f;
        return;
    }
    float drop = 0.0f;
    if (m.walking && m.player.knockbackSeconds <= 0.0f)
        drop = std::max(speed, m.tuning.stopSpeed) * m.tuning.friction * m.seconds;
    v *= std::max(0.0f, speed - drop) / speed;
}

void accelerate(Move& m, glm::vec3 wishDir, float wishSpeed, float acceleration) {
    const float add = wishSpeed - glm::dot(m.player.velocity, wishDir);
    if (add <= 0.0f) return;
    m.player.velocity += wishDir * std::min(add, acceleration * m.seconds * wishSpeed);
}

// PM_SlideMove: returns whether anything was hit.
bool slideMove(Move& m, bool gravity) {
    glm::vec3& v = m.player.velocity;
    const float overclip = m.tuning.overclip;
    glm::vec3 primal = v;
    glm::vec3 endVelocity(0.0f);
    if (gravity) {
        endVelocity = v;
        endVelocity.y -= m.tuning.gravity * m.seconds;
        v.y = 0.5f * (v.y + endVelocity.y);
        primal.y = endVelocity.y;
        if (m.groundPlane) v = clipVelocity(v, m.groundNormal, overclip);
    }
    float timeLeft = m.seconds;
    glm::vec3 planes[kMaxClipPlanes];
    int planeCount = 0;
    if (m.groundPlane) planes[planeCount++] = m.groundNormal;  // never turn against the ground
    planes[planeCount++] = normalizedOrZero(v);                // nor against the velocity
    int bump = 0;
    for (; bump < kBumps; ++bump) {
        const BoxTrace t = m.trace(m.feet, m.feet + v * timeLeft);
        if (t.allSolid) {  // trapped in a solid
            v.y = 0.0f;
            return true;
        }
        if (t.fraction > 0.0f) m.feet = t.end;
        if (t.fraction == 1.0f) break;
        timeLeft -= timeLeft * t.fraction;
        if (planeCount >= kMaxClipPlanes) {
            v = glm::vec3(0.0f);
            return true;
        }
        // The same plane again: nudge the velocity out along it (epsilon issues on slopes).
        bool same = false;
        for (int i = 0; i < planeCount && !same; ++i)
            if (glm::dot(t.normal, planes[i]) > 0.99f) {
                v += t.normal * kMetresPerQuakeUnit;  // Quake adds the unit normal in units/s
                same = true;
            }
        if (same) continue;
        planes[planeCount++] = t.normal;
        // Make the velocity parallel to every clip plane it enters.
        for (int i = 0; i < planeCount; ++i) {
            if (glm::dot(v, planes[i]) >= 0.1f * kMetresPerQuakeUnit) continue;
            glm::vec3 clipped = clipVelocity(v, planes[i], overclip);
            glm::vec3 endClipped =
                gravity ? clipVelocity(endVelocity, planes[i], overclip) : glm::vec3(0.0f);
            for (int j = 0; j < planeCount; ++j) {
                if (j == i) continue;
                if (glm::dot(clipped, planes[j]) >= 0.1f * kMetresPerQuakeUnit) continue;
                clipped = clipVelocity(clipped, planes[j], overclip);
                if (gravity) endClipped = clipVelocity(endClipped, planes[j], overclip);
                if (glm::dot(clipped, planes[i]) >= 0.0f) continue;
                // Along the crease of the two planes.
                const glm::vec3 crease = normalizedOrZero(glm::cross(planes[i], planes[j]));
                clipped = crease * glm::dot(crease, v);
                if (gravity) endClipped = crease * glm::dot(crease, endVelocity);
                for (int k = 0; k < planeCount; ++k) {
                    if (k == i || k == j) continue;
                    if (glm::dot(clipped, planes[k]) >= 0.1f * kMetresPerQuakeUnit) continue;
                    v = glm::vec3(0.0f);  // a corner of three planes: stop dead
                    return true;
                }
            }
            v = clipped;
            if (gravity) endVelocity = endClipped;
            break;
        }
    }
    if (gravity) v = endVelocity;
    if (m.player.knockbackSeconds > 0.0f) v = primal;  // held during the knockback time
    return bump != 0;
}

// PM_StepSlideMove: the plain slide, else the same from stepHeight up, pushed back down.
void stepSlideMove(Move& m, bool gravity) {
    const glm::vec3 startFeet = m.feet, startVelocity = m.player.velocity;
    if (!slideMove(m, gravity)) return;  // got there first try
    const glm::vec3 up(0.0f, 1.0f, 0.0f);
    const BoxTrace down = m.trace(startFeet, startFeet - up * m.tuning.stepHeight);
    // Never step up while still rising off nothing, or off a slope too steep to stand on.
    if (m.player.velocity.y > 0.0f &&
        (down.fraction == 1.0f || down.normal.y < m.tuning.maxSlopeCos))
        return;
    const BoxTrace raised = m.trace(startFeet, startFeet + up * m.tuning.stepHeight);
    if (raised.allSolid) return;  // no room to step up
    const float stepSize = raised.end.y - startFeet.y;
    m.feet = raised.end;
    m.player.velocity = startVelocity;
    slideMove(m, gravity);
    const BoxTrace settle = m.trace(m.feet, m.feet - up * stepSize);
    if (!settle.allSolid) m.feet = settle.end;
    if (settle.fraction < 1.0f)
        m.player.velocity = clipVelocity(m.player.velocity, settle.normal, m.tuning.overclip);
}

// The wish direction and speed on the flat (PM_CmdScale: any key combination runs at walkSpeed).
void wish(const Move& m, const MoveIntent& intent, glm::vec3 forward, glm::vec3 right,
          glm::vec3& direction, float& speed) {
    direction = normalizedOrZero(forward * intent.forward + right * intent.right);
    speed = direction == glm::vec3(0.0f) ? 0.0f : m.tuning.walkSpeed;
}

void airMove(Move& m, const MoveIntent& intent, glm::vec3 forward, glm::vec3 right) {
    friction(m);
    glm::vec3 direction;
    float speed;
    wish(m, intent, forward, right, direction, speed);
    accelerate(m, direction, speed, m.tuning.airAcceleration);
    // A ground too steep to stand on: slide along it.
    if (m.groundPlane)
        m.player.velocity = clipVelocity(m.player.velocity, m.groundNormal, m.tuning.overclip);
    stepSlideMove(m, true);
}

void walkMove(Move& m, const MoveIntent& intent, glm::vec3 forward, glm::vec3 right) {
    if (intent.jump && !m.player.jumpHeld) {  // PM_CheckJump
        m.groundPlane = m.walking = false;
        m.player.onGround = false;
        m.player.groundMover = world::kNoIndex;
        m.player.jumpHeld = true;
        m.player.velocity.y = m.tuning.jumpSpeed;
        airMove(m, intent, forward, right);
        return;
    }
    friction(m);
    // The wish directions follow the ground's slope.
    forward = normalizedOrZero(clipVelocity(forward, m.groundNormal, m.tuning.overclip));
    right = normalizedOrZero(clipVelocity(right, m.groundNormal, m.tuning.overclip));
    glm::vec3 direction;
    float speed;
    wish(m, intent, forward, right, direction, speed);
    const bool knockback = m.player.knockbackSeconds > 0.0f;
    accelerate(m, direction, speed,
               knockback ? m.tuning.airAcceleration : m.tuning.groundAcceleration);
    glm::vec3& v = m.player.velocity;
    if (knockback) v.y -= m.tuning.gravity * m.seconds;
    // Along the ground, keeping the speed on slopes.
    const float length = glm::length(v);
    v = normalizedOrZero(clipVelocity(v, m.groundNormal, m.tuning.overclip)) * length;
    if (v.x == 0.0f && v.z == 0.0f) return;  // standing still
    stepSlideMove(m, false);
}

}  // namespace

void quakeMove(const BrushWorld& brushes, const Tuning& tuning, float seconds,
               const MoveIntent& intent, glm::vec3& feet, Player& player) {
    Move m{brushes, tuning, seconds, feet, player};
    if (!intent.jump) player.jumpHeld = false;
    // Flat forward and right from the view's yaw (0 looks down -z, positive turns left).
    const glm::vec3 forward(-std::sin(player.yaw), 0.0f, -std::cos(player.yaw));
    const glm::vec3 right(std::cos(player.yaw), 0.0f, -std::sin(player.yaw));
    groundTrace(m);
    player.knockbackSeconds = std::max(0.0f, player.knockbackSeconds - seconds);  // PM_DropTimers
    if (m.walking)
        walkMove(m, intent, forward, right);
    else
        airMove(m, intent, forward, right);
    groundTrace(m);
}

}  // namespace onelight::game
