// The level's movers (world/movers.hpp) as the game runs them: a glTF level's shuttles, and a
// Quake 3 map's doors, plats, buttons, bobbing, rotating and pendulum movers and trains by the
// game's rules (g_mover.c): binary movers used by triggers, touch and each other, held, sent
// back and reversed where they stand; teams moving with their master; trains from corner to
// corner; the player carried by what it stands on or is pushed by (G_MoverPush), and a mover
// that cannot push it paused (doors and plats reverse, bobbers and pendulums crush).
#pragma once

#include <cstdint>
#include <vector>

#include <glm/glm.hpp>
#include <glm/gtc/quaternion.hpp>

#include "brush_trace.hpp"
#include "components.hpp"
#include "ecs/registry.hpp"
#include "ecs/schedule.hpp"
#include "input.hpp"
#include "tuning.hpp"
#include "world/compiled_level.hpp"

namespace onelight::game {

struct PlayerWorld;

// Quake 3's trajectory (bg_misc.c BG_EvaluateTrajectory), in seconds: a value that stands,
// slides and stops, swings on a sine, grows linearly, or (a shuttle's) goes and comes back.
struct Trajectory {
    enum class Type { kStationary, kLinearStop, kSine, kLinear, kTriangle };
    Type type = Type::kStationary;
    glm::vec3 base{0.0f};
    glm::vec3 delta{0.0f};  // linear: per second; sine: the peak; triangle: the far end's offset
    double start = 0.0;     // seconds
    double duration = 0.0;  // linear-stop, sine, triangle: seconds, > 0
};

[[nodiscard]] glm::vec3 evaluate(const Trajectory& trajectory, double seconds);

// A binary mover's state (Quake 3's moverState).
enum class MoverPhase { kAtPos1, kToPos2, kAtPos2, kToPos1 };

// On a mover's ECS entity: which mover it is and its phase this tick (moverPhase's), for
// replays.
struct MoverState {
    uint32_t index = 0;  // into the level's movers
    MoverPhase phase = MoverPhase::kAtPos1;
};

// One mover's motion this tick.
struct MoverMotion {
    Trajectory position;  // of its origin
    Trajectory angle;     // x: radians about the mover's axis
    MoverPhase phase = MoverPhase::kAtPos1;
    double thinkAt = -1.0;  // seconds: binary at pos2, when it returns; a train at a
                            // corner, when it leaves; < 0: nothing due
    uint32_t point = 0;     // a train: the corner it left last (into its points)
    world::MoverPose pose;  // where it is now
};

// Every mover's motion, by the level's mover index, and the uses that triggers and buttons asked
// for since the last tick.
struct MoverWorld {
    const world::CompiledLevel* level = nullptr;  // borrowed: its movers and entities
    std::vector<MoverMotion> motion;
    std::vector<std::vector<uint32_t>> team;  // a master's parts (itself first); empty for members
    std::vector<ecs::Entity> entityOf;        // the ECS entity drawing each mover
    std::vector<glm::vec3> centre;            // each one's meshes' bounds' centre, object space
    std::vector<uint32_t> pendingUses;        // movers to use at the next tick, in order
    uint32_t blocks = 0;                      // moves refused because the player was in the way
};

// Every mover at rest at time 0 (a train at its first corner); `entityOf` links each to the ECS
// entity that draws it, whose Transform, DynamicLighting and MoverState (added here when
// `registry` is given) the system keeps up to date.
[[nodiscard]] MoverWorld startMovers(const world::CompiledLevel& level,
                                     std::vector<ecs::Entity> entityOf,
                                     ecs::Registry* registry = nullptr);

// Quake 3's Use_BinaryMover on mover `index` (its team's master acts): from rest it starts to
// pos2 50 ms later; at pos2 it holds another `wait`; moving, it turns round where it stands.
// Other kinds ignore uses.
void useMover(MoverWorld& movers, uint32_t index, double now);

// The player touches a trigger of kind kUseMover or kRaisePlat: a door not already opening is
// used (Touch_DoorTrigger); a button or plat only at rest at pos1 (Touch_Button,
// Touch_PlatCenterTrigger). The use runs at the start of the next tick.
void touchMoverTrigger(MoverWorld& movers, const world::Trigger& trigger);

// A shot from `eye` along unit `direction` reaching `range` metres, through solid brushes (not
// player clips, as Quake 3's MASK_SHOT): the mover whose brush it meets first is used at the
// next tick when it is shootable (kMoverShootable) and its team at rest at pos1 (G_Damage on a
// mover). Returns the mover it met, or kNoIndex (a wall, or nothing).
uint32_t shootMovers(MoverWorld& movers, const BrushWorld& brushes, glm::vec3 eye,
                     glm::vec3 direction, float range);

// The player fires (InputState::fire): its shot from the eye along its view (shootMovers).
void shotSystem(ecs::Registry& registry, const InputState& input, const Tuning& tuning,
                MoverWorld& movers, const BrushWorld& brushes);

// One tick: the pending uses, then every team master's move (parts that push the player carry
// it; one that cannot is paused and, a door or plat, reversed; a bobber or pendulum respawns it
// instead), arrivals (a binary mover at pos2 holds and uses its target; a train takes its next
// leg) and what was due. Then the movers' brushes (`brushes.moverPoses`), their entities'
// Transforms and their lighting origins follow. `playerWorld` gives the respawns.
void moverSystem(ecs::Registry& registry, const ecs::Tick& tick, MoverWorld& movers,
                 BrushWorld& brushes, const Tuning& tuning, const PlayerWorld& playerWorld,
                 ecs::Entity player);

// What a replay reads of a mover (its team master's): a binary mover at pos1, at pos2, or on its
// way; a train held at a corner (kAtPos1) or on a leg (kToPos2); others kAtPos1.
[[nodiscard]] MoverPhase moverPhase(const MoverWorld& movers, uint32_t index);

}  // namespace onelight::game
