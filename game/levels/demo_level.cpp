// The demo level: a sunlit courtyard (the sun is its primary), a room whose primary is a spot
// shining in through its doorway, and a corridor lit by an omni lamp. The floor of the room is
// glossy; a gold pedestal and a chrome pillar are metal; a crate moves from the courtyard into
// the room, crossing from the sun's region into the spot's. Metres, y up; lights in glTF units
// (lux for the sun, candela for the spot and the lamp). Exposure is set per camera: the sunlit
// yard and the lamplit corridor differ by eight stops.
//
//        z
//        ^      courtyard            room          corridor
//    +10 |  +-----------------+
//        |  |                 |----------+
//     +5 |  |   gold          |  pillar  |
//        |  |  pedestal   crate -> door  |-door----------------+
//      0 |  |   spawn         |   glossy |      lamp            |
//        |  |                 |   floor  |----------------------+
//     -5 |  |                 |----------+
//        |  +-----------------+
//    -10 +--+-----------------+----------+----------------------+--> x
//          -12                8         18                      30
#include "demo_level.hpp"

#include <filesystem>

#include <glm/gtc/quaternion.hpp>

#include "world/gltf/gltf_builder.hpp"

namespace onelight::game {

namespace {

using nlohmann::json;
using world::boxMesh;
using world::GltfBuilder;
using world::MeshData;

json vec(glm::vec3 v) {
    return json::array({v.x, v.y, v.z});
}

// The glTF rotation that turns the node's -z (where lights and cameras look) to `yaw` degrees
// about +y (0 looks down -z, positive turns left) and `pitch` degrees up.
json lookRotation(float yawDegrees, float pitchDegrees) {
    glm::quat q = glm::angleAxis(glm::radians(yawDegrees), glm::vec3(0, 1, 0)) *
                  glm::angleAxis(glm::radians(pitchDegrees), glm::vec3(1, 0, 0));
    return json::array({q.x, q.y, q.z, q.w});
}

// Yaw and pitch (degrees) of a unit direction, in lookRotation's convention.
glm::vec2 yawPitchOf(glm::vec3 d) {
    d = glm::normalize(d);
    return {glm::degrees(std::atan2(-d.x, -d.z)), glm::degrees(std::asin(d.y))};
}

json material(const char* name, glm::vec3 base, float metallic, float roughness) {
    return {{"name", name},
            {"pbrMetallicRoughness",
             {{"baseColorFactor", json::array({base.x, base.y, base.z, 1.0f})},
              {"metallicFactor", metallic},
              {"roughnessFactor", roughness}}}};
}

struct Level {
    GltfBuilder gltf;

    // A static box from lo to hi with material m.
    void box(const char* name, glm::vec3 lo, glm::vec3 hi, int m) {
        MeshData mesh = boxMesh(name, lo, hi, 1, false);
        mesh.material = m;
        gltf.addNode({{"name", name}, {"mesh", gltf.addMesh(mesh)}});
    }
    void light(const char* name, json light, glm::vec3 position, glm::vec3 direction,
               const char* role = nullptr) {
        light["name"] = name;
        glm::vec2 yp = yawPitchOf(direction);
        json node = {{"name", name},
                     {"translation", vec(position)},
                     {"rotation", lookRotation(yp.x, yp.y)},
                     {"extensions", {{"KHR_lights_punctual", {{"light", gltf.addLight(light)}}}}}};
        if (role) node["extras"] = {{"onelight", {{"role", role}}}};
        gltf.addNode(node);
    }
    void camera(const char* name, glm::vec3 position, float yaw, float pitch, float ev100) {
        int c = gltf.addCamera({{"name", name},
                                {"type", "perspective"},
                                {"perspective",
                                 {{"yfov", 1.0f},
                                  {"znear", 0.05f},
                                  {"zfar", 200.0f},
                                  {"aspectRatio", 16.0f / 9.0f}}}});
        gltf.addNode({{"name", name},
                      {"translation", vec(position)},
                      {"rotation", lookRotation(yaw, pitch)},
                      {"camera", c},
                      {"extras", {{"onelight", {{"exposure", ev100}}}}}});
    }
};

}  // namespace

std::string writeDemoLevel(const std::string& folder) {
    Level l;
    GltfBuilder& g = l.gltf;
    int stone = g.addMaterial(material("stone", {0.35f, 0.33f, 0.30f}, 0.0f, 0.85f));
    int plaster = g.addMaterial(material("plaster", {0.60f, 0.58f, 0.55f}, 0.0f, 0.9f));
    int tiles = g.addMaterial(material("glossy_tiles", {0.10f, 0.10f, 0.11f}, 0.0f, 0.12f));
    int gold = g.addMaterial(material("gold", {1.0f, 0.78f, 0.34f}, 1.0f, 0.30f));
    int chrome = g.addMaterial(material("chrome", {0.55f, 0.56f, 0.55f}, 1.0f, 0.08f));
    int wood = g.addMaterial(material("crate_wood", {0.45f, 0.30f, 0.18f}, 0.0f, 0.7f));

    // Courtyard: ground and walls on the north, south and west; the building closes the east.
    MeshData ground = world::gridMesh("courtyard_ground", 10, 20.0, 0.0, -2.0, 0.0);
    ground.material = stone;
    g.addNode({{"name", "courtyard_ground"}, {"mesh", g.addMesh(ground)}});
    l.box("yard_wall_north", {-12.4f, 0, -10.4f}, {8.3f, 5, -10}, plaster);
    l.box("yard_wall_south", {-12.4f, 0, 10}, {8.3f, 5, 10.4f}, plaster);
    l.box("yard_wall_west", {-12.4f, 0, -10}, {-12, 5, 10}, plaster);
    l.box("yard_wall_east_north", {8, 0, -10}, {8.3f, 5, -5.3f}, plaster);
    l.box("yard_wall_east_south", {8, 0, 5.3f}, {8.3f, 5, 10}, plaster);
    l.box("gold_pedestal", {-4, 0, -3}, {-3, 1.2f, -2}, gold);

    // The room: 10 x 10 x 4 m, a doorway 2 m wide and 3 m high to the west, 2.5 m to the east.
    l.box("room_floor", {8, -0.1f, -5}, {18, 0, 5}, tiles);
    l.box("room_wall_west_north", {8, 0, -5.3f}, {8.3f, 4, -1}, plaster);
    l.box("room_wall_west_south", {8, 0, 1}, {8.3f, 4, 5.3f}, plaster);
    l.box("room_lintel_west", {8, 3, -1}, {8.3f, 4, 1}, plaster);
    l.box("room_wall_north", {8.3f, 0, -5.3f}, {17.7f, 4, -5}, plaster);
    l.box("room_wall_south", {8.3f, 0, 5}, {17.7f, 4, 5.3f}, plaster);
    l.box("room_wall_east_north", {17.7f, 0, -5.3f}, {18, 4, -1}, plaster);
    l.box("room_wall_east_south", {17.7f, 0, 1}, {18, 4, 5.3f}, plaster);
    l.box("room_lintel_east", {17.7f, 2.5f, -1}, {18, 4, 1}, plaster);
    l.box("room_roof", {8, 4, -5.3f}, {18, 4.3f, 5.3f}, plaster);
    l.box("chrome_pillar", {14, 0, 2.5f}, {14.6f, 4, 3.1f}, chrome);

    // The corridor: 12 m long, 3 m wide, 2.5 m high.
    l.box("corridor_floor", {18, -0.1f, -1.5f}, {30, 0, 1.5f}, stone);
    l.box("corridor_wall_north", {18, 0, -1.8f}, {30, 2.5f, -1.5f}, plaster);
    l.box("corridor_wall_south", {18, 0, 1.5f}, {30, 2.5f, 1.8f}, plaster);
    l.box("corridor_wall_end", {30, 0, -1.8f}, {30.3f, 2.5f, 1.8f}, plaster);
    l.box("corridor_roof", {18, 2.5f, -1.8f}, {30.3f, 2.8f, 1.8f}, plaster);

    // The crate: dynamic, from the courtyard into the room and back every 8 s.
    MeshData crate = boxMesh("crate_1", {-0.5f, -0.5f, -0.5f}, {0.5f, 0.5f, 0.5f}, 1, false);
    crate.material = wood;
    g.addNode(
        {{"name", "crate_1"},
         {"mesh", g.addMesh(crate)},
         {"translation", vec({1.0f, 0.5f, 0.0f})},
         {"extras",
          {{"onelight",
            {{"dynamic", true}, {"mover", {{"offset", vec({12, 0, 0})}, {"period", 8.0f}}}}}}}});

    // Primaries: the sun (late afternoon, from the south-west), a spot through the west doorway,
    // the corridor's lamp. A dim fill in the room is baked only.
    l.light(
        "sun",
        {{"type", "directional"}, {"color", vec({1.0f, 0.95f, 0.88f})}, {"intensity", 60000.0f}},
        {0, 20, 0}, {0.62f, -0.62f, -0.48f});
    l.light("door_spot",
            {{"type", "spot"},
             {"color", vec({1.0f, 0.92f, 0.8f})},
             {"intensity", 20000.0f},
             {"spot", {{"innerConeAngle", 0.30f}, {"outerConeAngle", 0.45f}}}},
            {4.5f, 3.4f, 0.0f}, {7.5f, -3.0f, 0.0f});
    l.light("corridor_lamp",
            {{"type", "point"}, {"color", vec({1.0f, 0.85f, 0.7f})}, {"intensity", 400.0f}},
            {24, 2.2f, 0}, {0, -1, 0});
    l.light("room_fill",
            {{"type", "point"}, {"color", vec({0.8f, 0.85f, 1.0f})}, {"intensity", 150.0f}},
            {13, 3.5f, -3}, {0, -1, 0}, "baked");

    // Level settings: lightmap density (17 cm texels keep the bake to seconds at draft quality),
    // the default exposure and a clear sky (luminance 4,900 cd/m^2, bluish: about 15 klx on the
    // courtyard floor beside the sun's 60 klx).
    g.addNode({{"name", "level_settings"},
               {"extras",
                {{"onelight",
                  {{"texels_per_metre", 6.0f},
                   {"exposure", 13.0f},
                   {"sky", vec({4000.0f, 5000.0f, 6500.0f})}}}}}});

    // Cameras (with their exposure) and the player's spawn.
    l.camera("courtyard", {-10, 1.7f, 6}, -115, -4, 14.5f);
    l.camera("doorway", {3, 1.7f, 3}, -70, -6, 12.0f);
    l.camera("interior", {10, 2.0f, -3.5f}, -125, -12, 8.0f);
    l.camera("corridor", {19, 1.7f, 0}, -90, -3, 6.0f);
    g.addNode({{"name", "spawn"},
               {"translation", vec({-6, 0, 0})},
               {"rotation", lookRotation(-90, 0)},
               {"extras", {{"onelight", {{"spawn", true}}}}}});

    // Probes: one for the yard, a box-projected one for the room.
    g.addNode({{"name", "probe_yard"},
               {"translation", vec({-2, 2, 0})},
               {"extras", {{"onelight", {{"probe", true}}}}}});
    g.addNode(
        {{"name", "probe_room"},
         {"translation", vec({13, 2, 0})},
         {"extras",
          {{"onelight",
            {{"probe", {{"box_min", vec({8.3f, 0, -5})}, {"box_max", vec({17.7f, 4, 5})}}}}}}}});

    std::filesystem::create_directories(folder);
    return g.write(folder, "demo");
}

}  // namespace onelight::game
