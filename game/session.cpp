#include "session.hpp"

#include <algorithm>
#include <array>
#include <cmath>

#include "shading.hpp"
#include "world/entity_transform.hpp"
#include "world/light_grid_sample.hpp"
#include "world/light_model.hpp"

namespace onelight::game {

namespace {

// The secondary (baked) illuminance on a surface at p with normal n: the light grid's ambient
// cube read along n (Valve's ambient cube: E(n) = sum_i n_i^2 cube[sign of n_i on axis i]), or
// the renderer's placeholder ambient for a level baked without a grid.
float secondaryIlluminance(const Session& s, glm::vec3 p, glm::vec3 n) {
    const world::LightGrid& grid = s.level->baked.grid;
    if (!s.level->hasBakedLighting || grid.cells.empty()) return s.secondaryLux;
    const std::array<glm::vec3, 6>& c = world::sampleLightGrid(grid, p).ambientCube;
    return glsl::luminance(glsl::irradianceAmbientCube(c[0], c[1], c[2], c[3], c[4], c[5], n));
}

}  // namespace

void startSession(Session& s, const assets::LoadedLevel& loaded) {
    s.level = &loaded;
    const world::CompiledLevel& level = loaded.level;
    s.bsp = world::bspView(level);
    if (!level.collision.brushes.empty()) s.tuning = quake3Tuning();
    s.brushes = makeBrushWorld(level.collision, level.movers.movers.size());
    s.world.fallLimitY = level.settings.boundsMin.y - s.tuning.fallMargin;
    for (const world::Entity& e : level.entities)
        if (e.flags & world::kEntitySpawn) {
            const glm::vec3 f = glm::normalize(e.rotation) * glm::vec3(0.0f, 0.0f, -1.0f);
            s.world.spawns.push_back({e.position, std::atan2(-f.x, -f.z)});
        }

    glm::vec3 feet = 0.5f * (level.settings.boundsMin + level.settings.boundsMax);
    glm::vec3 forward(0.0f, 0.0f, -1.0f);
    bool placed = false;
    for (const world::Entity& e : level.entities)
        if (!placed && (e.flags & world::kEntitySpawn)) {
            feet = e.position;
            forward = glm::normalize(e.rotation) * glm::vec3(0.0f, 0.0f, -1.0f);
            placed = true;
        }
    if (!placed && !level.cameras.empty()) {
        feet = level.cameras.front().position - glm::vec3(0.0f, s.tuning.eyeHeight, 0.0f);
        forward = glm::normalize(level.cameras.front().rotation) * glm::vec3(0.0f, 0.0f, -1.0f);
    }
    // On brushes a spawn sits 9 units up (Quake's SelectSpawnPoint), clear of the floor.
    if (!level.collision.brushes.empty()) feet.y += s.tuning.spawnLift;
    s.player = s.registry.create();
    s.registry.emplace<Name>(s.player, Name{"player"});
    s.registry.emplace<Transform>(s.player, Transform{feet});
    s.registry.emplace<Player>(s.player, Player{std::atan2(-forward.x, -forward.z),
                                                std::asin(std::clamp(forward.y, -1.0f, 1.0f))});
    s.registry.emplace<Flashlight>(s.player);
    s.registry.emplace<TriggerEvents>(s.player);

    std::vector<ecs::Entity> ecsOf(level.entities.size(), ecs::kNullEntity);
    for (uint32_t i = 0; i < level.entities.size(); ++i) {
        const world::Entity& e = level.entities[i];
        if (!(e.flags & world::kEntityDynamic)) continue;
        ecs::Entity entity = s.registry.create();
        ecsOf[i] = entity;
        s.registry.emplace<Name>(entity, Name{e.name});
        s.registry.emplace<Transform>(entity, Transform{e.position, e.scale});
        s.registry.emplace<LevelEntity>(entity, LevelEntity{i});
        s.registry.emplace<DynamicLighting>(entity);
        if (e.flags & world::kEntityItem) {
            Item item{e.position, e.itemRespawn, i};
            // An item whose box starts in a brush is left out, as the game leaves it out.
            if (!dropItem(level.collision.brushes.empty() ? nullptr : &s.brushes, e.position,
                          (e.flags & world::kEntitySuspended) != 0, item.rest)) {
                item.present = false;
                item.respawnSeconds = -1.0f;
            }
            s.registry.get<Transform>(entity).position = item.rest;
            DynamicLighting& lit = s.registry.get<DynamicLighting>(entity);
            lit.fixedOrigin = true;
            lit.origin = item.rest;
            s.registry.emplace<Item>(entity, item);
        }
    }
    std::vector<ecs::Entity> moverEntities;
    for (const world::Mover& mover : level.movers.movers)
        moverEntities.push_back(ecsOf[mover.entity]);
    s.movers = startMovers(level, std::move(moverEntities), &s.registry);
    for (uint32_t i = 0; i < level.lights.size(); ++i) {
        s.lightNames.push_back(level.lights[i].name);
        if (level.lights[i].role == world::LightRole::kPrimary) s.primaryCandidates.push_back(i);
    }
}

float primaryPickScore(const Session& s, uint32_t light, const glm::vec3& point) {
    const world::LightGrid& grid = s.level->baked.grid;
    if (!s.level->hasBakedLighting || grid.cells.empty()) return primaryScore(s, light, point);
    return world::gridPrimaryScore(s.level->level.lights, grid, world::sampleLightGrid(grid, point),
                                   light, point);
}

float primaryScore(const Session& s, uint32_t light, const glm::vec3& point) {
    const world::Light& l = s.level->level.lights[light];
    float e = world::unshadowedIlluminance(l, point);
    if (!(e > 0.0f)) return 0.0f;
    // Visibility: a ray from the point towards the light (1 km towards the sun).
    glm::dvec3 toLight = l.type == world::LightType::kDirectional
                             ? -glm::dvec3(l.direction) * 1000.0
                             : glm::dvec3(l.position) - glm::dvec3(point);
    double distance = glm::length(toLight);
    world::RayHit hit = world::raycast(s.bsp, glm::dvec3(point), toLight / distance, distance);
    return hit.hit ? 0.0f : e;
}

float meteredEv100(const Session& s, const render::Camera& camera, float fallback) {
    const world::CompiledLevel& level = s.level->level;
    const glm::vec3 eye = camera.position;
    double sumLog2 = 0.0;
    int hits = 0;
    for (int row = 0; row < 3; ++row)
        for (int column = 0; column < 5; ++column) {
            // A 5 x 3 grid over the central 70% of a 16:9 view with a 1-radian vertical field.
            float x = (column - 2) / 2.0f * 0.7f * std::tan(0.5f) * 16.0f / 9.0f;
            float y = (1 - row) * 0.7f * std::tan(0.5f);
            glm::vec3 d = glm::normalize(camera.rotation * glm::vec3(x, y, -1.0f));
            world::RayHit hit = world::raycast(s.bsp, glm::dvec3(eye), glm::dvec3(d), 200.0);
            if (!hit.hit) continue;
            const glm::vec3& a = s.bsp.vertices[s.bsp.indices[3 * hit.triangle]].position;
            const glm::vec3& b = s.bsp.vertices[s.bsp.indices[3 * hit.triangle + 1]].position;
            const glm::vec3& c = s.bsp.vertices[s.bsp.indices[3 * hit.triangle + 2]].position;
            glm::vec3 n = glm::normalize(glm::cross(b - a, c - a));
            if (glm::dot(n, d) > 0.0f) n = -n;  // the side the eye sees
            glm::vec3 p = eye + d * float(hit.t) + n * 0.02f;
            float illuminance = secondaryIlluminance(s, p, n);
            for (uint32_t light : s.primaryCandidates) {
                const world::LightAtPoint sample = world::evaluateLight(level.lights[light], p);
                float cosine = std::max(0.0f, glm::dot(n, sample.toLight));
                if (cosine > 0.0f) illuminance += cosine * primaryScore(s, light, p);
            }
            sumLog2 += double(std::log2(illuminance * 0.18f / glsl::PI * 100.0f / 12.5f));
            ++hits;
        }
    return hits ? std::clamp(float(sumLog2 / hits), 1.0f, 17.0f) : fallback;
}

namespace {

// The tick's last system: every dynamic object's primary, scored as the renderer draws it.
void selectPrimaries(Session& s, const ecs::Tick& tick) {
    primarySelectionSystem(
        s.registry, tick, s.primaryCandidates,
        [&s](uint32_t light, glm::vec3 p) { return primaryPickScore(s, light, p); });
}

}  // namespace

void stepSession(Session& s) {
    // The eye adapts to the metered exposure with a 0.4 s time constant (from the first tick
    // on, it starts adapted).
    if (!s.fixedExposure) {
        float target = meteredEv100(s, playerCamera(s), s.ev100);
        float rate = 1.0f - std::exp(-float(s.tickSeconds) / 0.4f);
        s.ev100 = s.tick == 0 ? target : s.ev100 + (target - s.ev100) * rate;
    }
    ecs::Tick tick{s.tick++, s.tickSeconds};
    s.world.surfaces = &s.bsp;
    s.world.brushes = s.level->level.collision.brushes.empty() ? nullptr : &s.brushes;
    moverSystem(s.registry, tick, s.movers, s.brushes, s.tuning, s.world, s.player);
    playerSystem(s.registry, tick, s.input, s.tuning, s.world);
    shotSystem(s.registry, s.input, s.tuning, s.movers, s.brushes);
    triggerSystem(s.registry, s.tuning, s.world, &s.movers);
    itemSystem(s.registry, tick, s.player);
    effectLightSystem(s.registry, tick, s.input, s.tuning, s.shotSerial);
    selectPrimaries(s, tick);
    s.input.endTick();
}

void pickPrimariesAtRest(Session& s) {
    selectPrimaries(s, ecs::Tick{s.tick, s.tickSeconds});
}

render::Camera playerCamera(const Session& s) {
    const Transform& t = s.registry.get<Transform>(s.player);
    const Player& p = s.registry.get<Player>(s.player);
    const glm::vec3 eye = eyeOf(t, s.tuning);
    render::Camera camera =
        render::cameraFromYawPitch(eye, glm::degrees(p.yaw), glm::degrees(p.pitch));
    camera.hasExposure = true;
    camera.ev100 = s.ev100;
    return camera;
}

render::FrameInputs frameInputsOf(const Session& s,
                                  std::vector<render::DynamicTransform>& transforms) {
    render::FrameInputs in;
    in.camera = playerCamera(s);
    const ecs::Registry& r = s.registry;

    for (auto [e, transform, flash] : r.view<Transform, GunFlash>().each()) {
        if (in.effects.omniCount >= render::kMaxEffectOmnis) break;
        render::EffectOmni& o = in.effects.omni[in.effects.omniCount++];
        o.position = transform.position;
        o.color = glm::vec3(1.0f, 0.75f, 0.45f);
        o.intensity = s.tuning.gunFlashIntensity;
        o.range = 12.0f;
    }
    const Flashlight& flashlight = r.get<Flashlight>(s.player);
    if (flashlight.on) {
        in.effects.spotOn = true;
        in.effects.spot.position = in.camera.position;
        in.effects.spot.direction = render::forwardOf(in.camera);
        in.effects.spot.color = glm::vec3(1.0f, 0.96f, 0.9f);
        in.effects.spot.intensity = s.tuning.flashlightIntensity;
        in.effects.spot.range = 30.0f;
        in.effects.spot.innerCone = glm::radians(s.tuning.flashlightInnerDeg);
        in.effects.spot.outerCone = glm::radians(s.tuning.flashlightOuterDeg);
    }

    transforms.clear();
    for (auto [e, transform, link] : r.view<Transform, LevelEntity>().each()) {
        render::DynamicTransform d;
        d.entity = link.index;
        d.worldFromObject = world::worldFromObject(
            s.level->level.entities[link.index], transform.position,
            transform.turn * glm::angleAxis(transform.yaw, glm::vec3(0.0f, 1.0f, 0.0f)));
        if (const DynamicLighting* lit = r.tryGet<DynamicLighting>(e)) {
            d.primary = lit->pick.primary;
            d.fadeWeight = primaryWeight(*lit, double(s.tick) * s.tickSeconds);
            if (d.fadeWeight < 1.0f) d.fadingFrom = lit->fadingFrom;
        }
        if (const Item* item = r.tryGet<Item>(e)) d.hidden = !item->present;
        transforms.push_back(d);
    }
    in.dynamicTransforms = transforms;
    return in;
}

}  // namespace onelight::game
