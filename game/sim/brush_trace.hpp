// A box swept through a level's collision brushes (world/collision.hpp), as Quake 3's
// CM_TraceThroughBrush does (cm_trace.c): each side's plane is pushed out by the box's support
// along its normal, the box stops `epsilon` short of the first plane it enters, and a start
// inside a brush is reported.
#pragma once

#include <vector>

#include <glm/glm.hpp>

#include "world/collision.hpp"

namespace onelight::game {

// The brushes with each one's box (from its axis-aligned sides; unbounded where it has none),
// for a quick rejection.
struct BrushWorld {
    const world::LevelCollision* collision = nullptr;  // borrowed
    std::vector<glm::vec3> brushMin, brushMax;         // per brush, metres
};

[[nodiscard]] BrushWorld makeBrushWorld(const world::LevelCollision& collision);

struct BoxTrace {
    float fraction = 1.0f;    // of the move done, [0, 1]
    glm::vec3 end{0.0f};      // start + fraction (end - start)
    glm::vec3 normal{0.0f};   // the plane it stopped at (when fraction < 1)
    bool startSolid = false;  // the box starts inside a brush
    bool allSolid = false;    // ... and stays inside it
};

// Sweeps the box [start + mins, start + maxs] to `end` through the brushes.
[[nodiscard]] BoxTrace traceBox(const BrushWorld& world, glm::vec3 start, glm::vec3 end,
                                glm::vec3 mins, glm::vec3 maxs, float epsilon);

}  // namespace onelight::game
