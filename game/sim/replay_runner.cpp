#include "replay_runner.hpp"

#include <algorithm>
#include <cstdio>

#include "items.hpp"
#include "movers.hpp"

namespace onelight::game {

namespace {

using replay::Command;
using replay::CommandKind;

std::string place(const ReplayRunner& r, const Command& c) {
    return r.script.path + ":" + std::to_string(c.line) + ": ";
}

ecs::Entity findNamed(const ecs::Registry& registry, const std::string& name) {
    for (auto [e, n] : registry.view<Name>().each())
        if (n.value == name) return e;
    return ecs::kNullEntity;
}

bool actsBeforeSystems(CommandKind k) {
    return k == CommandKind::kSpawn || k == CommandKind::kKey || k == CommandKind::kLook ||
           k == CommandKind::kFire || k == CommandKind::kFlashlight;
}

std::string vectorText(glm::vec3 v) {
    char text[96];
    std::snprintf(text, sizeof text, "(%.4f %.4f %.4f)", double(v.x), double(v.y), double(v.z));
    return text;
}

// The player expectations of Quake movement and triggers (replay_script.hpp).
void checkPlayer(const ReplayRunner& r, const Command& c, const ecs::Registry& registry) {
    const ecs::Entity player = findNamed(registry, "player");
    if (player == ecs::kNullEntity || !registry.allOf<Player, Transform>(player))
        throw ReplayFailure(place(r, c) + "there is no player");
    const glm::vec3 feet = registry.get<Transform>(player).position;
    const Player& p = registry.get<Player>(player);
    const std::string at = " (feet at " + vectorText(feet) + ", velocity " +
                           vectorText(p.velocity) +
                           (p.onGround ? ", on the ground)" : ", in the air)");
    const glm::vec3 expected(c.values[0], c.values[1], c.values[2]);
    switch (c.kind) {
        case CommandKind::kExpectInAir:
            if (p.onGround)
                throw ReplayFailure(place(r, c) + "expected the player in the air" + at);
            return;
        case CommandKind::kExpectFeet:
        case CommandKind::kExpectVelocity: {
            const bool isFeet = c.kind == CommandKind::kExpectFeet;
            const glm::vec3 actual = isFeet ? feet : p.velocity;
            const float off = glm::length(actual - expected);
            if (!(off <= c.values[3]))
                throw ReplayFailure(place(r, c) + "expected the player's " +
                                    (isFeet ? "feet at " : "velocity ") + vectorText(expected) +
                                    " within " + std::to_string(c.values[3]) + ", found " +
                                    vectorText(actual) + ", " + std::to_string(off) + " off" + at);
            return;
        }
        case CommandKind::kExpectHeight:
            if (!(feet.y >= c.values[0] && feet.y <= c.values[1]))
                throw ReplayFailure(place(r, c) + "expected the feet's height from " +
                                    std::to_string(c.values[0]) + " to " +
                                    std::to_string(c.values[1]) + " m, found " +
                                    std::to_string(feet.y) + at);
            return;
        default: {
            const TriggerEvents* events = registry.tryGet<TriggerEvents>(player);
            const TriggerEvents none;
            const TriggerEvents& e = events ? *events : none;
            const char* what = c.kind == CommandKind::kExpectTeleports  ? "teleports"
                               : c.kind == CommandKind::kExpectLaunches ? "jump pad launches"
                                                                        : "respawns";
            const uint32_t n = c.kind == CommandKind::kExpectTeleports  ? e.teleports
                               : c.kind == CommandKind::kExpectLaunches ? e.jumpPadLaunches
                                                                        : e.respawns;
            if (n != uint32_t(c.count))
                throw ReplayFailure(place(r, c) + "expected " + std::to_string(c.count) + " " +
                                    what + ", found " + std::to_string(n) + at);
            return;
        }
    }
}

}  // namespace

ReplayRunner makeReplayRunner(replay::Script script, std::vector<std::string> lightNames,
                              const ecs::Registry& registry) {
    ReplayRunner r{std::move(script), std::move(lightNames)};
    const ecs::Entity player = findNamed(registry, "player");
    if (player != ecs::kNullEntity && registry.allOf<Transform>(player))
        r.origin = registry.get<Transform>(player).position;
    for (const Command& c : r.script.commands) {
        if (c.kind == CommandKind::kExpectMover || c.kind == CommandKind::kExpectRiding) {
            const ecs::Entity e = findNamed(registry, c.name);
            if (e == ecs::kNullEntity || !registry.allOf<MoverState>(e))
                throw ReplayFailure(place(r, c) + "unknown mover '" + c.name +
                                    "' (the level's movers are named CLASSNAME_N, e.g. "
                                    "func_door_1)");
            continue;
        }
        if (c.kind == CommandKind::kExpectItem) {
            const ecs::Entity e = findNamed(registry, c.name);
            if (e == ecs::kNullEntity || !registry.allOf<Item>(e))
                throw ReplayFailure(place(r, c) + "unknown item '" + c.name +
                                    "' (the level's items are named CLASSNAME_N, e.g. "
                                    "weapon_rocketlauncher_1)");
            continue;
        }
        if (c.kind != CommandKind::kExpectPrimary) continue;
        ecs::Entity e = findNamed(registry, c.name);
        if (e == ecs::kNullEntity)
            throw ReplayFailure(place(r, c) + "unknown entity '" + c.name + "'");
        if (!registry.allOf<DynamicLighting>(e))
            throw ReplayFailure(place(r, c) + "entity '" + c.name +
                                "' is not a dynamic object (it has no primary to pick)");
        if (std::find(r.lightNames.begin(), r.lightNames.end(), c.light) == r.lightNames.end())
            throw ReplayFailure(place(r, c) + "unknown light '" + c.light + "'");
    }
    return r;
}

void applyReplayInput(ReplayRunner& r, uint64_t tick, InputState& input, ecs::Registry& registry,
                      ecs::Entity player, const Tuning& tuning) {
    const auto& commands = r.script.commands;
    for (; r.next < commands.size() && commands[r.next].tick <= tick; ++r.next) {
        const Command& c = commands[r.next];
        switch (c.kind) {
            case CommandKind::kKey:
                if (c.on) {
                    input.keysDown.insert(c.name);
                } else {
                    input.keysDown.erase(c.name);
                }
                if (c.name == "F" && c.on) input.toggleFlashlight = true;
                break;
            case CommandKind::kLook:
                input.lookYawDegrees += c.values[0];
                input.lookPitchDegrees += c.values[1];
                break;
            case CommandKind::kFire:
                input.fire = true;
                break;
            case CommandKind::kFlashlight:
                input.setFlashlight = true;
                input.flashlightValue = c.on;
                break;
            case CommandKind::kSpawn: {
                // The script gives the eye; the player's Transform is at the feet.
                registry.get<Transform>(player).position =
                    glm::vec3(c.values[0], c.values[1] - tuning.eyeHeight, c.values[2]);
                Player& p = registry.get<Player>(player);
                p.yaw = glm::radians(c.values[3]);
                p.pitch = glm::radians(c.values[4]);
                p.velocity = glm::vec3(0.0f);
                r.origin = registry.get<Transform>(player).position;
                break;
            }
            default:
                break;  // handled after the systems
        }
    }
}

ReplayAfterTick finishReplayTick(ReplayRunner& r, uint64_t tick, const ecs::Registry& registry) {
    ReplayAfterTick after;
    const auto& commands = r.script.commands;
    for (; r.nextCheck < commands.size() && commands[r.nextCheck].tick <= tick; ++r.nextCheck) {
        const Command& c = commands[r.nextCheck];
        if (actsBeforeSystems(c.kind)) continue;
        switch (c.kind) {
            case CommandKind::kCapture:
                after.captures.push_back(c.name);
                break;
            case CommandKind::kQuit:
                after.quit = true;
                break;
            case CommandKind::kExpectEffectLights: {
                const auto* pool = registry.findPool<GunFlash>();
                size_t flashes = pool ? pool->size() : 0;
                size_t spots = 0;
                for (auto [e, f] : registry.view<Flashlight>().each()) spots += f.on;
                size_t live = flashes + spots;
                if (live != size_t(c.count))
                    throw ReplayFailure(place(r, c) + "expected " + std::to_string(c.count) +
                                        " effect lights, found " + std::to_string(live) + " (" +
                                        std::to_string(flashes) + " gun flashes, " +
                                        std::to_string(spots) + " flashlight)");
                break;
            }
            case CommandKind::kExpectInAir:
            case CommandKind::kExpectFeet:
            case CommandKind::kExpectHeight:
            case CommandKind::kExpectVelocity:
            case CommandKind::kExpectTeleports:
            case CommandKind::kExpectLaunches:
            case CommandKind::kExpectRespawns:
                checkPlayer(r, c, registry);
                break;
            case CommandKind::kExpectItem: {
                const Item& item = registry.get<Item>(findNamed(registry, c.name));
                if (item.present != c.on)
                    throw ReplayFailure(place(r, c) + "expected item '" + c.name + "' " +
                                        (c.on ? "visible" : "taken") + ", but it is " +
                                        (item.present ? "visible" : "taken") + " (taken " +
                                        std::to_string(item.timesTaken) + " times so far)");
                break;
            }
            case CommandKind::kExpectMover: {
                static constexpr const char* kWords[] = {"rest", "open", "moving"};
                const MoverPhase phase =
                    registry.get<MoverState>(findNamed(registry, c.name)).phase;
                const int found = phase == MoverPhase::kAtPos1   ? 0
                                  : phase == MoverPhase::kAtPos2 ? 1
                                                                 : 2;
                if (found != c.count)
                    throw ReplayFailure(place(r, c) + "expected mover '" + c.name + "' " +
                                        kWords[c.count] + ", but it is " + kWords[found]);
                break;
            }
            case CommandKind::kExpectRiding: {
                const ecs::Entity player = findNamed(registry, "player");
                if (player == ecs::kNullEntity || !registry.allOf<Player>(player))
                    throw ReplayFailure(place(r, c) + "there is no player");
                const uint32_t mover = registry.get<MoverState>(findNamed(registry, c.name)).index;
                const uint32_t ground = registry.get<Player>(player).groundMover;
                if (ground != mover) {
                    std::string on = "on no mover";
                    for (auto [e, name, state] : registry.view<Name, MoverState>().each())
                        if (state.index == ground) on = "on " + name.value;
                    throw ReplayFailure(place(r, c) + "expected the player riding '" + c.name +
                                        "', but it stands " + on);
                }
                break;
            }
            case CommandKind::kExpectOnGround:
            case CommandKind::kExpectMoved: {
                const ecs::Entity player = findNamed(registry, "player");
                if (player == ecs::kNullEntity || !registry.allOf<Player, Transform>(player))
                    throw ReplayFailure(place(r, c) + "there is no player");
                const glm::vec3 feet = registry.get<Transform>(player).position;
                const std::string at = "(feet at " + std::to_string(feet.x) + " " +
                                       std::to_string(feet.y) + " " + std::to_string(feet.z) + ")";
                if (c.kind == CommandKind::kExpectOnGround) {
                    if (!registry.get<Player>(player).onGround)
                        throw ReplayFailure(place(r, c) + "expected the player on the ground " +
                                            at + ", but it is in the air");
                    break;
                }
                const float moved =
                    glm::length(glm::vec2(feet.x - r.origin.x, feet.z - r.origin.z));
                if (!(moved >= c.values[0]))
                    throw ReplayFailure(place(r, c) + "expected the player to have moved " +
                                        std::to_string(c.values[0]) + " m or more, found " +
                                        std::to_string(moved) + " m " + at);
                break;
            }
            case CommandKind::kExpectPrimary: {
                const DynamicLighting& lit =
                    registry.get<DynamicLighting>(findNamed(registry, c.name));
                std::string actual = lit.pick.primary < r.lightNames.size()
                                         ? r.lightNames[lit.pick.primary]
                                         : std::string("none");
                if (actual != c.light)
                    throw ReplayFailure(place(r, c) + "expected primary " + c.name +
                                        " == " + c.light + ", found " + actual);
                break;
            }
            default:
                break;
        }
    }
    return after;
}

bool replayFinished(const ReplayRunner& r) {
    return r.next >= r.script.commands.size() && r.nextCheck >= r.script.commands.size();
}

}  // namespace onelight::game
