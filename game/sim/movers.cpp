#include "movers.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "systems.hpp"
#include "world/entity_transform.hpp"

namespace onelight::game {
namespace {

constexpr double kUseDelaySeconds = 0.05;  // Use_BinaryMover: a mover at rest starts 50 ms late

const world::Mover& recordOf(const MoverWorld& w, uint32_t index) {
    return w.level->movers.movers[index];
}

uint32_t masterOf(const MoverWorld& w, uint32_t index) {
    const uint32_t master = recordOf(w, index).teamMaster;
    return master == world::kNoIndex ? index : master;
}

world::MoverPose poseAt(const MoverWorld& w, uint32_t index, double seconds) {
    const MoverMotion& m = w.motion[index];
    const world::Mover& record = recordOf(w, index);
    world::MoverPose pose;
    pose.origin = evaluate(m.position, seconds);
    // A rotator's angle grows without end: taken modulo a turn in doubles.
    const float angle = m.angle.type == Trajectory::Type::kLinear
                            ? float(std::fmod(double(m.angle.delta.x) * (seconds - m.angle.start),
                                              6.283185307179586))
                            : evaluate(m.angle, seconds).x;
    if (angle != 0.0f) pose.turn = glm::angleAxis(angle, record.axis);
    return pose;
}

// SetMoverState: a binary mover's phase from `seconds` on.
void setPhase(MoverWorld& w, uint32_t index, MoverPhase phase, double seconds) {
    const world::Mover& r = recordOf(w, index);
    MoverMotion& m = w.motion[index];
    m.phase = phase;
    Trajectory& t = m.position;
    switch (phase) {
        case MoverPhase::kAtPos1:
            t = {Trajectory::Type::kStationary, r.pos1, glm::vec3(0.0f), seconds, 0.0};
            break;
        case MoverPhase::kAtPos2:
            t = {Trajectory::Type::kStationary, r.pos2, glm::vec3(0.0f), seconds, 0.0};
            break;
        case MoverPhase::kToPos2:
            t = {Trajectory::Type::kLinearStop, r.pos1, (r.pos2 - r.pos1) / r.travelSeconds,
                 seconds, double(r.travelSeconds)};
            break;
        case MoverPhase::kToPos1:
            t = {Trajectory::Type::kLinearStop, r.pos2, (r.pos1 - r.pos2) / r.travelSeconds,
                 seconds, double(r.travelSeconds)};
            break;
    }
}

// MatchTeam: every part of `master`'s team to `phase` at the same time.
void matchTeam(MoverWorld& w, uint32_t master, MoverPhase phase, double seconds) {
    for (uint32_t part : w.team[master]) setPhase(w, part, phase, seconds);
}

// Reached_Train, on arriving at corner `corner`: hold its wait, then the leg to the next.
void trainAt(MoverWorld& w, uint32_t index, uint32_t corner, double seconds) {
    const world::Mover& r = recordOf(w, index);
    const std::vector<world::MoverPoint>& path = w.level->movers.path;
    const world::MoverPoint& from = path[r.firstPoint + corner];
    const world::MoverPoint& to = path[r.firstPoint + (corner + 1) % r.pointCount];
    MoverMotion& m = w.motion[index];
    m.point = corner;
    m.phase = from.wait > 0.0f ? MoverPhase::kAtPos1 : MoverPhase::kToPos2;
    m.position = {Trajectory::Type::kLinearStop, from.position,
                  (to.position - from.position) / from.legSeconds, seconds,
                  double(from.legSeconds)};
    m.thinkAt = -1.0;
    if (from.wait > 0.0f) {  // holds at the corner until Think_BeginMoving
        m.position.type = Trajectory::Type::kStationary;
        m.thinkAt = seconds + double(from.wait);
    }
}

// Reached_BinaryMover and Reached_Train.
void reached(MoverWorld& w, uint32_t index, double seconds) {
    const world::Mover& r = recordOf(w, index);
    MoverMotion& m = w.motion[index];
    if (r.kind == world::MoverKind::kTrain) {
        trainAt(w, index, (m.point + 1) % r.pointCount, seconds);
        return;
    }
    if (m.phase == MoverPhase::kToPos1) {
        setPhase(w, index, MoverPhase::kAtPos1, seconds);
        return;
    }
    setPhase(w, index, MoverPhase::kAtPos2, seconds);
    if (masterOf(w, index) == index) m.thinkAt = seconds + double(r.wait);
    // G_UseTargets: every mover named by its target (itself excepted).
    if (r.target == world::kNoIndex) return;
    const std::vector<world::Mover>& all = w.level->movers.movers;
    for (uint32_t other = 0; other < all.size(); ++other)
        if (other != index && all[other].name == r.target) useMover(w, other, seconds);
}

// Where the player's box is clear of every brush (at the movers' poses in `brushes`).
bool clearAt(const BrushWorld& brushes, const Tuning& tuning, glm::vec3 feet) {
    return !traceBox(brushes, feet, feet, tuning.boxMin, tuning.boxMax, 0.0f).startSolid;
}

enum class Push { kDone, kBlocked, kCrushed };

// G_TryPushingEntity for the player and part `index` going from `from` to `to` (its brushes are
// at `to` in `brushes` already): a rider, or a player the part now overlaps, is carried with the
// part (turned with it about its origin; the view turns with a turn about the vertical).
Push pushPlayer(const MoverWorld& w, uint32_t index, const world::MoverPose& from,
                const world::MoverPose& to, const BrushWorld& brushes, const Tuning& tuning,
                glm::vec3& feet, Player& player) {
    const bool rider = player.groundMover == index;
    if (!rider && !traceBox(brushes, feet, feet, tuning.boxMin, tuning.boxMax, 0.0f,
                            {TraceBrushes::kOneMover, index})
                       .startSolid)
        return Push::kDone;
    const glm::vec3 centre = 0.5f * (tuning.boxMin + tuning.boxMax);
    const glm::vec3 local = glm::inverse(from.turn) * (feet + centre - from.origin);
    const glm::vec3 moved = to.origin + to.turn * local - centre;
    if (clearAt(brushes, tuning, moved)) {
        const world::Mover& r = recordOf(w, index);
        if (std::fabs(r.axis.y) > 0.99f) {
            const glm::quat change = to.turn * glm::inverse(from.turn);
            player.yaw += 2.0f * std::atan2(change.y, change.w);  // about +y
        }
        feet = moved;
        if (!rider) player.groundMover = world::kNoIndex;
        return Push::kDone;
    }
    if (clearAt(brushes, tuning, feet)) {  // left behind where it stood
        player.groundMover = world::kNoIndex;
        return Push::kDone;
    }
    const world::MoverKind kind = recordOf(w, index).kind;
    return kind == world::MoverKind::kBobbing || kind == world::MoverKind::kPendulum
               ? Push::kCrushed
               : Push::kBlocked;
}

BrushPose brushPoseOf(const MoverWorld& w, uint32_t index, const world::MoverPose& pose) {
    const world::Entity& e = w.level->entities[recordOf(w, index).entity];
    return {pose.origin, pose.turn * glm::normalize(e.rotation)};
}

// G_MoverTeam: every part of `master`'s team to its place at `seconds`, pushing the player;
// returns false (and leaves every part and the player where they were) when one is blocked.
bool moveTeam(ecs::Registry& registry, MoverWorld& w, uint32_t master, double seconds,
              BrushWorld& brushes, const Tuning& tuning, const PlayerWorld& playerWorld,
              ecs::Entity playerEntity) {
    const std::vector<uint32_t>& parts = w.team[master];
    Transform* body =
        playerEntity != ecs::kNullEntity && brushes.moverPoses.size() == w.motion.size()
            ? registry.tryGet<Transform>(playerEntity)
            : nullptr;
    Player* player = body ? registry.tryGet<Player>(playerEntity) : nullptr;
    const glm::vec3 feetBefore = body ? body->position : glm::vec3(0.0f);
    const Player playerBefore = player ? *player : Player{};
    bool crushed = false;
    size_t moved = 0;
    for (; moved < parts.size(); ++moved) {
        const uint32_t part = parts[moved];
        if (!player) continue;  // nothing to push (no brushes: a glTF level)
        const world::MoverPose to = poseAt(w, part, seconds);
        brushes.moverPoses[part] = brushPoseOf(w, part, to);
        const Push push =
            pushPlayer(w, part, w.motion[part].pose, to, brushes, tuning, body->position, *player);
        if (push == Push::kBlocked) break;
        crushed |= push == Push::kCrushed;
    }
    if (moved < parts.size()) {  // blocked: everything back where it was
        for (size_t k = 0; k <= moved && k < parts.size(); ++k)
            brushes.moverPoses[parts[k]] = brushPoseOf(w, parts[k], w.motion[parts[k]].pose);
        body->position = feetBefore;
        *player = playerBefore;
        return false;
    }
    for (uint32_t part : parts) w.motion[part].pose = poseAt(w, part, seconds);
    if (crushed) respawnPlayer(registry, playerEntity, tuning, playerWorld);
    return true;
}

}  // namespace

glm::vec3 evaluate(const Trajectory& t, double seconds) {
    switch (t.type) {
        case Trajectory::Type::kStationary:
            return t.base;
        case Trajectory::Type::kLinearStop: {
            const double done = std::clamp(seconds - t.start, 0.0, t.duration);
            return t.base + t.delta * float(done);
        }
        case Trajectory::Type::kSine:
            return t.base +
                   t.delta * float(std::sin(6.283185307179586 * (seconds - t.start) / t.duration));
        case Trajectory::Type::kLinear:
            return t.base + t.delta * float(seconds - t.start);
        case Trajectory::Type::kTriangle: {
            double phase = std::fmod((seconds - t.start) / t.duration, 1.0);
            if (phase < 0.0) phase += 1.0;
            return t.base + t.delta * float(phase < 0.5 ? 2.0 * phase : 2.0 - 2.0 * phase);
        }
    }
    return t.base;
}

MoverWorld startMovers(const world::CompiledLevel& level, std::vector<ecs::Entity> entityOf,
                       ecs::Registry* registry) {
    MoverWorld w;
    w.level = &level;
    w.entityOf = std::move(entityOf);
    const std::vector<world::Mover>& all = level.movers.movers;
    w.motion.resize(all.size());
    w.team.resize(all.size());
    for (uint32_t i = 0; i < all.size(); ++i)
        if (all[i].teamMaster == world::kNoIndex) w.team[i].push_back(i);
    for (uint32_t i = 0; i < all.size(); ++i)
        if (all[i].teamMaster != world::kNoIndex) w.team[all[i].teamMaster].push_back(i);
    // Each mover's lighting origin: its meshes' bounds' centre, in its object space.
    w.centre.assign(all.size(), glm::vec3(0.0f));
    for (uint32_t i = 0; i < all.size(); ++i) {
        const world::Entity& e = level.entities[all[i].entity];
        glm::vec3 lo(std::numeric_limits<float>::max()), hi(std::numeric_limits<float>::lowest());
        for (uint32_t k = e.firstDynamicMesh; k < e.firstDynamicMesh + e.dynamicMeshCount; ++k) {
            const world::DynamicMesh& mesh = level.dynamicMeshes[k];
            for (uint32_t v = mesh.firstVertex; v < mesh.firstVertex + mesh.vertexCount; ++v) {
                lo = glm::min(lo, level.dynamicVertices[v].position);
                hi = glm::max(hi, level.dynamicVertices[v].position);
            }
        }
        if (lo.x <= hi.x) w.centre[i] = 0.5f * (lo + hi);
    }
    for (uint32_t i = 0; i < all.size(); ++i) {
        const world::Mover& r = all[i];
        MoverMotion& m = w.motion[i];
        m.position = {Trajectory::Type::kStationary, r.pos1, glm::vec3(0.0f), 0.0, 0.0};
        const double late = double(r.phase) * double(r.period);
        switch (r.kind) {
            case world::MoverKind::kShuttle:
                m.position = {Trajectory::Type::kTriangle, r.pos1, r.pos2 - r.pos1, 0.0,
                              double(r.period)};
                break;
            case world::MoverKind::kDoor:
            case world::MoverKind::kPlat:
            case world::MoverKind::kButton:
                setPhase(w, i, MoverPhase::kAtPos1, 0.0);
                break;
            case world::MoverKind::kBobbing:
                m.position = {Trajectory::Type::kSine, r.pos1, r.amplitude, late, double(r.period)};
                break;
            case world::MoverKind::kRotating:
                m.angle = {Trajectory::Type::kLinear, glm::vec3(0.0f),
                           glm::vec3(r.speed, 0.0f, 0.0f), 0.0, 0.0};
                break;
            case world::MoverKind::kPendulum:
                m.angle = {Trajectory::Type::kSine, glm::vec3(0.0f), glm::vec3(r.speed, 0.0f, 0.0f),
                           late, double(r.period)};
                break;
            case world::MoverKind::kTrain:
                trainAt(w, i, 0, 0.0);
                break;
        }
        m.pose = poseAt(w, i, 0.0);
        if (registry && i < w.entityOf.size() && w.entityOf[i] != ecs::kNullEntity)
            registry->emplace<MoverState>(w.entityOf[i], MoverState{i, moverPhase(w, i)});
    }
    return w;
}

void useMover(MoverWorld& w, uint32_t index, double now) {
    if (index >= w.motion.size() || !world::isBinaryMover(recordOf(w, index).kind)) return;
    const uint32_t master = masterOf(w, index);
    MoverMotion& m = w.motion[master];
    const double total = double(recordOf(w, master).travelSeconds);
    switch (m.phase) {
        case MoverPhase::kAtPos1:
            matchTeam(w, master, MoverPhase::kToPos2, now + kUseDelaySeconds);
            break;
        case MoverPhase::kAtPos2:
            m.thinkAt = now + double(recordOf(w, master).wait);
            break;
        case MoverPhase::kToPos1:
        case MoverPhase::kToPos2: {
            // Turn round where it stands: as far back as it came.
            const double partial = std::min(now - m.position.start, total);
            matchTeam(w, master,
                      m.phase == MoverPhase::kToPos1 ? MoverPhase::kToPos2 : MoverPhase::kToPos1,
                      now - (total - partial));
            break;
        }
    }
}

void touchMoverTrigger(MoverWorld& w, const world::Trigger& trigger) {
    if (trigger.mover >= w.motion.size()) return;
    const world::Mover& r = recordOf(w, trigger.mover);
    const MoverPhase phase = w.motion[masterOf(w, trigger.mover)].phase;
    const bool use = r.kind == world::MoverKind::kDoor ? phase != MoverPhase::kToPos2
                                                       : phase == MoverPhase::kAtPos1;
    if (use &&
        std::find(w.pendingUses.begin(), w.pendingUses.end(), trigger.mover) == w.pendingUses.end())
        w.pendingUses.push_back(trigger.mover);
}

uint32_t shootMovers(MoverWorld& w, const BrushWorld& brushes, glm::vec3 eye, glm::vec3 direction,
                     float range) {
    TraceFilter shot;
    shot.contents = world::kContentsSolid;
    const BoxTrace hit = traceBox(brushes, eye, eye + direction * range, glm::vec3(0.0f),
                                  glm::vec3(0.0f), 0.0f, shot);
    if (hit.fraction >= 1.0f || hit.mover >= w.motion.size()) return world::kNoIndex;
    const world::Mover& r = recordOf(w, hit.mover);
    if ((r.flags & world::kMoverShootable) &&
        w.motion[masterOf(w, hit.mover)].phase == MoverPhase::kAtPos1 &&
        std::find(w.pendingUses.begin(), w.pendingUses.end(), hit.mover) == w.pendingUses.end())
        w.pendingUses.push_back(hit.mover);
    return hit.mover;
}

void shotSystem(ecs::Registry& registry, const InputState& input, const Tuning& tuning,
                MoverWorld& movers, const BrushWorld& brushes) {
    if (!input.fire || movers.motion.empty()) return;
    for (auto [e, transform, player] : registry.view<Transform, Player>().each()) {
        (void)shootMovers(movers, brushes, eyeOf(transform, tuning),
                          viewDirection(player.yaw, player.pitch), tuning.shotRange);
    }
}

void moverSystem(ecs::Registry& registry, const ecs::Tick& tick, MoverWorld& w, BrushWorld& brushes,
                 const Tuning& tuning, const PlayerWorld& playerWorld, ecs::Entity player) {
    if (w.motion.empty()) return;
    const double now = tick.time();
    const std::vector<world::Mover>& all = w.level->movers.movers;
    std::vector<uint32_t> uses;
    uses.swap(w.pendingUses);
    for (uint32_t index : uses) useMover(w, index, now);
    // Touch_Plat: standing on a plat at the top keeps it there another wait.
    if (const Player* p = player != ecs::kNullEntity ? registry.tryGet<Player>(player) : nullptr;
        p && p->groundMover < all.size() && all[p->groundMover].kind == world::MoverKind::kPlat &&
        w.motion[p->groundMover].phase == MoverPhase::kAtPos2)
        w.motion[p->groundMover].thinkAt = now + double(all[p->groundMover].wait);

    for (uint32_t master = 0; master < all.size(); ++master) {
        if (w.team[master].empty()) continue;  // a member: its master moves it
        bool moving = false;
        for (uint32_t part : w.team[master])
            moving |= w.motion[part].position.type != Trajectory::Type::kStationary ||
                      w.motion[part].angle.type != Trajectory::Type::kStationary;
        if (moving) {
            if (moveTeam(registry, w, master, now, brushes, tuning, playerWorld, player)) {
                for (uint32_t part : w.team[master]) {
                    const Trajectory& t = w.motion[part].position;
                    if (t.type == Trajectory::Type::kLinearStop && now >= t.start + t.duration)
                        reached(w, part, now);
                }
            } else {
                // Paused: its clock held back a tick. A door or plat turns round (Blocked_Door),
                // unless it crushes; buttons, trains and rotators wait for the way to clear.
                ++w.blocks;
                for (uint32_t part : w.team[master]) {
                    w.motion[part].position.start += tick.seconds;
                    w.motion[part].angle.start += tick.seconds;
                }
                const world::Mover& r = all[master];
                if ((r.kind == world::MoverKind::kDoor || r.kind == world::MoverKind::kPlat) &&
                    !(r.flags & world::kMoverCrusher))
                    useMover(w, master, now);
            }
        }
        MoverMotion& m = w.motion[master];
        if (m.thinkAt >= 0.0 && m.thinkAt <= now) {
            m.thinkAt = -1.0;
            if (all[master].kind == world::MoverKind::kTrain) {
                m.position.type = Trajectory::Type::kLinearStop;  // Think_BeginMoving
                m.position.start = now;
                m.phase = MoverPhase::kToPos2;
            } else if (m.phase == MoverPhase::kAtPos2) {
                matchTeam(w, master, MoverPhase::kToPos1, now);  // ReturnToPos1
            }
        }
    }

    for (uint32_t i = 0; i < all.size(); ++i) {
        const world::MoverPose& pose = w.motion[i].pose;
        if (i < brushes.moverPoses.size()) brushes.moverPoses[i] = brushPoseOf(w, i, pose);
        if (i >= w.entityOf.size() || w.entityOf[i] == ecs::kNullEntity) continue;
        const ecs::Entity e = w.entityOf[i];
        if (Transform* t = registry.tryGet<Transform>(e)) {
            t->position = pose.origin;
            t->turn = pose.turn;
        }
        if (MoverState* state = registry.tryGet<MoverState>(e)) *state = {i, moverPhase(w, i)};
        if (DynamicLighting* lit = registry.tryGet<DynamicLighting>(e)) {
            const world::Entity& entity = w.level->entities[all[i].entity];
            lit->fixedOrigin = true;
            lit->origin = glm::vec3(world::worldFromObject(entity, pose.origin, pose.turn) *
                                    glm::vec4(w.centre[i], 1.0f));
        }
    }
}

MoverPhase moverPhase(const MoverWorld& w, uint32_t index) {
    return w.motion[masterOf(w, index)].phase;
}

}  // namespace onelight::game
