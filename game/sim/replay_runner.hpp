// Runs a parsed replay script against the simulation, tick by tick:
//   before the systems: key, look, fire, flashlight and spawn commands change the input/player;
//   after them: expect commands are checked, captures are requested, quit ends the replay.
// Names are resolved once, up front, so an unknown entity or light fails before anything runs.
#pragma once

#include <cstdint>
#include <stdexcept>
#include <string>
#include <vector>

#include "components.hpp"
#include "ecs/registry.hpp"
#include "input.hpp"
#include "replay/replay_script.hpp"
#include "tuning.hpp"

namespace onelight::game {

// A failed expectation or a name that does not resolve; what() is "PATH:LINE: ...".
struct ReplayFailure : std::runtime_error {
    using std::runtime_error::runtime_error;
};

struct ReplayRunner {
    replay::Script script;
    std::vector<std::string> lightNames;  // the level's lights, by index
    size_t next = 0;                      // first command not yet applied
    size_t nextCheck = 0;                 // first command not yet checked (post-systems)
    glm::vec3 origin{0.0f};  // the player's feet at the start or at the last spawn command
};

// Checks that every entity and light the script names exists (entities by their Name
// component); throws ReplayFailure naming the first that does not. Records where the entity
// named "player", if any, starts (ReplayRunner::origin).
[[nodiscard]] ReplayRunner makeReplayRunner(replay::Script script,
                                            std::vector<std::string> lightNames,
                                            const ecs::Registry& registry);

// Applies the commands due at `tick` that act before the systems.
void applyReplayInput(ReplayRunner& runner, uint64_t tick, InputState& input,
                      ecs::Registry& registry, ecs::Entity player, const Tuning& tuning);

struct ReplayAfterTick {
    std::vector<std::string> captures;  // capture names due at this tick, in script order
    bool quit = false;
};

// Checks the expectations due at `tick` (throws ReplayFailure with the line and both values)
// and returns the captures and whether to quit.
[[nodiscard]] ReplayAfterTick finishReplayTick(ReplayRunner& runner, uint64_t tick,
                                               const ecs::Registry& registry);

// Whether every command has run.
[[nodiscard]] bool replayFinished(const ReplayRunner& runner);

}  // namespace onelight::game
