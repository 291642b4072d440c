// The game's constants, in SI units, in one place.
#pragma once

namespace onelight::game {

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
};

}  // namespace onelight::game
