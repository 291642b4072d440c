// The dynamic objects a frame drew, read from its capture's JSON (`onelight --capture`'s
// "dynamic_objects": entity index and name, world-from-object matrix), so that the reference
// traces them where the frame drew them: an item dropped to the floor by the game is not where
// its node puts it.
#pragma once

#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "world/compile/static_split.hpp"
#include "world/static_geometry.hpp"

namespace onelight::bake {

struct FramePose {
    uint32_t entity = 0;  // into the level's entities
    std::string name;     // the entity's, checked against the level's
    glm::mat4 worldFromObject{1.0f};
};

/// Throws world::Error naming `path` and the entry when the file is not a capture's JSON with a
/// "dynamic_objects" list of {entity, name, world_from_object: 16 finite numbers}.
[[nodiscard]] std::vector<FramePose> readFramePoses(const std::string& path);

/// Appends each posed entity's dynamic meshes to `geometry`, in world space; with `items`, an
/// item's (world::kEntityItem: drawn by the frame without shadows, as Quake 3 draws them) go
/// there instead, for a scene that camera rays alone see (traceRadiance's `seenOnly`). Throws
/// world::Error naming `path` when a pose's entity is not in `split` or its name differs (the
/// capture is of another level).
void appendPosedDynamicMeshes(const world::SplitLevel& split, const std::vector<FramePose>& poses,
                              const std::string& path, world::StaticGeometry& geometry,
                              world::StaticGeometry* items = nullptr);

}  // namespace onelight::bake
