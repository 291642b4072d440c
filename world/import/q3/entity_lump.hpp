// The BSP's entity lump: { "key" "value" ... } blocks, one per entity (worldspawn first).
#pragma once

#include <map>
#include <string>
#include <vector>

#include <glm/glm.hpp>

namespace onelight::world::q3 {

struct MapEntity {
    std::map<std::string, std::string> keys;
    int line = 0;  // where its '{' is, for messages
    [[nodiscard]] std::string get(const std::string& key, const std::string& fallback = {}) const;
};

/// Throws world::Error "where: entities line N: ..." on a malformed lump.
[[nodiscard]] std::vector<MapEntity> parseEntities(const std::string& text,
                                                   const std::string& where);

/// A number or three numbers of an entity's key ("300", "0.5 1 1"); `fallback` when absent or
/// empty (Nexuiz's racetrack has "spawnflags" ""). Throws world::Error naming the entity's line
/// and the key when it is not that.
[[nodiscard]] float numberKey(const MapEntity& e, const std::string& key, float fallback,
                              const std::string& where);
[[nodiscard]] glm::vec3 vectorKey(const MapEntity& e, const std::string& key, glm::vec3 fallback,
                                  const std::string& where);

/// The first number of a key as q3map2 reads it (atof): "_light" "255 200 150 400", the
/// Half-Life form some Nexuiz sources use, is 255 to q3map2. `*more` is set when numbers follow.
[[nodiscard]] float firstNumberKey(const MapEntity& e, const std::string& key, float fallback,
                                   const std::string& where, bool* more);

}  // namespace onelight::world::q3
