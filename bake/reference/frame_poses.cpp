#include "bake/reference/frame_poses.hpp"

#include <cmath>

#include <nlohmann/json.hpp>

#include "world/error.hpp"
#include "world/file_read.hpp"

namespace onelight::bake {

std::vector<FramePose> readFramePoses(const std::string& path) {
    const std::vector<uint8_t> bytes =
        world::readRegularFile(path, "a frame capture's JSON", 64 << 20);
    const nlohmann::json j = nlohmann::json::parse(bytes.begin(), bytes.end(), nullptr, false);
    if (j.is_discarded() || !j.is_object() || !j.contains("dynamic_objects") ||
        !j["dynamic_objects"].is_array())
        throw world::Error(path +
                           ": not a frame capture's JSON; expected the NAME.json of `onelight "
                           "--capture` with a \"dynamic_objects\" list");
    std::vector<FramePose> poses;
    const nlohmann::json& list = j["dynamic_objects"];
    for (size_t i = 0; i < list.size(); ++i) {
        const nlohmann::json& o = list[i];
        const std::string where = path + ": dynamic_objects[" + std::to_string(i) + "]";
        if (!o.is_object() || !o.contains("entity") || !o["entity"].is_number_unsigned() ||
            !o.contains("name") || !o["name"].is_string() || !o.contains("world_from_object") ||
            !o["world_from_object"].is_array() || o["world_from_object"].size() != 16)
            throw world::Error(where +
                               ": expected {\"entity\": index, \"name\": text, "
                               "\"world_from_object\": 16 numbers}");
        FramePose pose;
        const uint64_t entity = o["entity"].get<uint64_t>();
        if (entity > UINT32_MAX)
            throw world::Error(where + ": entity " + std::to_string(entity) + " is out of range");
        pose.entity = uint32_t(entity);
        pose.name = o["name"].get<std::string>();
        for (int k = 0; k < 16; ++k) {
            const nlohmann::json& value = o["world_from_object"][size_t(k)];
            if (!value.is_number() || !std::isfinite(value.get<double>()))
                throw world::Error(where + ": world_from_object[" + std::to_string(k) +
                                   "] is not a finite number");
            pose.worldFromObject[k / 4][k % 4] = value.get<float>();
        }
        poses.push_back(std::move(pose));
    }
    return poses;
}

void appendPosedDynamicMeshes(const world::SplitLevel& split, const std::vector<FramePose>& poses,
                              const std::string& path, world::StaticGeometry& geometry,
                              world::StaticGeometry* items) {
    for (size_t i = 0; i < poses.size(); ++i) {
        const FramePose& pose = poses[i];
        const std::string where = path + ": dynamic_objects[" + std::to_string(i) + "]";
        if (pose.entity >= split.entities.size())
            throw world::Error(where + ": entity " + std::to_string(pose.entity) +
                               " is not in the level (it has " +
                               std::to_string(split.entities.size()) +
                               " entities): a capture of another level?");
        const world::Entity& entity = split.entities[pose.entity];
        if (entity.name != pose.name)
            throw world::Error(where + ": entity " + std::to_string(pose.entity) + " is '" +
                               world::clipForMessage(entity.name) + "' in the level, not '" +
                               world::clipForMessage(pose.name) + "': a capture of another level?");
        const world::InstanceTransform transform =
            world::instanceTransformOf(glm::dmat4(pose.worldFromObject));
        world::StaticGeometry& into =
            items && (entity.flags & world::kEntityItem) ? *items : geometry;
        for (uint32_t k = 0; k < entity.dynamicMeshCount; ++k) {
            const world::DynamicMesh& mesh = split.dynamicMeshes.at(entity.firstDynamicMesh + k);
            const uint32_t base = uint32_t(into.vertices.size());
            for (uint32_t v = 0; v < mesh.vertexCount; ++v)
                into.vertices.push_back(world::worldVertexOf(
                    split.dynamicVertices.at(mesh.firstVertex + v), transform));
            for (uint32_t t = 0; t + 2 < mesh.indexCount; t += 3) {
                world::StaticTriangle triangle;
                for (uint32_t c = 0; c < 3; ++c) {
                    // A mirror flips the winding: swap two corners to keep counter-clockwise
                    // fronts.
                    const uint32_t corner = transform.mirrored && c > 0 ? 3 - c : c;
                    const uint32_t index = split.dynamicIndices.at(mesh.firstIndex + t + corner);
                    if (index >= mesh.vertexCount)
                        throw world::Error(where + ": mesh '" + world::clipForMessage(mesh.name) +
                                           "' has an index past its vertices");
                    triangle.v[c] = base + index;
                }
                triangle.material = mesh.material;
                into.triangles.push_back(triangle);
            }
        }
    }
}

}  // namespace onelight::bake
