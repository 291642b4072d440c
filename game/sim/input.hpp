// What the player does during one tick, from the keyboard and mouse or from a replay.
#pragma once

#include <set>
#include <string>

namespace onelight::game {

struct InputState {
    std::set<std::string> keysDown;  // "W", "A", "S", "D", "SPACE", ...
    float lookYawDegrees = 0.0f;     // accumulated this tick, positive turns left
    float lookPitchDegrees = 0.0f;   // positive looks up
    bool fire = false;               // a shot this tick
    bool toggleFlashlight = false;   // F pressed this tick
    bool setFlashlight = false;      // a replay's explicit on/off...
    bool flashlightValue = false;    // ...and its value

    bool down(const std::string& key) const { return keysDown.count(key) != 0; }
    // Clears the one-tick events, keeping held keys.
    void endTick() {
        lookYawDegrees = lookPitchDegrees = 0.0f;
        fire = toggleFlashlight = setFlashlight = false;
    }
};

}  // namespace onelight::game
