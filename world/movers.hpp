// The level's movers: entities whose meshes (and, on a Quake 3 map, collision brushes) move as
// the game runs them (game/sim/movers.hpp), with what each needs to move by its game's rules:
// a glTF level's shuttles (extras.onelight.mover) and a Quake 3 map's doors, plats, buttons,
// bobbing, rotating and pendulum movers and trains (world/import/q3/mover_import.hpp). Metres,
// seconds, radians, world space, Y up. The package stores them in sections 43 and 44
// (package/format.hpp, package/mover_section.hpp).
#pragma once

#include <cstdint>
#include <vector>

#include <glm/glm.hpp>
#include <glm/gtc/quaternion.hpp>

#include "world/no_index.hpp"

namespace onelight::world {

enum class MoverKind : uint32_t {
    kShuttle = 0,   // pos1 -> pos2 -> pos1 every `period`, a triangle wave (a glTF level's)
    kDoor = 1,      // binary movers (Quake 3's Use_BinaryMover): rest at pos1, used -> pos2 in
    kPlat = 2,      //   travelSeconds, hold `wait`, back; a use while moving reverses it where
    kButton = 3,    //   it stands
    kBobbing = 4,   // origin = pos1 + amplitude sin(2 pi (t - phase period) / period)
    kRotating = 5,  // turns about `axis` at `speed` radians a second from t = 0
    kPendulum = 6,  // swings about `axis`: angle = speed sin(2 pi (t - phase period) / period)
    kTrain = 7,     // its origin from path point to path point (MoverPoint), looping
};
inline constexpr uint32_t kMoverKindCount = 8;

enum MoverFlags : uint32_t {
    kMoverCrusher = 1u << 0,    // a blocked door or plat keeps pushing instead of reversing
    kMoverShootable = 1u << 1,  // a door or button that a shot uses at rest (instead of a
                                // touch; Quake 3's health key)
};
inline constexpr uint32_t kAllMoverFlags = kMoverCrusher | kMoverShootable;

/// A binary mover's kind (door, plat, button).
[[nodiscard]] inline bool isBinaryMover(MoverKind kind) {
    return kind == MoverKind::kDoor || kind == MoverKind::kPlat || kind == MoverKind::kButton;
}

struct Mover {
    uint32_t entity = kNoIndex;  // into CompiledLevel::entities: its meshes, drawn at its origin
    MoverKind kind = MoverKind::kShuttle;
    uint32_t flags = 0;                // MoverFlags
    glm::vec3 pos1{0.0f};              // where its origin rests (shuttle, binary); bobbing,
                                       // rotating, pendulum: where it stays; train: unused (0)
    glm::vec3 pos2{0.0f};              // shuttle, binary: the other end; otherwise pos1
    glm::vec3 amplitude{0.0f};         // bobbing: the sine's peak offset; otherwise 0
    glm::vec3 axis{0.0f, 1.0f, 0.0f};  // rotating, pendulum: unit, world; otherwise +y
    float speed = 0.0f;                // rotating: radians a second; pendulum: peak angle, radians
    float period = 0.0f;               // shuttle, bobbing, pendulum: seconds, > 0; otherwise 0
    float phase = 0.0f;                // bobbing, pendulum: the cycle starts phase x period late
    float travelSeconds = 0.0f;        // binary: pos1 -> pos2 (and back), > 0; otherwise 0
    float wait = 0.0f;                 // binary: seconds held at pos2; < 0: back at once
    uint32_t teamMaster = kNoIndex;    // a team member's master (into movers): the master's use,
                                       // state and clock move it; kNoIndex: its own master
    uint32_t name = kNoIndex;          // the name others use it by (an id of the level's, e.g. a
                                       // Quake 3 targetname), or kNoIndex
    uint32_t target = kNoIndex;        // binary: on reaching pos2 it uses every mover of this name
    uint32_t firstPoint = 0, pointCount = 0;  // train: into LevelMovers::path, >= 2
};

/// A train's corner: its origin reaches `position`, holds `wait` seconds, then takes
/// `legSeconds` to the next point (the last point's leg goes back to the first).
struct MoverPoint {
    glm::vec3 position{0.0f};
    float wait = 0.0f;        // seconds, >= 0
    float legSeconds = 0.0f;  // > 0
};

struct LevelMovers {
    std::vector<Mover> movers;
    std::vector<MoverPoint> path;  // ranges owned by trains

    [[nodiscard]] bool empty() const { return movers.empty(); }
};

/// Where a mover's entity is: its origin (metres, world) and the turn applied after the entity's
/// own rotation (worldFromObject's).
struct MoverPose {
    glm::vec3 origin{0.0f};
    glm::quat turn{1.0f, 0.0f, 0.0f, 0.0f};
};

/// Poses that bound where `mover` goes (for the light grid's extent and the level's limits):
/// its ends, a bobber's peaks, a train's points, a pendulum's extremes and middle, a rotator's
/// turn in eighths. `movers` holds its path.
[[nodiscard]] std::vector<MoverPose> moverReach(const LevelMovers& movers, const Mover& mover);

}  // namespace onelight::world
