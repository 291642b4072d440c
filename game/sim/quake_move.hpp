// Quake 3's player movement on a map's brushes (bg_pmove.c PmoveSingle, PM_WalkMove, PM_AirMove,
// PM_Friction, PM_Accelerate, PM_GroundTrace; bg_slidemove.c PM_SlideMove, PM_StepSlideMove),
// rewritten in metres and Y up: ground acceleration and friction, air control, gravity
// integrated over the tick as Quake does (the mean of the start and end velocities: an exact
// parabola), sliding along up to five clip planes, stepping up stepHeight, floors whose normal.y
// >= maxSlopeCos, jumps that need the key released in between, and the knockback hold time after
// a teleport. Not modelled: water, ducking, crash-landing time, velocity snapping.
#pragma once

#include "brush_trace.hpp"
#include "components.hpp"
#include "tuning.hpp"

namespace onelight::game {

// What the player asks for in one tick.
struct MoveIntent {
    float forward = 0.0f;  // -1, 0 or 1 (S, W)
    float right = 0.0f;    // -1, 0 or 1 (A, D)
    bool jump = false;     // the jump key is down
};

// Moves the player's feet (`feet`) and `player` by one tick of `seconds` through `brushes`.
void quakeMove(const BrushWorld& brushes, const Tuning& tuning, float seconds,
               const MoveIntent& intent, glm::vec3& feet, Player& player);

}  // namespace onelight::game
