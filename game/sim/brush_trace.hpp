// A box swept through a level's collision brushes (world/collision.hpp), as Quake 3's
// CM_TraceThroughBrush does (cm_trace.c): each side's plane is pushed out by the box's support
// along its normal, the box stops `epsilon` short of the first plane it enters, and a start
// inside a brush is reported. Movers' brushes move with their poses (CM_TransformedBoxTrace).
#pragma once

#include <vector>

#include <glm/glm.hpp>
#include <glm/gtc/quaternion.hpp>

#include "world/collision.hpp"

namespace onelight::game {

// Where a mover's brushes are: world = origin + rotation * object (the mover's pose and its
// entity's rotation; Quake 3 movers are never scaled).
struct BrushPose {
    glm::vec3 origin{0.0f};
    glm::quat rotation{1.0f, 0.0f, 0.0f, 0.0f};
};

// The brushes with each one's box in its own space (from its axis-aligned sides; unbounded where
// it has none), for a quick rejection, and the movers' poses this tick.
struct BrushWorld {
    const world::LevelCollision* collision = nullptr;  // borrowed
    std::vector<glm::vec3> brushMin, brushMax;         // per brush, metres
    std::vector<BrushPose> moverPoses;  // per mover of the level (world::LevelMovers): where its
                                        // brushes are; the game's mover system moves them
};

// `moverCount`: the level's movers, each at rest at the origin until the mover system places it.
[[nodiscard]] BrushWorld makeBrushWorld(const world::LevelCollision& collision,
                                        size_t moverCount = 0);

struct BoxTrace {
    float fraction = 1.0f;             // of the move done, [0, 1]
    glm::vec3 end{0.0f};               // start + fraction (end - start)
    glm::vec3 normal{0.0f};            // the plane it stopped at (when fraction < 1)
    bool startSolid = false;           // the box starts inside a brush
    bool allSolid = false;             // ... and stays inside it
    uint32_t mover = world::kNoIndex;  // the mover whose brush it stopped at; kNoIndex: the
                                       // world's, or none
};

// Which brushes a trace meets.
enum class TraceBrushes {
    kAll,       // the world's and every mover's
    kOneMover,  // only mover `TraceFilter::mover`'s
    kButMover,  // all but mover `TraceFilter::mover`'s
};
struct TraceFilter {
    TraceBrushes brushes = TraceBrushes::kAll;
    uint32_t mover = world::kNoIndex;
    uint32_t contents = world::kPlayerSolidContents;  // brushes with any of these (a shot:
                                                      // kContentsSolid, through player clips)
};

// Sweeps the box [start + mins, start + maxs] to `end` through the brushes. A mover's brushes
// are met in its object space; a turned mover's are swept by the box's bounds in that space
// (Quake 3 sweeps a turned mover with a sphere; both are a little wider than the box).
[[nodiscard]] BoxTrace traceBox(const BrushWorld& world, glm::vec3 start, glm::vec3 end,
                                glm::vec3 mins, glm::vec3 maxs, float epsilon,
                                TraceFilter filter = {});

}  // namespace onelight::game
