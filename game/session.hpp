// A game in progress on a loaded level: the ECS world, the player, the fixed tick, and what each
// frame hands the renderer. The same inputs, tick by tick, give the same state and frames.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "assets/level_assets.hpp"
#include "render/renderer.hpp"
#include "sim/components.hpp"
#include "sim/input.hpp"
#include "sim/items.hpp"
#include "sim/systems.hpp"
#include "sim/tuning.hpp"

namespace onelight::game {

// Links an ECS entity to its record in the level (for the renderer's dynamic meshes).
struct LevelEntity {
    uint32_t index = 0;  // into level.entities
};

struct Session {
    const assets::LoadedLevel* level = nullptr;  // borrowed
    world::BspView bsp;                          // collision (glTF levels) and visibility
    BrushWorld brushes;  // a Quake 3 map's collision brushes and triggers (empty otherwise)
    PlayerWorld world;   // what the player moves through; its pointers are set each tick
    MoverWorld movers;   // the level's movers as they run
    ecs::Registry registry;
    ecs::Entity player = ecs::kNullEntity;
    Tuning tuning;
    InputState input;
    uint64_t tick = 0;  // the next tick to run
    double tickSeconds = 1.0 / 60.0;
    uint64_t shotSerial = 0;                  // gun flashes fired so far
    std::vector<uint32_t> primaryCandidates;  // lights that may be a dynamic object's primary
    std::vector<std::string> lightNames;      // by light index
    float ev100 = 0.0f;                       // the player's adapted exposure
    bool fixedExposure = false;               // ev100 is given (--ev100), not metered
    float secondaryLux = 30.0f;  // secondary illuminance the meter adds (the renderer's ambient)
};

// Sets up the player (at the level's spawn, else its first camera, else its centre) and one
// entity per dynamic object of the level. A level with collision brushes (a Quake 3 map) plays
// with quake3Tuning() on them; others with the default tuning on their drawn surfaces.
void startSession(Session& session, const assets::LoadedLevel& level);

// Runs one fixed tick: movers, player, its shot, triggers, items, effect lights, primary selection;
// then clears the tick's one-shot input.
void stepSession(Session& session);

// Picks every dynamic object's primary where it stands, as the tick's last system does, with no
// time passing: what a view of the level (not a game) draws them with.
void pickPrimariesAtRest(Session& session);

// The player's eye as a camera, with the adapted exposure.
[[nodiscard]] render::Camera playerCamera(const Session& session);

// The exposure a reflected-light meter in `camera`'s view asks for: 15 rays across the view
// find the surfaces it sees; each surface's luminance is the shadowed illuminance of every
// primary on it (its own normal) plus the baked secondary light there (the light grid's ambient
// cube along the normal; session.secondaryLux without a grid), on a middle-grey (18%)
// Lambertian surface; EV100 = log2(L * S / K) of their geometric
// mean, S = 100, K = 12.5 (ISO 2720; Lagarde and de Rousiers 2014, sec. 5.1). Keeps `fallback`
// when the view sees no surface.
[[nodiscard]] float meteredEv100(const Session& session, const render::Camera& camera,
                                 float fallback);

// The renderer's inputs for the current state; `transforms` holds what frame.dynamicTransforms
// points to.
[[nodiscard]] render::FrameInputs frameInputsOf(const Session& session,
                                                std::vector<render::DynamicTransform>& transforms);

// The shadowed contribution of primary `light` at `point`: its illuminance (luminance, lux) by
// the shared light model times its visibility along a ray through the BSP.
[[nodiscard]] float primaryScore(const Session& session, uint32_t light, const glm::vec3& point);

// What a dynamic object's primary is picked by (and handed to the renderer with): with a light
// grid, the grid's answer — the light's illuminance times its baked visibility where it is the
// dominant primary of the surrounding cells, as the renderer scores it; without one,
// primaryScore.
[[nodiscard]] float primaryPickScore(const Session& session, uint32_t light,
                                     const glm::vec3& point);

}  // namespace onelight::game
